// glTF accessors read into doubles: every component type, normalised integers, byteStride, sparse
// substitution, and every offset checked against its buffer before anything is allocated or read.
// Errors are invalid_input without a file; io/gltf.h adds the file.
#pragma once

#include <deformseg/exceptions.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace deformseg::io::internal::gltf {

/// The values of an accessor: `count` elements of `components` doubles each, element-major.
struct Accessor_values {
  std::vector<double> values{};
  std::size_t count = 0;
  std::size_t components = 0;

  const double* element(std::size_t i) const { return values.data() + i * components; }
};

/// An accessor without a buffer view (all zeros, maybe sparse) has no buffer to bound its count:
/// it may hold at most this many elements, and no more than the file's buffers have bytes (see
/// `elements_without_buffer_limit`).
inline constexpr std::size_t max_elements_without_buffer = std::size_t(1) << 24;

/// The bytes of all the file's buffers.
inline std::size_t buffer_bytes(const tinygltf::Model& model) {
  std::size_t bytes = 0;
  for (const tinygltf::Buffer& buffer : model.buffers) bytes += buffer.data.size();
  return bytes;
}

/// The most elements an accessor without a buffer view may have: one per byte of the file's
/// buffers, at most `max_elements_without_buffer`. Every other accessor holds at least a byte per
/// element, so this keeps the reader's work in proportion to the file: a few bytes of JSON that
/// ask for millions of zero vertices (which the reader would then weld and sample) are refused.
inline std::size_t elements_without_buffer_limit(const tinygltf::Model& model) {
  return std::min(max_elements_without_buffer, buffer_bytes(model));
}

inline std::string accessor_name(const tinygltf::Model& model, int index) {
  std::string s = "accessor " + std::to_string(index);
  if (index >= 0 && std::size_t(index) < model.accessors.size() && !model.accessors[std::size_t(index)].name.empty())
    s += " '" + model.accessors[std::size_t(index)].name + "'";
  return s;
}

inline std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // INT and DOUBLE are not glTF 2.0 accessor types
  }
}

inline std::size_t components_of_type(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;  // MAT2 and MAT3 (column padding) are never geometry or animation data here
  }
}

/// One component at `p`, converted to double; normalised integers map to [0, 1] or [-1, 1] as the
/// specification says (signed: max(c / (2^(n-1) - 1), -1)).
inline double read_component(const unsigned char* p, int component_type, bool normalized) {
  const auto load = [p]<class T>(T) {
    T value;
    std::memcpy(&value, p, sizeof value);
    return value;
  };
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double c = load(std::int8_t{});
      return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double c = load(std::uint8_t{});
      return normalized ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double c = load(std::int16_t{});
      return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const double c = load(std::uint16_t{});
      return normalized ? c / 65535.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      const double c = load(std::uint32_t{});
      return normalized ? c / 4294967295.0 : c;
    }
    default: return double(load(float{}));
  }
}

/// The bytes of buffer view `index`, checked to lie inside their buffer.
struct View_bytes {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t stride = 0;  // 0: tightly packed
};

inline View_bytes view_bytes(const tinygltf::Model& model, int index, const std::string& user) {
  if (index < 0 || std::size_t(index) >= model.bufferViews.size())
    throw invalid_input(user + " refers to buffer view " + std::to_string(index) + ", which does not exist");
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(index)];
  const std::string name = "buffer view " + std::to_string(index);
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
    throw invalid_input(name + " refers to buffer " + std::to_string(view.buffer) + ", which does not exist");
  const std::size_t buffer_size = model.buffers[std::size_t(view.buffer)].data.size();
  if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset)
    throw invalid_input(name + " (offset " + std::to_string(view.byteOffset) + ", length " +
                        std::to_string(view.byteLength) + ") lies outside its buffer of " +
                        std::to_string(buffer_size) + " bytes");
  if (view.byteStride != 0 && (view.byteStride < 4 || view.byteStride > 252 || view.byteStride % 4 != 0))
    throw invalid_input(name + " has byteStride " + std::to_string(view.byteStride) +
                        "; glTF allows 4 to 252, a multiple of 4");
  return {model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset, view.byteLength,
          view.byteStride};
}

/// Checks that `count` elements of `element_size` bytes, `stride` apart, from `offset` fit in
/// `size` bytes.
inline void check_fits(std::size_t offset, std::size_t count, std::size_t stride, std::size_t element_size,
                       std::size_t size, const std::string& what) {
  const bool fits = offset <= size && (count == 0 || ((count - 1) <= (size - offset) / stride &&
                                                      (count - 1) * stride + element_size <= size - offset));
  if (!fits)
    throw invalid_input(what + ": " + std::to_string(count) + " elements of " + std::to_string(element_size) +
                        " bytes from offset " + std::to_string(offset) + " do not fit in the " +
                        std::to_string(size) + " bytes of its buffer view");
}

/// Reads `count` elements of `components` components into `out` (already sized).
inline void read_elements(const unsigned char* base, std::size_t count, std::size_t components,
                          std::size_t stride, int component_type, bool normalized, double* out) {
  const std::size_t size = component_size(component_type);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < components; ++k)
      out[i * components + k] = read_component(base + i * stride + k * size, component_type, normalized);
}

inline void apply_sparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor, const std::string& name,
                         Accessor_values& result) {
  const auto& sparse = accessor.sparse;
  if (sparse.count < 1 || std::size_t(sparse.count) > result.count)
    throw invalid_input(name + " has a sparse count of " + std::to_string(sparse.count) + " for " +
                        std::to_string(result.count) + " elements");
  const std::size_t n = std::size_t(sparse.count);
  const int index_type = sparse.indices.componentType;
  if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw invalid_input(name + " has sparse indices of component type " + std::to_string(index_type) +
                        "; glTF allows unsigned byte, short or int");
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
    throw invalid_input(name + " has a negative sparse byteOffset");
  const View_bytes indices = view_bytes(model, sparse.indices.bufferView, name + " (sparse indices)");
  const View_bytes values = view_bytes(model, sparse.values.bufferView, name + " (sparse values)");
  const std::size_t index_size = component_size(index_type);
  const std::size_t value_size = component_size(accessor.componentType) * result.components;
  check_fits(std::size_t(sparse.indices.byteOffset), n, index_size, index_size, indices.size, name + " sparse indices");
  check_fits(std::size_t(sparse.values.byteOffset), n, value_size, value_size, values.size, name + " sparse values");
  std::vector<double> substitutes(n * result.components);
  read_elements(values.data + sparse.values.byteOffset, n, result.components, value_size, accessor.componentType,
                accessor.normalized, substitutes.data());
  for (std::size_t s = 0; s < n; ++s) {
    const double index = read_component(indices.data + sparse.indices.byteOffset + s * index_size, index_type, false);
    if (index >= double(result.count))
      throw invalid_input(name + " has sparse index " + std::to_string(std::size_t(index)) + " out of its " +
                          std::to_string(result.count) + " elements");
    std::copy_n(substitutes.begin() + std::ptrdiff_t(s * result.components), result.components,
                result.values.begin() + std::ptrdiff_t(std::size_t(index) * result.components));
  }
}

/// Reads accessor `index` as doubles. `user` says who refers to it, for the messages.
/// @throws invalid_input when the accessor does not exist, has a type glTF does not allow, or any
/// of its data lies outside its buffer view or buffer.
inline Accessor_values read_accessor(const tinygltf::Model& model, int index, const std::string& user) {
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    throw invalid_input(user + " refers to accessor " + std::to_string(index) + ", which does not exist");
  const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
  const std::string name = accessor_name(model, index) + " (" + user + ")";
  const std::size_t size = component_size(accessor.componentType);
  const std::size_t components = components_of_type(accessor.type);
  if (size == 0 || components == 0)
    throw invalid_input(name + " has component type " + std::to_string(accessor.componentType) + " and type " +
                        std::to_string(accessor.type) + ", which deformseg does not read");
  if (accessor.normalized && accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
    throw invalid_input(name + " is normalized floats; glTF normalizes integers only");
  Accessor_values result;
  result.count = accessor.count;
  result.components = components;
  if (accessor.bufferView >= 0) {
    const View_bytes view = view_bytes(model, accessor.bufferView, name);
    const std::size_t element_size = size * components;
    const std::size_t stride = view.stride != 0 ? view.stride : element_size;
    if (stride < element_size)
      throw invalid_input(name + ": byteStride " + std::to_string(stride) + " is smaller than its elements of " +
                          std::to_string(element_size) + " bytes");
    if (accessor.byteOffset % size != 0)
      throw invalid_input(name + ": byteOffset " + std::to_string(accessor.byteOffset) +
                          " is not a multiple of its component size");
    check_fits(accessor.byteOffset, accessor.count, stride, element_size, view.size, name);
    result.values.resize(accessor.count * components);
    read_elements(view.data + accessor.byteOffset, accessor.count, components, stride, accessor.componentType,
                  accessor.normalized, result.values.data());
  } else {
    if (accessor.count > elements_without_buffer_limit(model))
      throw invalid_input(name + " has no buffer view and " + std::to_string(accessor.count) +
                          " elements; deformseg reads at most one such element per byte of the file's buffers (" +
                          std::to_string(buffer_bytes(model)) + " bytes), and at most " +
                          std::to_string(max_elements_without_buffer));
    result.values.assign(accessor.count * components, 0.0);
  }
  if (accessor.sparse.isSparse) apply_sparse(model, accessor, name, result);
  return result;
}

/// Reads an accessor that must have `components` components per element.
inline Accessor_values read_accessor(const tinygltf::Model& model, int index, const std::string& user,
                                     std::size_t components) {
  Accessor_values values = read_accessor(model, index, user);
  if (values.components != components)
    throw invalid_input(accessor_name(model, index) + " (" + user + ") has " + std::to_string(values.components) +
                        " components per element, expected " + std::to_string(components));
  return values;
}

}  // namespace deformseg::io::internal::gltf
