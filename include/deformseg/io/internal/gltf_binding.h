// The clips of one file played on the body of another, as engines bind an animation to a model:
// each channel moves the body's node of the same name as the node it moved in its own file, its
// values carried from the clip file's frames (units, up axis) into the body's.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/gltf_animation.h>
#include <deformseg/io/internal/gltf_scene.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io::internal::gltf {

/// How the channels of a clip node change to move the body's node of its name: translations are
/// scaled by `scale`, turned by `rotation` and moved by `offset`; rotations turned by `rotation`.
struct Frame_change {
  double scale = 1;
  std::array<double, 4> rotation{0, 0, 0, 1};  // a unit quaternion (x, y, z, w)
  std::array<double, 3> offset{0, 0, 0};

  bool is_identity() const {
    return scale == 1 && rotation == std::array<double, 4>{0, 0, 0, 1} && offset == std::array<double, 3>{0, 0, 0};
  }
};

/// Where a body's clips come from when another file holds them.
struct Bound_clips {
  std::shared_ptr<const tinygltf::Model> model{};
  std::string file{};                                   // the clips' file, which their errors name
  std::string body_file{};                              // the body's, which they mention
  std::vector<std::optional<std::size_t>> body_node{};  // per node of `model`: the body's node of its name
  std::vector<Frame_change> change{};                   // per node of `model`: see `frame_changes`
};

/// A node's name without its namespace: the part after the last ':' ("mixamorig:Hips" -> "Hips"),
/// as FBX writes a rig's namespace before every joint's name.
inline std::string without_namespace(const std::string& name) {
  const std::size_t colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

/// The body's node of each node of `clips` of the same name (not empty), the first such; else,
/// for a name the body has not, the body's one node of the same name without namespace
/// (`without_namespace`: "mixamorig:Hips" and "Hips" match), when one alone has it.
inline std::vector<std::optional<std::size_t>> body_nodes_by_name(const tinygltf::Model& body,
                                                                  const tinygltf::Model& clips) {
  std::map<std::string, std::size_t> by_name;
  std::map<std::string, std::vector<std::size_t>> by_base_name;
  for (std::size_t i = 0; i < body.nodes.size(); ++i) {
    if (body.nodes[i].name.empty()) continue;
    by_name.emplace(body.nodes[i].name, i);
    by_base_name[without_namespace(body.nodes[i].name)].push_back(i);
  }
  std::vector<std::optional<std::size_t>> body_node(clips.nodes.size());
  for (std::size_t i = 0; i < clips.nodes.size(); ++i) {
    const std::string& name = clips.nodes[i].name;
    if (const auto found = by_name.find(name); found != by_name.end()) body_node[i] = found->second;
    else if (const auto base = by_base_name.find(without_namespace(name));
             !name.empty() && base != by_base_name.end() && base->second.size() == 1)
      body_node[i] = base->second.front();
  }
  return body_node;
}

/// The determinant of an affine transform's linear part.
inline double determinant(const Affine& a) {
  const auto& m = a.m;
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
}

/// The inverse of an invertible affine transform.
inline Affine inverse(const Affine& a) {
  const auto& m = a.m;
  const double det = determinant(a);
  Affine b;
  b.m = {(m[5] * m[10] - m[6] * m[9]) / det, (m[2] * m[9] - m[1] * m[10]) / det, (m[1] * m[6] - m[2] * m[5]) / det, 0,
         (m[6] * m[8] - m[4] * m[10]) / det, (m[0] * m[10] - m[2] * m[8]) / det, (m[2] * m[4] - m[0] * m[6]) / det, 0,
         (m[4] * m[9] - m[5] * m[8]) / det, (m[1] * m[8] - m[0] * m[9]) / det, (m[0] * m[5] - m[1] * m[4]) / det, 0};
  for (int r = 0; r < 3; ++r)
    b.m[4 * r + 3] = -(b.m[4 * r] * m[3] + b.m[4 * r + 1] * m[7] + b.m[4 * r + 2] * m[11]);
  return b;
}

/// The size of a transform: the cube root of its linear part's determinant's magnitude.
inline double size_of(const Affine& a) { return std::cbrt(std::abs(determinant(a))); }

/// The unit quaternion (x, y, z, w) of a rotation matrix given by `r(i, j)`.
template <class Entry>
std::array<double, 4> quaternion_of_rotation(Entry r) {
  std::array<double, 4> q{};
  const double trace = r(0, 0) + r(1, 1) + r(2, 2);
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    q = {(r(2, 1) - r(1, 2)) / s, (r(0, 2) - r(2, 0)) / s, (r(1, 0) - r(0, 1)) / s, s / 4};
  } else if (r(0, 0) > r(1, 1) && r(0, 0) > r(2, 2)) {
    const double s = 2 * std::sqrt(1 + r(0, 0) - r(1, 1) - r(2, 2));
    q = {s / 4, (r(0, 1) + r(1, 0)) / s, (r(0, 2) + r(2, 0)) / s, (r(2, 1) - r(1, 2)) / s};
  } else if (r(1, 1) > r(2, 2)) {
    const double s = 2 * std::sqrt(1 + r(1, 1) - r(0, 0) - r(2, 2));
    q = {(r(0, 1) + r(1, 0)) / s, s / 4, (r(1, 2) + r(2, 1)) / s, (r(0, 2) - r(2, 0)) / s};
  } else {
    const double s = 2 * std::sqrt(1 + r(2, 2) - r(0, 0) - r(1, 1));
    q = {(r(0, 2) + r(2, 0)) / s, (r(1, 2) + r(2, 1)) / s, s / 4, (r(1, 0) - r(0, 1)) / s};
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= norm;
  return q;
}

/// The rotation of an affine transform whose linear part is a rotation scaled by `size`, as a
/// unit quaternion (x, y, z, w).
inline std::array<double, 4> quaternion_of(const Affine& a, double size) {
  return quaternion_of_rotation([&](int i, int j) { return a.m[4 * i + j] / size; });
}

/// A node's fixed matrix as the translation, rotation and scale a clip's channels replace, as
/// engines hold a node: the scale is the columns' lengths (the first negated for a mirror), the
/// rotation the columns made unit, so T R S gives the matrix again when it has no shear (an FBX or
/// Collada node's local transform has none), and its nearest such transform otherwise.
/// Returns nullopt for a singular matrix, which no rotation and scale give.
inline std::optional<Node_pose> animatable_pose(const Affine& matrix) {
  const auto column = [&](int k) {
    return std::hypot(matrix.m[k], matrix.m[4 + k], matrix.m[8 + k]);
  };
  const double mirror = determinant(matrix) < 0 ? -1 : 1;
  const std::array<double, 3> scale{mirror * column(0), column(1), column(2)};
  if (!(scale[0] != 0 && scale[1] != 0 && scale[2] != 0) || determinant(matrix) == 0) return std::nullopt;
  Node_pose pose;
  pose.translation = {matrix.m[3], matrix.m[7], matrix.m[11]};
  pose.scale = scale;
  pose.rotation = quaternion_of_rotation([&](int i, int j) { return matrix.m[4 * i + j] / scale[std::size_t(j)]; });
  return pose;
}

/// Each node's rest transform in its file's world, and its parent.
struct Rest_frames {
  std::vector<Affine> world{};
  std::vector<int> parent{};
};

inline Rest_frames rest_frames(const tinygltf::Model& model) {
  const Node_forest forest = node_forest(model);
  std::vector<Affine> local;
  for (const Node_pose& pose : rest_poses(model)) local.push_back(pose.local());
  return {forest.world(local), forest.parent};
}

/// Per node of `clips`, how its channels change to move the body's node of its name (`body_node`).
/// Each file's world is in metres with Y up (FBX and Collada files are read so), so a node's
/// values carry over once expressed in the body's frames: a node whose parent is the body node's
/// parent by name keeps its rotations, its translations scaled by the ratio of the two parents'
/// sizes (a clip in centimetres on a body in metres); a node whose parent is not (the root of the
/// clip's skeleton, below other nodes in each file) is moved by the change from the body parent's
/// frame to the clip parent's (up axis, units, placement), so that it stands in the body's world
/// where it stood in its own. Where the two files' frames agree, every change is the identity and
/// the values are kept to the bit.
inline std::vector<Frame_change> frame_changes(const tinygltf::Model& body, const tinygltf::Model& clips,
                                               const std::vector<std::optional<std::size_t>>& body_node) {
  const Rest_frames in_body = rest_frames(body), in_clips = rest_frames(clips);
  std::vector<Frame_change> changes(clips.nodes.size());
  for (std::size_t i = 0; i < clips.nodes.size(); ++i) {
    if (!body_node[i]) continue;
    const int clip_parent = in_clips.parent[i], body_parent = in_body.parent[*body_node[i]];
    const Affine from = clip_parent < 0 ? Affine{} : in_clips.world[std::size_t(clip_parent)];
    const Affine to = body_parent < 0 ? Affine{} : in_body.world[std::size_t(body_parent)];
    const bool same_parent = clip_parent >= 0 && body_parent >= 0 && body_node[std::size_t(clip_parent)] == std::size_t(body_parent);
    if (same_parent) {
      const double a = size_of(from), b = size_of(to);
      if (a != b && a > 0 && b > 0) changes[i].scale = a / b;
      continue;
    }
    const Affine change = inverse(to) * from;
    const double size = size_of(change);
    if (!(size > 0) || !std::isfinite(size)) continue;
    if (change.m == Affine{}.m) continue;
    changes[i].scale = size;
    changes[i].rotation = quaternion_of(change, size);
    changes[i].offset = {change.m[3], change.m[7], change.m[11]};
  }
  return changes;
}

/// Makes each matrix node of the body that a channel of `clips` moves by translation, rotation or
/// scale (through `body_node`) a node of translation, rotation and scale (`animatable_pose`), in
/// the body's model and in its rig's rest poses `rest`, so that the channel replaces one of them:
/// an FBX or Collada body writes a matrix for every node its own clips leave still. A singular
/// matrix is kept, and refused when a clip moves it (`bound_clip`).
inline void make_animatable(tinygltf::Model& body, std::vector<Node_pose>& rest, const tinygltf::Model& clips,
                            const std::vector<std::optional<std::size_t>>& body_node) {
  for (const tinygltf::Animation& animation : clips.animations)
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
      if (channel.target_node < 0 || std::size_t(channel.target_node) >= body_node.size()) continue;
      if (channel.target_path == "weights" || !body_node[std::size_t(channel.target_node)]) continue;
      const std::size_t node = *body_node[std::size_t(channel.target_node)];
      if (!rest[node].has_matrix) continue;
      const std::optional<Node_pose> pose = animatable_pose(rest[node].matrix);
      if (!pose) continue;
      rest[node] = *pose;
      tinygltf::Node& written = body.nodes[node];
      written.matrix.clear();
      written.translation.assign(pose->translation.begin(), pose->translation.end());
      written.rotation.assign(pose->rotation.begin(), pose->rotation.end());
      written.scale.assign(pose->scale.begin(), pose->scale.end());
    }
}

/// `q` rotated by the unit quaternion `by` (by * q), in place.
inline void turn(const std::array<double, 4>& by, double* q) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double a = by[0], b = by[1], c = by[2], d = by[3];
  q[0] = d * x + a * w + b * z - c * y;
  q[1] = d * y - a * z + b * w + c * x;
  q[2] = d * z + a * y - b * x + c * w;
  q[3] = d * w - a * x - b * y - c * z;
}

/// `v` (3 values) rotated by the unit quaternion `q`, in place.
inline void rotate(const std::array<double, 4>& q, double* v) {
  const std::array<double, 3> t{0, 0, 0};
  const std::array<double, 3> one{1, 1, 1};
  const Affine r = affine_from_trs(t.data(), q.data(), one.data());
  const double p[3] = {v[0], v[1], v[2]};
  r.apply(p, v);
}

/// Applies `change` to a channel's keys (values and CUBICSPLINE tangents, which take no offset).
inline void change_frames(const Frame_change& change, Path path, Sampler& sampler) {
  if (change.is_identity() || (path != Path::translation && path != Path::rotation)) return;
  const bool cubic = sampler.interpolation == Interpolation::cubic_spline;
  for (std::size_t k = 0; k * sampler.width + sampler.width <= sampler.values.size(); ++k) {
    double* v = sampler.values.data() + k * sampler.width;
    if (path == Path::rotation) {
      turn(change.rotation, v);
      continue;
    }
    const bool tangent = cubic && k % 3 != 1;
    for (int c = 0; c < 3; ++c) v[c] *= change.scale;
    rotate(change.rotation, v);
    if (!tangent)
      for (int c = 0; c < 3; ++c) v[c] += change.offset[c];
  }
}

/// Per node of `body`: whether a clip that moves it moves the body, as engines bind clips: a
/// skin's joint, or a node of an unskinned mesh or an ancestor of one (a rigid body's parts). The
/// ancestors of the joints are not counted: a clip of another skeleton that shares the name of
/// the body's top node alone moves the whole body rigidly, and nothing of it.
inline std::vector<bool> moves_body(const tinygltf::Model& body) {
  std::vector<bool> moves(body.nodes.size(), false);
  for (std::size_t i = 0; i < body.nodes.size(); ++i)
    if (body.nodes[i].mesh >= 0 && body.nodes[i].skin < 0) moves[i] = true;
  const Node_forest forest = node_forest(body);
  for (auto i = forest.parents_first.rbegin(); i != forest.parents_first.rend(); ++i)  // children first
    if (moves[*i] && forest.parent[*i] >= 0) moves[std::size_t(forest.parent[*i])] = true;
  for (const tinygltf::Skin& skin : body.skins)
    for (const int joint : skin.joints)
      if (joint >= 0 && std::size_t(joint) < moves.size()) moves[std::size_t(joint)] = true;
  return moves;
}

/// A few names of the nodes a list of nodes holds ("'Hips', 'Spine', 'Head' and 21 more").
inline std::string some_node_names(const tinygltf::Model& model, const std::set<std::size_t>& nodes) {
  constexpr std::size_t shown = 3;
  std::string names;
  std::size_t count = 0;
  for (const std::size_t node : nodes) {
    if (count++ == shown) break;
    names += (names.empty() ? "'" : ", '") + model.nodes[node].name + "'";
  }
  if (nodes.size() > shown) names += " and " + std::to_string(nodes.size() - shown) + " more";
  return names.empty() ? "none" : names;
}

/// The refusal of a clip that moves nothing of the body (`moves_body`): its nodes are another
/// skeleton's.
inline invalid_input unfit_body(const Clip& clip, const tinygltf::Model& body, const Bound_clips& source) {
  std::set<std::size_t> animated, joints;
  for (const Channel& channel : clip.channels) animated.insert(channel.node);
  for (const tinygltf::Skin& skin : body.skins)
    for (const int joint : skin.joints)
      if (joint >= 0) joints.insert(std::size_t(joint));
  return invalid_input("clip '" + clip.name + "' moves nothing of the body " + source.body_file + ": it animates " +
                       some_node_names(*source.model, animated) + ", the body's joints are " +
                       some_node_names(body, joints) + " (a body of another skeleton?)");
}

/// `clip`, read from `source`'s model, as a clip of `body`: each channel moved to the body's node
/// of its node's name; the channels of nodes the body has not, and those of morph weights whose
/// count the body's mesh does not have, left out. Its start and end are those of the channels kept.
/// @throws invalid_input when a channel would move a body node given by a singular matrix (see
/// `make_animatable`), or when the channels kept move no joint, no morph weight and no rigid
/// part of the body (`moves_body`: the clip is another skeleton's), naming a few of the clip's
/// nodes and of the body's joints.
inline Clip bound_clip(Clip clip, const tinygltf::Model& body, const Bound_clips& source) {
  const std::vector<bool> moves = moves_body(body);
  const auto kept = [&](const Channel& channel) {
    const std::optional<std::size_t> node = source.body_node[channel.node];
    if (!node) return false;
    if (channel.path == Path::weights) return channel.sampler.width == morph_target_count(body, body.nodes[*node].mesh);
    if (!body.nodes[*node].matrix.empty())
      throw invalid_input("clip '" + clip.name + "' animates " + node_name(body, *node) + " of the body " +
                          source.body_file + ", whose matrix is singular: no translation, rotation and scale give it");
    return true;
  };
  const auto moves_something = [&](const Channel& channel) {
    return kept(channel) && (channel.path == Path::weights || moves[*source.body_node[channel.node]]);
  };
  if (std::none_of(clip.channels.begin(), clip.channels.end(), moves_something)) throw unfit_body(clip, body, source);
  std::erase_if(clip.channels, [&](const Channel& channel) { return !kept(channel); });
  for (Channel& channel : clip.channels) {
    change_frames(source.change[channel.node], channel.path, channel.sampler);
    channel.node = *source.body_node[channel.node];
  }
  clip.start = clip.channels.front().sampler.start(), clip.end = clip.channels.front().sampler.end();
  for (const Channel& channel : clip.channels)
    clip.start = std::min(clip.start, channel.sampler.start()), clip.end = std::max(clip.end, channel.sampler.end());
  return clip;
}

/// How many of the body's skin joints `clip` moves (by translation, rotation or scale), and how
/// many joints its skins have.
inline std::pair<std::size_t, std::size_t> animated_joints(const tinygltf::Model& body, const Clip& clip) {
  std::set<std::size_t> joints, moved;
  for (const tinygltf::Skin& skin : body.skins)
    for (const int joint : skin.joints)
      if (joint >= 0) joints.insert(std::size_t(joint));
  for (const Channel& channel : clip.channels)
    if (channel.path != Path::weights && joints.count(channel.node)) moved.insert(channel.node);
  return {moved.size(), joints.size()};
}

}  // namespace deformseg::io::internal::gltf
