/// @file io/bvh.h
/// @brief Reads BVH motion capture (`.bvh`): Assimp parses the skeleton and its one clip, and the
/// scene is written into the structures of glTF 2.0 (`bvh_model`) as FBX and Collada files are,
/// so that `Gltf_file` samples the clip, on a body made from the skeleton (the file has no mesh)
/// or on another file's body.
#pragma once

#if !__has_include(<assimp/Importer.hpp>) || !__has_include(<tiny_gltf.h>)
#error "deformseg/io/bvh.h needs Assimp (Debian: libassimp-dev) and tinygltf (libtinygltf-dev)"
#endif

#include <deformseg/exceptions.h>
#include <deformseg/internal/utf8.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/fbx_collada.h>
#include <deformseg/io/internal/bvh_checks.h>
#include <deformseg/io/internal/file_io.h>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::io::internal::bvh {

/// Assimp's message without the name it gives a file read from memory ("$$$___magic___$$$.bvh:12
/// - Unknown keyword" becomes "line 12: Unknown keyword").
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

/// Leaves out the channels Assimp makes up for what a BVH file does not record: a scale of 1 for
/// every joint, a translation (its OFFSET) for every joint without position channels, a rotation
/// (none) for every joint without rotation channels. On the body made from the skeleton nothing
/// changes (the OFFSET is the rest translation); played on another file's body, such a joint keeps
/// the body's own translation, rotation and scale, as retargeting keeps a body's proportions.
inline void leave_out_made_up_channels(tinygltf::Model& model, const Recorded& recorded) {
  for (tinygltf::Animation& animation : model.animations)
    std::erase_if(animation.channels, [&](const tinygltf::AnimationChannel& channel) {
      const std::string& joint = model.nodes.at(std::size_t(channel.target_node)).name;
      if (channel.target_path == "translation") return !recorded.positions.contains(joint);
      if (channel.target_path == "rotation") return !recorded.rotations.contains(joint);
      return true;
    });
}

/// Parses a BVH file's bytes into a glTF model, as `bvh_model` does.
inline tinygltf::Model model_from_bytes(std::string_view bytes) {
  const Recorded recorded = check_text(bytes);
  Assimp::Importer importer;
  // Assimp would add a mesh of pyramids along the bones; deformseg makes its own body (see
  // skeleton_body.h), the same for BVH as for any file without a mesh.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
  const aiScene* scene = nullptr;
  try {
    // No post-processing: Assimp's validation refuses a scene without a mesh.
    scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, "bvh");
  } catch (const std::exception& e) {
    throw invalid_input("Assimp could not parse the file: " + deformseg::internal::printable_text(e.what()));
  }
  // Assimp quotes the file's bytes ("Unknown keyword '...'"), which may be anything in a damaged file.
  if (!scene)
    throw invalid_input("not a valid BVH file: " +
                        deformseg::internal::printable_text(assimp_message(importer.GetErrorString())));
  tinygltf::Model model = assimp::model_of(*scene, 1.0);
  leave_out_made_up_channels(model, recorded);
  return model;
}

}  // namespace deformseg::io::internal::bvh

namespace deformseg::io {

/// @brief The most bytes of a BVH file read: 1 GiB (a clip of 6 hours at 120 frames per second
/// of a 60-joint skeleton, written with 6 digits, is about half of that).
inline constexpr std::size_t max_bvh_bytes = std::size_t(1) << 30;

/// @brief Reads a BVH motion capture file into the glTF 2.0 structures deformseg's glTF reader
/// samples: what `Gltf_file` does with such a file before it reads the scene.
///
/// Assimp parses the file; then, as `fbx_collada_model` writes an FBX scene:
/// - every joint becomes a node named as in the file, its OFFSET its rest translation; the end
///   of a chain ("End Site") a node "EndSite_" followed by its joint's name;
/// - the MOTION becomes one clip, "Motion": key k of every joint at k times the Frame Time, in
///   seconds (the frame rate is 1 / Frame Time); each joint's rotation channels, in the order the
///   file lists them, make one rotation (Zrotation Xrotation Yrotation gives Rz Rx Ry, as BVH
///   means); its position channels, when it has them, its translation. What a joint does not
///   record the clip does not animate: its translation stays its rest translation (its OFFSET,
///   or on another file's body the body's own), likewise its rotation, and no joint's scale;
/// - the units are the file's, taken as metres (BVH does not say which: most libraries write
///   centimetres, some their own scale), under a root node of scale 1. A body made from the
///   skeleton has the file's proportions whatever its unit (the strain does not depend on it);
///   played on another file's body (`Gltf_file(body, clips)`), the clip's translations are
///   carried into the body's world as metres, so a joint's position channels (the root's, mostly)
///   must be in metres to fit it (a clip in centimetres moves its root a hundred times as far).
///
/// The file has no mesh: `Gltf_file` makes a body from its skeleton (see `Gltf_file`).
/// Assimp keeps the values it reads as single-precision floats (about 7 significant digits).
///
/// @param path a `.bvh` file.
/// @return the model, whose buffers are held in memory.
/// @throws invalid_input naming the file (and the line, where it is known) for: a file that does
/// not exist or is larger than `max_bvh_bytes`; text that Assimp cannot parse (its message); a
/// joint with position channels among other than 6 channels (Assimp drops such positions); two
/// joints of one name; a hierarchy deeper than 1,000 levels; a frame count that is not a whole
/// number or that claims more values than the file holds; a Frame Time that is not a positive
/// number; a non-finite value.
/// @par Complexity O(file size), plus Assimp's parsing.
/// @par Example
/// @include read_bvh.cpp
inline tinygltf::Model bvh_model(const std::filesystem::path& path) {
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
