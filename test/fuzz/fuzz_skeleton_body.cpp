// libFuzzer harness of the body made from a skeleton (io/internal/skeleton_body.h) on node trees
// no file format would give: the input is decoded into a glTF model without a mesh (up to 12
// nodes with translations, rotations and scales, among them zero scales, non-unit quaternions,
// coincident joints and NaN; children out of range or twice; a scene or none) and one clip that
// moves some nodes; the model is then read as Gltf_file reads a file, sampled and repaired.
#include "fuzz_support.h"

#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/assimp_model_writer.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace skeleton_body_harness {

// The input read a byte at a time; zeros past its end.
struct Input {
  const std::uint8_t* data;
  std::size_t size, at = 0;

  unsigned below(unsigned count) { return count == 0 ? 0 : (at < size ? data[at++] : 0) % count; }
  // Small values in quarters, NaN for the byte 255.
  double value() {
    const unsigned byte = below(256);
    return byte == 255 ? std::numeric_limits<double>::quiet_NaN() : (double(byte) - 128) / 4;
  }
  std::vector<double> values(std::size_t count) {
    std::vector<double> result;
    for (std::size_t k = 0; k < count; ++k) result.push_back(value());
    return result;
  }
};

// A node of each present property (empty: absent); a child of an earlier node, or a root.
tinygltf::Node node(Input& in, std::size_t index) {
  tinygltf::Node node;
  node.name = "n" + std::to_string(index);
  if (in.below(2)) node.translation = in.values(3);
  if (in.below(3) == 0) node.rotation = in.values(4);
  if (in.below(4) == 0) node.scale = in.values(3);
  return node;
}

// One clip of up to 4 channels, each of 2 keys, on translation, rotation or scale.
tinygltf::Animation clip(Input& in, std::size_t nodes, tinygltf::Model& model) {
  deformseg::io::internal::assimp::Model_writer writer(model);
  tinygltf::Animation animation;
  const std::vector<float> times{0, 1};
  for (unsigned c = 0, count = in.below(5); c < count; ++c) {
    const unsigned path = in.below(3);
    const int width = path == 1 ? 4 : 3;
    std::vector<float> keys;
    for (int k = 0; k < 2 * width; ++k) keys.push_back(float(in.value()));
    tinygltf::AnimationSampler sampler;
    sampler.input = writer.accessor(std::span<const float>(times), TINYGLTF_TYPE_SCALAR, 1);
    const int type = width == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
    sampler.output = writer.accessor(std::span<const float>(keys), type, width);
    sampler.interpolation = "LINEAR";
    animation.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = int(animation.samplers.size() - 1);
    channel.target_node = int(in.below(unsigned(nodes) + 1));  // sometimes a node that does not exist
    channel.target_path = path == 0 ? "translation" : path == 1 ? "rotation" : "scale";
    animation.channels.push_back(channel);
  }
  return animation;
}

tinygltf::Model model(Input& in) {
  tinygltf::Model model;
  const std::size_t count = 1 + in.below(12);
  for (std::size_t n = 0; n < count; ++n) {
    model.nodes.push_back(node(in, n));
    if (n > 0 && in.below(4) != 0) model.nodes[in.below(unsigned(n))].children.push_back(int(n));
  }
  if (in.below(8) == 0) model.nodes[in.below(unsigned(count))].children.push_back(int(in.below(unsigned(count) + 1)));
  if (in.below(2)) {
    model.scenes.emplace_back();
    for (std::size_t n = 0; n < count; ++n)
      if (in.below(2)) model.scenes.front().nodes.push_back(int(n));
    model.defaultScene = 0;
  }
  model.animations.push_back(clip(in, count, model));
  return model;
}

}  // namespace skeleton_body_harness

DEFORMSEG_FUZZ_READER(skeleton_body) {
  skeleton_body_harness::Input in{data, size};
  tinygltf::Model model = skeleton_body_harness::model(in);
  const std::filesystem::path name = "fuzz.glb";
  deformseg::fuzz::expect_valid_outcome(name, [&](const std::filesystem::path& path) {
    const deformseg::io::Gltf_file file(path, std::move(model));
    file.sample({.fps = 4, .threads = 1});
    file.repair();
    file.contents();
  });
  return 0;
}
