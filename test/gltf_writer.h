// Hand-made glTF 2.0 files for the tests: a JSON document built with nlohmann::json and one
// binary buffer, written as .gltf (the buffer as a base64 data URI) or .glb.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace deformseg::test {

class Gltf_writer {
public:
  using json = nlohmann::json;

  static constexpr int byte_type = 5120, ubyte_type = 5121, short_type = 5122, ushort_type = 5123,
                       uint_type = 5125, float_type = 5126;

  /// The document; add to it freely ("nodes", "meshes", "animations", "skins", "scenes", ...).
  json doc = {{"asset", {{"version", "2.0"}}}};

  /// Appends raw bytes as a buffer view (4-byte aligned) and gives its index.
  int view(const void* data, std::size_t bytes, std::size_t stride = 0) {
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}};
    if (stride != 0) v["byteStride"] = stride;
    const auto* p = static_cast<const unsigned char*>(data);
    bin_.insert(bin_.end(), p, p + bytes);
    return push("bufferViews", v);
  }

  /// An accessor over buffer view `view_index` (-1: none) and gives its index.
  int accessor(int view_index, int component_type, std::size_t count, const std::string& type,
               bool normalized = false, std::size_t byte_offset = 0) {
    json a = {{"componentType", component_type}, {"count", count}, {"type", type}};
    if (view_index >= 0) a["bufferView"] = view_index;
    if (byte_offset != 0) a["byteOffset"] = byte_offset;
    if (normalized) a["normalized"] = true;
    return push("accessors", a);
  }

  /// A tightly packed accessor of values of type T.
  template <class T>
  int values(const std::vector<T>& v, int component_type, const std::string& type, bool normalized = false) {
    const std::size_t width = components(type);
    return accessor(view(v.data(), v.size() * sizeof(T)), component_type, v.size() / width, type, normalized);
  }

  int floats(const std::vector<float>& v, const std::string& type) { return values(v, float_type, type); }
  int indices(const std::vector<std::uint32_t>& v) { return values(v, uint_type, "SCALAR"); }

  /// Appends `value` to the array `key` of the document and gives its index.
  int push(const std::string& key, const json& value) {
    if (!doc.contains(key)) doc[key] = json::array();
    doc[key].push_back(value);
    return int(doc[key].size()) - 1;
  }

  /// The document with its buffer, as the JSON of a .gltf file (buffer as a data URI).
  std::string gltf_text() const {
    json d = doc;
    if (!bin_.empty())
      d["buffers"] = json::array({{{"byteLength", bin_.size()},
                                   {"uri", "data:application/octet-stream;base64," + base64(bin_)}}});
    return d.dump(1);
  }

  void write_gltf(const std::filesystem::path& path) const { std::ofstream(path, std::ios::binary) << gltf_text(); }

  /// The document as a .gltf whose buffer is the external file `bin_name` beside it.
  void write_gltf_with_bin(const std::filesystem::path& path, const std::string& bin_name) const {
    json d = doc;
    d["buffers"] = json::array({{{"byteLength", bin_.size()}, {"uri", bin_name}}});
    std::ofstream(path, std::ios::binary) << d.dump(1);
    std::ofstream(path.parent_path() / bin_name, std::ios::binary)
        .write(reinterpret_cast<const char*>(bin_.data()), std::streamsize(bin_.size()));
  }

  /// The document as a .glb: a JSON chunk and a BIN chunk.
  void write_glb(const std::filesystem::path& path) const {
    json d = doc;
    std::vector<unsigned char> bin = bin_;
    while (bin.size() % 4 != 0) bin.push_back(0);
    if (!bin.empty()) d["buffers"] = json::array({{{"byteLength", bin_.size()}}});
    std::string text = d.dump();
    while (text.size() % 4 != 0) text.push_back(' ');
    std::string out = "glTF";
    const auto put32 = [&out](std::uint32_t x) {
      for (int i = 0; i < 4; ++i) out.push_back(char((x >> (8 * i)) & 0xff));
    };
    const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    put32(2);
    put32(std::uint32_t(total));
    put32(std::uint32_t(text.size()));
    put32(0x4E4F534A);  // "JSON"
    out += text;
    if (!bin.empty()) {
      put32(std::uint32_t(bin.size()));
      put32(0x004E4942);  // "BIN\0"
      out.append(reinterpret_cast<const char*>(bin.data()), bin.size());
    }
    std::ofstream(path, std::ios::binary) << out;
  }

private:
  static std::size_t components(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    return 16;  // MAT4
  }

  static std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string s;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
      const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) |
                              (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                              (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
      s.push_back(digits[(n >> 18) & 63]);
      s.push_back(digits[(n >> 12) & 63]);
      s.push_back(i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=');
      s.push_back(i + 2 < bytes.size() ? digits[n & 63] : '=');
    }
    return s;
  }

  std::vector<unsigned char> bin_{};
};

}  // namespace deformseg::test
