/// @file spatiotemporal/part_links.h
/// @brief `part_links`: the pairs of triangles that join the separate parts of a mesh as the body
/// has them (parts that touch, parts that move as one rigid body), for the segments' adjacency
/// (@ref method_spatiotemporal): `Part_link_options`, `part_links`.
///
/// Real characters are built of separate meshes: armour plates, belts, hair, eyes, a robot's
/// limbs. Shared edges alone make each a segment of its own; these links make them neighbours.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/spatiotemporal/internal/part_geometry.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace deformseg::spatiotemporal {

/// @brief How `part_links` decides that two parts of a mesh (sets of triangles joined by shared
/// vertices) are neighbours; an aggregate for designated initializers. Both are fractions of the
/// diagonal of the rest pose's (frame 0's) bounding box; 0 turns the test off, and both 0 is the
/// thesis' adjacency (shared edges only).
struct Part_link_options {
  /// @brief Two parts **touch** when, at the rest pose, a vertex of one lies within this distance
  /// of a triangle of the other, or an edge of one crosses a triangle of the other
  /// (interpenetration). The vertex's first triangle is then linked to the nearest triangle of
  /// the other part, the edge's first triangle to the one it crosses; only edges longer than
  /// twice the distance are tested, as a shorter one that crosses a triangle has an end within
  /// the distance of it. Default 0.01 (2 cm on a 2 m body).
  double contact_distance = 0.01;
  /// @brief Two parts **move as one** when each stays within this distance of its rest shape
  /// moved rigidly (the best rigid motion, Kabsch), in every frame, and their two rigid motions
  /// move the corners of the rest pose's bounding box to within this distance of each other.
  /// Such parts are linked by their first triangles, so that they make one rigid node. Default
  /// 0.002.
  double rigid_tolerance = 0.002;
};

namespace internal {

// Each vertex's triangles, in compressed rows.
struct Vertex_faces {
  std::vector<std::uint32_t> offsets, faces;
  std::span<const std::uint32_t> of(std::size_t v) const {
    return std::span<const std::uint32_t>(faces).subspan(offsets[v], offsets[v + 1] - offsets[v]);
  }
};

inline Vertex_faces vertex_faces(std::span<const std::array<std::uint32_t, 3>> triangles, std::size_t vertices) {
  Vertex_faces incidence{std::vector<std::uint32_t>(vertices + 1, 0), std::vector<std::uint32_t>(3 * triangles.size())};
  for (const auto& t : triangles)
    for (std::uint32_t v : t) ++incidence.offsets[v + 1];
  std::partial_sum(incidence.offsets.begin(), incidence.offsets.end(), incidence.offsets.begin());
  std::vector<std::uint32_t> next(incidence.offsets.begin(), incidence.offsets.end() - 1);
  for (std::uint32_t f = 0; f < triangles.size(); ++f)
    for (std::uint32_t v : triangles[f]) incidence.faces[next[v]++] = f;
  return incidence;
}

// The grid's cell: the contact distance, or the median extent of a triangle when larger, so that
// most triangles fall in few cells and a vertex's reach in at most 27; never below
// diagonal / 2^20, so that 21 bits index a cell.
inline double grid_cell(const Eigen::Matrix3Xd& points, std::span<const std::array<std::uint32_t, 3>> triangles,
                        double distance, double diagonal) {
  std::vector<double> extent(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    const Eigen::Vector3d a = points.col(t[0]), b = points.col(t[1]), c = points.col(t[2]);
    extent[f] = (a.cwiseMax(b).cwiseMax(c) - a.cwiseMin(b).cwiseMin(c)).maxCoeff();
  }
  const auto middle = extent.begin() + std::ptrdiff_t(extent.size() / 2);
  std::nth_element(extent.begin(), middle, extent.end());
  return std::max({distance, extent.empty() ? 0.0 : *middle, diagonal / double(1 << 20)});
}

// The rest pose's triangles as the contact tests see them: their parts, boxes and grid.
struct Contact_scene {
  const Eigen::Matrix3Xd& rest;
  std::span<const std::array<std::uint32_t, 3>> triangles;
  const std::vector<std::uint32_t>& parts;
  double distance;
  Triangle_grid grid;
  std::vector<Eigen::AlignedBox3d> box;

  Contact_scene(const Eigen::Matrix3Xd& points, std::span<const std::array<std::uint32_t, 3>> faces,
                const std::vector<std::uint32_t>& part_of, double reach, double diagonal)
      : rest(points), triangles(faces), parts(part_of), distance(reach),
        grid(points, faces, part_of, points.rowwise().minCoeff(), grid_cell(points, faces, reach, diagonal),
             1e-9 * diagonal),
        box(faces.size()) {
    for (std::uint32_t f = 0; f < faces.size(); ++f)
      for (int k = 0; k < 3; ++k) box[f].extend(corner(f, k));
  }
  Eigen::Vector3d corner(std::uint32_t f, int k) const { return rest.col(triangles[f][std::size_t(k)]); }
  double squared_distance(const Eigen::Vector3d& p, std::uint32_t g) const {
    return squared_distance_to_triangle(p, corner(g, 0), corner(g, 1), corner(g, 2));
  }
};

// Each vertex within reach of another part: its first triangle linked to that part's nearest
// triangle (ties to the smaller index). The cells of its reach that hold only its own part are
// skipped, the boxes reject most triangles of the others, and a stamp per triangle tests it once
// per vertex.
inline void add_touching_vertices(const Contact_scene& scene, std::vector<std::pair<std::uint32_t, std::uint32_t>>& links) {
  const Vertex_faces incidence = vertex_faces(scene.triangles, std::size_t(scene.rest.cols()));
  std::vector<std::uint32_t> tested(scene.triangles.size(), ~0u);
  std::vector<std::tuple<std::uint32_t, double, std::uint32_t>> near;  // part, squared distance, triangle
  for (std::uint32_t v = 0; v < std::uint32_t(scene.rest.cols()); ++v) {
    const auto around = incidence.of(v);
    if (around.empty()) continue;
    const std::uint32_t part = scene.parts[around[0]];
    const Eigen::Vector3d p = scene.rest.col(v);
    const Eigen::AlignedBox3d reach(p.array() - scene.distance, p.array() + scene.distance);
    near.clear();
    scene.grid.for_cells(reach.min().array(), reach.max().array(), [&](std::uint64_t key) {
      for (std::uint32_t g : scene.grid.others(key, part)) {
        if (tested[g] == v || scene.parts[g] == part || !scene.box[g].intersects(reach)) continue;
        tested[g] = v;
        const double d = scene.squared_distance(p, g);
        if (d <= scene.distance * scene.distance) near.emplace_back(scene.parts[g], d, g);
      }
    });
    std::sort(near.begin(), near.end());
    for (std::size_t i = 0; i < near.size(); ++i)
      if (i == 0 || std::get<0>(near[i]) != std::get<0>(near[i - 1]))
        links.emplace_back(around[0], std::get<2>(near[i]));
  }
}

// The mesh's edges, each once, with the triangles around it: (smaller vertex, larger vertex,
// triangle) sorted, so that an edge's triangles are consecutive.
inline std::vector<std::array<std::uint32_t, 3>> edges_with_triangles(
    std::span<const std::array<std::uint32_t, 3>> triangles) {
  std::vector<std::array<std::uint32_t, 3>> edges;
  edges.reserve(3 * triangles.size());
  for (std::uint32_t f = 0; f < triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), f});
    }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// Each edge longer than twice the distance crossing a triangle of another part: the edge's first
// triangle linked to it. (A shorter edge has an end within the distance of the triangle it
// crosses, which add_touching_vertices links.) The crossing lies in a cell the edge passes through
// and the triangle is binned in; a stamp per triangle tests it once per edge, however many such
// cells the two share.
inline void add_crossing_edges(const Contact_scene& scene, std::vector<std::pair<std::uint32_t, std::uint32_t>>& links) {
  const auto edges = edges_with_triangles(scene.triangles);
  std::vector<std::size_t> tested(scene.triangles.size(), ~std::size_t(0));
  for (std::size_t first = 0, last = 0; first < edges.size(); first = last) {
    while (last < edges.size() && edges[last][0] == edges[first][0] && edges[last][1] == edges[first][1]) ++last;
    const std::uint32_t f = edges[first][2], part = scene.parts[f];  // a vertex's triangles are of one part
    const Eigen::Vector3d p = scene.rest.col(edges[first][0]), q = scene.rest.col(edges[first][1]);
    if ((q - p).norm() <= 2 * scene.distance) continue;
    const Eigen::AlignedBox3d edge_box(p.cwiseMin(q), p.cwiseMax(q));
    scene.grid.for_cells_on_segment(p, q, [&](std::uint64_t key) {
      for (std::uint32_t g : scene.grid.others(key, part)) {
        if (tested[g] == first || scene.parts[g] == part || !scene.box[g].intersects(edge_box)) continue;
        tested[g] = first;
        if (segment_crosses_triangle(p, q, scene.corner(g, 0), scene.corner(g, 1), scene.corner(g, 2)))
          links.emplace_back(f, g);
      }
    });
  }
}

// Each part's vertices, in ascending order, parts by number.
inline std::vector<std::vector<std::uint32_t>> part_vertices(std::span<const std::array<std::uint32_t, 3>> triangles,
                                                             const std::vector<std::uint32_t>& parts,
                                                             std::size_t vertices, std::size_t count) {
  std::vector<std::uint32_t> part_of(vertices, ~0u);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (std::uint32_t v : triangles[f]) part_of[v] = parts[f];
  std::vector<std::vector<std::uint32_t>> members(count);
  for (std::uint32_t v = 0; v < vertices; ++v)
    if (part_of[v] != ~0u) members[part_of[v]].push_back(v);
  return members;
}

// A model of DeformingMesh other than Deforming_mesh, read in place: the index tables of its
// connectivity (a Deforming_mesh of a copy of its graph, without frames) and each frame through
// its point map when asked for, vertex i the original of the copy's vertex i, as
// make_deforming_mesh pairs them; the same doubles as that copy's, without its 3 T V.
template <class Mesh>
class Point_map_frames {
public:
  explicit Point_map_frames(const Mesh& animation)
      : animation_(&animation), topology_(animation.face_graph()), original_(topology_.num_vertices()) {
    auto copied = vertices(topology_.face_graph()).begin();
    for (auto v : vertices(animation.face_graph())) original_[get(topology_.vertex_index_map(), *copied++)] = v;
  }
  std::size_t num_frames() const { return animation_->num_frames(); }
  std::size_t num_vertices() const { return topology_.num_vertices(); }
  auto triangles() const { return topology_.triangles(); }
  // Frame t as a 3 x V matrix; a non-finite coordinate throws, as the copy would.
  Eigen::Matrix3Xd frame_points(std::size_t t) const {
    Eigen::Matrix3Xd xyz(3, Eigen::Index(original_.size()));
    const auto points = animation_->frame_point_map(t);
    for (std::size_t i = 0; i < original_.size(); ++i) {
      const auto& p = get(points, original_[i]);
      for (int k = 0; k < 3; ++k) {
        xyz(k, Eigen::Index(i)) = CGAL::to_double(p[k]);
        if (!std::isfinite(xyz(k, Eigen::Index(i))))
          throw invalid_input("vertex " + std::to_string(i) + " has a non-finite coordinate", {.frame = t});
      }
    }
    return xyz;
  }

private:
  using Graph = typename Mesh::Face_graph;
  const Mesh* animation_;
  mesh::Deforming_mesh<Graph> topology_;
  std::vector<typename boost::graph_traits<Graph>::vertex_descriptor> original_;
};

// The frames of an animation as 3 x V matrices in double precision.
template <class Animation>
Eigen::Matrix3Xd frame_points(const Animation& animation, std::size_t t) {
  if constexpr (requires { animation.frame_points(t); })
    return animation.frame_points(t);
  else
    return animation.frame_matrix(t).template cast<double>();
}

// Per part, its best rigid motion from the rest pose in every frame, or none (an empty vector)
// when the part strays further than `tolerance` from it in some frame.
template <class Animation>
std::vector<std::vector<Rigid_motion>> rigid_part_motions(const Animation& animation,
                                                          const std::vector<std::vector<std::uint32_t>>& members,
                                                          double tolerance) {
  const Eigen::Matrix3Xd rest = frame_points(animation, 0);
  std::vector<std::vector<Rigid_motion>> motions(members.size());
  std::vector<bool> rigid(members.size(), true);
  std::vector<Eigen::Matrix3Xd> rest_of(members.size());
  for (std::size_t p = 0; p < members.size(); ++p) rest_of[p] = rest(Eigen::all, members[p]);
  for (std::size_t t = 0; t < animation.num_frames(); ++t) {
    const Eigen::Matrix3Xd points = frame_points(animation, t);
    for (std::size_t p = 0; p < members.size(); ++p) {
      if (!rigid[p]) continue;
      const Eigen::Matrix3Xd moved = points(Eigen::all, members[p]);
      const Rigid_motion motion = best_rigid_motion(rest_of[p], moved);
      const double stray = ((motion.rotation * rest_of[p]).colwise() + motion.translation - moved).colwise().norm().maxCoeff();
      if (stray > tolerance) rigid[p] = false, motions[p].clear();
      else motions[p].push_back(motion);
    }
  }
  return motions;
}

// Whether two parts' motions move every corner of the box [low, high] to within `tolerance`.
inline bool move_as_one(const std::vector<Rigid_motion>& a, const std::vector<Rigid_motion>& b,
                        const Eigen::Vector3d& low, const Eigen::Vector3d& high, double tolerance) {
  for (std::size_t t = 0; t < a.size(); ++t)
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d corner((c & 1) ? high.x() : low.x(), (c & 2) ? high.y() : low.y(),
                                   (c & 4) ? high.z() : low.z());
      if ((a[t](corner) - b[t](corner)).norm() > tolerance) return false;
    }
  return true;
}

// The group of each part (the smallest part of its group): rigid parts whose motions move the
// box [low, high] alike are grouped. Candidates are found by sweeping where their motions take
// the box's low corner in the middle frame, which parts that move as one bring within the
// tolerance of each other.
inline std::vector<std::uint32_t> rigid_groups(const std::vector<std::vector<Rigid_motion>>& motions,
                                               const Eigen::Vector3d& low, const Eigen::Vector3d& high,
                                               double tolerance) {
  std::vector<std::uint32_t> rigid;
  for (std::uint32_t p = 0; p < motions.size(); ++p)
    if (!motions[p].empty()) rigid.push_back(p);
  if (rigid.empty()) return {};
  const std::size_t middle = motions[rigid[0]].size() / 2;
  const auto key = [&](std::uint32_t p) { return motions[p][middle](low).x(); };
  std::sort(rigid.begin(), rigid.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::pair(key(a), a) < std::pair(key(b), b);
  });
  std::vector<std::uint32_t> group(motions.size());  // union-find, the smaller part the root
  std::iota(group.begin(), group.end(), 0u);
  const auto find = [&](std::uint32_t p) {
    while (group[p] != p) p = group[p] = group[group[p]];
    return p;
  };
  for (std::size_t i = 0; i < rigid.size(); ++i)
    for (std::size_t j = i + 1; j < rigid.size() && key(rigid[j]) - key(rigid[i]) <= tolerance; ++j)
      if (move_as_one(motions[rigid[i]], motions[rigid[j]], low, high, tolerance)) {
        const std::uint32_t a = find(rigid[i]), b = find(rigid[j]);
        group[std::max(a, b)] = std::min(a, b);
      }
  for (std::uint32_t p = 0; p < group.size(); ++p) group[p] = find(p);
  return group;
}

// Rigid parts that move as one, each linked by its first triangle to its group's first.
template <class Animation>
void add_rigid_groups(const Animation& animation, std::span<const std::array<std::uint32_t, 3>> triangles,
                      const std::vector<std::uint32_t>& parts, std::size_t count, double tolerance,
                      std::vector<std::pair<std::uint32_t, std::uint32_t>>& links) {
  const auto motions = rigid_part_motions(animation, part_vertices(triangles, parts, animation.num_vertices(), count),
                                          tolerance);
  const Eigen::Matrix3Xd rest = frame_points(animation, 0);
  const std::vector<std::uint32_t> group =
      rigid_groups(motions, rest.rowwise().minCoeff(), rest.rowwise().maxCoeff(), tolerance);
  std::vector<std::uint32_t> first_face(count, ~0u);
  for (std::uint32_t f = 0; f < triangles.size(); ++f)
    if (first_face[parts[f]] == ~0u) first_face[parts[f]] = f;
  for (std::uint32_t p = 0; p < group.size(); ++p)
    if (group[p] != p) links.emplace_back(first_face[group[p]], first_face[p]);
}

// part_links of a Deforming_mesh or of a Point_map_frames.
template <class Animation>
std::vector<std::pair<std::uint32_t, std::uint32_t>> part_links_of(const Animation& animation,
                                                                   const Part_link_options& options) {
  for (double value : {options.contact_distance, options.rigid_tolerance})
    if (!(value >= 0) || !std::isfinite(value))
      throw invalid_input("part_links: the contact distance and the rigid tolerance must be finite and >= 0");
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
  const auto triangles = animation.triangles();
  if (animation.num_frames() == 0 || triangles.empty()) return links;
  const std::vector<std::uint32_t> parts = internal::triangle_parts(triangles, animation.num_vertices());
  const std::size_t count = std::size_t(*std::max_element(parts.begin(), parts.end())) + 1;
  if (count < 2) return links;
  const Eigen::Matrix3Xd rest = internal::frame_points(animation, 0);
  const double diagonal = (rest.rowwise().maxCoeff() - rest.rowwise().minCoeff()).norm();
  if (options.contact_distance > 0) {
    const internal::Contact_scene scene(rest, triangles, parts, options.contact_distance * diagonal, diagonal);
    internal::add_touching_vertices(scene, links);
    internal::add_crossing_edges(scene, links);
  }
  if (options.rigid_tolerance > 0)
    internal::add_rigid_groups(animation, triangles, parts, count, options.rigid_tolerance * diagonal, links);
  for (auto& [f, g] : links)
    if (g < f) std::swap(f, g);
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  return links;
}

}  // namespace internal

/// @brief The pairs of triangles of different parts of `animation` that `options` makes
/// neighbours: parts that touch at the rest pose (frame 0) and parts that move as one rigid body
/// throughout, as `Part_link_options` defines them. Each pair once, smaller triangle first, in
/// ascending order: the links of `Body_layout`.
/// @tparam Mesh a `DeformingMesh`; a `Deforming_mesh` is read in place, any other model through
/// its point maps, one frame at a time, into the matrices the parts' rigid motions are fitted to,
/// with the triangles' vertex indices from a `Deforming_mesh` of a copy of its connectivity
/// (O(V + F), no frame): the same links as on a `Deforming_mesh` copy of it, without the copy's
/// 3 T V doubles.
/// @pre both options finite and >= 0; else throws `invalid_input`. Every coordinate finite; a
/// frame read with a non-finite one throws `invalid_input`.
/// @par Complexity Contacts: O(V + F) expected, with the triangles binned in a hashed grid of
/// cells of the contact distance (or the mean triangle size), for a surface whose triangles
/// overlap few cells. Rigid bodies: O(T V) for the parts' rigid motions, then the pairs of rigid
/// parts whose motions bring a probe point together in the middle frame, O(T) each; O(T P)
/// memory for P parts. A mesh of one part has no link.
template <mesh::DeformingMesh Mesh>
std::vector<std::pair<std::uint32_t, std::uint32_t>> part_links(const Mesh& animation,
                                                                const Part_link_options& options = {}) {
  if constexpr (!mesh::is_deforming_mesh_v<Mesh>) {
    return internal::part_links_of(internal::Point_map_frames<Mesh>(animation), options);
  } else {
    return internal::part_links_of(animation, options);
  }
}

/// @brief The links `part_links` gives an animation whose frames are handed over one at a time,
/// as a frame source read again from its start gives them, one frame in memory.
/// @tparam Frames a type with `num_frames()`, `num_vertices()`, `triangles()` (a span of
/// `std::array<std::uint32_t, 3>`, as `Deforming_mesh::triangles()`) and `frame_points(t)`, frame
/// `t` as a `3 x V` `Eigen::Matrix3Xd` of finite coordinates (else it throws `invalid_input`). It
/// is asked for frame 0 a few times, then for every frame in order from 0, once (when the mesh has
/// several parts and `options.rigid_tolerance` is not 0).
/// @pre as `part_links`.
/// @return the links of `part_links` of an animation of these frames and triangles, to the bit.
/// @par Complexity as `part_links`.
template <class Frames>
std::vector<std::pair<std::uint32_t, std::uint32_t>> part_links_of_frames(const Frames& frames,
                                                                          const Part_link_options& options = {}) {
  return internal::part_links_of(frames, options);
}

}  // namespace deformseg::spatiotemporal
