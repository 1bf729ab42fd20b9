// An Assimp scene's animations written as glTF animations (io/fbx_collada.h): a node channel's
// position, rotation and scaling keys become translation, rotation and scale samplers, a morph
// channel's keys a weights sampler; key times go from ticks to seconds.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/assimp_model_writer.h>
#include <deformseg/io/internal/assimp_scene.h>

#include <assimp/anim.h>
#include <assimp/scene.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace deformseg::io::internal::assimp {

/// Ticks per second of a clip that does not say (`mTicksPerSecond` 0): Assimp's own default.
inline constexpr double default_ticks_per_second = 25;

inline std::string clip_name(const aiScene& scene, std::size_t clip) {
  const std::string name = name_of(scene.mAnimations[clip]->mName);
  return "clip " + std::to_string(clip) + (name.empty() ? "" : " '" + name + "'");
}

/// The names of the nodes some clip moves.
inline std::set<std::string> animated_nodes(const aiScene& scene) {
  std::set<std::string> names;
  for (unsigned a = 0; a < scene.mNumAnimations; ++a)
    for (unsigned c = 0; c < scene.mAnimations[a]->mNumChannels; ++c)
      names.insert(name_of(scene.mAnimations[a]->mChannels[c]->mNodeName));
  return names;
}

/// Key times in seconds and their values, keys out of order (not after the one before) left out.
struct Keys {
  std::vector<float> times{};
  std::vector<float> values{};
};

/// Appends a sampler of `keys` and a channel of it on `node`'s `path`, when there are keys.
inline void write_channel(const Keys& keys, int components, int type, int node, const std::string& path,
                          Model_writer& writer, tinygltf::Animation& animation) {
  if (keys.times.empty()) return;
  tinygltf::AnimationSampler sampler;
  sampler.input = writer.accessor(std::span<const float>(keys.times), TINYGLTF_TYPE_SCALAR, 1);
  sampler.output = writer.accessor(std::span<const float>(keys.values), type, components);
  sampler.interpolation = "LINEAR";
  animation.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = int(animation.samplers.size() - 1);
  channel.target_node = node;
  channel.target_path = path;
  animation.channels.push_back(channel);
}

/// The keys of one channel (`aiVectorKey` or `aiQuatKey`), as seconds and the first `components`
/// values `values` gives of each.
/// @throws invalid_input naming `where` for a non-finite time or value.
template <class Key, class Values>
Keys keys_of(const Key* keys, unsigned count, double ticks_per_second, const std::string& where, std::size_t components,
             Values values) {
  Keys result;
  double last = -INFINITY;
  for (unsigned k = 0; k < count; ++k) {
    const double time = keys[k].mTime / ticks_per_second;
    const std::array<float, 4> value = values(keys[k].mValue);
    const auto end = value.begin() + std::ptrdiff_t(components);
    if (!std::isfinite(time) || !std::all_of(value.begin(), end, [](float x) { return std::isfinite(x); }))
      throw invalid_input(where + " key " + std::to_string(k) + " has a non-finite time or value");
    if (float(time) <= last) continue;
    last = float(time);
    result.times.push_back(float(time));
    result.values.insert(result.values.end(), value.begin(), end);
  }
  return result;
}

inline std::array<float, 4> vector_values(const aiVector3D& v) { return {v.x, v.y, v.z, 0}; }
inline std::array<float, 4> quaternion_values(const aiQuaternion& q) {  // glTF's order: x, y, z, w
  const double norm = std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z + double(q.w) * q.w);
  return {float(q.x / norm), float(q.y / norm), float(q.z / norm), float(q.w / norm)};
}

/// Writes a node channel's translation, rotation and scale keys.
/// @throws invalid_input for a channel on a node the scene does not have (a pivot helper of FBX
/// left out), naming it, since dropping it would change the motion.
inline void write_node_channel(const aiScene& scene, std::size_t clip, const aiNodeAnim& channel, double tps,
                               const Node_table& nodes, Model_writer& writer, tinygltf::Animation& animation) {
  const std::string node_name = name_of(channel.mNodeName);
  const auto found = nodes.by_name.find(node_name);
  const std::string where = clip_name(scene, clip) + " channel of node '" + node_name + "'";
  if (found == nodes.by_name.end())
    throw invalid_input(where + ": the scene has no such node (" +
                        (node_name.find("$AssimpFbx$") != std::string::npos
                             ? "an FBX pivot or offset deformseg cannot place"
                             : "a channel whose target is missing") +
                        "), and leaving it out would change the motion");
  const int node = int(found->second);
  write_channel(keys_of(channel.mPositionKeys, channel.mNumPositionKeys, tps, where + " position", 3, vector_values), 3,
                TINYGLTF_TYPE_VEC3, node, "translation", writer, animation);
  write_channel(keys_of(channel.mRotationKeys, channel.mNumRotationKeys, tps, where + " rotation", 4, quaternion_values),
                4, TINYGLTF_TYPE_VEC4, node, "rotation", writer, animation);
  write_channel(keys_of(channel.mScalingKeys, channel.mNumScalingKeys, tps, where + " scaling", 3, vector_values), 3,
                TINYGLTF_TYPE_VEC3, node, "scale", writer, animation);
}

/// A morph channel's name without the "*N" Assimp's FBX reader puts after the geometry's name
/// ("Head*0"), which names no node or mesh.
inline std::string without_morph_suffix(const std::string& name) {
  const std::size_t star = name.rfind('*');
  if (star == std::string::npos || star + 1 == name.size()) return name;
  const bool digits = std::all_of(name.begin() + std::ptrdiff_t(star) + 1, name.end(),
                                  [](char c) { return c >= '0' && c <= '9'; });
  return digits ? name.substr(0, star) : name;
}

/// The glTF node that shows the morph targets a morph channel names: Assimp names it after the
/// node, or the mesh, that holds them (after the FBX geometry, with a "*N" after it: see
/// `without_morph_suffix`).
inline int morph_node(const aiScene& scene, const std::string& channel_name, const Node_table& nodes,
                      const std::vector<int>& node_of_mesh, const tinygltf::Model& model) {
  const auto has_targets = [&](int node) {
    const int mesh = model.nodes[std::size_t(node)].mesh;
    if (mesh < 0) return false;
    for (const auto& primitive : model.meshes[std::size_t(mesh)].primitives)
      if (!primitive.targets.empty()) return true;
    return false;
  };
  const auto named = [&](const std::string& name) {
    if (const auto found = nodes.by_name.find(name); found != nodes.by_name.end() && has_targets(int(found->second)))
      return int(found->second);
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
      if (name_of(scene.mMeshes[m]->mName) == name && node_of_mesh[m] >= 0 && has_targets(node_of_mesh[m]))
        return node_of_mesh[m];
    return -1;
  };
  const int node = named(channel_name);
  return node >= 0 ? node : named(without_morph_suffix(channel_name));
}

/// Writes a morph channel's keys as a weights sampler: each key gives the weights of the targets
/// it lists, the others 0.
/// @throws invalid_input for a channel that names no node or mesh with targets, or a key of a
/// target out of range.
inline void write_morph_channel(const aiScene& scene, std::size_t clip, const aiMeshMorphAnim& channel, double tps,
                                const Node_table& nodes, const std::vector<int>& node_of_mesh,
                                Model_writer& writer, tinygltf::Model& model, tinygltf::Animation& animation) {
  const std::string name = name_of(channel.mName);
  const std::string where = clip_name(scene, clip) + " morph channel '" + name + "'";
  const int node = morph_node(scene, name, nodes, node_of_mesh, model);
  if (node < 0) throw invalid_input(where + ": no node or mesh of that name has morph targets");
  std::size_t targets = 0;
  for (const auto& primitive : model.meshes[std::size_t(model.nodes[std::size_t(node)].mesh)].primitives)
    targets = std::max(targets, primitive.targets.size());
  Keys keys;
  double last = -INFINITY;
  for (unsigned k = 0; k < channel.mNumKeys; ++k) {
    const aiMeshMorphKey& key = channel.mKeys[k];
    const double time = key.mTime / tps;
    if (!std::isfinite(time)) throw invalid_input(where + " key " + std::to_string(k) + " has a non-finite time");
    if (float(time) <= last) continue;
    last = float(time);
    std::vector<float> weights(targets, 0.0f);
    for (unsigned i = 0; i < key.mNumValuesAndWeights; ++i) {
      if (key.mValues[i] >= targets || !std::isfinite(key.mWeights[i]))
        throw invalid_input(where + " key " + std::to_string(k) + " weights target " + std::to_string(key.mValues[i]) +
                            " of " + std::to_string(targets) + " by " + std::to_string(key.mWeights[i]));
      weights[key.mValues[i]] = float(key.mWeights[i]);
    }
    keys.times.push_back(float(time));
    keys.values.insert(keys.values.end(), weights.begin(), weights.end());
  }
  // glTF's weights output: `targets` scalars per key.
  write_channel(keys, 1, TINYGLTF_TYPE_SCALAR, node, "weights", writer, animation);
}

/// Writes every clip of the scene as a glTF animation of the same name.
inline void write_clips(const aiScene& scene, const Node_table& nodes, const std::vector<int>& node_of_mesh,
                        Model_writer& writer, tinygltf::Model& model) {
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    const aiAnimation& clip = *scene.mAnimations[a];
    const double tps = clip.mTicksPerSecond > 0 ? clip.mTicksPerSecond : default_ticks_per_second;
    if (!std::isfinite(tps)) throw invalid_input(clip_name(scene, a) + " has non-finite ticks per second");
    tinygltf::Animation animation;
    animation.name = name_of(clip.mName);
    for (unsigned c = 0; c < clip.mNumChannels; ++c)
      write_node_channel(scene, a, *clip.mChannels[c], tps, nodes, writer, animation);
    for (unsigned c = 0; c < clip.mNumMorphMeshChannels; ++c)
      write_morph_channel(scene, a, *clip.mMorphMeshChannels[c], tps, nodes, node_of_mesh, writer, model, animation);
    model.animations.push_back(std::move(animation));
  }
}

}  // namespace deformseg::io::internal::assimp
