// The clips of one file played on the body of another, as engines bind an animation to a model:
// each channel moves the body's node of the same name as the node it moved in its own file.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/gltf_animation.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io::internal::gltf {

/// Where a body's clips come from when another file holds them.
struct Bound_clips {
  std::shared_ptr<const tinygltf::Model> model{};
  std::string file{};                                   // the clips' file, which their errors name
  std::string body_file{};                              // the body's, which they mention
  std::vector<std::optional<std::size_t>> body_node{};  // per node of `model`: the body's node of its name
};

/// The body's node of each node of `clips` whose name (not empty) a body node has: the first such.
inline std::vector<std::optional<std::size_t>> body_nodes_by_name(const tinygltf::Model& body,
                                                                  const tinygltf::Model& clips) {
  std::map<std::string, std::size_t> by_name;
  for (std::size_t i = 0; i < body.nodes.size(); ++i)
    if (!body.nodes[i].name.empty()) by_name.emplace(body.nodes[i].name, i);
  std::vector<std::optional<std::size_t>> body_node(clips.nodes.size());
  for (std::size_t i = 0; i < clips.nodes.size(); ++i)
    if (const auto found = by_name.find(clips.nodes[i].name); found != by_name.end()) body_node[i] = found->second;
  return body_node;
}

/// `clip`, read from `source`'s model, as a clip of `body`: each channel moved to the body's node
/// of its node's name; the channels of nodes the body has not, and those of morph weights whose
/// count the body's mesh does not have, left out. Its start and end are those of the channels kept.
/// @throws invalid_input when a channel would move a body node given by a matrix, or when no
/// channel is left (the clip animates nothing of the body).
inline Clip bound_clip(Clip clip, const tinygltf::Model& body, const Bound_clips& source) {
  std::vector<Channel> kept;
  for (Channel& channel : clip.channels) {
    const std::optional<std::size_t> node = source.body_node[channel.node];
    if (!node) continue;
    if (channel.path == Path::weights) {
      if (channel.sampler.width != morph_target_count(body, body.nodes[*node].mesh)) continue;
    } else if (!body.nodes[*node].matrix.empty()) {
      throw invalid_input("clip '" + clip.name + "' animates " + node_name(body, *node) + " of the body " +
                          source.body_file + ", which has a matrix; glTF animates TRS nodes only");
    }
    channel.node = *node;
    kept.push_back(std::move(channel));
  }
  if (kept.empty())
    throw invalid_input("clip '" + clip.name + "' animates no node of the body " + source.body_file +
                        ": none of its nodes' names is the body's");
  clip.channels = std::move(kept);
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
