// An Assimp scene's node tree, meshes, skins and morph targets written as glTF nodes, meshes and
// skins (io/fbx_collada.h): Assimp's bone offset is glTF's inverse bind matrix (an FBX bone's as
// the FBX SDK holds it), its bones name the joint nodes, its morph targets are absolute positions
// (glTF's are deltas). The local transforms of a binary FBX file, small parts of which Assimp drops,
// are read from the file (`fbx::local_transforms`).
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/assimp_model_writer.h>

#include <assimp/commonMetaData.h>
#include <assimp/scene.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace deformseg::io::internal::assimp {

/// The most influences a vertex keeps: glTF's JOINTS_0 and JOINTS_1 (the largest weights first).
inline constexpr std::size_t max_influences = 8;

inline std::string name_of(const aiString& name) { return std::string(name.C_Str(), name.length); }

inline std::string mesh_name(const aiScene& scene, std::size_t mesh) {
  const std::string name = name_of(scene.mMeshes[mesh]->mName);
  return "mesh " + std::to_string(mesh) + (name.empty() ? "" : " '" + name + "'");
}

using Matrix = aiMatrix4x4t<double>;

/// glTF's column-major layout of a row-major matrix.
template <class Real>
std::vector<double> column_major(const aiMatrix4x4t<Real>& m) {
  return {m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4};
}

template <class Real>
bool finite(const aiMatrix4x4t<Real>& m) {
  const Real* values = &m.a1;
  return std::all_of(values, values + 16, [](Real x) { return std::isfinite(x); });
}

/// Local transforms that replace Assimp's for some nodes, in double precision (an FBX node's as
/// its file gives it: see `fbx::local_transforms`).
using Local_transforms = std::unordered_map<const aiNode*, Matrix>;

/// The glTF nodes of the scene's nodes, depth first (a node before its children, in order).
struct Node_table {
  std::size_t base = 0;                                    // the glTF index of source[0]
  std::vector<const aiNode*> source{};                     // glTF node base + i -> Assimp node
  std::unordered_map<std::string, std::size_t> by_name{};  // the node a name stands for: `name_holder`
  Local_transforms local{};                                // replacements of Assimp's transforms
};

/// The local transform of `node`: its replacement in `nodes.local`, else Assimp's.
inline Matrix local_transform(const Node_table& nodes, const aiNode& node) {
  const auto found = nodes.local.find(&node);
  return found != nodes.local.end() ? found->second : Matrix(node.mTransformation);
}

/// Records glTF node `at`, of Assimp node `node`, as the one its name stands for (for a bone, a
/// channel) unless an earlier node of that name is a better one: a node without meshes before one
/// with. Assimp's FBX reader keeps the names of the file's objects, and Blender names a bone and
/// the mesh object parented to it alike (the robot's bone 'Torso' and, under bone 'Body', its
/// mesh 'Torso'), a name only a bone (a node without meshes) is bound to or animated by.
inline void name_holder(Node_table& table, const aiNode& node, std::size_t at) {
  const auto [found, added] = table.by_name.emplace(name_of(node.mName), at);
  if (!added && node.mNumMeshes == 0 && table.source[found->second - table.base]->mNumMeshes > 0) found->second = at;
}

/// The glTF node of `source`: translation, rotation and scale for an animated node, since a glTF
/// channel replaces one of those; else its matrix, exactly.
inline tinygltf::Node gltf_node(const aiNode& source, const Matrix& transform, bool animated) {
  tinygltf::Node node;
  node.name = name_of(source.mName);
  if (!animated) {
    node.matrix = column_major(transform);
    return node;
  }
  aiVector3t<double> scaling, position;
  aiQuaterniont<double> rotation;
  transform.Decompose(scaling, rotation, position);
  const bool finite_rotation = std::isfinite(rotation.w) && std::isfinite(rotation.x) && std::isfinite(rotation.y) &&
                               std::isfinite(rotation.z);
  if (!finite_rotation) rotation = aiQuaterniont<double>();  // a scale of 0 leaves the rotation free
  node.translation = {position.x, position.y, position.z};
  node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
  node.scale = {scaling.x, scaling.y, scaling.z};
  return node;
}

/// Writes the node tree under `root` as glTF nodes from index `model.nodes.size()`; `animated`
/// holds the names of the nodes a clip moves, `local` the nodes whose transform replaces Assimp's.
/// @throws invalid_input for a non-finite transform, a node reached twice, or a tree deeper than
/// `max_depth`.
inline Node_table write_nodes(const aiNode& root, const std::set<std::string>& animated, tinygltf::Model& model,
                              Local_transforms local = {}) {
  constexpr std::size_t max_depth = 10'000;  // bounds the work on a malformed tree
  Node_table table{.base = model.nodes.size(), .local = std::move(local)};
  std::set<const aiNode*> seen;
  struct Visit {
    const aiNode* node;
    std::size_t depth;
    int parent;
  };
  std::vector<Visit> stack{{&root, 0, -1}};
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    const aiNode& node = *visit.node;
    const std::string name = name_of(node.mName);
    if (!seen.insert(&node).second)
      throw invalid_input("node '" + name + "' is reached twice: the nodes are not a tree");
    if (visit.depth > max_depth)
      throw invalid_input("the node tree is deeper than " + std::to_string(max_depth) + " nodes");
    const Matrix transform = local_transform(table, node);
    if (!finite(transform)) throw invalid_input("node '" + name + "' has a non-finite transform");
    const std::size_t at = model.nodes.size();
    table.source.push_back(&node);
    name_holder(table, node, at);
    model.nodes.push_back(gltf_node(node, transform, animated.contains(name)));
    if (visit.parent >= 0) model.nodes[std::size_t(visit.parent)].children.push_back(int(at));
    for (unsigned c = node.mNumChildren; c-- > 0;)  // pushed last to first: visited in order
      if (node.mChildren && node.mChildren[c]) stack.push_back({node.mChildren[c], visit.depth + 1, int(at)});
  }
  return table;
}

/// Where a bone's offset (glTF's inverse bind matrix) comes from.
enum class Bind_rule {
  as_stored,  ///< Assimp's offset, as the file stores it (Collada, Blender 2.80's FBX on, scenes built in memory)
  fbx_sdk,    ///< as Autodesk's FBX SDK reads an FBX file's (`fbx_sdk_offset`)
};

/// The major version of the Blender FBX add-on that wrote `scene` (its FBX header's Creator,
/// "Blender (stable FBX IO) - 3.4.1 - 4.37.1", gives 4), or 0 when another tool wrote it.
inline int blender_fbx_io_version(const aiScene& scene) {
  aiString creator;
  if (!scene.mMetaData || !scene.mMetaData->Get(AI_METADATA_SOURCE_GENERATOR, creator)) return 0;
  const std::string text = name_of(creator);
  const std::size_t last = text.rfind(" - ");
  if (!text.starts_with("Blender (") || last == std::string::npos) return 0;
  int major = 0;
  std::from_chars(text.data() + last + 3, text.data() + text.size(), major);
  return major;
}

/// The bind rule of an FBX scene. Blender's exporter writes a cluster's Transform as the bone's
/// rest matrix (TransformLink: the armature object's world matrix x the bone's rest matrix) inverted
/// x the mesh object's world matrix: the inverse bind matrix its armature modifier deforms with,
/// which Assimp reads as the bone's offset. From its FBX add-on 4 (Blender 2.80) it is taken as
/// stored, shear included (an armature or parent scaled non-uniformly shears it), since Blender
/// deforms with it; files of other tools, and of Blender 2.76, whose only reference is the SDK's
/// reading, take the SDK's rule. Chapter 2 of the manual gives the figures.
inline Bind_rule fbx_bind_rule(const aiScene& scene) {
  return blender_fbx_io_version(scene) >= 4 ? Bind_rule::as_stored : Bind_rule::fbx_sdk;
}

/// `m` as a translation, XYZ Euler angles and a scale, as the FBX SDK holds an affine matrix
/// (FbxAMatrix): the scale is the columns' lengths, the angles are read from entries of the
/// columns made unit, and any shear is lost. A matrix with a zero column is kept.
inline Matrix without_shear(const Matrix& m) {
  const double sx = std::hypot(m.a1, m.b1, m.c1), sy = std::hypot(m.a2, m.b2, m.c2), sz = std::hypot(m.a3, m.b3, m.c3);
  if (!(sx > 0 && sy > 0 && sz > 0)) return m;
  const double cos_y = std::hypot(m.a1 / sx, m.b1 / sx);
  double x = 0, z = 0;
  const double y = std::atan2(-m.c1 / sx, cos_y);
  if (cos_y > 16 * FLT_EPSILON) {
    x = std::atan2(m.c2 / sy, m.c3 / sz);
    z = std::atan2(m.b1 / sx, m.a1 / sx);
  } else {
    x = std::atan2(-m.b3 / sz, m.b2 / sy);  // gimbal lock: x and z turn about one axis, z is 0
  }
  Matrix rx, ry, rz, scale;
  Matrix result = Matrix::RotationZ(z, rz) * Matrix::RotationY(y, ry) * Matrix::RotationX(x, rx) *
                  Matrix::Scaling({sx, sy, sz}, scale);
  result.a4 = m.a4;
  result.b4 = m.b4;
  result.c4 = m.c4;
  return result;
}

/// The offset the FBX SDK gives a bone whose offset Assimp reads as `offset`, on a mesh of
/// global transform `mesh`. An FBX cluster stores the bone's global transform at bind time
/// (TransformLink, here mesh x offset^-1); the SDK holds it as an FbxAMatrix (`without_shear`),
/// and its inverse bind matrix is that matrix's inverse x TransformLink x offset. The two differ
/// on a bone below a non-uniformly scaled one (Blender writes scales within 1e-4 of 1 on legs):
/// its bind matrix has a shear of about 1e-4, which the angles turn into rotations of up to 0.015
/// rad near gimbal lock. Returns `offset` when a matrix is singular.
inline aiMatrix4x4 fbx_sdk_offset(const aiMatrix4x4& offset, const Matrix& mesh) {
  const Matrix stored = Matrix(offset);
  Matrix link = stored;
  if (link.Determinant() == 0) return offset;
  link = mesh * link.Inverse();
  Matrix held = without_shear(link);
  if (held.Determinant() == 0) return offset;
  const aiMatrix4x4 result = aiMatrix4x4(held.Inverse() * link * stored);
  return finite(result) ? result : offset;
}

/// The global transform of `node` in its scene.
inline Matrix global_transform(const Node_table& nodes, const aiNode& node) {
  Matrix global = local_transform(nodes, node);
  for (const aiNode* parent = node.mParent; parent; parent = parent->mParent)
    global = local_transform(nodes, *parent) * global;
  return global;
}

/// A bone of a mesh: its joint node and its offset (glTF's inverse bind matrix).
struct Joint {
  std::size_t node = 0;
  aiMatrix4x4 offset{};
};

/// The joints of a mesh, from its bones, each bone's name naming a node; their offsets as
/// `fbx_sdk_offset` takes them when `mesh_global` (the mesh's node's global transform) is given.
/// @throws invalid_input for a bone that names no node, or a non-finite offset.
inline std::vector<Joint> mesh_joints(const aiScene& scene, std::size_t mesh, const Node_table& nodes,
                                      const std::optional<Matrix>& mesh_global = std::nullopt) {
  const aiMesh& m = *scene.mMeshes[mesh];
  std::vector<Joint> joints;
  for (unsigned b = 0; b < m.mNumBones; ++b) {
    const aiBone& bone = *m.mBones[b];
    const auto found = nodes.by_name.find(name_of(bone.mName));
    if (found == nodes.by_name.end())
      throw invalid_input(mesh_name(scene, mesh) + " bone '" + name_of(bone.mName) +
                          "' names no node of the scene: its vertices cannot follow it");
    if (!finite(bone.mOffsetMatrix))
      throw invalid_input(mesh_name(scene, mesh) + " bone '" + name_of(bone.mName) + "' has a non-finite offset");
    const aiMatrix4x4& stored = bone.mOffsetMatrix;
    joints.push_back({found->second, mesh_global ? fbx_sdk_offset(stored, *mesh_global) : stored});
  }
  return joints;
}

/// Meshes of one node that one glTF skin serves: their bones' offsets agree on every joint node.
struct Mesh_group {
  std::vector<std::size_t> meshes{};
  std::map<std::size_t, aiMatrix4x4> joints{};  // joint node -> offset
  bool skinned = false;
};

inline bool joins(const Mesh_group& group, const std::vector<Joint>& joints, bool skinned) {
  if (group.skinned != skinned) return false;
  return std::all_of(joints.begin(), joints.end(), [&](const Joint& joint) {
    const auto found = group.joints.find(joint.node);
    return found == group.joints.end() || found->second == joint.offset;
  });
}

/// The node's meshes grouped so that each group is one glTF mesh with at most one skin: Assimp
/// splits a mesh per material, and its parts share their bones, so a node has one group but for
/// unusual files (a part unskinned, or the same bone bound at two poses).
inline std::vector<Mesh_group> group_meshes(const aiScene& scene, const aiNode& node, const Node_table& nodes,
                                            Bind_rule rule) {
  std::vector<Mesh_group> groups;
  const std::optional<Matrix> mesh_global =
      rule == Bind_rule::fbx_sdk && node.mNumMeshes > 0 ? std::optional(global_transform(nodes, node)) : std::nullopt;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const std::size_t mesh = node.mMeshes[k];
    if (mesh >= scene.mNumMeshes)
      throw invalid_input("node '" + name_of(node.mName) + "' refers to mesh " + std::to_string(mesh) +
                          ", which does not exist");
    const std::vector<Joint> joints = mesh_joints(scene, mesh, nodes, mesh_global);
    const bool skinned = !joints.empty();
    const auto joinable = [&](const Mesh_group& g) { return joins(g, joints, skinned); };
    auto group = std::find_if(groups.begin(), groups.end(), joinable);
    if (group == groups.end()) group = groups.insert(groups.end(), Mesh_group{.skinned = skinned});
    group->meshes.push_back(mesh);
    for (const Joint& joint : joints) group->joints.emplace(joint.node, joint.offset);
  }
  return groups;
}

/// A vertex's influences: (joint, weight) pairs, the largest weights first.
using Influence_list = std::vector<std::pair<std::uint16_t, float>>;

/// Every vertex's influences in the group's skin (`joint_of` maps a joint node to its index there),
/// the largest `max_influences` of positive weight, as glTF keeps them.
/// @throws invalid_input for a weight of a vertex that does not exist, or a non-finite or negative weight.
inline std::vector<Influence_list> influences(const aiScene& scene, std::size_t mesh, const Node_table& nodes,
                                              const std::map<std::size_t, std::uint16_t>& joint_of) {
  const aiMesh& m = *scene.mMeshes[mesh];
  std::vector<Influence_list> result(m.mNumVertices);
  for (unsigned b = 0; b < m.mNumBones; ++b) {
    const aiBone& bone = *m.mBones[b];
    const std::uint16_t joint = joint_of.at(nodes.by_name.at(name_of(bone.mName)));
    const auto where = [&] { return mesh_name(scene, mesh) + " bone '" + name_of(bone.mName) + "'"; };
    for (unsigned w = 0; w < bone.mNumWeights; ++w) {
      const aiVertexWeight& weight = bone.mWeights[w];
      if (weight.mVertexId >= m.mNumVertices)
        throw invalid_input(where() + " weights vertex " + std::to_string(weight.mVertexId) + " of " +
                            std::to_string(m.mNumVertices));
      if (!std::isfinite(weight.mWeight) || weight.mWeight < 0)
        throw invalid_input(where() + " has a weight of " + std::to_string(weight.mWeight) + " (vertex " +
                            std::to_string(weight.mVertexId) + ")");
      if (weight.mWeight > 0) result[weight.mVertexId].emplace_back(joint, weight.mWeight);
    }
  }
  for (Influence_list& list : result) {
    std::stable_sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    if (list.size() > max_influences) list.resize(max_influences);
  }
  return result;
}

/// Writes one mesh's triangles, positions, influences and morph targets as a glTF primitive.
/// Faces that are not triangles (points and lines: Assimp triangulates polygons) are left out.
/// @throws invalid_input for an index out of range, a non-finite position, or a morph target
/// whose vertex count is not the mesh's.
inline tinygltf::Primitive write_primitive(const aiScene& scene, std::size_t mesh,
                                           const std::vector<Influence_list>& influence, Model_writer& writer) {
  const aiMesh& m = *scene.mMeshes[mesh];
  const std::string name = mesh_name(scene, mesh);
  if (m.mNumVertices > 0 && !m.mVertices) throw invalid_input(name + " has no positions");
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  std::vector<float> positions;
  positions.reserve(3 * std::size_t(m.mNumVertices));
  for (unsigned v = 0; v < m.mNumVertices; ++v) {
    const aiVector3D& p = m.mVertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw invalid_input(name + " vertex " + std::to_string(v) + " has a non-finite position");
    positions.insert(positions.end(), {p.x, p.y, p.z});
  }
  primitive.attributes["POSITION"] = writer.accessor(std::span<const float>(positions), TINYGLTF_TYPE_VEC3, 3);

  std::vector<std::uint32_t> indices;
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    if (face.mNumIndices != 3 || !face.mIndices) continue;
    for (unsigned k = 0; k < 3; ++k) {
      if (face.mIndices[k] >= m.mNumVertices)
        throw invalid_input(name + " face " + std::to_string(f) + " refers to vertex " +
                            std::to_string(face.mIndices[k]) + " of " + std::to_string(m.mNumVertices));
      indices.push_back(face.mIndices[k]);
    }
  }
  primitive.indices = writer.accessor(std::span<const std::uint32_t>(indices), TINYGLTF_TYPE_SCALAR, 1);

  if (!influence.empty()) {
    std::size_t most = 0;
    for (const Influence_list& list : influence) most = std::max(most, list.size());
    for (std::size_t set = 0; set * 4 < std::max<std::size_t>(most, 1); ++set) {
      std::vector<std::uint16_t> joints(4 * influence.size(), 0);
      std::vector<float> weights(4 * influence.size(), 0.0f);
      for (std::size_t v = 0; v < influence.size(); ++v)
        for (std::size_t k = 0; k < 4 && set * 4 + k < influence[v].size(); ++k)
          std::tie(joints[4 * v + k], weights[4 * v + k]) = influence[v][set * 4 + k];
      const std::string suffix = "_" + std::to_string(set);
      primitive.attributes["JOINTS" + suffix] =
          writer.accessor(std::span<const std::uint16_t>(joints), TINYGLTF_TYPE_VEC4, 4);
      primitive.attributes["WEIGHTS" + suffix] = writer.accessor(std::span<const float>(weights), TINYGLTF_TYPE_VEC4, 4);
    }
  }

  for (unsigned t = 0; t < m.mNumAnimMeshes; ++t) {
    const aiAnimMesh& target = *m.mAnimMeshes[t];
    std::vector<float> deltas(positions.size(), 0.0f);
    if (target.mVertices) {
      if (target.mNumVertices != m.mNumVertices)
        throw invalid_input(name + " morph target " + std::to_string(t) + " has " + std::to_string(target.mNumVertices) +
                            " vertices for the mesh's " + std::to_string(m.mNumVertices));
      for (unsigned v = 0; v < m.mNumVertices; ++v)
        for (unsigned k = 0; k < 3; ++k) deltas[3 * v + k] = target.mVertices[v][k] - m.mVertices[v][k];
      if (!std::all_of(deltas.begin(), deltas.end(), [](float x) { return std::isfinite(x); }))
        throw invalid_input(name + " morph target " + std::to_string(t) + " has a non-finite position");
    }
    primitive.targets.push_back({{"POSITION", writer.accessor(std::span<const float>(deltas), TINYGLTF_TYPE_VEC3, 3)}});
  }
  return primitive;
}

/// Writes a group of meshes as one glTF mesh, and its skin when it has bones; returns the mesh's
/// index and the skin's (-1 for none). The mesh's morph weights are its targets' default weights.
inline std::pair<int, int> write_group(const aiScene& scene, const Mesh_group& group, const Node_table& nodes,
                                       Model_writer& writer, tinygltf::Model& model) {
  std::map<std::size_t, std::uint16_t> joint_of;
  int skin = -1;
  if (group.skinned) {
    if (group.joints.size() > 65'535) throw invalid_input("a skin has more than 65,535 joints");
    tinygltf::Skin gltf_skin;
    std::vector<float> inverse_binds;
    for (const auto& [node, offset] : group.joints) {
      joint_of[node] = std::uint16_t(gltf_skin.joints.size());
      gltf_skin.joints.push_back(int(node));
      for (const double x : column_major(offset)) inverse_binds.push_back(float(x));
    }
    gltf_skin.inverseBindMatrices = writer.accessor(std::span<const float>(inverse_binds), TINYGLTF_TYPE_MAT4, 16);
    model.skins.push_back(std::move(gltf_skin));
    skin = int(model.skins.size() - 1);
  }
  tinygltf::Mesh gltf_mesh;
  for (const std::size_t mesh : group.meshes) {
    if (!gltf_mesh.name.empty()) gltf_mesh.name += "+";
    gltf_mesh.name += name_of(scene.mMeshes[mesh]->mName);
    const std::vector<Influence_list> influence =
        group.skinned ? influences(scene, mesh, nodes, joint_of) : std::vector<Influence_list>{};
    gltf_mesh.primitives.push_back(write_primitive(scene, mesh, influence, writer));
    const aiMesh& m = *scene.mMeshes[mesh];
    for (unsigned t = 0; t < m.mNumAnimMeshes; ++t) {
      if (gltf_mesh.weights.size() <= t) gltf_mesh.weights.push_back(0);
      gltf_mesh.weights[t] = m.mAnimMeshes[t]->mWeight;
    }
  }
  model.meshes.push_back(std::move(gltf_mesh));
  return {int(model.meshes.size() - 1), skin};
}

/// Writes every node's meshes: the first group on the node itself, any other on a child node of
/// identity transform, bone offsets taken by `rule`. Returns, for each Assimp mesh, the glTF node
/// that shows it.
inline std::vector<int> write_meshes(const aiScene& scene, const Node_table& nodes, Bind_rule rule,
                                     Model_writer& writer, tinygltf::Model& model) {
  std::vector<int> node_of_mesh(scene.mNumMeshes, -1);
  for (std::size_t n = 0; n < nodes.source.size(); ++n) {
    const std::vector<Mesh_group> groups = group_meshes(scene, *nodes.source[n], nodes, rule);
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const auto [mesh, skin] = write_group(scene, groups[g], nodes, writer, model);
      std::size_t holder = nodes.base + n;
      if (g > 0) {
        tinygltf::Node child;
        child.name = model.nodes[holder].name + " (part " + std::to_string(g) + ")";
        model.nodes.push_back(std::move(child));
        model.nodes[holder].children.push_back(int(model.nodes.size() - 1));
        holder = model.nodes.size() - 1;
      }
      model.nodes[holder].mesh = mesh;
      model.nodes[holder].skin = skin;
      for (const std::size_t m : groups[g].meshes) node_of_mesh[m] = int(holder);
    }
  }
  return node_of_mesh;
}

}  // namespace deformseg::io::internal::assimp
