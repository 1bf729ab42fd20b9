// Assimp's import of a file's bytes, through its C API resolved at run time (src/io/assimp_import.cpp):
// the io library does not link libassimp, so that a program starts without loading it (and the
// libraries it needs); the first FBX, Collada or BVH file read loads it, once for the process.
#pragma once

#include <assimp/scene.h>

#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>

namespace deformseg::io::internal::assimp {

/// An integer (or boolean: 0 or 1) import property of Assimp: its name (`AI_CONFIG_*`) and value.
struct Import_property {
  const char* name = nullptr;
  int value = 0;
};

/// Gives an imported scene back to Assimp (`aiReleaseImport`), which frees it.
struct Scene_release {
  /// Releases `scene`, which `import_from_memory` returned (null: nothing). Never throws.
  void operator()(const aiScene* scene) const noexcept;
};

/// A scene Assimp imported, owned: released when it goes out of scope.
using Imported_scene = std::unique_ptr<const aiScene, Scene_release>;

/// What an import gives: the scene, or none and Assimp's message of why.
struct Import_result {
  Imported_scene scene{};  ///< null when Assimp refused the bytes
  std::string error{};     ///< Assimp's message when `scene` is null, as it gives it
};

/// Imports `bytes` as a file of extension `hint` ("fbx", "dae", "bvh") with Assimp's post-processing
/// `steps` (`aiProcess_*`) and the `properties` set, as `Assimp::Importer::ReadFileFromMemory` does.
/// Loads Assimp's shared library on the first call (thread-safe); the imports of a process run one
/// at a time, since Assimp's C API keeps the last error in one global string.
/// Throws invalid_input when Assimp's library cannot be loaded (its name, its Debian package and the
/// loader's reason in the message) or the bytes are more than 4 GiB - 1 (Assimp's size type).
/// Complexity: Assimp's parse of the file.
Import_result import_from_memory(std::string_view bytes, unsigned steps, const char* hint,
                                 std::initializer_list<Import_property> properties);

}  // namespace deformseg::io::internal::assimp
