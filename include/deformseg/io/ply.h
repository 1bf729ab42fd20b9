/// @file io/ply.h
/// @brief Reads a PLY mesh (text or binary): `read_ply`.
#pragma once

#include <deformseg/color/color.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/mesh_writer.h>
#include <deformseg/io/internal/text_scanner.h>
#include <deformseg/io/triangle_soup.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

// deformseg reads PLY itself rather than with CGAL::IO::read_PLY, which trusts its input: a
// property before any element, a list count beyond the file, or an x of an integer type make it
// dereference null or allocate gigabytes (found by fuzzing, test/fuzz/regressions/ply). Here the
// header is parsed and checked whole (elements, properties, types, counts against the file's
// size) before anything is allocated, then the body is read with the text scanner or byte loads.

namespace deformseg::io::internal {

/// The scalar types of PLY, in the order of `ply_type_names`.
enum class Ply_type : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// Each type's names: the original one and the sized one.
inline constexpr std::array<std::array<std::string_view, 2>, 8> ply_type_names{
    {{"char", "int8"}, {"uchar", "uint8"}, {"short", "int16"}, {"ushort", "uint16"},
     {"int", "int32"}, {"uint", "uint32"}, {"float", "float32"}, {"double", "float64"}}};

constexpr std::size_t ply_type_size(Ply_type type) noexcept {
  constexpr std::array<std::size_t, 8> sizes{1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[static_cast<std::size_t>(type)];
}
constexpr bool is_ply_integer(Ply_type type) noexcept { return type < Ply_type::float32; }

/// The range of an integer type.
constexpr std::array<double, 2> ply_integer_range(Ply_type type) noexcept {
  constexpr std::array<std::array<double, 2>, 6> ranges{
      {{-128, 127}, {0, 255}, {-32768, 32767}, {0, 65535}, {-2147483648.0, 2147483647}, {0, 4294967295.0}}};
  return ranges[static_cast<std::size_t>(type)];
}

struct Ply_property {
  std::string name;
  Ply_type type = Ply_type::float32;      ///< of the value, or of a list's items
  std::optional<Ply_type> count_type{};   ///< set for a list
};

struct Ply_element {
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties{};
};

enum class Ply_format { ascii, binary_little_endian, binary_big_endian };

/// What deformseg reads of a PLY: where the coordinates and the face list are.
struct Ply_header {
  Ply_format format = Ply_format::ascii;
  std::vector<Ply_element> elements{};
  std::size_t vertex_element = 0;                       ///< index in `elements`
  std::array<std::size_t, 3> xyz{};                     ///< property indices of x, y, z
  std::optional<std::size_t> face_element{};            ///< index in `elements`, when there are faces
  std::size_t face_list = 0;                            ///< property index of vertex_indices
  const char* body = nullptr;                           ///< the first byte after end_header
};

/// The type a header names at the scanner, or a failure naming the line.
inline Ply_type read_ply_type(Text_scanner& scanner) {
  const char* start = scanner.position();
  const std::string_view word = scanner.word();
  for (std::size_t t = 0; t < ply_type_names.size(); ++t)
    if (word == ply_type_names[t][0] || word == ply_type_names[t][1]) return static_cast<Ply_type>(t);
  scanner.fail_at(start, join("unknown PLY type ", Text_scanner::quoted_token_at(start)));
}

/// The name that ends a header line.
inline std::string read_ply_name(Text_scanner& scanner, const char* what) {
  scanner.skip_blanks();
  const char* start = scanner.position();
  const std::string_view name = scanner.word();
  if (name.empty()) scanner.fail_at(start, join("expected ", what, ", found the end of the line"));
  scanner.skip_blanks();
  if (!scanner.at_line_end())
    scanner.fail_at(scanner.position(), join("unexpected ", Text_scanner::quoted_token_at(scanner.position()),
                                             " after ", what));
  return std::string(name);
}

/// A "property" line, whose keyword the scanner has passed.
inline Ply_property read_ply_property(Text_scanner& scanner) {
  Ply_property property;
  scanner.skip_blanks();
  if (scanner.peek() == 'l' && scanner.word() == "list") {
    const char* at = (scanner.skip_blanks(), scanner.position());
    property.count_type = read_ply_type(scanner);
    if (!is_ply_integer(*property.count_type))
      scanner.fail_at(at, join("a list's count must be of an integer type, not ", Text_scanner::quoted_token_at(at)));
  }
  property.type = read_ply_type(scanner);
  property.name = read_ply_name(scanner, "a property name");
  return property;
}

/// Reads the header lines up to end_header, leaving the scanner after it.
inline void read_ply_lines(Text_scanner& scanner, Ply_header& header) {
  scanner.next_line();  // "ply", checked by check_ply_magic
  const char* start = scanner.position();
  if (scanner.word() != "format")
    scanner.fail_at(
        start, "expected the line \"format ascii 1.0\" (or binary_little_endian, binary_big_endian) after \"ply\"");
  const char* at = (scanner.skip_blanks(), scanner.position());
  const std::string_view format = scanner.word();
  if (format == "ascii") header.format = Ply_format::ascii;
  else if (format == "binary_little_endian") header.format = Ply_format::binary_little_endian;
  else if (format == "binary_big_endian") header.format = Ply_format::binary_big_endian;
  else scanner.fail_at(at, join("unknown PLY format ", Text_scanner::quoted_token_at(at)));
  for (scanner.next_line(); !scanner.at_end(); scanner.next_line()) {
    scanner.skip_blanks();
    const char* line = scanner.position();
    const std::string_view keyword = scanner.word();
    if (keyword == "end_header") {
      scanner.next_line();
      return;
    }
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
    if (keyword == "element") {
      Ply_element element;
      element.name = std::string(scanner.word());
      element.count = scanner.count("an element count");
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) scanner.fail_at(line, "a property before any element");
      header.elements.back().properties.push_back(read_ply_property(scanner));
    } else {
      scanner.fail_at(line, join("unknown PLY header line ", Text_scanner::quoted_token_at(line)));
    }
  }
  scanner.file().fail("the PLY header has no end_header line");
}

/// The index of the scalar (or, with `list`, list) property `name` of `element`, if any.
inline std::optional<std::size_t> find_ply_property(const Ply_element& element, std::string_view name, bool list) {
  for (std::size_t k = 0; k < element.properties.size(); ++k)
    if (element.properties[k].name == name) {
      if (element.properties[k].count_type.has_value() != list) return std::nullopt;
      return k;
    }
  return std::nullopt;
}

/// Finds the vertex element's x, y, z and the face element's vertex index list.
inline void locate_ply_mesh(const Text_file& file, Ply_header& header) {
  std::optional<std::size_t> vertex;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const std::string& name = header.elements[e].name;
    if (name == "vertex" || name == "vertices") {
      if (vertex) file.fail("two vertex elements");
      vertex = e;
    } else if (name == "face" || name == "faces") {
      if (!vertex) file.fail("the face element comes before the vertex element");
      if (header.face_element) file.fail("two face elements");
      header.face_element = e;
    }
  }
  if (!vertex || header.elements[*vertex].count == 0) file.fail("no vertex: the mesh is empty");
  header.vertex_element = *vertex;
  for (std::size_t k = 0; k < 3; ++k) {
    const char* axis = std::array{"x", "y", "z"}[k];
    const auto found = find_ply_property(header.elements[*vertex], axis, false);
    if (!found) file.fail(join("the vertex element has no scalar property ", axis));
    header.xyz[k] = *found;
  }
  if (header.elements[*vertex].count > std::numeric_limits<std::uint32_t>::max())
    file.fail(
        join(std::to_string(header.elements[*vertex].count), " vertices: more than deformseg's 32-bit indices hold"));
  if (!header.face_element) return;
  const Ply_element& faces = header.elements[*header.face_element];
  auto list = find_ply_property(faces, "vertex_indices", true);
  if (!list) list = find_ply_property(faces, "vertex_index", true);
  if (!list || !is_ply_integer(faces.properties[*list].type))
    file.fail("the face element has no vertex_indices list of an integer type");
  header.face_list = *list;
}

/// The fewest bytes an item of `element` takes: its binary size without the lists' items, or in
/// text a digit and a separator per property.
inline std::size_t min_ply_item_bytes(const Ply_element& element, Ply_format format) {
  std::size_t bytes = 0;
  for (const Ply_property& property : element.properties)
    bytes += format == Ply_format::ascii ? 2 : ply_type_size(property.count_type.value_or(property.type));
  return bytes;
}

/// Fails unless the body can hold every element the header announces.
inline void check_ply_counts(const Text_file& file, const Ply_header& header) {
  for (const Ply_element& element : header.elements)
    if (element.count != 0 && element.properties.empty())
      file.fail(join("element ", element.name, " has no property but ", std::to_string(element.count), " items"));
  std::size_t left = static_cast<std::size_t>(file.end() - header.body) + 1;  // the last separator may be missing
  for (const Ply_element& element : header.elements) {
    if (element.count == 0) continue;
    const std::size_t item = min_ply_item_bytes(element, header.format);
    if (element.count > left / item)
      file.fail(join("the header announces ", std::to_string(element.count), " ", element.name, " items of ",
                     std::to_string(item), " bytes or more, more than the ",
                     std::to_string(file.end() - header.body), " bytes of the body hold"));
    left -= element.count * item;
  }
}

/// Reads and checks the header of a PLY text or binary file.
inline Ply_header read_ply_header(const Text_file& file) {
  Text_scanner scanner(file);
  Ply_header header;
  read_ply_lines(scanner, header);
  header.body = std::min(scanner.position(), file.end());  // past the sentinel when end_header ends the file
  locate_ply_mesh(file, header);
  check_ply_counts(file, header);
  return header;
}

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

namespace deformseg::io {

/// @brief Reads a PLY mesh, text (`format ascii`) or binary (either byte order): its vertices and
/// triangles.
///
/// The vertices are the `vertex` element's `x`, `y`, `z` properties (float or double); the faces
/// are the `face` element's `vertex_indices` (or `vertex_index`) list, indices from 0. Other
/// properties (normals, colours, texture coordinates) and elements are passed over. The header
/// is checked whole before the body is read: its lines, types, and element counts against the
/// size of the file, so that nothing is allocated for counts the file cannot hold.
///
/// @param path the file to read.
/// @param options `triangulate` (default false): fan-triangulate faces of more than 3 vertices
/// instead of rejecting them.
/// @return the vertices and triangles in the order of the file.
/// @pre the file is a PLY with at least one vertex, finite coordinates, and faces of 3 vertices
/// (or more, with `triangulate`) whose indices are in `[0, V)`; the `vertex` element comes before
/// the `face` element.
/// @throws invalid_input naming the file (and the line of a text PLY's error; the element and
/// item of a value) when the file is missing or unreadable, is not a PLY, has a malformed header
/// (an unknown line or type, a property before any element, no x, y or z, no integer
/// vertex_indices list, counts more than the file holds), a truncated body, a malformed or
/// out-of-range value, a non-finite coordinate, a face that is not a triangle, an index out of
/// range, or no vertex.
/// @par Complexity O(size of the file).
inline Triangle_soup read_ply(const std::filesystem::path& path, const Mesh_read_options& options = {}) {
  return internal::read_ply_soup(path, options);
}

}  // namespace deformseg::io

namespace deformseg::io {

/// @brief How a PLY file stores its numbers.
enum class Ply_encoding {
  binary,  ///< `binary_little_endian`: compact and fast, read by every PLY reader
  ascii    ///< text, for reading by eye; each number in its shortest exact form
};

/// @brief How `write_ply` writes.
struct Ply_write_options {
  /// @brief Binary (little-endian) or text. Default: `Ply_encoding::binary`.
  Ply_encoding encoding = Ply_encoding::binary;
};

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// The PLY type of the coordinates: `float` stays float, any other is written as double.
template <class Coordinate>
using Ply_coordinate = std::conditional_t<std::same_as<Coordinate, float>, float, double>;

/// Appends the PLY header of a mesh of `vertices` and `faces`, with face colours or not.
template <class Coordinate>
void append_ply_header(std::string& out, std::size_t vertices, std::size_t faces, bool colored,
                       io::Ply_encoding encoding, std::size_t frame, std::size_t num_frames) {
  const char* type = std::same_as<Ply_coordinate<Coordinate>, float> ? "float" : "double";
  out.append(encoding == io::Ply_encoding::binary ? "ply\nformat binary_little_endian 1.0\n"
                                                  : "ply\nformat ascii 1.0\n");
  out.append(join("comment deformseg: frame ", std::to_string(frame), " of ", std::to_string(num_frames), "\n"));
  out.append(join("element vertex ", std::to_string(vertices), "\n"));
  for (const char* axis : {"x", "y", "z"}) out.append(join("property ", type, " ", axis, "\n"));
  out.append(join("element face ", std::to_string(faces), "\n", "property list uchar int vertex_indices\n"));
  if (colored) out.append("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  out.append("end_header\n");
}

/// Appends the vertices and faces of frame `frame` as binary little-endian PLY.
template <class Graph, class Coordinate>
void append_ply_binary_body(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
                            std::span<const color::Rgb> colors, std::string& out) {
  using Stored = Ply_coordinate<Coordinate>;
  constexpr auto little = std::endian::little;
  const auto xyz = animation.frame_positions(frame);
  const std::size_t face_size = 1 + 3 * 4 + (colors.empty() ? 0 : 3);
  const std::size_t start = out.size();
  out.resize(start + xyz.size() * sizeof(Stored) + animation.num_faces() * face_size);
  char* p = out.data() + start;
  for (const Coordinate x : xyz) {
    store_word<little>(p, static_cast<Stored>(x));
    p += sizeof(Stored);
  }
  for (std::size_t j = 0; j < animation.num_faces(); ++j) {
    *p++ = 3;
    for (const std::uint32_t v : animation.triangles()[j]) {
      store_word<little>(p, static_cast<std::int32_t>(v));
      p += 4;
    }
    if (colors.empty()) continue;
    for (const std::uint8_t channel : {colors[j].r, colors[j].g, colors[j].b}) *p++ = static_cast<char>(channel);
  }
}

/// Appends the vertices and faces of frame `frame` as text PLY.
template <class Graph, class Coordinate>
void append_ply_ascii_body(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
                           std::span<const color::Rgb> colors, std::string& out) {
  const auto xyz = animation.frame_positions(frame);
  out.reserve(out.size() + xyz.size() * 25 + animation.num_faces() * (2 + 3 * 11 + 3 * 4));
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      append_shortest(out, static_cast<Ply_coordinate<Coordinate>>(xyz[i + k]));
      out.push_back(k == 2 ? '\n' : ' ');
    }
  }
  for (std::size_t j = 0; j < animation.num_faces(); ++j) {
    out.push_back('3');
    for (const std::uint32_t v : animation.triangles()[j]) {
      out.push_back(' ');
      append_decimal(out, v);
    }
    if (!colors.empty())
      for (const std::uint8_t channel : {colors[j].r, colors[j].g, colors[j].b}) {
        out.push_back(' ');
        append_decimal(out, unsigned{channel});
      }
    out.push_back('\n');
  }
}

/// Throws invalid_input naming `path` unless there are no colours or one per face.
inline void check_face_colors(std::size_t colors, std::size_t faces, const std::filesystem::path& path,
                              std::optional<std::size_t> frame = std::nullopt) {
  if (colors != 0 && colors != faces)
    throw invalid_input(join(std::to_string(colors), " face colours for ", std::to_string(faces), " faces"),
                        {.file = path.string(), .frame = frame});
}

/// Appends frame `frame` of `animation` to `out` as a PLY file.
/// @pre `frame < animation.num_frames()`, `colors` empty or of one colour per face.
template <class Graph, class Coordinate>
void append_ply(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
                std::span<const color::Rgb> colors, io::Ply_encoding encoding, std::string& out) {
  append_ply_header<Coordinate>(out, animation.num_vertices(), animation.num_faces(), !colors.empty(), encoding,
                                frame, animation.num_frames());
  if (encoding == io::Ply_encoding::binary)
    append_ply_binary_body(animation, frame, colors, out);
  else
    append_ply_ascii_body(animation, frame, colors, out);
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Writes frame `frame` of an animation as a PLY file, optionally with a colour per face,
/// with one call.
///
/// The file has a `vertex` element (`x`, `y`, `z`: `float` for a `float` animation, else
/// `double`, so that no precision is lost) in vertex index order, and a `face` element
/// (`vertex_indices` as a list of `uchar` count and `int` indices, in the order of
/// `Deforming_mesh::triangles()`) in face index order, with `uchar red`, `green` and `blue`
/// properties when colours are given: the layout MeshLab, ParaView, Blender and CGAL read.
/// Text PLY writes each number as the shortest decimal text that reads back to the same value.
///
/// @param animation the animation.
/// @param frame the frame to write, from 0.
/// @param file the file to write, replaced if it exists; its folder must exist.
/// @param face_colors one colour per face, in face index order; empty (default) for none.
/// @param options `encoding`: `Ply_encoding::binary` (default, little-endian) or `ascii`.
/// @pre `frame < animation.num_frames()`; `face_colors` is empty or has `animation.num_faces()`
/// colours.
/// @throws invalid_input naming `file` when a precondition fails or the file cannot be written
/// (the path being the caller's input); no partial file is left then.
/// @par Complexity O(V + F).
/// @sa write_obj, write_sequence, Rgb
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
void write_ply(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
               const std::filesystem::path& file, std::span<const color::Rgb> face_colors = {},
               const Ply_write_options& options = {}) {
  internal::check_frame_to_write(frame, animation.num_frames(), file);
  internal::check_face_colors(face_colors.size(), animation.num_faces(), file);
  std::string bytes;
  internal::append_ply(animation, frame, face_colors, options.encoding, bytes);
  internal::write_file_bytes(file, bytes);
}

}  // namespace deformseg::io
