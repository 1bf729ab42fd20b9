/// @file io/mesh_repair.h
/// @brief Meshes as real assets come: welding of vertices that coincide in every frame, and the
/// repair of triangles that break a 2-manifold (`repair_triangles`, `make_repaired_animation`).
#pragma once

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/soup_orientation.h>
#include <deformseg/io/internal/vertex_welding.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
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
  /// Default false for frame sequences and point caches; the glTF reader's default is true, and
  /// it welds by what the file fixes for all its clips (rest position, skin influences, morph
  /// deltas: see `Gltf_file::repair`), so that every clip of a file has one mesh.
  bool weld = false;
  /// @brief Two vertices coincide when, in every frame, no coordinate differs by more than this
  /// fraction of the diagonal of the bounding box over all frames (glTF: of the bounding box of
  /// the rest positions, and skin weights differ by no more than this). Default 1e-6.
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
  /// @brief Vertices whose triangles form more than one fan, as CGAL's orientation finds them:
  /// the ends of non-manifold edges are not counted again, the vertices of the seam along which
  /// CGAL cuts a part that cannot be oriented (a Moebius strip) are.
  std::size_t non_manifold_vertices = 0;
  std::size_t duplicated_vertices = 0;    ///< copies made so that every edge and vertex is manifold
  std::size_t reoriented_triangles = 0;   ///< reversed to agree with their neighbours
  /// @brief Dropped: still running along an edge in the same direction as an earlier triangle
  /// after CGAL's repair. A guard: no input tried so far (random soups, Moebius strips, the
  /// projective plane) needs it, since CGAL cuts such parts along a seam of copied vertices.
  std::size_t unrepairable_triangles = 0;
  /// @brief glTF skin influences dropped: a weight NaN, infinite or negative, or a weighted joint
  /// outside its skin (the vertex keeps its other influences, renormalised).
  std::size_t dropped_influences = 0;
  /// @brief glTF skinned vertices without weight (all zero, or all dropped), bound to their
  /// mesh's node as engines bind them.
  std::size_t unweighted_vertices = 0;
  std::size_t vertices = 0;               ///< vertices after the repair
  std::size_t triangles = 0;              ///< triangles after the repair

  /// @brief Every count by its member's name, in the order above: one list for the writers of a
  /// report (the tool's JSON, the Python module's dict).
  /// @par Complexity O(1).
  std::array<std::pair<std::string_view, std::size_t>, 14> counts() const noexcept {
    return {{{"input_vertices", input_vertices},
             {"input_triangles", input_triangles},
             {"welded_vertices", welded_vertices},
             {"degenerate_triangles", degenerate_triangles},
             {"duplicate_triangles", duplicate_triangles},
             {"non_manifold_edges", non_manifold_edges},
             {"non_manifold_vertices", non_manifold_vertices},
             {"duplicated_vertices", duplicated_vertices},
             {"reoriented_triangles", reoriented_triangles},
             {"unrepairable_triangles", unrepairable_triangles},
             {"dropped_influences", dropped_influences},
             {"unweighted_vertices", unweighted_vertices},
             {"vertices", vertices},
             {"triangles", triangles}}};
  }

  /// @brief Whether the repair changed anything.
  bool changed() const noexcept {
    return welded_vertices + degenerate_triangles + duplicate_triangles + duplicated_vertices +
               reoriented_triangles + unrepairable_triangles + dropped_influences + unweighted_vertices != 0;
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

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// Throws unless positions, triangles and options fit together.
template <std::floating_point T>
void check_repair_input(std::span<const T> positions, std::size_t num_vertices,
                        std::span<const Soup_triangle> triangles, const io::Repair_options& options) {
  if (num_vertices > std::numeric_limits<std::uint32_t>::max())
    throw invalid_input(join(std::to_string(num_vertices), " vertices: more than 32-bit indices address"));
  const std::size_t block = 3 * num_vertices;
  if (block == 0 ? !positions.empty() : positions.size() % block != 0)
    throw invalid_input(join("expected a multiple of 3 x ", std::to_string(num_vertices), " coordinates, got ",
                             std::to_string(positions.size())));
  for (std::size_t j = 0; j < triangles.size(); ++j)
    for (const std::uint32_t v : triangles[j])
      if (v >= num_vertices)
        throw invalid_input(join("triangle ", std::to_string(j), " has vertex index ", std::to_string(v),
                                 " out of range [0, ", std::to_string(num_vertices), ")"));
  if (!std::isfinite(options.weld_tolerance) || options.weld_tolerance < 0)
    throw invalid_input(
        join("weld_tolerance must be finite and at least 0, not ", shortest_text(options.weld_tolerance)));
}

/// Which welded vertex each input vertex became, and which input vertex names each welded one
/// (its smallest, whose trajectory it keeps).
struct Welding {
  std::vector<std::uint32_t> welded{};
  std::vector<std::uint32_t> representative{};
};

/// The welding of `welded`, the welded vertex of each input vertex numbered in the order of their
/// smallest input vertex; the identity when it is empty and `num_vertices` is not.
inline Welding welding_of(std::vector<std::uint32_t> welded, std::size_t num_vertices) {
  Welding result{.welded = std::move(welded)};
  if (result.welded.empty()) {
    result.welded.resize(num_vertices);
    std::iota(result.welded.begin(), result.welded.end(), 0u);
  }
  for (std::uint32_t v = 0; v < result.welded.size(); ++v)
    if (result.welded[v] == result.representative.size()) result.representative.push_back(v);
  return result;
}

template <std::floating_point T>
Welding weld(std::span<const T> positions, std::size_t num_vertices, const io::Repair_options& options) {
  if (!options.weld || positions.empty()) return welding_of({}, num_vertices);
  check_finite_positions(positions, num_vertices);
  return welding_of(weld_vertices(positions, num_vertices, options.weld_tolerance), num_vertices);
}

/// The vertex a triangle repeats, if any.
inline std::optional<std::uint32_t> repeated_vertex(const Soup_triangle& t) {
  if (t[0] == t[1] || t[0] == t[2]) return t[0];
  if (t[1] == t[2]) return t[1];
  return std::nullopt;
}

/// The triangles after welding that repeat no vertex and are the first with their vertex set,
/// what was left out, and the first of each kind of defect (for `Defect_policy::refuse`).
struct Screened_triangles {
  std::vector<std::uint32_t> kept{};
  std::size_t degenerate = 0;
  std::size_t duplicate = 0;
  std::optional<std::pair<std::uint32_t, std::uint32_t>> first_degenerate{};  ///< triangle, vertex
  std::optional<std::pair<std::uint32_t, std::uint32_t>> first_duplicate{};   ///< earlier, later triangle
};

inline Screened_triangles screen_triangles(std::span<const Soup_triangle> welded) {
  Screened_triangles result;
  std::vector<std::pair<Soup_triangle, std::uint32_t>> by_vertex_set;  // sorted vertices, triangle
  for (std::uint32_t j = 0; j < welded.size(); ++j) {
    if (const auto v = repeated_vertex(welded[j])) {
      ++result.degenerate;
      if (!result.first_degenerate) result.first_degenerate.emplace(j, *v);
      continue;
    }
    Soup_triangle sorted = welded[j];
    std::sort(sorted.begin(), sorted.end());
    by_vertex_set.emplace_back(sorted, j);
  }
  std::sort(by_vertex_set.begin(), by_vertex_set.end());
  std::vector<bool> is_duplicate(welded.size(), false);
  std::size_t earliest = 0;  // the first triangle with the vertex set of triangle i
  for (std::size_t i = 1; i < by_vertex_set.size(); ++i) {
    if (by_vertex_set[i].first != by_vertex_set[i - 1].first) {
      earliest = i;
      continue;
    }
    const std::uint32_t later = by_vertex_set[i].second;
    is_duplicate[later] = true;
    ++result.duplicate;
    if (!result.first_duplicate || later < result.first_duplicate->second)
      result.first_duplicate.emplace(by_vertex_set[earliest].second, later);
  }
  for (const auto& [vertices, j] : by_vertex_set)
    if (!is_duplicate[j]) result.kept.push_back(j);
  std::sort(result.kept.begin(), result.kept.end());
  return result;
}

/// The soup of the kept triangles, over the welded vertices.
inline Oriented_soup soup_of(std::span<const Soup_triangle> welded, std::span<const std::uint32_t> kept,
                             std::size_t welded_vertices) {
  Oriented_soup soup;
  for (const std::uint32_t j : kept) {
    soup.triangles.push_back(welded[j]);
    soup.source_triangle.push_back(j);
  }
  soup.reversed.assign(kept.size(), false);
  soup.origin.resize(welded_vertices);
  std::iota(soup.origin.begin(), soup.origin.end(), 0u);
  return soup;
}

/// Throws the first edge of `soup` that more than two triangles share, naming them all (the edge
/// whose third triangle comes first).
inline void refuse_non_manifold_edges(const Oriented_soup& soup, std::span<const std::uint32_t> name) {
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> on_edge;
  std::optional<std::uint64_t> first;
  for (std::uint32_t j = 0; j < soup.triangles.size(); ++j)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint64_t key = undirected_edge_key(soup.triangles[j][k], soup.triangles[j][(k + 1) % 3]);
      std::vector<std::uint32_t>& triangles = on_edge[key];
      triangles.push_back(soup.source_triangle[j]);
      if (triangles.size() == 3 && !first) first = key;
    }
  if (!first) return;
  const std::vector<std::uint32_t>& triangles = on_edge[*first];
  std::string list;
  for (const std::uint32_t j : triangles) list += (list.empty() ? "" : ", ") + std::to_string(j);
  throw invalid_input(join("edge (", std::to_string(name[*first >> 32]), ", ",
                           std::to_string(name[*first & 0xffffffffu]), ") is shared by ",
                           std::to_string(triangles.size()), " triangles (", list, ")"));
}

/// Throws for the first triangle of `soup` that runs along an edge in the same direction as an
/// earlier one. @pre no edge has more than two triangles.
inline void refuse_inconsistent_orientation(const Oriented_soup& soup, std::span<const std::uint32_t> name) {
  std::unordered_map<std::uint64_t, std::uint32_t> first_along;
  for (std::uint32_t j = 0; j < soup.triangles.size(); ++j)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = soup.triangles[j][k];
      const std::uint32_t b = soup.triangles[j][(k + 1) % 3];
      const auto [found, inserted] = first_along.emplace(directed_edge_key(a, b), soup.source_triangle[j]);
      if (!inserted)
        throw invalid_input(join("triangles ", std::to_string(found->second), " and ",
                                 std::to_string(soup.source_triangle[j]),
                                 " are inconsistently oriented: both go from vertex ", std::to_string(name[a]),
                                 " to vertex ", std::to_string(name[b]), " on their shared edge"));
    }
}

/// Throws the first defect that `Defect_policy::refuse` refuses, in this order: a triangle that
/// repeats a vertex, one with the same vertices as an earlier one, an edge of more than two
/// triangles, two triangles oriented against each other, a vertex of several fans.
inline void refuse_defects(std::span<const Soup_triangle> input, std::span<const Soup_triangle> welded,
                           const Screened_triangles& screened, const Welding& welding) {
  const std::span<const std::uint32_t> name = welding.representative;
  if (const auto& d = screened.first_degenerate)
    throw invalid_input(join("triangle ", std::to_string(d->first), " repeats vertex ", std::to_string(name[d->second]),
                             repeated_vertex(input[d->first]) ? "" : " once its vertices are welded"));
  if (const auto& d = screened.first_duplicate)
    throw invalid_input(join("triangles ", std::to_string(d->first), " and ", std::to_string(d->second),
                             " have the same vertices"));
  Oriented_soup soup = soup_of(welded, screened.kept, welding.representative.size());
  refuse_non_manifold_edges(soup, name);
  refuse_inconsistent_orientation(soup, name);
  if (is_oriented_manifold(soup.triangles, soup.origin.size())) return;
  orient_with_cgal(soup);  // it finds the vertices of several fans
  if (const auto& v = soup.first_non_manifold_vertex)
    throw invalid_input(join("vertex ", std::to_string(name[v->first]), " joins ", std::to_string(v->second),
                             " separate fans of triangles"));
}

/// The triangles and counts of a repaired soup.
inline io::Repaired_triangles repaired_triangles(Oriented_soup soup, const Welding& welding,
                                                 const Screened_triangles& screened, std::size_t input_triangles) {
  io::Repaired_triangles result;
  io::Repair_report& report = result.report;
  report.input_vertices = welding.welded.size();
  report.input_triangles = input_triangles;
  report.welded_vertices = welding.welded.size() - welding.representative.size();
  report.degenerate_triangles = screened.degenerate;
  report.duplicate_triangles = screened.duplicate;
  report.non_manifold_edges = soup.non_manifold_edges.size();
  std::set<std::uint32_t> edge_ends;
  for (const auto& [a, b] : soup.non_manifold_edges) edge_ends.insert({a, b});
  report.non_manifold_vertices = static_cast<std::size_t>(std::count_if(
      soup.non_manifold_vertices.begin(), soup.non_manifold_vertices.end(),
      [&](std::uint32_t v) { return !edge_ends.contains(v); }));
  report.duplicated_vertices = soup.duplicated_vertices;
  report.reoriented_triangles = static_cast<std::size_t>(std::count(soup.reversed.begin(), soup.reversed.end(), true));
  report.unrepairable_triangles = soup.unrepairable_triangles;
  report.vertices = soup.origin.size();
  report.triangles = soup.triangles.size();
  result.source_vertex.resize(soup.origin.size());
  for (std::size_t i = 0; i < soup.origin.size(); ++i) result.source_vertex[i] = welding.representative[soup.origin[i]];
  result.triangles = std::move(soup.triangles);
  result.source_triangle = std::move(soup.source_triangle);
  return result;
}

/// Steps 2 to 4 of `repair_triangles` (or the refusal of the first defect) once `welding` is made.
inline io::Repaired_triangles repair_welded(std::span<const Soup_triangle> triangles, const Welding& welding,
                                            io::Defect_policy defects) {
  std::vector<Soup_triangle> welded(triangles.size());
  for (std::size_t j = 0; j < triangles.size(); ++j)
    for (std::size_t k = 0; k < 3; ++k) welded[j][k] = welding.welded[triangles[j][k]];
  const Screened_triangles screened = screen_triangles(welded);
  if (defects == io::Defect_policy::refuse) refuse_defects(triangles, welded, screened, welding);
  Oriented_soup soup = soup_of(welded, screened.kept, welding.representative.size());
  make_oriented_manifold(soup);
  return repaired_triangles(std::move(soup), welding, screened, triangles.size());
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Welds and repairs the connectivity of an animation given as positions and triangles,
/// so that `make_face_graph` accepts it, and says where every vertex and triangle comes from.
///
/// In order:
/// 1. with `options.weld`, vertices that coincide in every frame are merged: two coincide when, in
///    every frame, no coordinate differs by more than `weld_tolerance` times the diagonal of the
///    bounding box of all frames; vertices that coincide with a welded one join it (transitive
///    closure). The welded vertices are numbered in the order of their smallest input vertex,
///    whose trajectory they keep. Without `weld`, output vertex `i` is input vertex `i`.
/// 2. triangles that repeat a vertex (after welding) are dropped; so is every triangle with the
///    same three vertices as an earlier one, whatever their order.
/// 3. CGAL's `orient_polygon_soup` orients every part consistently and copies the vertices of
///    edges shared by more than two triangles and of vertices whose triangles form several fans,
///    the copies appended after the vertices of step 1 and moving as their source; a part that
///    cannot be oriented (a Moebius strip) is cut along a seam of copied vertices. Should a triangle
///    still run along an edge in the same direction as an earlier one, it is dropped
///    (`unrepairable_triangles`) and CGAL runs again on the rest.
/// 4. a part of which CGAL reversed more than half is reversed back whole, so that the fewest
///    triangles run against the input.
///
/// Vertices that no triangle uses are kept: they still move, and `compute_strain` and
/// `Deforming_mesh` ignore them. Output triangles keep the input order, each as its input
/// triangle's vertices (replaced by copies where made), maybe reversed.
///
/// With `Defect_policy::refuse`, the first defect throws instead, in this order: a triangle that
/// repeats a vertex ("triangle 16 repeats vertex 5"), a triangle with the same vertices as an
/// earlier one ("triangles 3 and 8 have the same vertices"), an edge of more than two triangles
/// ("edge (3, 7) is shared by 3 triangles (2, 9, 11)"), two triangles oriented against each other
/// ("triangles 2 and 5 are inconsistently oriented: ..."), a vertex of several fans ("vertex 4
/// joins 2 separate fans of triangles"). Vertices and triangles are named by their input index (a
/// welded vertex by its smallest). Welding is not a defect: it happens under both policies.
///
/// @param positions `T x 3V` coordinates, frames one after the other; only read for welding.
/// @param num_vertices V.
/// @param triangles each as 3 vertex indices in `[0, V)`.
/// @param options `weld` (default false), `weld_tolerance` (default 1e-6), `defects` (default
/// `Defect_policy::repair`).
/// @return the triangles, over the output vertices, an oriented 2-manifold; the source of every
/// output vertex and triangle; the counts of what changed.
/// @pre `positions.size()` is a multiple of `3 V`; every index is in `[0, V)`; `weld_tolerance` is
/// finite and at least 0; with `weld`, every coordinate is finite. With no frame nothing is welded.
/// @throws invalid_input naming what breaks a precondition, or the first defect with
/// `Defect_policy::refuse`.
/// @par Complexity O(T V + F log F) expected (welding: vertices of one trajectory united by a hash
/// of it, then a hash grid on frame 0, each candidate pair checked over all frames; many vertices
/// of different trajectories within the tolerance of each other in frame 0 cost a check per pair);
/// O(F log F) more per round of step 3 after the first, which only inputs that cannot be oriented
/// need.
template <std::floating_point T>
Repaired_triangles repair_triangles(std::span<const T> positions, std::size_t num_vertices,
                                    std::span<const std::array<std::uint32_t, 3>> triangles,
                                    const Repair_options& options = {}) {
  internal::check_repair_input(positions, num_vertices, triangles, options);
  return internal::repair_welded(triangles, internal::weld(positions, num_vertices, options), options.defects);
}

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// Whether output vertex `i` is input vertex `i` for every vertex, so that positions serve as they are.
inline bool keeps_input_vertices(const io::Repaired_triangles& repaired, std::size_t num_vertices) {
  if (repaired.source_vertex.size() != num_vertices) return false;
  for (std::size_t i = 0; i < num_vertices; ++i)
    if (repaired.source_vertex[i] != i) return false;
  return true;
}

/// The positions of every output vertex in every frame: those of its source vertex.
template <std::floating_point Coordinate, std::floating_point T>
mesh::Coordinate_buffer<Coordinate> positions_of_sources(std::span<const T> positions, std::size_t num_vertices,
                                                         std::span<const std::uint32_t> source) {
  const std::size_t frames = num_vertices == 0 ? 0 : positions.size() / (3 * num_vertices);
  mesh::Coordinate_buffer<Coordinate> out(frames * 3 * source.size());
  Coordinate* next = out.data();
  for (std::size_t t = 0; t < frames; ++t) {
    const T* frame = positions.data() + t * 3 * num_vertices;
    for (const std::uint32_t v : source)
      for (std::size_t k = 0; k < 3; ++k) *next++ = static_cast<Coordinate>(frame[3 * v + k]);
  }
  return out;
}

/// The animation of repaired triangles whose positions are given per output vertex.
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> animation_of(const io::Repaired_triangles& repaired,
                                                     mesh::Coordinate_buffer<Coordinate> positions,
                                                     io::Repair_report* report) {
  const std::size_t vertices = repaired.source_vertex.size();
  std::vector<std::array<double, 3>> first_frame(vertices, std::array<double, 3>{});
  for (std::size_t i = 0; i < vertices && !positions.empty(); ++i)
    for (std::size_t k = 0; k < 3; ++k) first_frame[i][k] = double(positions[3 * i + k]);
  Graph graph = mesh::make_face_graph<Graph>(first_frame, repaired.triangles);
  mesh::Deforming_mesh<Graph, Coordinate> animation(std::move(graph), std::move(positions));
  if (report) *report = repaired.report;
  return animation;
}

/// `make_repaired_animation` for readers that own the positions: when the repair keeps every
/// vertex they become the animation's without a copy.
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> repaired_animation(mesh::Coordinate_buffer<Coordinate>&& positions,
                                                           std::size_t num_vertices,
                                                           const io::Repaired_triangles& repaired,
                                                           io::Repair_report* report) {
  if (keeps_input_vertices(repaired, num_vertices))
    return animation_of<Graph, Coordinate>(repaired, std::move(positions), report);
  mesh::Coordinate_buffer<Coordinate> moved =
      positions_of_sources<Coordinate>(std::span<const Coordinate>(positions), num_vertices, repaired.source_vertex);
  positions = {};
  return animation_of<Graph, Coordinate>(repaired, std::move(moved), report);
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Builds an animation from positions and triangles after `repair_triangles`: the
/// connectivity from the repaired triangles, each output vertex moving as its source vertex.
///
/// Dropped triangles have no face (and no strain); a copied vertex moves with its source; a
/// welded vertex moves as its smallest input vertex, which all its input vertices follow within
/// the tolerance. Output face `j` is input triangle `repair_triangles(...).source_triangle[j]`.
///
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`).
/// @param positions `T x 3V` coordinates, frames one after the other.
/// @param num_vertices V.
/// @param triangles each as 3 vertex indices in `[0, V)`.
/// @param options as `repair_triangles`: `weld` (default false), `weld_tolerance` (1e-6),
/// `defects` (repair).
/// @param report where to store what the repair changed, when not null (default null).
/// @pre as `repair_triangles`, and every coordinate is finite.
/// @throws invalid_input as `repair_triangles`, and for a non-finite coordinate (naming its frame
/// and vertex).
/// @par Complexity O(T V + F log F) expected, as `repair_triangles`, plus one copy of the positions.
/// @sa repair_triangles
template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double, std::floating_point T>
mesh::Deforming_mesh<Graph, Coordinate> make_repaired_animation(std::span<const T> positions, std::size_t num_vertices,
                                                          std::span<const std::array<std::uint32_t, 3>> triangles,
                                                          const Repair_options& options = {},
                                                          Repair_report* report = nullptr) {
  const Repaired_triangles repaired = repair_triangles(positions, num_vertices, triangles, options);
  return internal::animation_of<Graph, Coordinate>(
      repaired, internal::positions_of_sources<Coordinate>(positions, num_vertices, repaired.source_vertex), report);
}

}  // namespace deformseg::io
