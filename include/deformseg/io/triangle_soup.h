/// @file io/triangle_soup.h
/// @brief `Triangle_soup`, one mesh as the readers give it, and the options they share.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <span>
#include <vector>

namespace deformseg::io {

/// @brief One mesh as read from a file: vertex coordinates and triangles.
///
/// The readers give vertices and triangles in the order of the file; a polygon fan-triangulated
/// by `Mesh_read_options::triangulate` gives its triangles in a row, in its place.
struct Triangle_soup {
  /// @brief `3 V` coordinates: x, y, z of vertex 0, then of vertex 1, ...
  std::vector<double> points{};
  /// @brief Each triangle as 3 vertex indices in `[0, V)`, in the order of the file.
  std::vector<std::array<std::uint32_t, 3>> triangles{};

  /// @brief The number of vertices V.
  std::size_t num_vertices() const noexcept { return points.size() / 3; }
};

/// @brief How the mesh readers treat what is not a triangle mesh.
struct Mesh_read_options {
  /// @brief Fan-triangulate a face of n > 3 vertices into n - 2 triangles (v0, vi, vi+1), instead
  /// of rejecting it. Default: false, since a triangulation the file did not choose changes what
  /// per-triangle strain measures.
  bool triangulate = false;
};

/// @brief The vertices of `soup` as a range of 3-coordinate points, for
/// `deformseg::mesh::make_face_graph(points_of(soup), soup.triangles)`.
/// @return a view of `std::span<const double, 3>`, valid while `soup.points` is not changed.
/// @par Complexity O(1).
inline auto points_of(const Triangle_soup& soup) {
  const double* xyz = soup.points.data();
  return std::views::iota(std::size_t{0}, soup.num_vertices()) |
         std::views::transform([xyz](std::size_t i) { return std::span<const double, 3>(xyz + 3 * i, 3); });
}

}  // namespace deformseg::io
