// Compressed copies of glTF characters, made at test time with the encoders of the libraries whose
// decoders deformseg uses (libdraco, libmeshoptimizer), never committed:
// - `write_draco_copy`: every triangle primitive without morph targets as KHR_draco_mesh_compression
//   (edgebreaker, which reorders and may split vertices; positions on `position_bits` bits);
// - `write_meshopt_copy`: the vertex attributes and indices of those primitives, and every clip's
//   keys, in EXT_meshopt_compression views with the filters gltfpack uses (positions, translations
//   and scales as exponential floats, normals octahedral in bytes and rotations as quaternion shorts,
//   both KHR_mesh_quantization), over a fallback buffer without bytes.
// Draco primitives get accessors of their own (a Draco mesh's vertex order is its own); meshopt
// accessors are compressed in place. The original bytes stay in the buffer, unused, so the copies
// are not smaller: they test decoding, not file size. The source must be a .glb with one buffer.
#pragma once

#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/gltf_accessor.h>
#include <deformseg/io/internal/gltf_document.h>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::test {

namespace compression_detail {

namespace gltf = deformseg::io::internal::gltf;
using Json = gltf::Json;

/// A character's document and its parse by tinygltf (whose accessors give the values).
struct Source {
  gltf::Gltf_document document;
  tinygltf::Model model;
};

inline bool keep_no_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                          void*) {
  return true;
}

inline Source load_source(const std::filesystem::path& from) {
  const auto file = deformseg::io::internal::read_file_bytes(from);
  const std::span<const unsigned char> bytes(reinterpret_cast<const unsigned char*>(file.begin()), file.size);
  Source source{gltf::parse_document(bytes, from.parent_path()), {}};
  if (source.document.buffers.size() != 1) throw std::runtime_error(from.string() + ": not a .glb of one buffer");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_no_image, nullptr);
  std::string err, warn;
  if (!loader.LoadBinaryFromMemory(&source.model, &err, &warn, bytes.data(), unsigned(bytes.size())))
    throw std::runtime_error(from.string() + ": " + err);
  return source;
}

/// The accessor's values as its own component type would store them (normalised integers scaled
/// back to integers).
inline std::vector<double> stored_values(const tinygltf::Model& model, int index) {
  const auto values = gltf::read_accessor(model, index, "test");
  const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
  std::vector<double> out = values.values;
  if (!accessor.normalized) return out;
  const double scale = accessor.componentType == TINYGLTF_COMPONENT_TYPE_BYTE             ? 127
                       : accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? 255
                       : accessor.componentType == TINYGLTF_COMPONENT_TYPE_SHORT          ? 32767
                       : accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 65535
                                                                                          : 1;
  for (double& v : out) v = std::round(v * scale);
  return out;
}

/// The triangle primitives that get compressed: triangle lists without morph targets.
template <typename Visit>
void for_each_compressible_primitive(Json& json, Visit visit) {
  for (Json& mesh : json["meshes"])
    for (Json& primitive : mesh["primitives"])
      if (primitive.value("mode", 4) == 4 && !primitive.contains("targets")) visit(primitive);
}

/// A copy of accessor `index` without data, for a compressed view to fill; gives its index.
inline std::size_t accessor_copy(Json& json, std::size_t index) {
  Json copy = json["accessors"][index];
  copy.erase("bufferView");
  copy.erase("byteOffset");
  copy.erase("sparse");
  json["accessors"].push_back(std::move(copy));
  return json["accessors"].size() - 1;
}

inline void list_extension(Json& json, const char* name) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    Json& list = json[key];
    if (std::find(list.begin(), list.end(), Json(name)) == list.end()) list.push_back(name);
  }
}

inline void write_glb(gltf::Gltf_document& document, const std::filesystem::path& to) {
  document.json["buffers"][0]["byteLength"] = document.buffers[0].size();
  const gltf::Bytes bytes = gltf::glb_bytes(document.json, document.buffers[0]);
  std::filesystem::create_directories(to.parent_path());
  deformseg::io::internal::write_file_bytes(to, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

// ---- Draco ----------------------------------------------------------------------------------

inline draco::GeometryAttribute::Type draco_type(const std::string& name) {
  if (name == "POSITION") return draco::GeometryAttribute::POSITION;
  if (name == "NORMAL") return draco::GeometryAttribute::NORMAL;
  if (name.starts_with("TEXCOORD_")) return draco::GeometryAttribute::TEX_COORD;
  if (name.starts_with("COLOR_")) return draco::GeometryAttribute::COLOR;
  return draco::GeometryAttribute::GENERIC;
}

inline draco::DataType draco_data_type(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return draco::DT_INT8;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return draco::DT_UINT8;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return draco::DT_INT16;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return draco::DT_UINT16;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return draco::DT_UINT32;
    default: return draco::DT_FLOAT32;
  }
}

/// Adds accessor `index` to `mesh` as an attribute of its own type; gives the attribute's unique id.
inline std::uint32_t add_draco_attribute(draco::Mesh& mesh, const tinygltf::Model& model, int index,
                                         const std::string& name) {
  const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
  const std::size_t components = gltf::components_of_type(accessor.type);
  const std::size_t size = gltf::component_size(accessor.componentType);
  draco::GeometryAttribute attribute;
  attribute.Init(draco_type(name), nullptr, std::uint8_t(components), draco_data_type(accessor.componentType),
                 accessor.normalized, std::int64_t(components * size), 0);
  const int id = mesh.AddAttribute(attribute, true, mesh.num_points());
  const std::vector<double> values = stored_values(model, index);
  std::vector<unsigned char> element(components * size);
  for (std::size_t i = 0; i < accessor.count; ++i) {
    for (std::size_t c = 0; c < components; ++c) {
      const double v = values[i * components + c];
      unsigned char* at = element.data() + c * size;
      switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: *reinterpret_cast<std::int8_t*>(at) = std::int8_t(v); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: *at = std::uint8_t(v); break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: { const auto s = std::int16_t(v); std::memcpy(at, &s, 2); break; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { const auto s = std::uint16_t(v); std::memcpy(at, &s, 2); break; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { const auto s = std::uint32_t(v); std::memcpy(at, &s, 4); break; }
        default: { const auto f = float(v); std::memcpy(at, &f, 4); }
      }
    }
    mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(std::uint32_t(i)), element.data());
  }
  return mesh.attribute(id)->unique_id();
}

/// The Draco encoding of one primitive, and the unique id of each of its attributes.
inline std::pair<draco::EncoderBuffer, Json> draco_encoding(const tinygltf::Model& model, const Json& primitive,
                                                           int position_bits) {
  const Json& attributes = primitive["attributes"];
  const auto& positions = model.accessors[attributes["POSITION"].get<std::size_t>()];
  draco::Mesh mesh;
  mesh.set_num_points(std::uint32_t(positions.count));
  std::vector<double> indices;
  if (primitive.contains("indices")) {
    indices = stored_values(model, primitive["indices"].get<int>());
  } else {
    for (std::size_t i = 0; i < positions.count; ++i) indices.push_back(double(i));
  }
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
    mesh.AddFace({draco::PointIndex(std::uint32_t(indices[t])), draco::PointIndex(std::uint32_t(indices[t + 1])),
                  draco::PointIndex(std::uint32_t(indices[t + 2]))});
  Json ids = Json::object();
  for (const auto& [name, index] : attributes.items()) ids[name] = add_draco_attribute(mesh, model, index.get<int>(), name);
  draco::Encoder encoder;
  encoder.SetEncodingMethod(draco::MESH_EDGEBREAKER_ENCODING);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, position_bits);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &buffer);
  if (!status.ok()) throw std::runtime_error("Draco could not encode a primitive: " + status.error_msg_string());
  return {std::move(buffer), std::move(ids)};
}

// ---- meshopt --------------------------------------------------------------------------------

/// Appends `count` elements of `stride` bytes as a meshopt-compressed view; gives its index.
struct Meshopt_writer {
  gltf::Gltf_document& document;
  std::size_t fallback_bytes = 0;

  std::size_t view(const std::vector<unsigned char>& data, std::size_t count, std::size_t stride, const char* mode,
                   const char* filter, bool vertex_attribute) {
    std::vector<unsigned char> encoded;
    if (std::string(mode) == "ATTRIBUTES") {
      encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
      encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), data.data(), count, stride));
    } else {
      std::vector<unsigned> indices(count);
      std::memcpy(indices.data(), data.data(), count * 4);
      encoded.resize(meshopt_encodeIndexBufferBound(count, *std::max_element(indices.begin(), indices.end()) + 1));
      encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), count));
    }
    const std::size_t at = gltf::append_aligned(document.buffers[0], encoded);
    fallback_bytes = (fallback_bytes + 3) / 4 * 4;
    Json v = {{"buffer", 1}, {"byteOffset", fallback_bytes}, {"byteLength", count * stride},
              {"extensions",
               {{"EXT_meshopt_compression",
                 {{"buffer", 0}, {"byteOffset", at}, {"byteLength", encoded.size()}, {"byteStride", stride},
                  {"count", count}, {"mode", mode}, {"filter", filter}}}}}};
    if (vertex_attribute) v["byteStride"] = stride;
    fallback_bytes += count * stride;
    document.json["bufferViews"].push_back(std::move(v));
    return document.json["bufferViews"].size() - 1;
  }
};

inline std::vector<float> float_values(const tinygltf::Model& model, int index, std::size_t padded_components) {
  const auto values = gltf::read_accessor(model, index, "test");
  std::vector<float> out(values.count * padded_components, 0.0f);
  for (std::size_t i = 0; i < values.count; ++i)
    for (std::size_t c = 0; c < values.components; ++c) out[i * padded_components + c] = float(values.element(i)[c]);
  return out;
}

/// The raw bytes of an accessor's elements, each padded to a multiple of 4 bytes.
inline std::pair<std::vector<unsigned char>, std::size_t> padded_elements(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
  const std::size_t size = gltf::components_of_type(accessor.type) * gltf::component_size(accessor.componentType);
  const std::size_t stride = (size + 3) / 4 * 4;
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
  const std::size_t from_stride = view.byteStride != 0 ? view.byteStride : size;
  const unsigned char* base = model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + accessor.byteOffset;
  std::vector<unsigned char> out(accessor.count * stride, 0);
  for (std::size_t i = 0; i < accessor.count; ++i) std::memcpy(out.data() + i * stride, base + i * from_stride, size);
  return {std::move(out), stride};
}

/// Whether `meshopt_accessor` copies accessor `index` byte for byte (no filter for its role).
inline bool padded_raw(const tinygltf::Model& model, std::size_t index, const std::string& role) {
  const bool is_float = model.accessors[index].componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  const bool filtered = is_float && (role == "POSITION" || role == "translation" || role == "scale" ||
                                     role == "NORMAL" || role == "rotation");
  return role != "indices" && !filtered;
}

/// Compresses accessor `index` in place (its data moved to a compressed view) with the filter its
/// role calls for.
inline void meshopt_accessor(Meshopt_writer& writer, const tinygltf::Model& model, std::size_t index,
                             const std::string& role) {
  Json& json = writer.document.json;
  Json& accessor = json["accessors"][index];
  if (accessor.contains("sparse") && padded_raw(model, index, role))
    throw std::runtime_error("a sparse accessor without a filter is not compressed here");
  accessor.erase("byteOffset");
  accessor.erase("sparse");  // the values written are those after the sparse substitution
  const std::size_t count = model.accessors[index].count;
  const bool is_float = model.accessors[index].componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  std::vector<unsigned char> data;
  if (role == "indices") {
    const std::vector<double> values = stored_values(model, int(index));
    std::vector<unsigned> indices(values.begin(), values.end());
    data.resize(count * 4);
    std::memcpy(data.data(), indices.data(), data.size());
    accessor["componentType"] = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor["bufferView"] = writer.view(data, count, 4, "TRIANGLES", "NONE", false);
  } else if (is_float && (role == "POSITION" || role == "translation" || role == "scale")) {
    data.resize(count * 12);
    meshopt_encodeFilterExp(data.data(), count, 12, 18, float_values(model, int(index), 3).data());
    accessor["bufferView"] = writer.view(data, count, 12, "ATTRIBUTES", "EXPONENTIAL", role == "POSITION");
  } else if (is_float && role == "NORMAL") {
    std::vector<float> normals = float_values(model, int(index), 4);
    data.resize(count * 4);
    meshopt_encodeFilterOct(data.data(), count, 4, 8, normals.data());
    accessor["componentType"] = TINYGLTF_COMPONENT_TYPE_BYTE;
    accessor["normalized"] = true;
    accessor["bufferView"] = writer.view(data, count, 4, "ATTRIBUTES", "OCTAHEDRAL", true);
  } else if (is_float && role == "rotation") {
    data.resize(count * 8);
    meshopt_encodeFilterQuat(data.data(), count, 8, 16, float_values(model, int(index), 4).data());
    accessor["componentType"] = TINYGLTF_COMPONENT_TYPE_SHORT;
    accessor["normalized"] = true;
    accessor["bufferView"] = writer.view(data, count, 8, "ATTRIBUTES", "QUATERNION", false);
  } else {
    auto [bytes, stride] = padded_elements(model, int(index));
    const bool vertex = role != "input" && role != "weights";
    accessor["bufferView"] = writer.view(bytes, count, stride, "ATTRIBUTES", "NONE", vertex);
  }
  if (role != "input" && role != "POSITION") {  // the bounds glTF asks for; others may not fit the new type
    accessor.erase("min");
    accessor.erase("max");
  }
}

}  // namespace compression_detail

/// Writes to `to` a copy of the .glb file `from` whose triangle primitives without morph targets
/// are compressed with Draco (KHR_draco_mesh_compression, required).
inline void write_draco_copy(const std::filesystem::path& from, const std::filesystem::path& to,
                             int position_bits = 14) {
  using namespace compression_detail;
  Source source = load_source(from);
  Json& json = source.document.json;
  for_each_compressible_primitive(json, [&](Json& primitive) {
    auto [encoded, ids] = draco_encoding(source.model, primitive, position_bits);
    const std::span<const unsigned char> bytes(reinterpret_cast<const unsigned char*>(encoded.data()), encoded.size());
    const std::size_t view = gltf::append_view(source.document, 0, bytes);
    if (primitive.contains("indices")) primitive["indices"] = accessor_copy(json, primitive["indices"].get<std::size_t>());
    for (auto& [name, index] : primitive["attributes"].items()) index = accessor_copy(json, index.get<std::size_t>());
    primitive["extensions"]["KHR_draco_mesh_compression"] = {{"bufferView", view}, {"attributes", ids}};
  });
  list_extension(json, "KHR_draco_mesh_compression");
  write_glb(source.document, to);
}

/// Writes to `to` a copy of the .glb file `from` whose triangle primitives without morph targets,
/// and every clip's keys, are in meshopt-compressed views (EXT_meshopt_compression and
/// KHR_mesh_quantization, required).
inline void write_meshopt_copy(const std::filesystem::path& from, const std::filesystem::path& to) {
  using namespace compression_detail;
  Source source = load_source(from);
  Json& json = source.document.json;
  Meshopt_writer writer{source.document};
  std::map<std::size_t, std::string> roles;  // each accessor compressed once, for its first role
  for_each_compressible_primitive(json, [&](Json& primitive) {
    if (primitive.contains("indices")) roles.emplace(primitive["indices"].get<std::size_t>(), "indices");
    for (const auto& [name, index] : primitive["attributes"].items()) roles.emplace(index.get<std::size_t>(), name);
  });
  for (const Json& animation : json["animations"])
    for (const Json& channel : animation["channels"]) {
      const Json& sampler = animation["samplers"][channel["sampler"].get<std::size_t>()];
      roles.emplace(sampler["input"].get<std::size_t>(), "input");
      if (sampler.value("interpolation", "LINEAR") != "CUBICSPLINE")  // tangents are not unit quaternions
        roles.emplace(sampler["output"].get<std::size_t>(), channel["target"]["path"].get<std::string>());
    }
  for (const auto& [index, role] : roles) meshopt_accessor(writer, source.model, index, role);
  json["buffers"].push_back({{"byteLength", writer.fallback_bytes},
                             {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  list_extension(json, "EXT_meshopt_compression");
  list_extension(json, "KHR_mesh_quantization");
  write_glb(source.document, to);
}

}  // namespace deformseg::test
