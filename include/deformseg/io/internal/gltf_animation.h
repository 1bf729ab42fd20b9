// A glTF clip (animation) and the scene it moves: the channels of the clip, the frame times it is
// sampled at, and the positions of every vertex of the scene at a time.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/gltf_mesh.h>
#include <deformseg/io/internal/gltf_sampler.h>
#include <deformseg/io/internal/gltf_scene.h>
#include <deformseg/io/internal/gltf_skinning.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace deformseg::io::internal::gltf {

/// The most frames a clip may be sampled into: bounds what is allocated for a malformed key time.
inline constexpr std::size_t max_frames = 1'000'000;

/// A key time on the sampling grid within this fraction of a frame is taken as on it, so that
/// float-stored key times add no spurious last frame.
inline constexpr double frame_tolerance = 1e-3;

enum class Path { translation, rotation, scale, weights };

struct Channel {
  std::size_t node = 0;
  Path path = Path::translation;
  Sampler sampler{};
};

/// A clip: its channels, and its start and end (the smallest and largest key time over them).
struct Clip {
  std::string name{};
  std::vector<Channel> channels{};
  double start = 0, end = 0;
};

/// The number of morph targets of a mesh (the most over its primitives).
inline std::size_t morph_target_count(const tinygltf::Model& model, int mesh) {
  if (mesh < 0 || std::size_t(mesh) >= model.meshes.size()) return 0;
  std::size_t targets = 0;
  for (const auto& primitive : model.meshes[std::size_t(mesh)].primitives)
    targets = std::max(targets, primitive.targets.size());
  return targets;
}

inline Clip read_clip(const tinygltf::Model& model, std::size_t index) {
  const tinygltf::Animation& animation = model.animations[index];
  const std::string name =
      "animation " + std::to_string(index) + (animation.name.empty() ? "" : " '" + animation.name + "'");
  Clip clip{.name = animation.name};
  for (std::size_t c = 0; c < animation.channels.size(); ++c) {
    const tinygltf::AnimationChannel& source = animation.channels[c];
    if (source.target_node < 0) continue;  // the specification says to ignore such channels
    const std::string channel = name + " channel " + std::to_string(c);
    if (std::size_t(source.target_node) >= model.nodes.size())
      throw invalid_input(channel + " targets node " + std::to_string(source.target_node) + ", which does not exist");
    const std::size_t node = std::size_t(source.target_node);
    Channel target{.node = node};
    std::size_t width = 0;
    if (source.target_path == "translation") target.path = Path::translation, width = 3;
    else if (source.target_path == "rotation") target.path = Path::rotation, width = 4;
    else if (source.target_path == "scale") target.path = Path::scale, width = 3;
    else if (source.target_path == "weights") target.path = Path::weights;
    else continue;  // a path of an extension (KHR_animation_pointer): not geometry of a node
    if (target.path != Path::weights && !model.nodes[node].matrix.empty())
      throw invalid_input(channel + " animates " + node_name(model, node) +
                          ", which has a matrix; glTF animates TRS nodes only");
    target.sampler = read_sampler(model, animation, source.sampler, width, target.path == Path::rotation, channel);
    if (target.path == Path::weights && target.sampler.width != morph_target_count(model, model.nodes[node].mesh))
      throw invalid_input(channel + " animates " + std::to_string(target.sampler.width) + " weights of " +
                          node_name(model, node) + ", whose mesh has " +
                          std::to_string(morph_target_count(model, model.nodes[node].mesh)) + " morph targets");
    clip.start = clip.channels.empty() ? target.sampler.start() : std::min(clip.start, target.sampler.start());
    clip.end = clip.channels.empty() ? target.sampler.end() : std::max(clip.end, target.sampler.end());
    clip.channels.push_back(std::move(target));
  }
  return clip;
}

/// The number of frames of [start, end] sampled at `fps`: t = start + k / fps while t <= end, and
/// the end itself when it is off that grid (by more than `frame_tolerance` of a frame).
inline std::size_t frame_count(double start, double end, double fps) {
  const double span = std::max(0.0, (end - start) * fps);
  if (!(span < double(max_frames)))
    throw invalid_input("a clip of " + std::to_string(end - start) + " s at " + std::to_string(fps) +
                        " frames per second has more than " + std::to_string(max_frames) + " frames");
  const double on_grid = std::floor(span + frame_tolerance);
  return std::size_t(on_grid) + 1 + (span - on_grid > frame_tolerance ? 1 : 0);
}

inline double frame_time(double start, double end, double fps, std::size_t frame, std::size_t frames) {
  const double t = start + double(frame) / fps;
  return frame + 1 == frames ? std::min(t, end) : t;
}

/// The scene's geometry and what moves it.
struct Rig {
  Node_forest forest{};
  std::vector<Node_pose> rest{};
  Skins skins{};
  Scene_geometry geometry{};
  std::vector<std::vector<double>> rest_weights{};  // per node: its morph target weights at rest
};

inline Rig read_rig(const tinygltf::Model& model) {
  Rig rig;
  rig.forest = node_forest(model);
  rig.rest = rest_poses(model);
  rig.skins = read_skins(model);
  rig.geometry = read_scene_geometry(model, rig.forest);
  rig.rest_weights.resize(model.nodes.size());
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const std::size_t targets = morph_target_count(model, model.nodes[i].mesh);
    if (targets == 0) continue;
    const auto& mesh_weights = model.meshes[std::size_t(model.nodes[i].mesh)].weights;
    const auto& weights = !model.nodes[i].weights.empty() ? model.nodes[i].weights : mesh_weights;
    rig.rest_weights[i].assign(targets, 0.0);
    std::copy_n(weights.begin(), std::min(weights.size(), targets), rig.rest_weights[i].begin());
  }
  return rig;
}

/// What posing a frame needs besides the rig, reused from frame to frame by one thread.
struct Pose_scratch {
  std::vector<Node_pose> nodes{};
  std::vector<std::vector<double>> weights{};
  std::vector<Affine> local{}, world{}, table{};
  std::vector<double> morphed{};
};

/// The nodes' world transforms (`scratch.world`), the joint table (`scratch.table`) and the morph
/// weights (`scratch.weights`) at time `t` of `clip` (rest pose when null): what every vertex of
/// the frame is posed with, computed once per frame.
inline void pose_nodes(const Rig& rig, const Clip* clip, double t, Pose_scratch& scratch) {
  scratch.nodes = rig.rest;
  scratch.weights = rig.rest_weights;
  for (std::size_t c = 0; clip && c < clip->channels.size(); ++c) {
    const Channel& channel = clip->channels[c];
    Node_pose& node = scratch.nodes[channel.node];
    switch (channel.path) {
      case Path::translation: channel.sampler.sample(t, node.translation.data()); break;
      case Path::rotation: channel.sampler.sample(t, node.rotation.data()); break;
      case Path::scale: channel.sampler.sample(t, node.scale.data()); break;
      case Path::weights: channel.sampler.sample(t, scratch.weights[channel.node].data()); break;
    }
  }
  scratch.local.resize(scratch.nodes.size());
  for (std::size_t i = 0; i < scratch.nodes.size(); ++i) scratch.local[i] = scratch.nodes[i].local();
  rig.forest.world(scratch.local, scratch.world);
  joint_table(rig.skins, rig.geometry.parts, scratch.world, scratch.table);
}

/// Writes the positions of every vertex at time `t` of `clip` (rest pose when null) to `out`
/// (3 per vertex, in part order).
inline void pose_at(const Rig& rig, const Clip* clip, double t, Pose_scratch& scratch, double* out) {
  pose_nodes(rig, clip, t, scratch);
  for (const Mesh_part& part : rig.geometry.parts)
    pose_part(part, scratch.world, scratch.table, &scratch.weights[part.node], scratch.morphed,
              out + 3 * part.first_vertex);
}

/// Some of a scene's vertices, to be posed alone, by part: output vertex i is scene vertex
/// `input[i]` (vertices in part order, as `pose_at` writes them).
struct Vertex_selection {
  std::vector<Part_selection> parts{};
  std::vector<std::uint32_t> input{};
};

/// The selection of scene vertices `vertices` (each below `geometry.vertices`, in any order,
/// repeats allowed), output vertex i being `vertices[i]`.
/// @throws invalid_input for a vertex outside the scene.
inline Vertex_selection select_vertices(const Scene_geometry& geometry, std::span<const std::uint32_t> vertices) {
  Vertex_selection selection{.input = {vertices.begin(), vertices.end()}};
  std::vector<std::uint32_t> by_vertex(vertices.size());  // output vertices by scene vertex: parts in order
  for (std::uint32_t i = 0; i < by_vertex.size(); ++i) by_vertex[i] = i;
  std::stable_sort(by_vertex.begin(), by_vertex.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return vertices[a] < vertices[b]; });
  std::size_t part = 0;
  for (const std::uint32_t slot : by_vertex) {
    const std::uint32_t v = vertices[slot];
    if (v >= geometry.vertices)
      throw invalid_input("vertex " + std::to_string(v) + " asked of a scene of " + std::to_string(geometry.vertices));
    while (v >= geometry.parts[part].first_vertex + geometry.parts[part].vertex_count) ++part;
    if (selection.parts.empty() || selection.parts.back().part != part) selection.parts.push_back({.part = part});
    selection.parts.back().vertex.push_back(std::uint32_t(v - geometry.parts[part].first_vertex));
    selection.parts.back().slot.push_back(slot);
  }
  return selection;
}

/// Writes the positions of the vertices of `selection` at time `t` of `clip` (rest pose when null)
/// to `out` (3 per output vertex): bit for bit those `pose_at` gives the same vertices.
inline void pose_selected_at(const Rig& rig, const Clip* clip, double t, const Vertex_selection& selection,
                             Pose_scratch& scratch, double* out) {
  pose_nodes(rig, clip, t, scratch);
  for (const Part_selection& of_part : selection.parts) {
    const Mesh_part& part = rig.geometry.parts[of_part.part];
    pose_selected(part, of_part, scratch.world, scratch.table, &scratch.weights[part.node], out);
  }
}

}  // namespace deformseg::io::internal::gltf
