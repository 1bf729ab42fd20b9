/// @file io/fbx_collada.h
/// @brief Reads FBX (`.fbx`) and Collada (`.dae`) characters: Assimp parses the file, and its
/// scene is written into the structures of glTF 2.0 (`fbx_collada_model`), which the glTF reader
/// samples and skins (`Gltf_file` opens either), so that a clip read from an FBX file and from
/// its glTF conversion gives the same frames.
///
/// Assimp parses and evaluates nothing: the bind pose, bones with offset matrices and weights,
/// the node tree and key lists. The reading is the glTF reader's: the same clips by name or
/// index, the same frame rule, the same welding and repair.
#pragma once

#if !__has_include(<assimp/Importer.hpp>) || !__has_include(<tiny_gltf.h>)
#error "deformseg/io/fbx_collada.h needs Assimp (Debian: libassimp-dev) and tinygltf (libtinygltf-dev)"
#endif

#include <deformseg/exceptions.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/internal/assimp_clips.h>
#include <deformseg/io/internal/assimp_model_writer.h>
#include <deformseg/io/internal/assimp_scene.h>
#include <deformseg/io/internal/collada_checks.h>
#include <deformseg/io/internal/fbx_local_transforms.h>
#include <deformseg/io/internal/file_io.h>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/metadata.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io::internal::assimp {

/// The metres per unit of an FBX scene: its "UnitScaleFactor" is centimetres per unit, FBX's
/// default 1 when the file gives none. (Collada's unit Assimp puts in the root node's transform.)
inline double metres_per_unit(const aiScene& scene) {
  double centimetres = 1;
  if (scene.mMetaData) {
    float f = 0;
    double d = 0;
    if (scene.mMetaData->Get("UnitScaleFactor", d)) centimetres = d;
    else if (scene.mMetaData->Get("UnitScaleFactor", f)) centimetres = f;
  }
  if (!std::isfinite(centimetres) || centimetres <= 0)
    throw invalid_input("the scene's UnitScaleFactor is " + std::to_string(centimetres) + ", not a positive unit");
  return centimetres / 100;
}

/// Writes an Assimp scene as a glTF model: a root node in metres (scaling by `metres`) above the
/// scene's node tree (its nodes in `local` placed so, in place of Assimp's transforms), the meshes
/// and skins (bone offsets taken by `rule`), the clips. See `fbx_collada_model`.
inline tinygltf::Model model_of(const aiScene& scene, double metres, Bind_rule rule = Bind_rule::as_stored,
                                Local_transforms local = {}) {
  if (!scene.mRootNode) throw invalid_input("the scene has no root node");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "deformseg (from Assimp)";
  Model_writer writer(model);
  tinygltf::Node units;
  units.name = "deformseg: metres";
  units.scale = {metres, metres, metres};
  model.nodes.push_back(units);
  const Node_table nodes = write_nodes(*scene.mRootNode, animated_nodes(scene), model, std::move(local));
  model.nodes.front().children = {int(nodes.base)};
  const std::vector<int> node_of_mesh = write_meshes(scene, nodes, rule, writer, model);
  write_clips(scene, nodes, node_of_mesh, writer, model);
  model.scenes.push_back({});
  model.scenes.front().nodes = {0};
  model.defaultScene = 0;
  return model;
}

/// The settings of the import: Assimp's FBX reader keeps a pivot's pre-rotation both in the keys
/// and in a helper node unless PRESERVE_PIVOTS is off, which applies it twice.
inline const aiScene* read_scene(Assimp::Importer& importer, const std::string& bytes, const std::string& extension) {
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);
  return importer.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_Triangulate | aiProcess_ValidateDataStructure,
                                     extension.c_str());
}

/// Parses a file's bytes, `format` "fbx" or "dae", as `fbx_collada_model` does.
inline tinygltf::Model model_from_bytes(const std::string& bytes, const std::string& format) {
  Assimp::Importer importer;
  const aiScene* scene = nullptr;
  try {
    scene = read_scene(importer, bytes, format);
  } catch (const std::exception& e) {
    throw invalid_input(std::string("Assimp could not parse the file: ") + e.what());
  }
  const std::string what = format == "fbx" ? "FBX" : "Collada";
  if (!scene) {
    std::string error = importer.GetErrorString();
    while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
    throw invalid_input("not a valid " + what + " file: " + (error.empty() ? "Assimp refused it" : error));
  }
  if (format == "dae") collada::check_channel_targets(bytes);
  if (format == "dae" && collada::has_morph(bytes)) {
    bool targets = false;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) targets = targets || scene->mMeshes[m]->mNumAnimMeshes > 0;
    if (!targets)
      throw invalid_input("the file has a Collada morph controller (<morph>) that Assimp does not import (a morph "
                          "under a skin): its targets would be lost");
  }
  if (format == "fbx")
    return model_of(*scene, metres_per_unit(*scene), fbx_bind_rule(*scene), fbx::local_transforms(bytes, *scene));
  return model_of(*scene, 1.0);
}

}  // namespace deformseg::io::internal::assimp

namespace deformseg::io {

/// @brief The most bytes of an FBX or Collada file read: 2 GiB, Assimp's own limit.
inline constexpr std::size_t max_fbx_collada_bytes = std::size_t(1) << 31;

/// @brief Reads an FBX or Collada file into the glTF 2.0 structures deformseg's glTF reader
/// samples: what `Gltf_file` does with such a file before it reads the scene.
///
/// Assimp parses the file (triangulating polygons; FBX pivots baked into the keys, its
/// `AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS` off). Then:
/// - a root node scales the scene to metres, as glTF's unit is: FBX gives its unit
///   (`UnitScaleFactor`, centimetres per unit), Collada's `<unit>` and up axis are in Assimp's
///   root transform already;
/// - every node becomes a glTF node (a node some clip moves as translation, rotation and scale,
///   else as its matrix); a binary FBX file's nodes placed by translation, rotation and scaling
///   alone take them from the file, in double precision (Assimp 5.2 drops tiny ones, which a
///   parent's scale makes large: `internal::assimp::fbx::local_transforms`);
/// - a name that a bone and a mesh share (Blender names a mesh parented to a bone after it)
///   stands for the node without meshes, for the bones and the clips' channels;
/// - a node's meshes (Assimp splits a mesh per material) become one glTF mesh of one primitive
///   each, with one skin of their bones (bone offsets are inverse bind matrices; an FBX bone's
///   as Autodesk's FBX SDK gives it, its bind matrix without shear, but for files of Blender 2.80
///   and later, as stored: Blender deforms with them, shear included), the 8 largest weights of
///   each vertex kept (glTF's reader then divides them by their sum), morph targets as deltas;
/// - every clip becomes a glTF animation of its name, key times in seconds (ticks per second, 25
///   when the file gives none), interpolated linearly.
///
/// @param path a `.fbx` (binary or ASCII) or `.dae` file; the format is told by the extension.
/// @return the model, whose buffers are held in memory.
/// @throws invalid_input naming the file for: a file that does not exist or is a folder
/// ("cannot open: no such file", as every reader says), is larger than
/// `max_fbx_collada_bytes`, or that Assimp cannot parse (its message); a clip channel aimed at a
/// node the scene does not have (an FBX pivot helper, a missing target), naming the clip and the
/// node; a Collada `<channel>` whose target no element of the file has, or a Collada morph under
/// a skin, both of which Assimp drops; a bone that names no node; a non-finite position,
/// transform, weight or key.
/// @par Complexity O(file size), plus Assimp's parsing.
inline tinygltf::Model fbx_collada_model(const std::filesystem::path& path) {
  try {
    if (!is_fbx_or_collada(path))
      throw invalid_input("not an FBX or Collada file name: the extension is not .fbx or .dae");
    std::error_code error;  // a missing file or a folder in the words of every reader (read_file_bytes)
    if (!std::filesystem::exists(path, error)) throw invalid_input("cannot open: no such file");
    if (!std::filesystem::is_regular_file(path, error)) throw invalid_input("cannot open: it is a folder, not a file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw invalid_input("cannot read the file: " + error.message());
    if (size > max_fbx_collada_bytes)
      throw invalid_input("the file is larger than " + std::to_string(max_fbx_collada_bytes) + " bytes");
    std::string bytes(size, '\0');
    std::ifstream in(path, std::ios::binary);
    if (!in.read(bytes.data(), std::streamsize(bytes.size()))) throw invalid_input("cannot read the file");
    return internal::assimp::model_from_bytes(bytes, internal::lower_extension(path).substr(1));
  } catch (const invalid_input& e) {
    throw e.located({.file = path.string()});
  }
}

}  // namespace deformseg::io
