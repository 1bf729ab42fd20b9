/// @file io/character_files.h
/// @brief The names of character files, whose clips the glTF reader samples (`Gltf_file`):
/// glTF (`is_gltf`), FBX and Collada (`is_fbx_or_collada`), BVH motion capture (`is_bvh`), any of
/// them (`is_character_file`).
#pragma once

#include <deformseg/io/internal/file_io.h>

#include <filesystem>
#include <string>

namespace deformseg::io {

/// @brief Whether `input` names a glTF file, by its extension (`.gltf` or `.glb`, in any case).
/// @par Complexity O(length of the name).
/// @par Example
/// @include is_gltf.cpp
inline bool is_gltf(const std::filesystem::path& input) {
  const std::string extension = internal::lower_extension(input);
  return extension == ".gltf" || extension == ".glb";
}

/// @brief Whether `input` names an FBX or Collada file, by its extension (`.fbx` or `.dae`, in
/// any case): files `Gltf_file` reads through Assimp (see `fbx_collada_model`).
/// @par Complexity O(length of the name).
inline bool is_fbx_or_collada(const std::filesystem::path& input) {
  const std::string extension = internal::lower_extension(input);
  return extension == ".fbx" || extension == ".dae";
}

/// @brief Whether `input` names a BVH motion capture file, by its extension (`.bvh`, in any
/// case): a skeleton and one clip, which `Gltf_file` reads through Assimp (see `bvh_model`).
/// @par Complexity O(length of the name).
/// @par Example
/// @include read_bvh.cpp
inline bool is_bvh(const std::filesystem::path& input) { return internal::lower_extension(input) == ".bvh"; }

/// @brief Whether `input` names a character file, with clips and a node tree: glTF, FBX,
/// Collada or BVH (`is_gltf`, `is_fbx_or_collada` or `is_bvh`). Such a file is read clip by clip
/// ("FILE.fbx#CLIP"), with `Gltf_file`; one without a mesh on a body made from its skeleton.
/// @par Complexity O(length of the name).
inline bool is_character_file(const std::filesystem::path& input) {
  return is_gltf(input) || is_fbx_or_collada(input) || is_bvh(input);
}

}  // namespace deformseg::io
