/// @file spatiotemporal/body_layout.h
/// @brief `Body_layout`: what the spatio-temporal segmentation needs of a mesh besides its strain:
/// each triangle's neighbours (shared edges and links between parts) and its share of the area
/// (@ref method_spatiotemporal): `Body_layout`, `body_layout`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/spatiotemporal/internal/face_adjacency.h>
#include <deformseg/spatiotemporal/part_links.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::spatiotemporal {

/// @brief The triangles of a mesh as the segmentation sees them: two triangles are neighbours
/// when they share an edge (the thesis) or are linked (`part_links`: parts that touch or move as
/// one), and each weighs its share of the mesh's area.
class Body_layout {
public:
  /// @brief The layout of `triangles`.
  /// @param triangles the face-vertex index table (for a `Deforming_mesh`, its `triangles()`).
  /// @param face_areas each triangle's area (typically at the rest pose; any scale); empty
  /// (default): every triangle weighs the same.
  /// @param links pairs of triangles that are neighbours besides those sharing an edge; empty
  /// (default): shared edges only, the thesis' adjacency.
  /// @pre `face_areas` empty or of `triangles.size()` finite entries >= 0 with a positive sum;
  /// every link names two triangles. Else throws `invalid_input`.
  /// @par Complexity O((F + L) log(F + L)) for F triangles and L links.
  explicit Body_layout(std::span<const std::array<std::uint32_t, 3>> triangles, std::span<const double> face_areas = {},
                       std::span<const std::pair<std::uint32_t, std::uint32_t>> links = {})
      : adjacency_(internal::face_adjacency(triangles, checked(links, triangles.size()))),
        area_shares_(shares(face_areas, triangles.size())),
        links_(links.size()) {}

  /// @brief The number of triangles F.
  std::size_t num_faces() const noexcept { return area_shares_.size(); }
  /// @brief The number of links it was given.
  std::size_t num_links() const noexcept { return links_; }
  /// @brief The neighbours of triangle `face`, ascending. @pre `face < num_faces()` (unchecked).
  std::span<const std::uint32_t> neighbours(std::size_t face) const { return adjacency_.of(face); }
  /// @brief Each triangle's share of the area, summing to 1.
  std::span<const double> area_shares() const noexcept { return area_shares_; }

private:
  static std::span<const std::pair<std::uint32_t, std::uint32_t>> checked(
      std::span<const std::pair<std::uint32_t, std::uint32_t>> links, std::size_t faces) {
    for (const auto& [f, g] : links)
      if (f >= faces || g >= faces)
        throw invalid_input("Body_layout: the link " + std::to_string(f) + "-" + std::to_string(g) + " names a triangle beyond the " +
                            std::to_string(faces) + " triangles");
    return links;
  }

  static std::vector<double> shares(std::span<const double> areas, std::size_t faces) {
    if (areas.empty()) return std::vector<double>(faces, faces ? 1.0 / double(faces) : 0.0);
    if (areas.size() != faces)
      throw invalid_input("Body_layout: " + std::to_string(areas.size()) + " face areas for " + std::to_string(faces) +
                          " triangles");
    double total = 0;
    for (std::size_t f = 0; f < faces; ++f) {
      if (!(areas[f] >= 0) || !std::isfinite(areas[f]))
        throw invalid_input("Body_layout: the area of triangle " + std::to_string(f) + " is not finite and >= 0");
      total += areas[f];
    }
    if (!(total > 0)) throw invalid_input("Body_layout: the face areas sum to 0");
    std::vector<double> result(areas.begin(), areas.end());
    for (double& s : result) s /= total;
    return result;
  }

  internal::Face_adjacency adjacency_;
  std::vector<double> area_shares_;
  std::size_t links_ = 0;
};

/// @brief The layout of an animation: its triangles, their areas in frame 0 and the links
/// `part_links` finds with `options`.
/// @tparam Mesh a `DeformingMesh`; a `Deforming_mesh` is read in place, any other model is first
/// copied once with `make_deforming_mesh`, for the triangles' vertex indices and frame 0's areas,
/// and `part_links` reads the copy: O(T V) time and 3 T V doubles.
/// @throws invalid_input as `part_links`, or for an animation whose frame 0 has no area.
/// @par Complexity as `part_links`, then as the constructor.
template <mesh::DeformingMesh Mesh>
Body_layout body_layout(const Mesh& animation, const Part_link_options& options = {}) {
  if constexpr (!mesh::is_deforming_mesh_v<Mesh>) {
    return body_layout(mesh::make_deforming_mesh(animation), options);
  } else {
    const std::vector<double> areas = mesh::face_areas(animation, 0);
    const auto links = part_links(animation, options);
    return Body_layout(animation.triangles(), areas, links);
  }
}

}  // namespace deformseg::spatiotemporal
