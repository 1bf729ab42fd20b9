// The geometry of a glTF scene: one part per TRIANGLES primitive of every mesh node instance, in
// the order of the scene's depth-first traversal, with its rest positions, morph target deltas
// and, for skinned parts, up to 8 joint influences per vertex with weights normalised to sum 1.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/gltf_accessor.h>
#include <deformseg/io/internal/gltf_scene.h>

#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace deformseg::io::internal::gltf {

/// The most vertices (over all mesh instances) a scene may have: bounds what is allocated before
/// the data is read.
inline constexpr std::size_t max_scene_vertices = std::size_t(1) << 26;

/// One TRIANGLES primitive of one mesh node instance.
struct Mesh_part {
  std::size_t node = 0, mesh = 0, primitive = 0;
  std::size_t first_vertex = 0, vertex_count = 0;
  std::vector<double> rest{};           // 3 per vertex
  std::size_t targets = 0;              // morph targets
  std::vector<double> target_deltas{};  // targets x 3 per vertex: POSITION deltas (0 when absent)
  int skin = -1;                        // the node's skin when the part is skinned, else -1
  std::size_t influences = 0;           // joints per vertex: 4 or 8 when skinned
  std::vector<std::uint32_t> joints{};  // vertex x influences, into the frame's joint table
  std::vector<double> weights{};        // vertex x influences, summing to 1 per vertex
};

/// What a scene's skin weights needed, as engines load them: influences dropped (a weight NaN,
/// infinite or negative, or a weighted joint outside its skin) and vertices left without weight,
/// which follow their mesh's node. The first defect in words, for `Defect_policy::refuse`.
struct Weight_defects {
  std::size_t dropped_influences = 0;
  std::size_t unweighted_vertices = 0;
  std::string first{};

  void note(std::size_t& count, std::string what) {
    if (first.empty()) first = std::move(what);
    ++count;
  }
};

inline const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
    default: return "unknown";
  }
}

/// The primitive's mode, TRIANGLES when it has none.
inline int primitive_mode(const tinygltf::Primitive& primitive) {
  return primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
}

inline std::string primitive_name(const tinygltf::Model& model, std::size_t mesh, std::size_t primitive) {
  const std::string& name = model.meshes[mesh].name;
  return "mesh " + (name.empty() ? std::to_string(mesh) : "'" + name + "'") + " primitive " + std::to_string(primitive);
}

inline int attribute(const tinygltf::Primitive& primitive, const char* name) {
  const auto found = primitive.attributes.find(name);
  return found == primitive.attributes.end() ? -1 : found->second;
}

/// Why a primitive gives no triangle, or empty when it does.
inline std::string skip_reason(const tinygltf::Primitive& primitive) {
  if (primitive_mode(primitive) != TINYGLTF_MODE_TRIANGLES)
    return std::string("mode ") + mode_name(primitive_mode(primitive));
  if (attribute(primitive, "POSITION") < 0) return "no POSITION";
  return {};
}

inline std::size_t accessor_count(const tinygltf::Model& model, int index, const std::string& user) {
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    throw invalid_input(user + " refers to accessor " + std::to_string(index) + ", which does not exist");
  return model.accessors[std::size_t(index)].count;
}

/// Reads an attribute that must have `count` elements of `components` components.
inline Accessor_values read_attribute(const tinygltf::Model& model, int index, std::size_t count,
                                      std::size_t components, const std::string& user) {
  Accessor_values values = read_accessor(model, index, user, components);
  if (values.count != count)
    throw invalid_input(user + " has " + std::to_string(values.count) + " elements for " + std::to_string(count) +
                        " vertices");
  return values;
}

/// The morph target deltas of a primitive: targets x 3 per vertex.
inline std::vector<double> read_target_deltas(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                              std::size_t count, const std::string& name) {
  std::vector<double> deltas(primitive.targets.size() * 3 * count, 0.0);
  for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
    const auto found = primitive.targets[t].find("POSITION");
    if (found == primitive.targets[t].end()) continue;
    const Accessor_values d =
        read_attribute(model, found->second, count, 3, name + " target " + std::to_string(t) + " POSITION");
    std::copy(d.values.begin(), d.values.end(), deltas.begin() + std::ptrdiff_t(t * 3 * count));
  }
  return deltas;
}

/// Reads JOINTS_n / WEIGHTS_n (n = 0, and 1 when present) into the part: joints become indices
/// into the frame's joint table (skin's joints from `joint_base`); an influence whose weight is
/// not finite and at least 0, or whose joint is outside the skin, is dropped, and a vertex whose
/// weights are all zero follows `rigid_entry`, the table's entry for the mesh node itself (both
/// noted in `defects`, as three.js and Blender load such files).
inline void read_influences(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                            std::size_t joint_count, std::uint32_t joint_base, std::uint32_t rigid_entry,
                            const std::string& name, Mesh_part& part, Weight_defects& defects) {
  const std::size_t n = part.vertex_count;
  const bool second_set = attribute(primitive, "JOINTS_1") >= 0 && attribute(primitive, "WEIGHTS_1") >= 0;
  part.influences = second_set ? 8 : 4;
  part.joints.assign(n * part.influences, rigid_entry);
  part.weights.assign(n * part.influences, 0.0);
  for (std::size_t set = 0; set < part.influences / 4; ++set) {
    const std::string j = "JOINTS_" + std::to_string(set), w = "WEIGHTS_" + std::to_string(set);
    const Accessor_values joints = read_attribute(model, attribute(primitive, j.c_str()), n, 4, name + " " + j);
    const Accessor_values weights = read_attribute(model, attribute(primitive, w.c_str()), n, 4, name + " " + w);
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t k = 0; k < 4; ++k) {
        const double joint = joints.element(v)[k], weight = weights.element(v)[k];
        if (!(weight >= 0) || !std::isfinite(weight)) {
          defects.note(defects.dropped_influences, name + " vertex " + std::to_string(v) + " has weight " +
                                                       shortest_text(weight) + "; glTF needs finite weights >= 0");
          continue;
        }
        if (weight == 0) continue;
        // Checked before any conversion: a joint read from a signed or float accessor may be
        // negative, fractional or huge, and converting such a value to an integer is undefined.
        if (!(joint >= 0 && joint < double(joint_count)) || joint != std::floor(joint)) {
          defects.note(defects.dropped_influences, name + " vertex " + std::to_string(v) + " refers to joint " +
                                                       shortest_text(joint) + " of a skin with " +
                                                       std::to_string(joint_count) + " joints");
          continue;
        }
        part.joints[v * part.influences + set * 4 + k] = joint_base + std::uint32_t(joint);
        part.weights[v * part.influences + set * 4 + k] = weight;
      }
  }
  for (std::size_t v = 0; v < n; ++v) {
    double* w = part.weights.data() + v * part.influences;
    double sum = 0;
    for (std::size_t k = 0; k < part.influences; ++k) sum += w[k];
    if (sum == 0) {  // no influence: the vertex stays rigid to the mesh node (joints are rigid_entry)
      defects.note(defects.unweighted_vertices,
                   name + " vertex " + std::to_string(v) + " has no weight; glTF needs weights summing to 1");
      w[0] = 1;
      continue;
    }
    for (std::size_t k = 0; k < part.influences; ++k) w[k] /= sum;
  }
}

/// The triangles of a part, offset by its first vertex.
inline void append_triangles(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                             const Mesh_part& part, const std::string& name,
                             std::vector<std::array<std::uint32_t, 3>>& triangles) {
  std::vector<double> indices;
  if (primitive.indices >= 0) {
    accessor_count(model, primitive.indices, name + " indices");  // throws when it does not exist
    const int type = model.accessors[std::size_t(primitive.indices)].componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      throw invalid_input(name + " indices have component type " + std::to_string(type) +
                          "; glTF allows unsigned byte, short or int");
    indices = read_accessor(model, primitive.indices, name + " indices", 1).values;
  } else {
    indices.resize(part.vertex_count);
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = double(i);
  }
  if (indices.size() % 3 != 0)
    throw invalid_input(name + " has " + std::to_string(indices.size()) + " indices, not a multiple of 3");
  for (std::size_t i = 0; i < indices.size(); i += 3) {
    std::array<std::uint32_t, 3> triangle{};
    for (std::size_t k = 0; k < 3; ++k) {
      if (indices[i + k] >= double(part.vertex_count))
        throw invalid_input(name + " index " + std::to_string(i + k) + " is " +
                            std::to_string(std::uint64_t(indices[i + k])) + ", out of its " +
                            std::to_string(part.vertex_count) + " vertices");
      triangle[k] = std::uint32_t(part.first_vertex + std::size_t(indices[i + k]));
    }
    triangles.push_back(triangle);
  }
}

/// The geometry of the scene: parts in traversal order, their triangles, and the primitives
/// skipped (not TRIANGLES, or no POSITION), as text.
struct Scene_geometry {
  std::vector<Mesh_part> parts{};
  std::vector<std::array<std::uint32_t, 3>> triangles{};
  std::vector<std::string> skipped{};
  std::size_t vertices = 0;
  Weight_defects weights{};
};

/// Where each skin's joints start in the frame's joint table; after them come one entry per
/// skinned part, for the mesh node itself.
inline std::vector<std::uint32_t> skin_joint_bases(const tinygltf::Model& model) {
  std::vector<std::uint32_t> bases;
  std::size_t next = 0;
  for (const tinygltf::Skin& skin : model.skins) {
    bases.push_back(std::uint32_t(next));
    next += skin.joints.size();
  }
  bases.push_back(std::uint32_t(next));
  return bases;
}

/// A mesh node instance of the scene: the node and the mesh it shows.
struct Mesh_instance {
  std::size_t node = 0, mesh = 0;
};

/// The scene's mesh node instances, in the order of its depth-first traversal.
/// @throws invalid_input for a node that refers to a mesh that does not exist.
inline std::vector<Mesh_instance> mesh_instances(const tinygltf::Model& model, const Node_forest& forest) {
  std::vector<Mesh_instance> instances;
  for (std::size_t node : forest.scene_nodes) {
    const int mesh = model.nodes[node].mesh;
    if (mesh < 0) continue;
    if (std::size_t(mesh) >= model.meshes.size())
      throw invalid_input(node_name(model, node) + " refers to mesh " + std::to_string(mesh) +
                          ", which does not exist");
    instances.push_back({.node = node, .mesh = std::size_t(mesh)});
  }
  return instances;
}

/// The vertices of the TRIANGLES primitives of all `instances`, before anything is read.
/// @throws invalid_input past `max_scene_vertices`.
inline std::size_t count_scene_vertices(const tinygltf::Model& model, const std::vector<Mesh_instance>& instances) {
  std::size_t total = 0;
  for (const Mesh_instance& instance : instances)
    for (std::size_t p = 0; p < model.meshes[instance.mesh].primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = model.meshes[instance.mesh].primitives[p];
      if (!skip_reason(primitive).empty()) continue;
      total += accessor_count(model, attribute(primitive, "POSITION"), primitive_name(model, instance.mesh, p));
      if (total > max_scene_vertices)
        throw invalid_input("the scene has more than " + std::to_string(max_scene_vertices) + " vertices");
    }
  return total;
}

/// Reads every TRIANGLES primitive of every mesh instance of the scene.
inline Scene_geometry read_scene_geometry(const tinygltf::Model& model, const Node_forest& forest) {
  Scene_geometry geometry;
  const std::vector<Mesh_instance> instances = mesh_instances(model, forest);
  count_scene_vertices(model, instances);
  const std::vector<std::uint32_t> bases = skin_joint_bases(model);
  std::uint32_t next_rigid_entry = bases.back();
  std::vector<bool> reported(model.meshes.size(), false);
  for (const auto [node, mesh] : instances) {
    const tinygltf::Node& instance = model.nodes[node];
    if (instance.skin >= 0 && std::size_t(instance.skin) >= model.skins.size())
      throw invalid_input(node_name(model, node) + " refers to skin " + std::to_string(instance.skin) +
                          ", which does not exist");
    for (std::size_t p = 0; p < model.meshes[mesh].primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = model.meshes[mesh].primitives[p];
      const std::string name = primitive_name(model, mesh, p);
      if (const std::string reason = skip_reason(primitive); !reason.empty()) {
        if (!reported[mesh]) geometry.skipped.push_back(name + ": " + reason + ", skipped");
        continue;
      }
      Mesh_part part{.node = node, .mesh = mesh, .primitive = p};
      part.first_vertex = geometry.vertices;
      part.rest = read_accessor(model, attribute(primitive, "POSITION"), name + " POSITION", 3).values;
      part.vertex_count = part.rest.size() / 3;
      part.targets = primitive.targets.size();
      part.target_deltas = read_target_deltas(model, primitive, part.vertex_count, name);
      if (instance.skin >= 0 && attribute(primitive, "JOINTS_0") >= 0 && attribute(primitive, "WEIGHTS_0") >= 0) {
        part.skin = instance.skin;
        read_influences(model, primitive, model.skins[std::size_t(instance.skin)].joints.size(),
                        bases[std::size_t(instance.skin)], next_rigid_entry++, name, part, geometry.weights);
      }
      append_triangles(model, primitive, part, name, geometry.triangles);
      geometry.vertices += part.vertex_count;
      geometry.parts.push_back(std::move(part));
    }
    reported[mesh] = true;
  }
  return geometry;
}

}  // namespace deformseg::io::internal::gltf
