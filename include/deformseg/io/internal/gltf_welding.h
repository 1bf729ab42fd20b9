// The welding of a glTF scene's vertices from what the file fixes, so that every clip of a file
// has one mesh: two vertices are welded when their rest positions (POSITION, in their mesh's
// space) coincide, they have the same influences (the same joints with the same weights after
// normalisation, or the same node for a vertex rigid to it) and the same morph target deltas on the
// same node; such vertices coincide in every frame of every clip.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/gltf_mesh.h>
#include <deformseg/io/internal/vertex_welding.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io::internal::gltf {

/// A vertex's influences, made comparable: its (entry, weight) pairs of positive weight, one per
/// entry (a joint listed twice counts once, with the sum of its weights), by entry. A vertex rigid
/// to its node (an unskinned part, or a skinned vertex of no weight) has the one influence of entry
/// `rigid_base + node` and weight 1.
struct Influences {
  std::array<std::uint32_t, 8> entry{};
  std::array<double, 8> weight{};
  std::size_t count = 0;
};

/// The data of the scene's vertices that fixes their trajectories in every clip.
class Scene_vertices {
public:
  explicit Scene_vertices(const Scene_geometry& geometry, std::size_t skin_joints)
      : geometry_(geometry), rigid_base_(std::uint32_t(skin_joints)) {
    vertex_.reserve(geometry.vertices);
    for (std::uint32_t p = 0; p < geometry.parts.size(); ++p)
      for (std::uint32_t i = 0; i < geometry.parts[p].vertex_count; ++i) vertex_.push_back({p, i});
  }

  std::size_t size() const noexcept { return vertex_.size(); }
  const Mesh_part& part(std::uint32_t v) const { return geometry_.parts[vertex_[v].first]; }
  const double* rest(std::uint32_t v) const { return part(v).rest.data() + 3 * vertex_[v].second; }

  /// The delta of morph target `t` of vertex `v` (0 past its part's targets).
  std::array<double, 3> delta(std::uint32_t v, std::size_t t) const {
    const Mesh_part& p = part(v);
    if (t >= p.targets) return {};
    const double* d = p.target_deltas.data() + (t * p.vertex_count + vertex_[v].second) * 3;
    return {d[0], d[1], d[2]};
  }

  /// Whether a morph target moves `v`: then its trajectory depends on its node's morph weights.
  bool morphed(std::uint32_t v) const {
    for (std::size_t t = 0; t < part(v).targets; ++t)
      for (const double x : delta(v, t))
        if (x != 0) return true;
    return false;
  }

  Influences influences(std::uint32_t v) const {
    const Mesh_part& p = part(v);
    const std::uint32_t rigid = rigid_base_ + std::uint32_t(p.node);
    Influences result;
    if (p.skin < 0) {
      result.entry[0] = rigid, result.weight[0] = 1, result.count = 1;
      return result;
    }
    for (std::size_t k = 0; k < p.influences; ++k) {
      const double w = p.weights[vertex_[v].second * p.influences + k];
      const std::uint32_t joint = p.joints[vertex_[v].second * p.influences + k];
      if (w > 0) add(result, joint < rigid_base_ ? joint : rigid, w);  // past the joints: the node itself
    }
    return result;
  }

  /// Adds weight `w` of `entry`, keeping the entries in increasing order and each once.
  static void add(Influences& influences, std::uint32_t entry, double w) {
    std::size_t k = 0;
    while (k < influences.count && influences.entry[k] < entry) ++k;
    if (k < influences.count && influences.entry[k] == entry) {
      influences.weight[k] += w;
      return;
    }
    for (std::size_t m = influences.count; m > k; --m)
      influences.entry[m] = influences.entry[m - 1], influences.weight[m] = influences.weight[m - 1];
    influences.entry[k] = entry, influences.weight[k] = w;
    ++influences.count;
  }

  /// The most morph targets of the parts of `v` and `w`.
  std::size_t targets(std::uint32_t v, std::uint32_t w) const { return std::max(part(v).targets, part(w).targets); }

private:
  const Scene_geometry& geometry_;
  std::uint32_t rigid_base_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> vertex_{};  // part, index in the part
};

/// A hash of what fixes a vertex's trajectory (0 and -0 alike), and its exact comparison.
struct Same_scene_vertex {
  const Scene_vertices* vertices;
  std::span<const std::uint64_t> hashes;

  static std::uint64_t mix(std::uint64_t h, double x) {
    return (h ^ std::bit_cast<std::uint64_t>(x == 0 ? 0.0 : x)) * 0x100000001b3ull;  // FNV-1a
  }

  static std::uint64_t hash(const Scene_vertices& vertices, std::uint32_t v) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t k = 0; k < 3; ++k) h = mix(h, vertices.rest(v)[k]);
    const Influences influences = vertices.influences(v);
    for (std::size_t k = 0; k < influences.count; ++k)
      h = mix(mix(h, double(influences.entry[k])), influences.weight[k]);
    if (vertices.morphed(v)) {  // the targets that move it: a part with fewer targets has zeros past them
      h = mix(h, double(vertices.part(v).node));
      for (std::size_t t = 0; t < vertices.part(v).targets; ++t) {
        const std::array<double, 3> d = vertices.delta(v, t);
        if (d[0] != 0 || d[1] != 0 || d[2] != 0) h = mix(mix(mix(mix(h, double(t)), d[0]), d[1]), d[2]);
      }
    }
    return h ^ (h >> 29);
  }

  std::size_t operator()(std::uint32_t v) const noexcept { return static_cast<std::size_t>(hashes[v]); }

  bool operator()(std::uint32_t a, std::uint32_t b) const noexcept {
    const Scene_vertices& s = *vertices;
    for (std::size_t k = 0; k < 3; ++k)
      if (s.rest(a)[k] != s.rest(b)[k]) return false;
    const Influences ia = s.influences(a), ib = s.influences(b);
    if (ia.count != ib.count) return false;
    for (std::size_t k = 0; k < ia.count; ++k)
      if (ia.entry[k] != ib.entry[k] || ia.weight[k] != ib.weight[k]) return false;
    return morph_alike(s, a, b, 0);
  }

  /// The same morph target deltas within `distance`, on the same node unless neither is morphed.
  static bool morph_alike(const Scene_vertices& s, std::uint32_t a, std::uint32_t b, double distance) {
    const bool morphed_a = s.morphed(a), morphed_b = s.morphed(b);
    if (!morphed_a && !morphed_b) return true;
    if (s.part(a).node != s.part(b).node) return false;
    for (std::size_t t = 0; t < s.targets(a, b); ++t) {
      const std::array<double, 3> da = s.delta(a, t), db = s.delta(b, t);
      for (std::size_t k = 0; k < 3; ++k)
        if (!(std::abs(da[k] - db[k]) <= distance)) return false;
    }
    return true;
  }
};

/// Vertices `a` and `b` coincide in every frame of every clip: rest positions within `distance` in
/// each coordinate, the same influences with weights within `weight_tolerance`, and the same morph
/// target deltas within `distance` on the same node.
inline bool alike_in_every_clip(const Scene_vertices& s, std::uint32_t a, std::uint32_t b, double distance,
                                double weight_tolerance) {
  for (std::size_t k = 0; k < 3; ++k)
    if (!(std::abs(s.rest(a)[k] - s.rest(b)[k]) <= distance)) return false;
  const Influences ia = s.influences(a), ib = s.influences(b);
  if (ia.count != ib.count) return false;
  for (std::size_t k = 0; k < ia.count; ++k)
    if (ia.entry[k] != ib.entry[k] || !(std::abs(ia.weight[k] - ib.weight[k]) <= weight_tolerance)) return false;
  return Same_scene_vertex::morph_alike(s, a, b, distance);
}

/// Welds the scene's vertices from what the file fixes (see the top of this file): rest positions
/// and morph deltas within `tolerance` times the diagonal of the bounding box of all rest
/// positions, weights within `tolerance`; and the transitive closure.
/// @return the welded vertex of each vertex, numbered in the order of their smallest vertex.
/// @throws invalid_input for a non-finite rest position.
/// O(V) expected, unless many vertices of different data lie within the distance of each other.
inline std::vector<std::uint32_t> weld_scene_vertices(const Scene_geometry& geometry, std::size_t skin_joints,
                                                      double tolerance) {
  const Scene_vertices vertices(geometry, skin_joints);
  std::vector<double> points(3 * vertices.size());
  for (std::uint32_t v = 0; v < vertices.size(); ++v)
    for (std::size_t k = 0; k < 3; ++k) {
      points[3 * v + k] = vertices.rest(v)[k];
      if (!std::isfinite(points[3 * v + k]))
        throw invalid_input("vertex " + std::to_string(v) + " has a non-finite POSITION");
    }
  const double extent = bounding_box(std::span<const double>(points)).diagonal();
  const double distance = tolerance * extent;
  std::vector<std::uint64_t> hashes(vertices.size());
  for (std::uint32_t v = 0; v < vertices.size(); ++v) hashes[v] = Same_scene_vertex::hash(vertices, v);
  return weld_on_grid(std::span<const double>(points), welding_cell(distance, extent),
                      Same_scene_vertex{&vertices, hashes}, [&](std::uint32_t a, std::uint32_t b) {
                        return alike_in_every_clip(vertices, a, b, distance, tolerance);
                      });
}

}  // namespace deformseg::io::internal::gltf
