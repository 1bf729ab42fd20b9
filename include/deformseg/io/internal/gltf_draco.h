// Primitives compressed with KHR_draco_mesh_compression, decoded with Debian's libdraco: the
// triangles become a 32-bit index accessor, each compressed attribute its accessor's own type
// (quantised positions come back dequantised, integers as they were), in a buffer of their own.
// Draco may reorder and split vertices: the accessors take the decoded count, and the primitive's
// attributes all come from the one decoded mesh, so they stay consistent.
#pragma once

#include <deformseg/io/internal/gltf_document.h>

#include <draco/compression/decode.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace deformseg::io::internal::gltf {

inline constexpr const char* draco_extension = "KHR_draco_mesh_compression";

/// The most faces, vertices or split symbols a Draco header may claim: libdraco allocates for the
/// counts it reads before it decodes them, whatever the data's size.
inline constexpr std::uint64_t max_draco_elements = std::uint64_t(1) << 24;

/// The counts a Draco mesh header claims, read as libdraco reads bitstream 2.2.
class Draco_header_reader {
public:
  explicit Draco_header_reader(std::span<const unsigned char> bytes) : bytes_(bytes) {}

  std::optional<std::uint64_t> byte() {
    if (at_ >= bytes_.size()) return std::nullopt;
    return bytes_[at_++];
  }

  /// A LEB128 varint of at most 5 bytes (libdraco's 32-bit counts).
  std::optional<std::uint64_t> varint() {
    std::uint64_t value = 0;
    for (int shift = 0; shift < 35; shift += 7) {
      const auto b = byte();
      if (!b) return std::nullopt;
      value |= (*b & 0x7f) << shift;
      if ((*b & 0x80) == 0) return value;
    }
    return std::nullopt;
  }

  void skip(std::size_t n) { at_ += n; }

private:
  std::span<const unsigned char> bytes_;
  std::size_t at_ = 0;
};

/// Refuses Draco data that are not a mesh in the bitstream KHR_draco_mesh_compression names (2.2),
/// that carry metadata (whose size is not known before it is parsed), or whose header claims more
/// than `max_draco_elements` faces or vertices.
inline void check_draco_header(std::span<const unsigned char> bytes, const std::string& where) {
  const auto refuse = [&](const std::string& why) { throw invalid_input(where + ": " + why); };
  if (bytes.size() < 11 || std::memcmp(bytes.data(), "DRACO", 5) != 0) refuse("the data are not Draco's");
  if (bytes[5] != 2 || bytes[6] != 2)
    refuse("Draco bitstream " + std::to_string(bytes[5]) + "." + std::to_string(bytes[6]) +
           ", not the 2.2 that KHR_draco_mesh_compression names");
  if (bytes[7] != 1) refuse("the Draco data are not a triangle mesh");
  const unsigned method = bytes[8];
  if (method > 1) refuse("unknown Draco encoding method " + std::to_string(method));
  if ((bytes[9] | bytes[10] << 8) & 0x8000) refuse("Draco metadata are not read");
  Draco_header_reader header(bytes.subspan(11));
  std::vector<std::optional<std::uint64_t>> counts;
  if (method == 0) {  // sequential: faces, points
    counts = {header.varint(), header.varint()};
  } else {  // edgebreaker: traversal, vertices, faces, attribute data, symbols, split symbols
    header.skip(1);
    counts = {header.varint(), header.varint()};
    header.skip(1);
    counts.push_back(header.varint());
    counts.push_back(header.varint());
  }
  for (const auto& count : counts)
    if (!count || *count > max_draco_elements)
      refuse("the Draco header claims more than " + std::to_string(max_draco_elements) +
             " faces or vertices, or ends early");
}

/// The decoded mesh of a Draco-compressed primitive's buffer view.
inline std::unique_ptr<draco::Mesh> decoded_draco_mesh(const Gltf_document& document, std::size_t view_index,
                                                       const std::string& where) {
  const auto& views = document.json.at("bufferViews");
  if (!views.is_array() || view_index >= views.size())
    throw invalid_input(where + ".bufferView is " + std::to_string(view_index) + ", not a buffer view");
  const Json& view = views[view_index];
  const std::string view_where = "bufferViews[" + std::to_string(view_index) + "]";
  if (!view.is_object()) throw invalid_input(view_where + " must be an object");
  const auto bytes = buffer_range(document, whole_number(view, "buffer", view_where),
                                  whole_number(view, "byteOffset", view_where, 0),
                                  whole_number(view, "byteLength", view_where), view_where);
  check_draco_header(bytes, where);
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) throw invalid_input(where + ": the Draco data do not decode: " + decoded.status().error_msg_string());
  return std::move(decoded).value();
}

/// Component `c` of stored value `value` of `attribute`, as a double. Read from the attribute's
/// bytes rather than with its ConvertValue, which loads the decoded "normalized" byte as a bool
/// whatever its value (undefined behaviour that a damaged file reaches).
inline double draco_component(const draco::PointAttribute& attribute, draco::AttributeValueIndex value, std::size_t c) {
  const unsigned char* at = attribute.GetAddress(value) + c * draco::DataTypeLength(attribute.data_type());
  const auto load = [at]<typename T>(T) {
    T x;
    std::memcpy(&x, at, sizeof x);
    return double(x);
  };
  switch (attribute.data_type()) {
    case draco::DT_INT8: return load(std::int8_t());
    case draco::DT_UINT8: return load(std::uint8_t());
    case draco::DT_INT16: return load(std::int16_t());
    case draco::DT_UINT16: return load(std::uint16_t());
    case draco::DT_INT32: return load(std::int32_t());
    case draco::DT_UINT32: return load(std::uint32_t());
    case draco::DT_INT64: return load(std::int64_t());
    case draco::DT_UINT64: return load(std::uint64_t());
    case draco::DT_FLOAT32: return load(float());
    case draco::DT_FLOAT64: return load(double());
    case draco::DT_BOOL: return load(std::uint8_t()) != 0 ? 1 : 0;
    default: return 0;
  }
}

/// `x` as a component of type `T`: rounded and clamped into an integer type's range, NaN as 0.
template <typename T>
T component_as(double x) {
  if constexpr (std::is_floating_point_v<T>) {
    return T(x);
  } else {
    if (!(x == x)) return 0;
    return T(std::clamp(std::round(x), double(std::numeric_limits<T>::lowest()), double(std::numeric_limits<T>::max())));
  }
}

/// The values of `attribute` for every point of `mesh`, as `components` values of type `T` each
/// (missing components zero).
template <typename T>
Bytes draco_values(const draco::Mesh& mesh, const draco::PointAttribute& attribute, std::size_t components,
                   const std::string& where) {
  const std::size_t stored = attribute.num_components();
  if (draco::DataTypeLength(attribute.data_type()) == 0 || stored == 0)
    throw invalid_input(where + ": the Draco attribute has no data type glTF knows");
  const auto stride = std::size_t(attribute.byte_stride());
  if (stride < stored * std::size_t(draco::DataTypeLength(attribute.data_type())) || attribute.buffer() == nullptr ||
      attribute.buffer()->data_size() < std::size_t(attribute.byte_offset()) + attribute.size() * stride)
    throw invalid_input(where + ": the Draco attribute's values do not fit its buffer");
  Bytes out(mesh.num_points() * components * sizeof(T));
  for (draco::PointIndex point(0); point < mesh.num_points(); ++point) {
    const draco::AttributeValueIndex value = attribute.mapped_index(point);
    if (value.value() >= attribute.size())
      throw invalid_input(where + ": point " + std::to_string(point.value()) + " maps to a value the attribute lacks");
    for (std::size_t c = 0; c < components; ++c) {
      const T x = c < stored ? component_as<T>(draco_component(attribute, value, c)) : T(0);
      std::memcpy(out.data() + (point.value() * components + c) * sizeof(T), &x, sizeof(T));
    }
  }
  return out;
}

/// The values of `attribute` in the type of accessor `accessor` (its componentType and type).
inline Bytes draco_accessor_values(const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                                   const Json& accessor, const std::string& where) {
  const int type = accessor.value("componentType", 0);
  const std::string shape = accessor.value("type", std::string());
  const std::size_t components = shape == "SCALAR" ? 1 : shape == "VEC2" ? 2 : shape == "VEC3" ? 3 : shape == "VEC4" ? 4 : 0;
  if (components == 0) throw invalid_input(where + ": the accessor's type must be SCALAR or VEC2 to VEC4");
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return draco_values<std::int8_t>(mesh, attribute, components, where);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return draco_values<std::uint8_t>(mesh, attribute, components, where);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return draco_values<std::int16_t>(mesh, attribute, components, where);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return draco_values<std::uint16_t>(mesh, attribute, components, where);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return draco_values<std::uint32_t>(mesh, attribute, components, where);
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return draco_values<float>(mesh, attribute, components, where);
    default: throw invalid_input(where + ": the accessor's componentType " + std::to_string(type) + " is not glTF's");
  }
}

/// Points accessor `index` of `document` at a new view of `bytes`, holding `count` elements.
inline void replace_accessor_data(Gltf_document& document, std::size_t index, std::size_t buffer,
                                  std::span<const unsigned char> bytes, std::size_t count) {
  Json& accessor = document.json["accessors"][index];
  accessor["bufferView"] = append_view(document, buffer, bytes);
  accessor["count"] = count;
  accessor.erase("byteOffset");
  accessor.erase("sparse");
}

/// The index of accessor `key` of `object` (a primitive's "indices", or one of its attributes).
inline std::size_t accessor_index(const Gltf_document& document, const Json& object, const char* key,
                                  const std::string& where) {
  const std::size_t index = whole_number(object, key, where);
  const auto accessors = document.json.find("accessors");
  if (accessors == document.json.end() || !accessors->is_array() || index >= accessors->size() ||
      !(*accessors)[index].is_object())
    throw invalid_input(where + "." + key + " is " + std::to_string(index) + ", not an accessor");
  return index;
}

/// Decodes one Draco-compressed primitive into `buffer`.
inline void decode_draco_primitive(Gltf_document& document, Json& primitive, std::size_t buffer,
                                   Decoding_budget& budget, const std::string& where) {
  const Json& extension = *extension_object(primitive, draco_extension);
  const std::string ext_where = where + ".extensions." + draco_extension;
  if (!extension.is_object()) throw invalid_input(ext_where + " must be an object");
  const auto mesh = decoded_draco_mesh(document, whole_number(extension, "bufferView", ext_where), ext_where);
  const std::size_t points = mesh->num_points(), faces = mesh->num_faces();
  budget.spend(faces * 3 * sizeof(std::uint32_t), ext_where);
  std::vector<std::uint32_t> indices;
  indices.reserve(faces * 3);
  for (draco::FaceIndex f(0); f < faces; ++f)
    for (const draco::PointIndex& point : mesh->face(f)) indices.push_back(point.value());
  if (!primitive.contains("indices")) {
    document.json["accessors"].push_back({{"componentType", TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}, {"type", "SCALAR"}});
    primitive["indices"] = document.json["accessors"].size() - 1;
  }
  const std::size_t indices_accessor = accessor_index(document, primitive, "indices", where);
  document.json["accessors"][indices_accessor]["componentType"] = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  replace_accessor_data(document, indices_accessor, buffer,
                        {reinterpret_cast<const unsigned char*>(indices.data()), indices.size() * 4}, indices.size());
  const Json& attributes = object_at(extension, "attributes", ext_where);
  const Json& accessors_of = object_at(primitive, "attributes", where);
  for (const auto& [name, id] : attributes.items()) {
    const std::string attribute_where = ext_where + ".attributes." + name;
    if (!id.is_number_unsigned()) throw invalid_input(attribute_where + " must be a Draco attribute id");
    const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(id.get<std::uint32_t>());
    if (attribute == nullptr) throw invalid_input(attribute_where + ": the Draco data have no attribute " + id.dump());
    if (!accessors_of.contains(name)) throw invalid_input(attribute_where + ": the primitive has no attribute " + name);
    const std::size_t index = accessor_index(document, accessors_of, name.c_str(), where + ".attributes");
    const Json& accessor = document.json["accessors"][index];
    budget.spend(points * 16, attribute_where);  // the most a glTF attribute takes: 4 floats
    const Bytes bytes = draco_accessor_values(*mesh, *attribute, accessor, attribute_where);
    replace_accessor_data(document, index, buffer, bytes, points);
  }
  erase_extension(primitive, draco_extension);
}

/// Decodes every Draco-compressed primitive of `document` into a new buffer.
inline void decode_draco_primitives(Gltf_document& document, Decoding_budget& budget) {
  const auto meshes = document.json.find("meshes");
  if (meshes == document.json.end() || !meshes->is_array()) return;
  std::optional<std::size_t> decoded;
  for (std::size_t m = 0; m < meshes->size(); ++m) {
    Json& mesh = (*meshes)[m];
    if (!mesh.is_object()) continue;
    const auto primitives = mesh.find("primitives");
    if (primitives == mesh.end() || !primitives->is_array()) continue;
    for (std::size_t p = 0; p < primitives->size(); ++p) {
      Json& primitive = (*primitives)[p];
      if (!primitive.is_object() || extension_object(primitive, draco_extension) == nullptr) continue;
      if (!decoded) decoded = open_buffer(document);
      const std::string where = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
      decode_draco_primitive(document, primitive, *decoded, budget, where);
    }
  }
  if (decoded) close_buffer(document, *decoded);
}

}  // namespace deformseg::io::internal::gltf
