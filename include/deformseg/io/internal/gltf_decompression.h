// Compressed glTF geometry (KHR_draco_mesh_compression, EXT_meshopt_compression) decoded before
// tinygltf parses the file: the document's compressed views and primitives are rewritten as plain
// ones over new buffers, and the file handed on as one GLB. Each codec is there when deformseg was
// configured with its library (DEFORMSEG_HAS_DRACO, DEFORMSEG_HAS_MESHOPT); a file that needs one
// that is not is refused by the extension's name and the package to install.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/config.h>
#include <deformseg/io/internal/gltf_document.h>

#if DEFORMSEG_HAS_DRACO
#include <deformseg/io/internal/gltf_draco.h>
#endif
#if DEFORMSEG_HAS_MESHOPT
#include <deformseg/io/internal/gltf_meshopt.h>
#endif

#include <algorithm>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace deformseg::io::internal::gltf {

/// Whether the JSON of a .gltf or .glb file names a compression extension: a look at its text,
/// that never throws, before anything is parsed.
inline bool names_compression(std::span<const unsigned char> file) {
  std::string_view json(reinterpret_cast<const char*>(file.data()), file.size());
  if (is_glb(file) && file.size() >= 20) json = json.substr(20, read_u32(file.data() + 12));
  return json.find("KHR_draco_mesh_compression") != std::string_view::npos ||
         json.find("_meshopt_compression") != std::string_view::npos;
}

/// Whether the document lists `name` among the extensions it uses or requires.
inline bool lists_extension(const Json& json, std::string_view name) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    const auto list = json.find(key);
    if (list != json.end() && list->is_array() && std::ranges::find(*list, Json(name)) != list->end()) return true;
  }
  return false;
}

/// Removes `name` from the extensions the document uses and requires.
inline void unlist_extension(Json& json, std::string_view name) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    const auto list = json.find(key);
    if (list == json.end() || !list->is_array()) continue;
    list->erase(std::remove(list->begin(), list->end(), Json(name)), list->end());
  }
}

inline void refuse_without(std::string_view extension, std::string_view what, std::string_view package) {
  throw invalid_input("the file uses " + std::string(extension) + " (" + std::string(what) +
                      "), which this deformseg was built without (Debian: " + std::string(package) + ")");
}

/// Decodes the compressed views and primitives of `document` with the codecs it lists.
inline void decode_compressed(Gltf_document& document, Decoding_budget& budget) {
  for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"}) {
    if (!lists_extension(document.json, name)) continue;
#if DEFORMSEG_HAS_MESHOPT
    decode_meshopt_views(document, name, budget);
#else
    refuse_without(name, "meshopt-compressed buffers", "libmeshoptimizer-dev");
#endif
    unlist_extension(document.json, name);
  }
  if (lists_extension(document.json, "KHR_draco_mesh_compression")) {
#if DEFORMSEG_HAS_DRACO
    decode_draco_primitives(document, budget);
#else
    refuse_without("KHR_draco_mesh_compression", "Draco-compressed geometry", "libdraco-dev");
#endif
    unlist_extension(document.json, "KHR_draco_mesh_compression");
  }
}

/// The file `file` (a .gltf or .glb whose buffers' files are in `base_dir`) as one GLB file with its
/// compressed geometry decoded. A document whose values have the wrong JSON types is refused with
/// nlohmann-json's words.
inline Bytes decompressed_glb(std::span<const unsigned char> file, const std::filesystem::path& base_dir) {
  try {
    Gltf_document document = parse_document(file, base_dir);
    std::size_t buffer_bytes = 0;
    for (const Bytes& buffer : document.buffers) buffer_bytes += buffer.size();
    Decoding_budget budget(std::max(buffer_bytes, file.size()));
    decode_compressed(document, budget);
    return packed_glb(std::move(document));
  } catch (const Json::exception& e) {
    throw invalid_input(std::string("the glTF document does not have the shape glTF gives it: ") + e.what());
  }
}

}  // namespace deformseg::io::internal::gltf
