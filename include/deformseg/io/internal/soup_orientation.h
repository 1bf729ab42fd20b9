/// @file io/internal/soup_orientation.h
/// @brief Details of `io::repair_triangles`: making a triangle soup an oriented 2-manifold with
/// CGAL's `orient_polygon_soup`, tracking where every copied vertex and reversed triangle comes from.
#pragma once

#include <deformseg/io/internal/vertex_welding.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace deformseg::io::internal {

using Soup_triangle = std::array<std::uint32_t, 3>;

/// A key for the edge from `a` to `b`, directed.
inline std::uint64_t directed_edge_key(std::uint32_t a, std::uint32_t b) noexcept {
  return (std::uint64_t(a) << 32) | b;
}
/// A key for the edge between `a` and `b`, undirected.
inline std::uint64_t undirected_edge_key(std::uint32_t a, std::uint32_t b) noexcept {
  return directed_edge_key(std::min(a, b), std::max(a, b));
}

/// Triangles without repeated vertices nor duplicates, on their way to an oriented 2-manifold,
/// and what was done to them.
struct Oriented_soup {
  std::vector<Soup_triangle> triangles{};
  std::vector<std::uint32_t> source_triangle{};  ///< the input triangle of each
  std::vector<bool> reversed{};                  ///< whether each runs against its input triangle
  std::vector<std::uint32_t> origin{};           ///< per vertex, the (welded) vertex it copies
  std::set<std::pair<std::uint32_t, std::uint32_t>> non_manifold_edges{};  ///< as origins, smaller first
  std::set<std::uint32_t> non_manifold_vertices{};  ///< as origins, the ends of those edges included
  /// The first non-manifold vertex CGAL reported, as an origin, and its number of fans.
  std::optional<std::pair<std::uint32_t, std::size_t>> first_non_manifold_vertex{};
  std::size_t duplicated_vertices = 0;
  std::size_t unrepairable_triangles = 0;
};

/// Records what CGAL's orientation reports into an `Oriented_soup`. CGAL copies its visitor, so
/// this one only points to the record.
class Recording_visitor : public CGAL::Polygon_mesh_processing::Default_orientation_visitor {
public:
  explicit Recording_visitor(Oriented_soup& soup) : soup_(&soup) {}

  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t) {
    const std::uint32_t u = soup_->origin[a];
    const std::uint32_t v = soup_->origin[b];
    soup_->non_manifold_edges.emplace(std::min(u, v), std::max(u, v));
  }
  void non_manifold_vertex(std::size_t v, std::size_t fans) {
    soup_->non_manifold_vertices.insert(soup_->origin[v]);
    if (!soup_->first_non_manifold_vertex) soup_->first_non_manifold_vertex.emplace(soup_->origin[v], fans);
  }
  void duplicated_vertex(std::size_t v, std::size_t) {
    soup_->origin.push_back(soup_->origin[v]);
    ++soup_->duplicated_vertices;
  }
  void polygon_orientation_reversed(std::size_t p) { soup_->reversed[p] = !soup_->reversed[p]; }

private:
  Oriented_soup* soup_;
};

/// One pass of CGAL's `orient_polygon_soup` over `soup`: orients each part consistently where it
/// can, and copies the vertices at non-manifold edges and vertices so that every part is manifold.
inline void orient_with_cgal(Oriented_soup& soup) {
  // CGAL only copies points; the visitor tracks which vertex each copy comes from.
  std::vector<std::size_t> points(soup.origin.size());
  std::vector<std::array<std::size_t, 3>> polygons(soup.triangles.size());
  for (std::size_t j = 0; j < polygons.size(); ++j)
    for (std::size_t k = 0; k < 3; ++k) polygons[j][k] = soup.triangles[j][k];
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons,
                                                     CGAL::parameters::visitor(Recording_visitor(soup)));
  for (std::size_t j = 0; j < polygons.size(); ++j)
    for (std::size_t k = 0; k < 3; ++k) soup.triangles[j][k] = static_cast<std::uint32_t>(polygons[j][k]);
}

/// The triangles that run along an edge in the same direction as an earlier triangle. After
/// CGAL's pass every vertex has one fan (connected through edges of at most two triangles), so
/// these are the only triangles that a halfedge mesh could still refuse. CGAL cuts the parts it
/// cannot orient along seams of copied vertices (around a vertex, an even number of edges join
/// triangles of opposite orientations, so a cut vertex always splits), so this is a guard.
inline std::vector<bool> misoriented_triangles(const std::vector<Soup_triangle>& triangles) {
  std::unordered_map<std::uint64_t, std::uint32_t> first_along;  // directed edge -> triangle
  first_along.reserve(3 * triangles.size());
  std::vector<bool> refused(triangles.size(), false);
  for (std::uint32_t j = 0; j < triangles.size(); ++j) {
    const Soup_triangle& t = triangles[j];
    for (std::size_t k = 0; k < 3; ++k)
      if (first_along.contains(directed_edge_key(t[k], t[(k + 1) % 3]))) refused[j] = true;
    if (refused[j]) continue;
    for (std::size_t k = 0; k < 3; ++k) first_along.emplace(directed_edge_key(t[k], t[(k + 1) % 3]), j);
  }
  return refused;
}

/// Removes the triangles marked in `drop`, keeping the others' order.
inline void drop_triangles(Oriented_soup& soup, const std::vector<bool>& drop) {
  std::size_t kept = 0;
  for (std::size_t j = 0; j < soup.triangles.size(); ++j) {
    if (drop[j]) continue;
    soup.triangles[kept] = soup.triangles[j];
    soup.source_triangle[kept] = soup.source_triangle[j];
    soup.reversed[kept] = soup.reversed[j];
    ++kept;
  }
  soup.unrepairable_triangles += soup.triangles.size() - kept;
  soup.triangles.resize(kept);
  soup.source_triangle.resize(kept);
  soup.reversed.resize(kept);
}

/// Reverses every part (triangles connected through their edges) of which CGAL reversed more
/// than half, so that the fewest triangles run against the input: CGAL keeps the orientation of
/// each part's first triangle, even when that triangle is the one that disagrees.
/// @pre every edge has at most two triangles, running along it in opposite directions.
inline void reverse_majority_reversed_parts(Oriented_soup& soup) {
  const std::size_t count = soup.triangles.size();
  Smallest_union_find parts(count);
  std::unordered_map<std::uint64_t, std::uint32_t> first_on_edge;
  first_on_edge.reserve(3 * count);
  for (std::uint32_t j = 0; j < count; ++j)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [found, inserted] =
          first_on_edge.emplace(undirected_edge_key(soup.triangles[j][k], soup.triangles[j][(k + 1) % 3]), j);
      if (!inserted) parts.unite(found->second, j);
    }
  const std::vector<std::uint32_t> part = parts.numbered_sets();
  std::vector<std::size_t> size, reversed;
  for (std::size_t j = 0; j < count; ++j) {
    if (part[j] >= size.size()) size.resize(part[j] + 1), reversed.resize(part[j] + 1);
    ++size[part[j]];
    reversed[part[j]] += soup.reversed[j];
  }
  for (std::size_t j = 0; j < count; ++j)
    if (2 * reversed[part[j]] > size[part[j]]) {
      std::reverse(soup.triangles[j].begin(), soup.triangles[j].end());
      soup.reversed[j] = !soup.reversed[j];
    }
}

/// The halfedges of a soup sorted by their directed edge, to find the triangle along an edge.
class Halfedge_table {
public:
  explicit Halfedge_table(const std::vector<Soup_triangle>& triangles) {
    halfedges_.reserve(3 * triangles.size());
    for (std::uint32_t j = 0; j < triangles.size(); ++j)
      for (std::size_t k = 0; k < 3; ++k)
        halfedges_.emplace_back(directed_edge_key(triangles[j][k], triangles[j][(k + 1) % 3]), j);
    std::sort(halfedges_.begin(), halfedges_.end());
  }
  /// Whether some directed edge belongs to two triangles.
  bool has_repeated_halfedge() const {
    return std::adjacent_find(halfedges_.begin(), halfedges_.end(),
                              [](const auto& a, const auto& b) { return a.first == b.first; }) != halfedges_.end();
  }
  /// The triangle that runs from `a` to `b`, if any.
  std::optional<std::uint32_t> triangle_along(std::uint32_t a, std::uint32_t b) const {
    const std::uint64_t key = directed_edge_key(a, b);
    const auto found =
        std::lower_bound(halfedges_.begin(), halfedges_.end(), std::pair<std::uint64_t, std::uint32_t>(key, 0));
    if (found == halfedges_.end() || found->first != key) return std::nullopt;
    return found->second;
  }

private:
  std::vector<std::pair<std::uint64_t, std::uint32_t>> halfedges_;
};

/// The vertex after `v` in triangle `t`, and the one before it.
inline std::uint32_t after(const Soup_triangle& t, std::uint32_t v) {
  return t[0] == v ? t[1] : t[1] == v ? t[2] : t[0];
}
inline std::uint32_t before(const Soup_triangle& t, std::uint32_t v) {
  return t[0] == v ? t[2] : t[1] == v ? t[0] : t[1];
}

/// The number of triangles around `v` reached from triangle `start` through edges, turning both ways.
/// @pre no directed edge belongs to two triangles.
inline std::size_t fan_size(const std::vector<Soup_triangle>& triangles, const Halfedge_table& table, std::uint32_t v,
                            std::uint32_t start) {
  std::size_t count = 1;
  std::optional<std::uint32_t> t = table.triangle_along(after(triangles[start], v), v);
  for (; t && *t != start; t = table.triangle_along(after(triangles[*t], v), v)) ++count;
  if (t) return count;  // back to `start`: closed around v
  for (t = table.triangle_along(v, before(triangles[start], v)); t;
       t = table.triangle_along(v, before(triangles[*t], v)))
    ++count;
  return count;
}

/// Whether triangles without repeated vertices are already an oriented 2-manifold: no directed
/// edge twice, every vertex one fan. Then CGAL's pass, which would change nothing, is skipped.
/// O(F log F), a few times faster than that pass.
inline bool is_oriented_manifold(const std::vector<Soup_triangle>& triangles, std::size_t num_vertices) {
  const Halfedge_table table(triangles);
  if (table.has_repeated_halfedge()) return false;
  std::vector<std::uint32_t> degree(num_vertices, 0), first(num_vertices, 0);
  for (std::uint32_t j = 0; j < triangles.size(); ++j)
    for (const std::uint32_t v : triangles[j])
      if (degree[v]++ == 0) first[v] = j;
  for (std::uint32_t v = 0; v < num_vertices; ++v)
    if (degree[v] != 0 && fan_size(triangles, table, v, first[v]) != degree[v]) return false;
  return true;
}

/// Makes `soup` an oriented 2-manifold that `make_face_graph` accepts: CGAL's orientation, then
/// the triangles a halfedge mesh still refuses dropped and CGAL run again on the rest, until none
/// is left (each round drops at least one triangle; one round on all but contrived inputs).
inline void make_oriented_manifold(Oriented_soup& soup) {
  if (is_oriented_manifold(soup.triangles, soup.origin.size())) return;
  for (;;) {
    orient_with_cgal(soup);
    const std::vector<bool> refused = misoriented_triangles(soup.triangles);
    if (std::find(refused.begin(), refused.end(), true) == refused.end()) break;
    drop_triangles(soup, refused);
  }
  reverse_majority_reversed_parts(soup);
}

}  // namespace deformseg::io::internal
