// A body made from a skeleton, for a file that has no mesh (a BVH clip, an animation-only glTF or
// FBX export): a closed tube along every bone, skinned to the skeleton, added to the model as one
// skinned glTF mesh, so that the glTF reader samples, welds and repairs it as any character's.
//
// The skeleton is every node of the scene that a clip moves, with the nodes below them (an end
// site moves with its joint). A bone runs from a joint's rest origin to a child joint's, and is
// moved by the joint. The tube's radius is an eighth of the bone's length; its rings in the middle
// half of the bone follow the joint rigidly, and those within a quarter of the bone's length of
// either end blend linearly towards the joint at that end (the parent's joint at the start, the
// child at the end), a share that would reach a half at the end itself, so that a bent joint
// bends the tube as linear blend skinning bends skin. Everything comes from the rest pose, so every clip of one
// skeleton plays on the same body, vertex for vertex.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/assimp_model_writer.h>
#include <deformseg/io/internal/gltf_binding.h>
#include <deformseg/io/internal/gltf_mesh.h>
#include <deformseg/io/internal/gltf_scene.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io::internal::gltf {

/// The shape of the made body's tubes, one per bone.
struct Tube_shape {
  static constexpr std::size_t sides = 8;  ///< vertices of a ring
  /// Where the rings lie along the bone, as fractions of its length from its joint: not at the
  /// ends, so that the rings of two bones that meet at a joint never coincide (they would be
  /// welded into a surface that is not a manifold).
  static constexpr std::array<double, 7> rings{0.05, 0.15, 0.25, 0.5, 0.75, 0.85, 0.95};
  static constexpr double radius = 0.125;  ///< the tube's radius, a fraction of the bone's length
  static constexpr double blend = 0.25;    ///< the fraction of the bone at either end whose rings blend
  /// Vertices of a tube: the rings in order, each from angle 0, then the apex of each end's cap,
  /// half a radius beyond the joint along the bone (so that the tubes of one joint share none),
  /// skinned as the ring next to it.
  static constexpr std::size_t vertices = sides * rings.size() + 2;
  static constexpr std::size_t triangles = 2 * sides * (rings.size() - 1) + 2 * sides;
};

/// The name of the node, mesh and skin of a made body.
inline constexpr const char* skeleton_body_name = "deformseg: skeleton body";

/// A bone: from the rest origin of node `joint` to that of its child node `child`, moved by `joint`.
struct Bone {
  std::size_t joint = 0, child = 0;
};

/// A skeleton in its rest pose: its joints (nodes, parents first) and bones.
struct Skeleton {
  std::vector<std::size_t> joints{};  ///< nodes, in the scene's depth-first order
  std::vector<Bone> bones{};          ///< one per joint below a joint, in the joints' order
  std::vector<Affine> rest{};         ///< per node of the model: its world transform at rest
  std::vector<int> parent{};          ///< per node: its parent, or -1
  std::vector<bool> in_skeleton{};    ///< per node: whether it is a joint
};

/// Per node, whether some clip moves its translation, rotation or scale.
inline std::vector<bool> animated_nodes(const tinygltf::Model& model) {
  std::vector<bool> animated(model.nodes.size(), false);
  for (const tinygltf::Animation& animation : model.animations)
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
      const bool moves = channel.target_path == "translation" || channel.target_path == "rotation" ||
                         channel.target_path == "scale";
      if (moves && channel.target_node >= 0 && std::size_t(channel.target_node) < animated.size())
        animated[std::size_t(channel.target_node)] = true;
    }
  return animated;
}

inline std::array<double, 3> origin(const Affine& a) { return {a.m[3], a.m[7], a.m[11]}; }

inline double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/// The diagonal of the box of the joints' rest origins.
inline double extent(const Skeleton& skeleton) {
  std::array<double, 3> low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  for (const std::size_t joint : skeleton.joints)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], origin(skeleton.rest[joint])[k]);
      high[k] = std::max(high[k], origin(skeleton.rest[joint])[k]);
    }
  return skeleton.joints.empty() ? 0 : distance(low, high);
}

/// The skeleton of the scene (see the file's comment); a node whose rest transform cannot be
/// inverted (a scale of 0) is left out, with the bones that touch it. Bones shorter than 10^-6 of
/// the skeleton's extent are left out: their tubes would be degenerate.
inline Skeleton skeleton_of(const tinygltf::Model& model) {
  const Node_forest forest = node_forest(model);
  Skeleton skeleton{.parent = forest.parent};
  std::vector<Affine> local;
  for (const Node_pose& pose : rest_poses(model)) local.push_back(pose.local());
  skeleton.rest = forest.world(local);
  const std::vector<bool> animated = animated_nodes(model);
  skeleton.in_skeleton.assign(model.nodes.size(), false);
  for (const std::size_t node : forest.scene_nodes) {  // parents first
    const int parent = forest.parent[node];
    const bool below_joint = parent >= 0 && skeleton.in_skeleton[std::size_t(parent)];
    const double det = determinant(skeleton.rest[node]);
    skeleton.in_skeleton[node] = (animated[node] || below_joint) && std::isfinite(det) && det != 0;
    if (skeleton.in_skeleton[node]) skeleton.joints.push_back(node);
  }
  const double shortest = 1e-6 * extent(skeleton);
  for (const std::size_t child : skeleton.joints) {
    const int joint = forest.parent[child];
    if (joint < 0 || !skeleton.in_skeleton[std::size_t(joint)]) continue;
    const double length = distance(origin(skeleton.rest[std::size_t(joint)]), origin(skeleton.rest[child]));
    if (length > shortest && std::isfinite(length)) skeleton.bones.push_back({std::size_t(joint), child});
  }
  return skeleton;
}

/// The joints (nodes) and weights of a vertex of `bone`'s ring at `fraction` of its length: its
/// joint alone, but within `Tube_shape::blend` of an end, where the joint at that end takes a
/// share growing linearly to a half at the end.
inline std::array<std::pair<std::size_t, double>, 2> ring_influences(const Skeleton& skeleton, const Bone& bone,
                                                                     double fraction) {
  const double near_end = (fraction - (1 - Tube_shape::blend)) / Tube_shape::blend;
  const double near_start = (Tube_shape::blend - fraction) / Tube_shape::blend;
  const int above = skeleton.parent[bone.joint];
  if (near_end > 0) return {{{bone.joint, 1 - near_end / 2}, {bone.child, near_end / 2}}};
  if (near_start > 0 && above >= 0 && skeleton.in_skeleton[std::size_t(above)])
    return {{{bone.joint, 1 - near_start / 2}, {std::size_t(above), near_start / 2}}};
  return {{{bone.joint, 1.0}, {bone.joint, 0.0}}};
}

/// Two unit vectors that make a right-handed frame with the unit vector `d` (d, u, v), chosen from
/// `d` alone.
inline std::pair<std::array<double, 3>, std::array<double, 3>> perpendiculars(const std::array<double, 3>& d) {
  std::size_t axis = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (std::abs(d[k]) < std::abs(d[axis])) axis = k;
  std::array<double, 3> u{0, 0, 0};
  u[axis] = 1;
  const double along = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
  for (int k = 0; k < 3; ++k) u[k] -= along * d[k];
  const double norm = std::hypot(u[0], u[1], u[2]);
  for (double& x : u) x /= norm;
  const std::array<double, 3> v{d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]};
  return {u, v};
}

/// The made body's arrays, as its glTF primitive holds them.
struct Body_arrays {
  std::vector<float> positions{};         // 3 per vertex
  std::vector<std::uint16_t> joints{};    // 4 per vertex, indices into the skin's joints
  std::vector<float> weights{};           // 4 per vertex
  std::vector<std::uint32_t> indices{};   // 3 per triangle
};

/// Appends a vertex at `p` with the influences `of` (skin indices by `skin_index`).
inline void append_vertex(Body_arrays& body, const std::array<double, 3>& p,
                          const std::array<std::pair<std::size_t, double>, 2>& of,
                          const std::vector<std::uint16_t>& skin_index) {
  body.positions.insert(body.positions.end(), {float(p[0]), float(p[1]), float(p[2])});
  body.joints.insert(body.joints.end(), {skin_index[of[0].first], skin_index[of[1].first], 0, 0});
  body.weights.insert(body.weights.end(), {float(of[0].second), float(of[1].second), 0.0f, 0.0f});
}

/// Appends the triangles of a tube whose vertices start at `first`, facing outwards.
inline void append_tube_triangles(Body_arrays& body, std::uint32_t first) {
  constexpr std::uint32_t sides = Tube_shape::sides;
  const auto at = [&](std::size_t ring, std::uint32_t side) {
    return first + std::uint32_t(ring) * sides + side % sides;
  };
  for (std::size_t ring = 0; ring + 1 < Tube_shape::rings.size(); ++ring)
    for (std::uint32_t s = 0; s < sides; ++s)
      body.indices.insert(body.indices.end(), {at(ring, s), at(ring, s + 1), at(ring + 1, s + 1),
                                               at(ring, s), at(ring + 1, s + 1), at(ring + 1, s)});
  const std::uint32_t start_apex = first + sides * std::uint32_t(Tube_shape::rings.size()), end_apex = start_apex + 1;
  const std::size_t last = Tube_shape::rings.size() - 1;
  for (std::uint32_t s = 0; s < sides; ++s)
    body.indices.insert(body.indices.end(),
                        {start_apex, at(0, s + 1), at(0, s), end_apex, at(last, s), at(last, s + 1)});
}

/// Appends the tube of `bone` (see `Tube_shape`).
inline void append_tube(Body_arrays& body, const Skeleton& skeleton, const Bone& bone,
                        const std::vector<std::uint16_t>& skin_index) {
  const std::array<double, 3> a = origin(skeleton.rest[bone.joint]), b = origin(skeleton.rest[bone.child]);
  const double length = distance(a, b), radius = Tube_shape::radius * length;
  const std::array<double, 3> d{(b[0] - a[0]) / length, (b[1] - a[1]) / length, (b[2] - a[2]) / length};
  const auto [u, v] = perpendiculars(d);
  const auto first = std::uint32_t(body.positions.size() / 3);
  for (const double fraction : Tube_shape::rings) {
    const auto influences = ring_influences(skeleton, bone, fraction);
    for (std::size_t s = 0; s < Tube_shape::sides; ++s) {
      const double angle = 2 * std::numbers::pi * double(s) / double(Tube_shape::sides);
      const double cu = radius * std::cos(angle), sv = radius * std::sin(angle);
      std::array<double, 3> p{};
      for (int k = 0; k < 3; ++k) p[k] = a[k] + fraction * length * d[k] + cu * u[k] + sv * v[k];
      append_vertex(body, p, influences, skin_index);
    }
  }
  const double beyond = radius / 2;
  append_vertex(body, {a[0] - beyond * d[0], a[1] - beyond * d[1], a[2] - beyond * d[2]},
                ring_influences(skeleton, bone, Tube_shape::rings.front()), skin_index);
  append_vertex(body, {b[0] + beyond * d[0], b[1] + beyond * d[1], b[2] + beyond * d[2]},
                ring_influences(skeleton, bone, Tube_shape::rings.back()), skin_index);
  append_tube_triangles(body, first);
}

/// glTF's column-major 4x4 layout of an affine transform.
inline std::array<float, 16> column_major_floats(const Affine& a) {
  std::array<float, 16> c{};
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 3; ++row) c[std::size_t(4 * col + row)] = float(a.m[std::size_t(4 * row + col)]);
    c[std::size_t(4 * col + 3)] = col == 3 ? 1.0f : 0.0f;
  }
  return c;
}

/// Adds the skin of the skeleton's joints (inverse bind matrices: their rest transforms
/// inverted) and gives each node's index in it.
inline std::vector<std::uint16_t> write_skin(const Skeleton& skeleton, assimp::Model_writer& writer,
                                             tinygltf::Model& model) {
  if (skeleton.joints.size() > 65'535) throw invalid_input("a skeleton of more than 65,535 joints");
  std::vector<std::uint16_t> skin_index(model.nodes.size(), 0);
  tinygltf::Skin skin;
  skin.name = skeleton_body_name;
  std::vector<float> inverse_binds;
  for (const std::size_t joint : skeleton.joints) {
    skin_index[joint] = std::uint16_t(skin.joints.size());
    skin.joints.push_back(int(joint));
    const std::array<float, 16> matrix = column_major_floats(inverse(skeleton.rest[joint]));
    inverse_binds.insert(inverse_binds.end(), matrix.begin(), matrix.end());
  }
  skin.inverseBindMatrices = writer.accessor(std::span<const float>(inverse_binds), TINYGLTF_TYPE_MAT4, 16);
  model.skins.push_back(std::move(skin));
  return skin_index;
}

/// Adds a node of the made body's mesh and skin to the default scene (a root of its own).
inline void add_body_node(tinygltf::Model& model, int mesh, int skin) {
  tinygltf::Node node;
  node.name = skeleton_body_name;
  node.mesh = mesh;
  node.skin = skin;
  model.nodes.push_back(std::move(node));
  if (model.scenes.empty()) return;  // then every root node is shown
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  model.scenes[std::size_t(scene)].nodes.push_back(int(model.nodes.size() - 1));
}

/// Adds the body made from the model's skeleton (see the file's comment), when the skeleton has
/// a bone; returns whether it did.
/// @throws invalid_input for a node hierarchy that is not a forest, a malformed node, a skeleton
/// of more than 65,535 joints, or more tube vertices than a scene may have.
inline bool add_skeleton_body(tinygltf::Model& model) {
  const Skeleton skeleton = skeleton_of(model);
  if (skeleton.bones.empty()) return false;
  if (skeleton.bones.size() > max_scene_vertices / Tube_shape::vertices)
    throw invalid_input("a skeleton of " + std::to_string(skeleton.bones.size()) +
                        " bones: its body would have more than " + std::to_string(max_scene_vertices) + " vertices");
  assimp::Model_writer writer(model);
  const std::vector<std::uint16_t> skin_index = write_skin(skeleton, writer, model);
  Body_arrays body;
  for (const Bone& bone : skeleton.bones) append_tube(body, skeleton, bone, skin_index);
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  auto& attributes = primitive.attributes;
  attributes["POSITION"] = writer.accessor(std::span<const float>(body.positions), TINYGLTF_TYPE_VEC3, 3);
  attributes["JOINTS_0"] = writer.accessor(std::span<const std::uint16_t>(body.joints), TINYGLTF_TYPE_VEC4, 4);
  attributes["WEIGHTS_0"] = writer.accessor(std::span<const float>(body.weights), TINYGLTF_TYPE_VEC4, 4);
  primitive.indices = writer.accessor(std::span<const std::uint32_t>(body.indices), TINYGLTF_TYPE_SCALAR, 1);
  tinygltf::Mesh mesh;
  mesh.name = skeleton_body_name;
  mesh.primitives.push_back(std::move(primitive));
  model.meshes.push_back(std::move(mesh));
  add_body_node(model, int(model.meshes.size() - 1), int(model.skins.size() - 1));
  return true;
}

/// Whether the model holds a body made by `add_skeleton_body`.
inline bool has_skeleton_body(const tinygltf::Model& model) {
  return std::any_of(model.nodes.begin(), model.nodes.end(), [&](const tinygltf::Node& node) {
    return node.name == skeleton_body_name && node.mesh >= 0 && std::size_t(node.mesh) < model.meshes.size() &&
           model.meshes[std::size_t(node.mesh)].name == skeleton_body_name;
  });
}

}  // namespace deformseg::io::internal::gltf
