// The header of a PLY file (io/ply.h), parsed and checked whole before its body is read: the
// elements, properties and types, where the coordinates and the faces are, and counts the file can hold.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/text_scanner.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
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

}  // namespace deformseg::io::internal
