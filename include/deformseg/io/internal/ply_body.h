// The body of a PLY file (io/ply.h), text or binary, read value by value after its checked header
// (ply_header.h) into points and triangles.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/ply_header.h>
#include <deformseg/io/internal/text_scanner.h>
#include <deformseg/io/triangle_soup.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::io::internal {

/// A cursor over the body of a PLY: one value at a time, text or binary.
class Ply_body {
public:
  Ply_body(const Text_file& file, const Ply_header& header)
      : file_(file), scanner_(file), format_(header.format) {
    scanner_.advance(static_cast<std::size_t>(header.body - file.begin()));
  }

  /// The next value of `type`. Integers are always checked for their form and range; a float only
  /// when `checked` (one that is used): an unused one, a normal say, may be "nan".
  double value(Ply_type type, bool checked) {
    return format_ == Ply_format::ascii ? text_value(type, checked) : binary_value(type);
  }

  /// Fails, naming the item the file ends in.
  [[noreturn]] void fail_truncated() const {
    file_.fail(join("the file ends inside ", item_name(), " of the ", std::to_string(element_->count),
                    " the header announces"));
  }
  /// Fails, naming the item being read (and its line in a text file).
  [[noreturn]] void fail(const std::string& message) const {
    if (format_ == Ply_format::ascii) file_.fail_at(token_, join(item_name(), ": ", message));
    file_.fail(join(item_name(), ": ", message));
  }

  void start_item(const Ply_element& element, std::size_t index) noexcept {
    element_ = &element;
    index_ = index;
  }

private:
  std::string item_name() const { return join(element_->name, " ", std::to_string(index_)); }

  double text_value(Ply_type type, bool checked) {
    scanner_.skip_empty_lines();
    if (scanner_.at_end()) fail_truncated();
    token_ = scanner_.position();
    if (!checked && !is_ply_integer(type)) {
      scanner_.word();
      return 0;
    }
    if (!is_ply_integer(type)) return type == Ply_type::float32 ? scanner_.number<float>() : scanner_.number<double>();
    const auto value = static_cast<double>(scanner_.integer("an integer"));
    if (!ends_token(scanner_.peek())) fail(join("malformed integer ", Text_scanner::quoted_token_at(token_)));
    check_range(value, type);
    return value;
  }

  double binary_value(Ply_type type) {
    const std::size_t size = ply_type_size(type);
    if (static_cast<std::size_t>(file_.end() - scanner_.position()) < size) fail_truncated();
    const char* p = scanner_.position();
    scanner_.advance(size);
    return format_ == Ply_format::binary_little_endian ? decode<std::endian::little>(p, type)
                                                       : decode<std::endian::big>(p, type);
  }

  template <std::endian order>
  static double decode(const char* p, Ply_type type) noexcept {
    const std::size_t size = ply_type_size(type);
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < size; ++k)
      bits |= std::uint64_t(static_cast<unsigned char>(p[byte_position(order, k, size)])) << (8 * k);
    switch (type) {
      case Ply_type::int8: return static_cast<std::int8_t>(bits);
      case Ply_type::uint8: return static_cast<std::uint8_t>(bits);
      case Ply_type::int16: return static_cast<std::int16_t>(bits);
      case Ply_type::uint16: return static_cast<std::uint16_t>(bits);
      case Ply_type::int32: return static_cast<std::int32_t>(bits);
      case Ply_type::uint32: return static_cast<std::uint32_t>(bits);
      case Ply_type::float32: return std::bit_cast<float>(static_cast<std::uint32_t>(bits));
      case Ply_type::float64: return std::bit_cast<double>(bits);
    }
    return 0;
  }

  void check_range(double value, Ply_type type) const {
    const auto [low, high] = ply_integer_range(type);
    if (value < low || value > high)
      fail(join(Text_scanner::quoted_token_at(token_), " is out of the range of ",
                ply_type_names[static_cast<std::size_t>(type)][0]));
  }

  const Text_file& file_;
  Text_scanner scanner_;
  Ply_format format_;
  const Ply_element* element_ = nullptr;
  std::size_t index_ = 0;
  const char* token_ = nullptr;
};

/// Reads the elements of the body in order, keeping the coordinates and the faces.
class Ply_reader {
public:
  Ply_reader(const Text_file& file, const io::Mesh_read_options& options)
      : file_(file), header_(read_ply_header(file)), body_(file, header_), options_(options) {}

  io::Triangle_soup read() {
    for (std::size_t e = 0; e < header_.elements.size(); ++e)
      for (std::size_t i = 0; i < header_.elements[e].count; ++i) read_item(e, i);
    return std::move(soup_);
  }

private:
  void read_item(std::size_t e, std::size_t i) {
    const Ply_element& element = header_.elements[e];
    body_.start_item(element, i);
    const bool is_vertex = e == header_.vertex_element, is_face = e == header_.face_element;
    if (is_vertex && i == 0) soup_.points.reserve(3 * element.count);
    std::array<double, 3> xyz{};
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
      const Ply_property& property = element.properties[k];
      const auto axis = std::find(header_.xyz.begin(), header_.xyz.end(), k) - header_.xyz.begin();
      if (property.count_type) read_list(property, is_face && k == header_.face_list);
      else if (is_vertex && axis < 3) xyz[static_cast<std::size_t>(axis)] = body_.value(property.type, true);
      else body_.value(property.type, false);
    }
    if (is_vertex) add_vertex(xyz);
    if (is_face) add_face();
  }

  void read_list(const Ply_property& property, bool is_face_list) {
    const double count = body_.value(*property.count_type, true);
    if (count < 0) body_.fail(join("a list of ", shortest_text(count), " items"));
    if (is_face_list) corners_.clear();
    for (double n = 0; n < count; ++n) {
      const double index = body_.value(property.type, is_face_list);
      if (is_face_list) add_corner(index);
    }
  }

  void add_vertex(const std::array<double, 3>& xyz) {
    for (const double c : xyz)
      if (!std::isfinite(c))
        file_.fail(join("vertex ", std::to_string(soup_.num_vertices()), " has a non-finite coordinate"));
    soup_.points.insert(soup_.points.end(), xyz.begin(), xyz.end());
  }

  void add_corner(double index) {
    const std::size_t vertices = soup_.num_vertices();
    if (index < 0 || index >= static_cast<double>(vertices))
      file_.fail(join("face ", std::to_string(faces_read_), " has vertex index ", shortest_text(index),
                      " out of range [0, ", std::to_string(vertices), ")"));
    corners_.push_back(static_cast<std::uint32_t>(index));
  }

  void add_face() {
    if (const std::string problem = polygon_problem(corners_.size(), options_); !problem.empty())
      file_.fail(join("face ", std::to_string(faces_read_), ": ", problem));
    append_fan(corners_, soup_.triangles);
    ++faces_read_;
  }

  const Text_file& file_;
  Ply_header header_;
  Ply_body body_;
  io::Mesh_read_options options_;
  io::Triangle_soup soup_;
  std::vector<std::uint32_t> corners_;
  std::size_t faces_read_ = 0;
};

/// Fails unless `path` names a readable file that starts with PLY's magic word, so that the
/// common mistakes get a message of their own.
inline void check_ply_magic(const std::filesystem::path& path) {
  const File_bytes start = read_file_bytes(path, 4);
  const std::string_view magic(start.begin(), start.size);
  if (magic.size() != 4 || !magic.starts_with("ply") || !(magic[3] == '\n' || magic[3] == '\r'))
    throw invalid_input("not a PLY file: it does not start with the line \"ply\"", {.file = path.string()});
}

/// Reads a PLY file into points and triangles.
inline io::Triangle_soup read_ply_soup(const std::filesystem::path& path, const io::Mesh_read_options& options) {
  check_ply_magic(path);
  const Text_file file(path);
  return Ply_reader(file, options).read();
}

/// Reads only the vertex positions of a PLY file into `xyz` (3 V values). The file is read
/// whole, faces included: this is as slow as `read_ply`.
template <std::floating_point T>
void read_ply_points(const std::filesystem::path& path, std::span<T> xyz) {
  const io::Triangle_soup soup = read_ply_soup(path, {.triangulate = true});
  if (soup.points.size() != xyz.size())
    throw invalid_input(join("has ", std::to_string(soup.num_vertices()), " vertices instead of ",
                               std::to_string(xyz.size() / 3)),
                        {.file = path.string()});
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    xyz[i] = static_cast<T>(soup.points[i]);
    if (!std::isfinite(xyz[i]))  // a double beyond the range of float
      throw invalid_input(join("vertex ", std::to_string(i / 3), " has a coordinate out of the range of float"),
                          {.file = path.string()});
  }
}

}  // namespace deformseg::io::internal
