// An FBX node's local transform as a binary FBX file gives it (io/fbx_collada.h), for the nodes
// Assimp's transform would misplace: a small binary FBX record walker, bounds-checked, and the
// Models' Lcl Translation, Lcl Rotation (in their RotationOrder) and Lcl Scaling.
//
// Assimp 5.2's FBX reader leaves out of a node's transform a translation or rotation (in degrees)
// whose squared length, and a scaling whose squared distance to 1, is at most FLT_EPSILON (1.2e-7),
// as if they were noise. They are not when the node's parent is scaled up: Blender's export of a
// glTF robot whose armature is scaled by 100 (and by 100 again for its centimetre unit) loses the
// 4e-5-unit offsets of the shoulders' meshes from their bones, 4 mm once scaled. A binary FBX
// file's node records are simple to walk, so the local transforms are read from the file.
#pragma once

#include <deformseg/io/internal/assimp_scene.h>

#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace deformseg::io::internal::assimp::fbx {

/// A node record of a binary FBX file: its name, and where its properties and nested records lie.
struct Record {
  std::string_view name;
  std::size_t properties = 0;  // offset of its first property
  std::size_t property_count = 0;
  std::size_t children = 0;  // offset of its first nested record (past its properties)
  std::size_t end = 0;       // offset past it
};

/// A property of a record: a number (any of FBX's scalar types), or a string (S, R). Arrays are
/// skipped: none is needed here.
struct Property {
  char type = 0;
  double number = 0;
  std::int64_t integer = 0;  // an L's exact value: an object's id
  std::string_view text{};
};

/// Walks the records of a binary FBX file; every read is bounds-checked, and a malformed file
/// gives no record (`valid` false, or an empty list).
class Binary_file {
public:
  explicit Binary_file(std::string_view bytes) : bytes_(bytes) {
    constexpr std::string_view magic("Kaydara FBX Binary  \0", 21);
    if (bytes_.size() < 27 || !bytes_.starts_with(magic)) return;
    version_ = std::uint32_t(unsigned_at(23, 4));
    valid_ = true;
  }

  bool valid() const { return valid_; }

  /// The top-level records.
  std::vector<Record> top() const { return valid_ ? records(27, bytes_.size()) : std::vector<Record>{}; }

  /// The nested records of `record`.
  std::vector<Record> children(const Record& record) const { return records(record.children, record.end); }

  /// The records of name `name` among `records`.
  static std::vector<Record> named(const std::vector<Record>& records, std::string_view name) {
    std::vector<Record> result;
    std::copy_if(records.begin(), records.end(), std::back_inserter(result),
                 [&](const Record& r) { return r.name == name; });
    return result;
  }

  /// The properties of `record`; empty when one is malformed.
  std::vector<Property> properties(const Record& record) const {
    std::vector<Property> result;
    std::size_t at = record.properties;
    for (std::size_t k = 0; k < record.property_count; ++k) {
      if (at >= record.children) return {};
      Property property{.type = bytes_[at++]};
      const std::size_t size = value_size(property.type, at, record.children);
      if (size == npos || at + size > record.children) return {};
      read_value(property, at);
      result.push_back(property);
      at += size;
    }
    return result;
  }

private:
  static constexpr std::size_t npos = std::size_t(-1);

  std::uint64_t unsigned_at(std::size_t at, std::size_t size) const {
    std::uint64_t value = 0;
    for (std::size_t k = size; k-- > 0;) value = value << 8 | std::uint8_t(bytes_[at + k]);  // little-endian
    return value;
  }

  template <class T>
  T value_at(std::size_t at) const {
    T value;
    std::memcpy(&value, bytes_.data() + at, sizeof value);  // FBX is little-endian, as x86 and ARM are
    return value;
  }

  /// The records from `at` to the null record that ends a list, or to `limit`.
  std::vector<Record> records(std::size_t at, std::size_t limit) const {
    const std::size_t field = version_ >= 7500 ? 8 : 4;  // FBX 7.5 widened the header's fields
    const std::size_t header = 3 * field + 1;
    std::vector<Record> result;
    while (at + header <= limit) {
      const std::uint64_t end = unsigned_at(at, field);
      if (end == 0) break;  // the null record
      const std::uint64_t count = unsigned_at(at + field, field), length = unsigned_at(at + 2 * field, field);
      const std::size_t name_length = std::uint8_t(bytes_[at + 3 * field]);
      const std::size_t properties = at + header + name_length;
      if (end <= at || end > limit || properties > end || length > end - properties) return {};
      result.push_back({.name = bytes_.substr(at + header, name_length),
                        .properties = properties,
                        .property_count = std::size_t(count),
                        .children = properties + std::size_t(length),
                        .end = std::size_t(end)});
      at = std::size_t(end);
    }
    return result;
  }

  /// The size of a value of `type` at `at` (past the type code), or npos for an unknown type.
  std::size_t value_size(char type, std::size_t at, std::size_t limit) const {
    switch (type) {
      case 'C': return 1;
      case 'Y': return 2;
      case 'I': case 'F': return 4;
      case 'D': case 'L': return 8;
      case 'S': case 'R': return at + 4 <= limit ? 4 + std::size_t(unsigned_at(at, 4)) : npos;
      case 'f': case 'd': case 'l': case 'i': case 'b':  // length, encoding, stored bytes, data
        return at + 12 <= limit ? 12 + std::size_t(unsigned_at(at + 8, 4)) : npos;
      default: return npos;
    }
  }

  void read_value(Property& property, std::size_t at) const {
    switch (property.type) {
      case 'C': property.number = double(std::uint8_t(bytes_[at])); break;
      case 'Y': property.number = value_at<std::int16_t>(at); break;
      case 'I': property.number = value_at<std::int32_t>(at); break;
      case 'F': property.number = value_at<float>(at); break;
      case 'D': property.number = value_at<double>(at); break;
      case 'L': property.integer = value_at<std::int64_t>(at), property.number = double(property.integer); break;
      case 'S': case 'R': property.text = bytes_.substr(at + 4, std::size_t(unsigned_at(at, 4))); break;
      default: break;
    }
  }

  std::string_view bytes_;
  std::uint32_t version_ = 0;
  bool valid_ = false;
};

/// The properties of an FBX node (a Model) that place it, by name ("Lcl Translation"...): three
/// numbers each, one for "RotationOrder".
using Node_properties = std::map<std::string, std::vector<double>, std::less<>>;

/// Reads a Properties70 record's P records into `properties`: each P gives a name, a type, a
/// label, flags, then its values.
inline void read_properties(const Binary_file& file, const Record& properties70, Node_properties& properties) {
  for (const Record& p : Binary_file::named(file.children(properties70), "P")) {
    const std::vector<Property> values = file.properties(p);
    if (values.size() < 5 || values[0].type != 'S') continue;
    std::vector<double>& numbers = properties[std::string(values[0].text)];
    numbers.clear();
    for (std::size_t k = 4; k < values.size(); ++k) numbers.push_back(values[k].number);
  }
}

/// The defaults of a Model's properties: the Definitions' template of "Model" objects, which a
/// Model's own Properties70 overrides.
inline Node_properties model_template(const Binary_file& file, const std::vector<Record>& top) {
  Node_properties properties;
  for (const Record& definitions : Binary_file::named(top, "Definitions"))
    for (const Record& type : Binary_file::named(file.children(definitions), "ObjectType")) {
      const std::vector<Property> name = file.properties(type);
      if (name.empty() || name[0].text != "Model") continue;
      for (const Record& property_template : Binary_file::named(file.children(type), "PropertyTemplate"))
        for (const Record& p70 : Binary_file::named(file.children(property_template), "Properties70"))
          read_properties(file, p70, properties);
    }
  return properties;
}

/// An FBX Model: its name (Assimp's node name) and its placing properties.
struct Model {
  std::string name;
  Node_properties properties;
};

/// The Models of a binary FBX file and their tree: each Model's children in the order of their
/// connections, as Assimp makes its nodes (id 0 is the scene's root).
struct Model_tree {
  std::unordered_map<std::int64_t, Model> models;
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> children;
};

/// The Models of `file`: a Model record's properties are its id, "NAME\0\1Model" and its type.
inline Model_tree model_tree(const Binary_file& file) {
  Model_tree tree;
  const std::vector<Record> top = file.top();
  const Node_properties defaults = model_template(file, top);
  for (const Record& objects : Binary_file::named(top, "Objects"))
    for (const Record& record : Binary_file::named(file.children(objects), "Model")) {
      const std::vector<Property> id = file.properties(record);
      if (id.size() < 2 || id[0].type != 'L' || id[1].type != 'S') continue;
      Model model{.name = std::string(id[1].text.substr(0, id[1].text.find(std::string_view("\0\1", 2)))),
                  .properties = defaults};
      for (const Record& p70 : Binary_file::named(file.children(record), "Properties70"))
        read_properties(file, p70, model.properties);
      tree.models.emplace(id[0].integer, std::move(model));
    }
  for (const Record& connections : Binary_file::named(top, "Connections"))
    for (const Record& c : Binary_file::named(file.children(connections), "C")) {
      const std::vector<Property> link = file.properties(c);  // "OO", child, parent (OP links a property)
      if (link.size() == 3 && link[0].text == "OO" && tree.models.contains(link[1].integer))
        tree.children[link[2].integer].push_back(link[1].integer);
    }
  return tree;
}

/// The property `name` of a Model, or `fallback` when it is absent or not as many numbers.
inline std::vector<double> property(const Node_properties& properties, std::string_view name,
                                    std::vector<double> fallback) {
  const auto found = properties.find(name);
  return found != properties.end() && found->second.size() == fallback.size() ? found->second : fallback;
}

/// The rotation of Euler angles `degrees` about x, y, z, turned in FBX's order `order`
/// (0 XYZ: x first, ..., 5 ZYX).
inline Matrix euler_rotation(const std::vector<double>& degrees, int order) {
  static constexpr std::array<std::array<int, 3>, 6> axes{
      {{0, 1, 2}, {0, 2, 1}, {1, 2, 0}, {1, 0, 2}, {2, 0, 1}, {2, 1, 0}}};
  Matrix result;
  for (const int axis : axes[std::size_t(order)]) {  // each later turn is applied after: on the left
    const double angle = degrees[std::size_t(axis)] * (std::acos(-1.0) / 180);
    Matrix turn;
    if (axis == 0) Matrix::RotationX(angle, turn);
    if (axis == 1) Matrix::RotationY(angle, turn);
    if (axis == 2) Matrix::RotationZ(angle, turn);
    result = turn * result;
  }
  return result;
}

/// The local transform of a Model placed by its translation, rotation and scaling alone (T x R x
/// S, as Assimp composes them), or none when any other part of FBX's transform is set (pivots,
/// offsets, pre- and post-rotations, geometric transforms: Assimp's matrix is kept) or when its
/// rotation order is not an Euler order.
inline std::optional<Matrix> simple_transform(const Node_properties& properties) {
  static constexpr std::array<std::string_view, 7> zero_parts{"RotationOffset", "RotationPivot", "ScalingOffset",
                                                              "ScalingPivot",   "PreRotation",   "PostRotation",
                                                              "GeometricTranslation"};
  for (const std::string_view part : zero_parts)
    if (property(properties, part, {0, 0, 0}) != std::vector<double>{0, 0, 0}) return std::nullopt;
  if (property(properties, "GeometricRotation", {0, 0, 0}) != std::vector<double>{0, 0, 0} ||
      property(properties, "GeometricScaling", {1, 1, 1}) != std::vector<double>{1, 1, 1})
    return std::nullopt;
  const double order = property(properties, "RotationOrder", {0})[0];
  if (!(order >= 0 && order <= 5 && order == std::floor(order))) return std::nullopt;
  const std::vector<double> t = property(properties, "Lcl Translation", {0, 0, 0});
  const std::vector<double> s = property(properties, "Lcl Scaling", {1, 1, 1});
  Matrix translation, scaling;
  const Matrix result = Matrix::Translation({t[0], t[1], t[2]}, translation) *
                        euler_rotation(property(properties, "Lcl Rotation", {0, 0, 0}), int(order)) *
                        Matrix::Scaling({s[0], s[1], s[2]}, scaling);
  return finite(result) ? std::optional(result) : std::nullopt;
}

/// Pairs the nodes under `node` with the Models under `id`, child by child, recording the simple
/// transforms of the Models in `result`. Returns false when the two trees differ (a child count
/// or a name).
inline bool pair_nodes(const aiNode& node, std::int64_t id, const Model_tree& tree, std::size_t depth,
                       Local_transforms& result) {
  constexpr std::size_t max_depth = 10'000;  // as write_nodes: bounds the work on a malformed tree
  const auto found = tree.children.find(id);
  const std::size_t count = found == tree.children.end() ? 0 : found->second.size();
  if (depth > max_depth || count != node.mNumChildren || (count > 0 && !node.mChildren)) return false;
  for (std::size_t c = 0; c < count; ++c) {
    const aiNode* child = node.mChildren[c];
    const Model& model = tree.models.at(found->second[c]);
    if (!child || name_of(child->mName) != model.name) return false;
    if (const std::optional<Matrix> transform = simple_transform(model.properties)) result[child] = *transform;
    if (!pair_nodes(*child, found->second[c], tree, depth + 1, result)) return false;
  }
  return true;
}

/// The local transforms of the nodes of `scene`, read from its binary FBX file `bytes`, for the
/// nodes placed by a translation, rotation and scaling alone (see the top of this section). None
/// when the file is not binary FBX (ASCII FBX keeps Assimp's transforms), or when its Models and
/// Assimp's nodes do not pair (Assimp made pivot nodes, or left a Model out).
inline Local_transforms local_transforms(const std::string& bytes, const aiScene& scene) {
  const Binary_file file(bytes);
  if (!file.valid() || !scene.mRootNode) return {};
  Local_transforms result;
  return pair_nodes(*scene.mRootNode, 0, model_tree(file), 0, result) ? result : Local_transforms{};
}

}  // namespace deformseg::io::internal::assimp::fbx
