// Writes arrays into a tinygltf::Model held in memory: one buffer, a buffer view and an accessor
// per array, as a glTF file would store them, so that the glTF reader reads them unchanged.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

namespace deformseg::io::internal::assimp {

/// Appends arrays to `model`'s one buffer, each under an accessor of its own.
class Model_writer {
public:
  explicit Model_writer(tinygltf::Model& model) : model_(model) {
    if (model_.buffers.empty()) model_.buffers.emplace_back();
  }

  /// An accessor of `values.size() / components` elements of `type` (TINYGLTF_TYPE_SCALAR,
  /// _VEC3, _VEC4, _MAT4), stored as float, std::uint16_t or std::uint32_t.
  template <class T>
  int accessor(std::span<const T> values, int type, int components) {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, std::uint16_t> || std::is_same_v<T, std::uint32_t>);
    std::vector<unsigned char>& data = model_.buffers.front().data;
    while (data.size() % 4 != 0) data.push_back(0);  // glTF aligns accessors to their component size
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size_bytes();
    data.resize(data.size() + values.size_bytes());
    if (!values.empty()) std::memcpy(data.data() + view.byteOffset, values.data(), values.size_bytes());
    model_.bufferViews.push_back(view);

    tinygltf::Accessor accessor;
    accessor.bufferView = int(model_.bufferViews.size() - 1);
    accessor.componentType = std::is_same_v<T, float>           ? TINYGLTF_COMPONENT_TYPE_FLOAT
                             : std::is_same_v<T, std::uint16_t> ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                                                : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.type = type;
    accessor.count = values.size() / std::size_t(components);
    model_.accessors.push_back(accessor);
    return int(model_.accessors.size() - 1);
  }

private:
  tinygltf::Model& model_;
};

}  // namespace deformseg::io::internal::assimp
