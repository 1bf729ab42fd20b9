// Linear blend skinning and morph targets for glTF parts: the joint table of a pose (world(joint)
// * inverse bind matrix for every skin's joints, then each skinned part's own node), morph target
// deltas added to the rest positions, and the per-vertex blend of 3x4 matrices; of every vertex of
// a part, or of some of them (`Part_selection`), each vertex by the same operations either way, so
// that a vertex posed alone equals, bit for bit, the same vertex posed with its part.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/gltf_accessor.h>
#include <deformseg/io/internal/gltf_mesh.h>
#include <deformseg/io/internal/gltf_scene.h>

#include <tiny_gltf.h>

#if defined(__AVX__) && defined(__FMA__)
#include <immintrin.h>
#endif

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace deformseg::io::internal::gltf {

/// The skins: joint nodes and inverse bind matrices (identity when the file has none).
struct Skins {
  std::vector<std::vector<std::size_t>> joints{};
  std::vector<std::vector<Affine>> inverse_bind{};
};

inline Skins read_skins(const tinygltf::Model& model) {
  Skins skins;
  for (std::size_t s = 0; s < model.skins.size(); ++s) {
    const tinygltf::Skin& skin = model.skins[s];
    const std::string name = "skin " + std::to_string(s) + (skin.name.empty() ? "" : " '" + skin.name + "'");
    std::vector<std::size_t> joints;
    for (int joint : skin.joints) {
      if (joint < 0 || std::size_t(joint) >= model.nodes.size())
        throw invalid_input(name + " has joint node " + std::to_string(joint) + ", which does not exist");
      joints.push_back(std::size_t(joint));
    }
    std::vector<Affine> inverse_bind(joints.size());
    if (skin.inverseBindMatrices >= 0) {
      const Accessor_values matrices =
          read_accessor(model, skin.inverseBindMatrices, name + " inverseBindMatrices", 16);
      if (matrices.count != joints.size())
        throw invalid_input(name + " has " + std::to_string(matrices.count) + " inverse bind matrices for " +
                            std::to_string(joints.size()) + " joints");
      for (std::size_t j = 0; j < joints.size(); ++j) inverse_bind[j] = affine_from_column_major(matrices.element(j));
    }
    skins.joints.push_back(std::move(joints));
    skins.inverse_bind.push_back(std::move(inverse_bind));
  }
  return skins;
}

/// The joint table of a pose: every skin's joint matrices, in skin order, then the world
/// transform of each skinned part's node (for its vertices without weight).
inline void joint_table(const Skins& skins, const std::vector<Mesh_part>& parts, const std::vector<Affine>& world,
                        std::vector<Affine>& table) {
  table.clear();
  for (std::size_t s = 0; s < skins.joints.size(); ++s)
    for (std::size_t j = 0; j < skins.joints[s].size(); ++j)
      table.push_back(world[skins.joints[s][j]] * skins.inverse_bind[s][j]);
  for (const Mesh_part& part : parts)
    if (part.skin >= 0) table.push_back(world[part.node]);
}

/// rest + sum_t weight_t delta_t, into `out` (3 per vertex); `weights` has one per target.
inline void morph(const Mesh_part& part, const std::vector<double>& weights, std::vector<double>& out) {
  out.assign(part.rest.begin(), part.rest.end());
  const std::size_t block = 3 * part.vertex_count;
  for (std::size_t t = 0; t < part.targets && t < weights.size(); ++t) {
    if (weights[t] == 0) continue;
    const double w = weights[t];
    const double* delta = part.target_deltas.data() + t * block;
    for (std::size_t i = 0; i < block; ++i) out[i] += w * delta[i];
  }
}

/// `morph` of vertex `v` of the part alone, into `out` (3 values): the same sums in the same order.
inline void morph_vertex(const Mesh_part& part, const std::vector<double>& weights, std::size_t v, double* out) {
  for (std::size_t c = 0; c < 3; ++c) out[c] = part.rest[3 * v + c];
  const std::size_t block = 3 * part.vertex_count;
  for (std::size_t t = 0; t < part.targets && t < weights.size(); ++t) {
    if (weights[t] == 0) continue;
    const double w = weights[t];
    const double* delta = part.target_deltas.data() + t * block + 3 * v;
    for (std::size_t c = 0; c < 3; ++c) out[c] += w * delta[c];
  }
}

/// One skinned vertex: the weighted sum of its joints' matrices (`joints` and `weights`, Influences
/// each, at least 2) applied to `p`, into `q`.
template <std::size_t Influences>
inline void skin_vertex(const std::uint32_t* joints, const double* weights, const Affine* table, const double* p,
                        double* q) {
  static_assert(Influences >= 2);
  alignas(32) double m[12];
#if defined(__AVX__) && defined(__FMA__)
  // The blend's 12 entries as three vectors of 4, which g++ does not make of the plain loop below;
  // fused as it fuses that loop on an FMA target (the first influence's product added to the
  // second's by one fma, then one fma per influence), so that the positions keep their bits.
  const double* first = table[joints[0]].m.data();
  const double* second = table[joints[1]].m.data();
  const __m256d w0 = _mm256_set1_pd(weights[0]), w1 = _mm256_set1_pd(weights[1]);
  __m256d rows[3];
  for (int r = 0; r < 3; ++r)
    rows[r] = _mm256_fmadd_pd(w0, _mm256_loadu_pd(first + 4 * r), _mm256_mul_pd(w1, _mm256_loadu_pd(second + 4 * r)));
  for (std::size_t k = 2; k < Influences; ++k) {
    const double* joint = table[joints[k]].m.data();
    const __m256d w = _mm256_set1_pd(weights[k]);
    for (int r = 0; r < 3; ++r) rows[r] = _mm256_fmadd_pd(w, _mm256_loadu_pd(joint + 4 * r), rows[r]);
  }
  for (int r = 0; r < 3; ++r) _mm256_store_pd(m + 4 * r, rows[r]);
#else
  const double* first = table[joints[0]].m.data();
  for (int i = 0; i < 12; ++i) m[i] = weights[0] * first[i];
  for (std::size_t k = 1; k < Influences; ++k) {
    const double* joint = table[joints[k]].m.data();
    const double w = weights[k];
    for (int i = 0; i < 12; ++i) m[i] += w * joint[i];
  }
#endif
  for (int r = 0; r < 3; ++r) q[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
}

/// Positions of a skinned part: per vertex, the weighted sum of its joints' matrices applied to it.
template <std::size_t Influences>
void skin_vertices(const Mesh_part& part, const double* positions, const Affine* table, double* out) {
  for (std::size_t v = 0; v < part.vertex_count; ++v)
    skin_vertex<Influences>(part.joints.data() + Influences * v, part.weights.data() + Influences * v, table,
                            positions + 3 * v, out + 3 * v);
}

/// Positions of a part in the pose given by `world` and `table`, after morphing by `weights`.
/// `scratch` holds the morphed rest positions between calls.
inline void pose_part(const Mesh_part& part, const std::vector<Affine>& world, const std::vector<Affine>& table,
                      const std::vector<double>* weights, std::vector<double>& scratch, double* out) {
  const double* positions = part.rest.data();
  if (part.targets > 0 && weights) {
    morph(part, *weights, scratch);
    positions = scratch.data();
  }
  if (part.skin < 0) {
    const Affine& transform = world[part.node];
    for (std::size_t v = 0; v < part.vertex_count; ++v) transform.apply(positions + 3 * v, out + 3 * v);
  } else if (part.influences == 8) {
    skin_vertices<8>(part, positions, table.data(), out);
  } else {
    skin_vertices<4>(part, positions, table.data(), out);
  }
}

/// Some vertices of one part, to be posed alone: their indices in the part, and for each the
/// output vertex it is written to.
struct Part_selection {
  std::size_t part = 0;
  std::vector<std::uint32_t> vertex{};
  std::vector<std::uint32_t> slot{};
};

/// The vertices of `selection`'s part posed as `pose_part` poses them, vertex i into output
/// vertex `selection.slot[i]` of `out` (3 per output vertex): each morphed (when `weights`) and
/// then skinned or moved with its node, alone.
inline void pose_selected(const Mesh_part& part, const Part_selection& selection, const std::vector<Affine>& world,
                          const std::vector<Affine>& table, const std::vector<double>* weights, double* out) {
  const bool morphed = part.targets > 0 && weights;
  const auto each = [&](const auto& move) {
    double p[3];
    for (std::size_t i = 0; i < selection.vertex.size(); ++i) {
      const std::size_t v = selection.vertex[i];
      const double* at = part.rest.data() + 3 * v;
      if (morphed) morph_vertex(part, *weights, v, p), at = p;
      move(v, at, out + 3 * std::size_t(selection.slot[i]));
    }
  };
  if (part.skin < 0) {
    const Affine& transform = world[part.node];
    each([&](std::size_t, const double* p, double* q) { transform.apply(p, q); });
  } else if (part.influences == 8) {
    each([&](std::size_t v, const double* p, double* q) {
      skin_vertex<8>(part.joints.data() + 8 * v, part.weights.data() + 8 * v, table.data(), p, q);
    });
  } else {
    each([&](std::size_t v, const double* p, double* q) {
      skin_vertex<4>(part.joints.data() + 4 * v, part.weights.data() + 4 * v, table.data(), p, q);
    });
  }
}

}  // namespace deformseg::io::internal::gltf
