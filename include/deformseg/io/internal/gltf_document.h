// A glTF file as JSON and buffers, for the decoders of compressed geometry, which rewrite a file
// before tinygltf parses it: tinygltf refuses what they decode (accessors of indices without a
// buffer view, buffer views on a fallback buffer that has no bytes).
// Errors are invalid_input without a file; io/gltf.h adds the file.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::io::internal::gltf {

using Json = nlohmann::json;
using Bytes = std::vector<unsigned char>;

/// A glTF document and the bytes of each of its buffers (a fallback buffer of
/// EXT_meshopt_compression, which has none, is empty).
struct Gltf_document {
  Json json;
  std::vector<Bytes> buffers;
};

inline constexpr std::uint32_t glb_magic = 0x46546C67, glb_json_chunk = 0x4E4F534A, glb_bin_chunk = 0x004E4942;

inline std::uint32_t read_u32(const unsigned char* p) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | p[i];
  return value;
}

inline void append_u32(Bytes& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back((unsigned char)(value >> (8 * i)));
}

inline bool is_glb(std::span<const unsigned char> file) { return file.size() >= 4 && read_u32(file.data()) == glb_magic; }

/// The chunks of a GLB file: its JSON text and its binary chunk (empty when it has none).
struct Glb_chunks {
  std::string_view json;
  std::span<const unsigned char> bin;
};

inline Glb_chunks glb_chunks(std::span<const unsigned char> file) {
  if (file.size() < 20) throw invalid_input("a GLB file of " + std::to_string(file.size()) + " bytes: too short");
  Glb_chunks chunks;
  std::size_t at = 12;
  for (int index = 0; at + 8 <= file.size(); ++index) {
    const std::size_t length = read_u32(file.data() + at), type = read_u32(file.data() + at + 4);
    at += 8;
    if (length > file.size() - at)
      throw invalid_input("GLB chunk " + std::to_string(index) + " claims " + std::to_string(length) +
                          " bytes, past the end of the file");
    const auto* data = file.data() + at;
    if (index == 0 && type != glb_json_chunk) throw invalid_input("the first GLB chunk is not JSON");
    if (index == 0) chunks.json = {reinterpret_cast<const char*>(data), length};
    if (index == 1 && type == glb_bin_chunk) chunks.bin = {data, length};
    at += length;
  }
  return chunks;
}

/// `uri` with its %XX escapes decoded, as a file name.
inline std::string decoded_uri(const std::string& uri) {
  std::string path;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    const auto hex = [](char c) { return std::isxdigit((unsigned char)c) != 0; };
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) && hex(uri[i + 2])) {
      path.push_back(char(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      path.push_back(uri[i]);
    }
  }
  return path;
}

/// A whole number at `json[key]`, `fallback` when absent; refused, naming `where`, when it is not
/// a whole number in [0, 2^53].
inline std::size_t whole_number(const Json& json, const char* key, const std::string& where,
                                std::optional<std::size_t> fallback = std::nullopt) {
  const auto it = json.find(key);
  if (it == json.end()) {
    if (fallback) return *fallback;
    throw invalid_input(where + " has no " + key);
  }
  if (!it->is_number_unsigned() || it->get<std::uint64_t>() > (std::uint64_t(1) << 53))
    throw invalid_input(where + "." + key + " must be a whole number, got " + it->dump());
  return std::size_t(it->get<std::uint64_t>());
}

/// The object at `json[key]`, refused naming `where` when absent or not an object.
inline const Json& object_at(const Json& json, const char* key, const std::string& where) {
  const auto it = json.find(key);
  if (it == json.end() || !it->is_object()) throw invalid_input(where + "." + key + " must be an object");
  return *it;
}

/// What the decoders of one file may write in all: bytes in proportion to the file's own (no codec
/// here expands a byte to more than 64), so that a few bytes of JSON that claim billions of decoded
/// elements, or that name one compressed block a thousand times, are refused before any is made.
class Decoding_budget {
public:
  static constexpr std::size_t expansion = 64, slack = std::size_t(1) << 20;

  explicit Decoding_budget(std::size_t file_bytes) : left_(file_bytes * expansion + slack) {}

  /// Takes `bytes` from the budget; refuses, naming `where`, when they are not left.
  void spend(std::size_t bytes, const std::string& where) {
    if (bytes > left_)
      throw invalid_input(where + " would decode to " + std::to_string(bytes) + " bytes, more than " +
                          std::to_string(expansion) + " times the file's size allows");
    left_ -= bytes;
  }

private:
  std::size_t left_;
};

/// The extension object `name` of a glTF object (a buffer view, a primitive), or null.
inline Json* extension_object(Json& object, const char* name) {
  const auto extensions = object.find("extensions");
  if (extensions == object.end() || !extensions->is_object()) return nullptr;
  const auto it = extensions->find(name);
  return it == extensions->end() ? nullptr : &*it;
}

/// Removes extension `name` from `object`, and its "extensions" when that is left empty.
inline void erase_extension(Json& object, const char* name) {
  Json& extensions = object["extensions"];
  extensions.erase(name);
  if (extensions.empty()) object.erase("extensions");
}

/// The bytes `[offset, offset + length)` of buffer `buffer`, refused naming `where` when outside it.
inline std::span<const unsigned char> buffer_range(const Gltf_document& document, std::size_t buffer,
                                                   std::size_t offset, std::size_t length, const std::string& where) {
  if (buffer >= document.buffers.size())
    throw invalid_input(where + " names buffer " + std::to_string(buffer) + ", which the file does not have");
  const Bytes& bytes = document.buffers[buffer];
  if (offset > bytes.size() || length > bytes.size() - offset)
    throw invalid_input(where + " takes bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) +
                        " of buffer " + std::to_string(buffer) + ", which has " + std::to_string(bytes.size()));
  return {bytes.data() + offset, length};
}

/// Appends `bytes` to `out` at the next multiple of 4, and gives where they start.
inline std::size_t append_aligned(Bytes& out, std::span<const unsigned char> bytes) {
  out.resize((out.size() + 3) / 4 * 4, 0);
  const std::size_t start = out.size();
  out.insert(out.end(), bytes.begin(), bytes.end());
  return start;
}

/// Appends `bytes` to the document's buffer `buffer` as a new buffer view, and gives its index.
inline std::size_t append_view(Gltf_document& document, std::size_t buffer, std::span<const unsigned char> bytes) {
  const std::size_t start = append_aligned(document.buffers[buffer], bytes);
  Json& views = document.json["bufferViews"];
  views.push_back({{"buffer", buffer}, {"byteOffset", start}, {"byteLength", bytes.size()}});
  return views.size() - 1;
}

/// Adds an empty buffer to `document`, for decoded bytes, and gives its index; `close_buffer` sets its
/// length once they are written.
inline std::size_t open_buffer(Gltf_document& document) {
  document.buffers.emplace_back();
  document.json["buffers"].push_back({{"byteLength", 0}});
  return document.buffers.size() - 1;
}

inline void close_buffer(Gltf_document& document, std::size_t buffer) {
  document.json["buffers"][buffer]["byteLength"] = document.buffers[buffer].size();
}

/// The buffer `buffer` of the document: the GLB's binary chunk, a data URI, a file beside the
/// document, or nothing for a meshopt fallback buffer.
inline Bytes buffer_bytes(const Json& buffer, std::size_t index, const Glb_chunks* glb,
                          const std::filesystem::path& base_dir) {
  const std::string where = "buffers[" + std::to_string(index) + "]";
  if (!buffer.is_object()) throw invalid_input(where + " must be an object");
  const std::size_t length = whole_number(buffer, "byteLength", where);
  const auto extensions = buffer.find("extensions");
  if (extensions != buffer.end() && extensions->is_object())
    for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"})
      if (extensions->contains(name) && (*extensions)[name].value("fallback", false)) return {};
  const auto uri = buffer.find("uri");
  Bytes bytes;
  if (uri == buffer.end()) {
    if (glb == nullptr || index != 0) throw invalid_input(where + " has no uri");
    bytes.assign(glb->bin.begin(), glb->bin.end());
  } else if (!uri->is_string()) {
    throw invalid_input(where + ".uri must be a string");
  } else if (tinygltf::IsDataURI(uri->get<std::string>())) {
    std::string mime;
    if (!tinygltf::DecodeDataURI(&bytes, mime, uri->get<std::string>(), length, true))
      throw invalid_input(where + " has a data URI that is not " + std::to_string(length) + " bytes of base64");
  } else {
    const std::filesystem::path path = base_dir / decoded_uri(uri->get<std::string>());
    try {
      const File_bytes file = read_file_bytes(path, length);
      bytes.assign(file.begin(), file.begin() + file.size);
    } catch (const invalid_input& e) {  // refused as the document's: its buffer is the file named
      throw invalid_input(where + ", " + path.string() + ": " + e.message());
    }
  }
  if (bytes.size() < length)
    throw invalid_input(where + " has " + std::to_string(bytes.size()) + " bytes, not the " + std::to_string(length) +
                        " of its byteLength");
  bytes.resize(length);
  return bytes;
}

/// Parses a .gltf or .glb file's document and reads its buffers (files named by a uri relative to
/// `base_dir`).
inline Gltf_document parse_document(std::span<const unsigned char> file, const std::filesystem::path& base_dir) {
  const bool glb = is_glb(file);
  const Glb_chunks chunks =
      glb ? glb_chunks(file) : Glb_chunks{{reinterpret_cast<const char*>(file.data()), file.size()}, {}};
  Gltf_document document;
  document.json = Json::parse(chunks.json, nullptr, false);
  if (document.json.is_discarded()) throw invalid_input("the glTF document is not valid JSON");
  if (!document.json.is_object()) throw invalid_input("the glTF document is not a JSON object");
  const auto buffers = document.json.find("buffers");
  if (buffers == document.json.end()) return document;
  if (!buffers->is_array()) throw invalid_input("buffers must be an array");
  for (std::size_t i = 0; i < buffers->size(); ++i)
    document.buffers.push_back(buffer_bytes((*buffers)[i], i, glb ? &chunks : nullptr, base_dir));
  return document;
}

/// A GLB file of `json` and the binary chunk `bin` (buffer 0 of the document, when it has no uri).
inline Bytes glb_bytes(const Json& json, std::span<const unsigned char> bin) {
  std::string text = json.dump();
  while (text.size() % 4 != 0) text.push_back(' ');
  const std::size_t padded_bin = (bin.size() + 3) / 4 * 4;
  Bytes out;
  out.reserve(12 + 8 + text.size() + 8 + padded_bin);
  append_u32(out, glb_magic);
  append_u32(out, 2);
  append_u32(out, std::uint32_t(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + padded_bin)));
  append_u32(out, std::uint32_t(text.size()));
  append_u32(out, glb_json_chunk);
  out.insert(out.end(), text.begin(), text.end());
  if (bin.empty()) return out;
  append_u32(out, std::uint32_t(padded_bin));
  append_u32(out, glb_bin_chunk);
  out.insert(out.end(), bin.begin(), bin.end());
  out.resize(out.size() + padded_bin - bin.size(), 0);
  return out;
}

/// `document` as one GLB file: its buffers laid end to end, 4-byte aligned, as its binary chunk,
/// and every buffer view moved onto it.
inline Bytes packed_glb(Gltf_document&& document) {
  std::vector<std::size_t> starts;
  Bytes bin;
  for (const Bytes& buffer : document.buffers) {
    bin.resize((bin.size() + 3) / 4 * 4, 0);
    starts.push_back(bin.size());
    bin.insert(bin.end(), buffer.begin(), buffer.end());
  }
  Json& json = document.json;
  if (auto views = json.find("bufferViews"); views != json.end() && views->is_array())
    for (std::size_t i = 0; i < views->size(); ++i) {
      Json& view = (*views)[i];
      const std::string where = "bufferViews[" + std::to_string(i) + "]";
      if (!view.is_object()) throw invalid_input(where + " must be an object");
      const std::size_t buffer = whole_number(view, "buffer", where);
      if (buffer >= starts.size()) throw invalid_input(where + ".buffer is " + std::to_string(buffer) + ", not a buffer");
      view["buffer"] = 0;
      view["byteOffset"] = starts[buffer] + whole_number(view, "byteOffset", where, 0);
    }
  json.erase("buffers");
  if (!bin.empty()) json["buffers"] = Json::array({{{"byteLength", bin.size()}}});
  return glb_bytes(json, bin);
}

}  // namespace deformseg::io::internal::gltf
