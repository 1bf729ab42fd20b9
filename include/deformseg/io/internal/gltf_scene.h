// The glTF node hierarchy: local transforms (matrix, or translation * rotation * scale), the
// forest of nodes (each node has at most one parent, no cycle), and world transforms per pose.
#pragma once

#include <deformseg/exceptions.h>

#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace deformseg::io::internal::gltf {

/// An affine transform as the top three rows of a 4x4 matrix, row-major: m[4 r + c].
struct Affine {
  std::array<double, 12> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

  /// this * b
  Affine operator*(const Affine& b) const {
    Affine c;
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 4; ++k)
        c.m[4 * r + k] = m[4 * r] * b.m[k] + m[4 * r + 1] * b.m[4 + k] + m[4 * r + 2] * b.m[8 + k] +
                         (k == 3 ? m[4 * r + 3] : 0.0);
    return c;
  }

  /// The transform of point `p` (3 values) into `out` (3 values).
  void apply(const double* p, double* out) const {
    for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
  }
};

/// From a column-major 4x4 matrix (glTF's layout); the last row is (0, 0, 0, 1) for a node.
inline Affine affine_from_column_major(const double* c) {
  Affine a;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 4; ++k) a.m[4 * r + k] = c[4 * k + r];
  return a;
}

/// T * R * S for a translation, a unit quaternion (x, y, z, w) and a scale.
inline Affine affine_from_trs(const double* t, const double* q, const double* s) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double rotation[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                                 {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                                 {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  Affine a;
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) a.m[4 * r + k] = rotation[r][k] * s[k];
    a.m[4 * r + 3] = t[r];
  }
  return a;
}

/// The animatable state of a node: translation, rotation (x, y, z, w), scale; or a fixed matrix.
struct Node_pose {
  std::array<double, 3> translation{0, 0, 0};
  std::array<double, 4> rotation{0, 0, 0, 1};
  std::array<double, 3> scale{1, 1, 1};
  bool has_matrix = false;
  Affine matrix{};

  Affine local() const {
    return has_matrix ? matrix : affine_from_trs(translation.data(), rotation.data(), scale.data());
  }
};

inline std::string node_name(const tinygltf::Model& model, std::size_t index) {
  std::string s = "node " + std::to_string(index);
  if (index < model.nodes.size() && !model.nodes[index].name.empty()) s += " '" + model.nodes[index].name + "'";
  return s;
}

/// The rest pose of every node, from its matrix or its TRS properties.
/// @throws invalid_input for a property of the wrong length or a non-finite value.
inline std::vector<Node_pose> rest_poses(const tinygltf::Model& model) {
  std::vector<Node_pose> poses(model.nodes.size());
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const tinygltf::Node& node = model.nodes[i];
    const auto take = [&](const std::vector<double>& from, auto& to, const char* property) {
      if (from.empty()) return;
      if (from.size() != to.size())
        throw invalid_input(node_name(model, i) + " has a " + property + " of " + std::to_string(from.size()) +
                            " values, glTF needs " + std::to_string(to.size()));
      for (std::size_t k = 0; k < from.size(); ++k) {
        if (!std::isfinite(from[k])) throw invalid_input(node_name(model, i) + " has a non-finite " + property);
        to[k] = from[k];
      }
    };
    take(node.translation, poses[i].translation, "translation");
    take(node.rotation, poses[i].rotation, "rotation");
    take(node.scale, poses[i].scale, "scale");
    if (!node.matrix.empty()) {
      std::array<double, 16> matrix{};
      take(node.matrix, matrix, "matrix");
      poses[i].has_matrix = true;
      poses[i].matrix = affine_from_column_major(matrix.data());
    }
  }
  return poses;
}

/// The nodes as a forest: each node's parent, an order with parents before children (every node),
/// and the nodes of the displayed scene in depth-first pre-order.
struct Node_forest {
  std::vector<int> parent{};
  std::vector<std::size_t> parents_first{};
  std::vector<std::size_t> scene_nodes{};

  /// World transforms of every node from their local ones.
  std::vector<Affine> world(const std::vector<Affine>& local) const {
    std::vector<Affine> result;
    world(local, result);
    return result;
  }

  /// The same into `result`, whose memory serves again from frame to frame.
  void world(const std::vector<Affine>& local, std::vector<Affine>& result) const {
    result.resize(local.size());
    for (std::size_t i : parents_first)
      result[i] = parent[i] < 0 ? local[i] : result[std::size_t(parent[i])] * local[i];
  }
};

inline void append_preorder(const tinygltf::Model& model, std::size_t root, std::vector<std::size_t>& out) {
  std::vector<std::size_t> stack{root};
  while (!stack.empty()) {
    const std::size_t node = stack.back();
    stack.pop_back();
    out.push_back(node);
    const auto& children = model.nodes[node].children;
    for (auto c = children.rbegin(); c != children.rend(); ++c) stack.push_back(std::size_t(*c));
  }
}

/// The roots of the scene displayed: `defaultScene`, else scene 0, else every parentless node.
inline std::vector<std::size_t> scene_roots(const tinygltf::Model& model, const std::vector<int>& parent) {
  std::vector<std::size_t> roots;
  if (model.scenes.empty()) {
    for (std::size_t i = 0; i < parent.size(); ++i)
      if (parent[i] < 0) roots.push_back(i);
    return roots;
  }
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (std::size_t(scene) >= model.scenes.size())
    throw invalid_input("the default scene " + std::to_string(scene) + " does not exist");
  for (int node : model.scenes[std::size_t(scene)].nodes) {
    if (node < 0 || std::size_t(node) >= model.nodes.size())
      throw invalid_input("scene " + std::to_string(scene) + " refers to node " + std::to_string(node) +
                          ", which does not exist");
    if (parent[std::size_t(node)] >= 0)
      throw invalid_input("scene " + std::to_string(scene) + " lists " + node_name(model, std::size_t(node)) +
                          ", which is not a root node");
    roots.push_back(std::size_t(node));
  }
  return roots;
}

/// @throws invalid_input for a child that does not exist, a node with two parents, a cycle, or a
/// scene listing a node twice or a node that is not a root.
inline Node_forest node_forest(const tinygltf::Model& model) {
  const std::size_t n = model.nodes.size();
  Node_forest forest;
  forest.parent.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i)
    for (int child : model.nodes[i].children) {
      if (child < 0 || std::size_t(child) >= n)
        throw invalid_input(node_name(model, i) + " has child " + std::to_string(child) + ", which does not exist");
      if (forest.parent[std::size_t(child)] >= 0 || std::size_t(child) == i)
        throw invalid_input(node_name(model, std::size_t(child)) + " has more than one parent");
      forest.parent[std::size_t(child)] = int(i);
    }
  for (std::size_t i = 0; i < n; ++i)
    if (forest.parent[i] < 0) append_preorder(model, i, forest.parents_first);
  if (forest.parents_first.size() != n)  // the nodes left out lie on a cycle
    throw invalid_input("the node hierarchy has a cycle");
  std::vector<bool> listed(n, false);
  for (std::size_t root : scene_roots(model, forest.parent)) {
    if (listed[root]) throw invalid_input("the scene lists " + node_name(model, root) + " twice");
    listed[root] = true;
    append_preorder(model, root, forest.scene_nodes);
  }
  return forest;
}

}  // namespace deformseg::io::internal::gltf
