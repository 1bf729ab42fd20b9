/// @file io/character_files.h
/// @brief The names of character files, whose clips the glTF reader samples (`Gltf_file`):
/// glTF (`is_gltf`), FBX and Collada (`is_fbx_or_collada`), any of them (`is_character_file`).
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

/// @brief Whether `input` names a character file, with clips, a skin and a node tree: glTF, FBX
/// or Collada (`is_gltf` or `is_fbx_or_collada`). Such a file is read clip by clip
/// ("FILE.fbx#CLIP"), with `Gltf_file`.
/// @par Complexity O(length of the name).
inline bool is_character_file(const std::filesystem::path& input) { return is_gltf(input) || is_fbx_or_collada(input); }

}  // namespace deformseg::io
