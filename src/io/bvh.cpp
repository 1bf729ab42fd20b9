// The BVH reader of io/bvh.h: deformseg's checks of the text, Assimp's parsing, and the scene
// written into glTF's structures as FBX and Collada scenes are.
#include <deformseg/io/bvh.h>

#include <deformseg/exceptions.h>
#include <deformseg/internal/utf8.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/internal/assimp_import.h>
#include <deformseg/io/internal/assimp_model.h>
#include <deformseg/io/internal/bvh_checks.h>
#include <deformseg/io/internal/file_io.h>

#include <assimp/config.h>
#include <assimp/scene.h>
#include <tiny_gltf.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::io::internal::bvh {

// Assimp's message without the name it gives a file read from memory ("$$$___magic___$$$.bvh:12
// - Unknown keyword" becomes "line 12: Unknown keyword").
inline std::string assimp_message(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  constexpr std::string_view magic = "$$$___magic___$$$.bvh:";
  const std::size_t at = message.find(magic);
  if (at == std::string::npos) return message.empty() ? "Assimp refused it" : message;
  std::string rest = message.substr(at + magic.size());
  const std::size_t dash = rest.find(" - ");
  if (dash != std::string::npos) rest = "line " + rest.substr(0, dash) + ": " + rest.substr(dash + 3);
  return message.substr(0, at) + rest;
}

// Leaves out the channels Assimp makes up for what a BVH file does not record: a scale of 1 for
// every joint, a translation (its OFFSET) for every joint without position channels, a rotation
// (none) for every joint without rotation channels. On the body made from the skeleton nothing
// changes (the OFFSET is the rest translation); played on another file's body, such a joint keeps
// the body's own translation, rotation and scale, as retargeting keeps a body's proportions.
inline void leave_out_made_up_channels(tinygltf::Model& model, const Recorded& recorded) {
  for (tinygltf::Animation& animation : model.animations)
    std::erase_if(animation.channels, [&](const tinygltf::AnimationChannel& channel) {
      const std::string& joint = model.nodes.at(std::size_t(channel.target_node)).name;
      if (channel.target_path == "translation") return !recorded.positions.contains(joint);
      if (channel.target_path == "rotation") return !recorded.rotations.contains(joint);
      return true;
    });
}

// Parses a BVH file's bytes into a glTF model, as `bvh_model` does.
inline tinygltf::Model model_from_bytes(std::string_view bytes) {
  const Recorded recorded = check_text(bytes);
  // Assimp would add a mesh of pyramids along the bones; deformseg makes its own body (see
  // skeleton_body.h), the same for BVH as for any file without a mesh. No post-processing:
  // Assimp's validation refuses a scene without a mesh.
  const assimp::Import_result imported =
      assimp::import_from_memory(bytes, 0, "bvh", {{AI_CONFIG_IMPORT_NO_SKELETON_MESHES, 1}});
  // Assimp quotes the file's bytes ("Unknown keyword '...'"), which may be anything in a damaged file.
  if (!imported.scene)
    throw invalid_input("not a valid BVH file: " + deformseg::internal::printable_text(assimp_message(imported.error)));
  tinygltf::Model model = assimp::model_of(*imported.scene, 1.0);
  leave_out_made_up_channels(model, recorded);
  return model;
}

}  // namespace deformseg::io::internal::bvh

namespace deformseg::io {

tinygltf::Model bvh_model(const std::filesystem::path& path) {
  try {
    if (!is_bvh(path)) throw invalid_input("not a BVH file name: the extension is not .bvh");
    const internal::File_bytes bytes = internal::read_file_bytes(path, max_bvh_bytes + 1);
    if (bytes.file_size > max_bvh_bytes)
      throw invalid_input("the file is larger than " + std::to_string(max_bvh_bytes) + " bytes");
    return internal::bvh::model_from_bytes(std::string_view(bytes.begin(), bytes.size));
  } catch (const invalid_input& e) {
    throw e.located({.file = path.string()});
  }
}

}  // namespace deformseg::io
