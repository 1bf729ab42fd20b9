// Assimp's scene written into glTF's structures (io/fbx_collada.h, io/bvh.h): the unit, the
// model, the import's settings and the parsing of a file's bytes. The library compiles it
// (src/io/); the readers' tests and fuzz harnesses include it for the adapter alone.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/assimp_clips.h>
#include <deformseg/io/internal/assimp_import.h>
#include <deformseg/io/internal/assimp_model_writer.h>
#include <deformseg/io/internal/assimp_scene.h>
#include <deformseg/io/internal/collada_checks.h>
#include <deformseg/io/internal/fbx_local_transforms.h>

#include <assimp/config.h>
#include <assimp/metadata.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <tiny_gltf.h>

#include <cmath>
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

/// Imports a file's bytes, `extension` "fbx" or "dae". The settings: Assimp's FBX reader keeps a
/// pivot's pre-rotation both in the keys and in a helper node unless PRESERVE_PIVOTS is off, which
/// applies it twice.
inline Import_result read_scene(const std::string& bytes, const std::string& extension) {
  constexpr unsigned steps = aiProcess_Triangulate | aiProcess_ValidateDataStructure;
  return import_from_memory(bytes, steps, extension.c_str(), {{AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, 0}});
}

/// Parses a file's bytes, `format` "fbx" or "dae", as `fbx_collada_model` does.
inline tinygltf::Model model_from_bytes(const std::string& bytes, const std::string& format) {
  const Import_result imported = read_scene(bytes, format);
  const std::string what = format == "fbx" ? "FBX" : "Collada";
  if (!imported.scene) {
    std::string error = imported.error;
    while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
    throw invalid_input("not a valid " + what + " file: " + (error.empty() ? "Assimp refused it" : error));
  }
  const aiScene* scene = imported.scene.get();
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
