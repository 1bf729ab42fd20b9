/// @file mesh_repair.h
/// @brief Meshes as real assets come: welding of vertices that coincide in every frame, and the
/// repair of triangles that break a 2-manifold (`repair_triangles`, `make_repaired_animation`).
#pragma once

#include <deformseg/default_mesh.h>
#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

namespace deformseg::io {

/// @brief What a reader does with triangles that are not part of an oriented 2-manifold.
enum class Defect_policy {
  repair,  ///< drop degenerate and duplicate triangles, duplicate vertices to make it manifold
  refuse   ///< throw `invalid_input` naming the first defect found
};

/// @brief How a mesh is repaired (every reader takes these).
struct Repair_options {
  /// @brief Merge vertices whose positions coincide in every frame (within `weld_tolerance`).
  /// Default false for frame sequences and point caches; the glTF reader's default is true.
  bool weld = false;
  /// @brief Two vertices coincide when, in every frame, no coordinate differs by more than this
  /// fraction of the diagonal of the bounding box over all frames. Default 1e-6.
  double weld_tolerance = 1e-6;
  /// @brief Repair (default) or refuse degenerate, duplicate and non-manifold triangles.
  Defect_policy defects = Defect_policy::repair;
};

/// @brief What a repair changed, in counts.
struct Repair_report {
  std::size_t input_vertices = 0;         ///< vertices as read
  std::size_t input_triangles = 0;        ///< triangles as read
  std::size_t welded_vertices = 0;        ///< vertices merged into another that coincides with them
  std::size_t degenerate_triangles = 0;   ///< dropped: they repeat a vertex (after welding)
  std::size_t duplicate_triangles = 0;    ///< dropped: the same three vertices as an earlier one
  std::size_t non_manifold_edges = 0;     ///< edges shared by more than two triangles
  std::size_t non_manifold_vertices = 0;  ///< vertices whose triangles form more than one fan
  std::size_t duplicated_vertices = 0;    ///< copies made so that every edge and vertex is manifold
  std::size_t reoriented_triangles = 0;   ///< reversed to agree with their neighbours
  std::size_t vertices = 0;               ///< vertices after the repair
  std::size_t triangles = 0;              ///< triangles after the repair

  /// @brief Whether the repair changed anything.
  bool changed() const noexcept {
    return welded_vertices + degenerate_triangles + duplicate_triangles + duplicated_vertices +
               reoriented_triangles != 0;
  }
};

/// @brief A repaired connectivity, and where each of its vertices and triangles comes from.
struct Repaired_triangles {
  /// @brief The triangles, over the output vertices, an oriented 2-manifold.
  std::vector<std::array<std::uint32_t, 3>> triangles{};
  /// @brief Output vertex `i` moves as input vertex `source_vertex[i]`. Without welding the
  /// first `input_vertices` entries are the identity and copies come after them.
  std::vector<std::uint32_t> source_vertex{};
  /// @brief Output triangle `j` is input triangle `source_triangle[j]` (maybe reversed).
  std::vector<std::uint32_t> source_triangle{};
  /// @brief The counts of what changed.
  Repair_report report{};
};

/// @brief Welds and repairs the connectivity of an animation given as positions and triangles.
///
/// @param positions `T x 3V` coordinates, frames one after the other.
/// @param num_vertices V.
/// @param triangles each as 3 vertex indices in `[0, V)`.
/// @param options `weld` (default false), `weld_tolerance` (1e-6), `defects` (repair).
/// @throws invalid_input naming the first defect with `Defect_policy::refuse`, or an index out of
/// range.
/// @par Complexity O(T V + F log F) expected.
template <std::floating_point T>
Repaired_triangles repair_triangles(std::span<const T> positions, std::size_t num_vertices,
                                    std::span<const std::array<std::uint32_t, 3>> triangles,
                                    const Repair_options& options = {}) {
  // Interface placeholder, replaced by the repair in this same header.
  static_cast<void>(positions);
  static_cast<void>(options);
  Repaired_triangles result;
  result.triangles.assign(triangles.begin(), triangles.end());
  result.source_vertex.resize(num_vertices);
  std::iota(result.source_vertex.begin(), result.source_vertex.end(), 0u);
  result.source_triangle.resize(triangles.size());
  std::iota(result.source_triangle.begin(), result.source_triangle.end(), 0u);
  result.report.input_vertices = result.report.vertices = num_vertices;
  result.report.input_triangles = result.report.triangles = triangles.size();
  return result;
}

/// @brief Builds an animation from positions and triangles after `repair_triangles`: the
/// connectivity from the repaired triangles, each output vertex moving as its source vertex.
///
/// @tparam Graph the connectivity type (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`).
/// @param positions `T x 3V` coordinates, frames one after the other.
/// @param num_vertices V.
/// @param triangles each as 3 vertex indices in `[0, V)`.
/// @param options as `repair_triangles`.
/// @param report where to store what the repair changed, when not null.
/// @throws invalid_input as `repair_triangles`, and for a non-finite coordinate.
/// @par Complexity O(T V + F log F) expected.
template <FaceGraph Graph = Surface_mesh, std::floating_point Coordinate = double, std::floating_point T>
Deforming_mesh<Graph, Coordinate> make_repaired_animation(std::span<const T> positions, std::size_t num_vertices,
                                                          std::span<const std::array<std::uint32_t, 3>> triangles,
                                                          const Repair_options& options = {},
                                                          Repair_report* report = nullptr) {
  Repaired_triangles repaired = repair_triangles(positions, num_vertices, triangles, options);
  const std::size_t frames = num_vertices == 0 ? 0 : positions.size() / (3 * num_vertices);
  const std::size_t out_vertices = repaired.source_vertex.size();
  std::vector<Coordinate> out(frames * 3 * out_vertices);
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t i = 0; i < out_vertices; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        out[(t * out_vertices + i) * 3 + k] =
            static_cast<Coordinate>(positions[(t * num_vertices + repaired.source_vertex[i]) * 3 + k]);
  std::vector<std::array<double, 3>> first(out_vertices);
  for (std::size_t i = 0; i < out_vertices && frames > 0; ++i)
    for (std::size_t k = 0; k < 3; ++k) first[i][k] = double(out[3 * i + k]);
  Graph graph = make_face_graph<Graph>(first, repaired.triangles);
  if (report) *report = repaired.report;
  return Deforming_mesh<Graph, Coordinate>(std::move(graph), std::move(out));
}

}  // namespace deformseg::io
