// The FBX and Collada reader of io/fbx_collada.h: the file's bytes parsed by Assimp and its scene
// written into glTF's structures (io/internal/assimp_model.h).
#include <deformseg/io/fbx_collada.h>

#include <deformseg/exceptions.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/internal/assimp_model.h>
#include <deformseg/io/internal/file_io.h>

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace deformseg::io {

tinygltf::Model fbx_collada_model(const std::filesystem::path& path) {
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
