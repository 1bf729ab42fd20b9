/// @file io/off.h
/// @brief Reads an OFF mesh (Object File Format, text): `read_off`.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/mesh_writer.h>
#include <deformseg/io/internal/text_scanner.h>
#include <deformseg/io/triangle_soup.h>

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::io::internal {

/// The counts an OFF header gives.
struct Off_header {
  std::size_t vertices = 0;
  std::size_t faces = 0;
};

/// Reads the keyword line and the counts, leaving the scanner at the first vertex line. The
/// keyword may be OFF, COFF, NOFF or CNOFF: the colours and normals these add after the
/// coordinates are not read. The counts may follow the keyword on its line.
inline Off_header read_off_header(Text_scanner& scanner) {
  scanner.skip_empty_lines();
  const char* start = scanner.position();
  const std::string_view keyword = scanner.word();
  if (keyword != "OFF" && keyword != "COFF" && keyword != "NOFF" && keyword != "CNOFF") {
    if (keyword.ends_with("OFF"))
      scanner.fail_at(start, join("unsupported OFF variant \"", keyword,
                                    "\": deformseg reads OFF, COFF, NOFF and CNOFF"));
    scanner.fail_at(start, join("not an OFF file: it starts with \"", Text_scanner::token_at(start),
                                  "\" instead of OFF"));
  }
  scanner.skip_blanks();
  if (scanner.peek() == 'B')  // "OFF BINARY"
    scanner.fail_at(start, "binary OFF is not supported: write it as text");
  if (scanner.at_line_end()) {
    scanner.next_line();
    scanner.skip_empty_lines();
  }
  if (scanner.at_end()) scanner.file().fail("the OFF header has no vertex and face counts");
  Off_header header;
  header.vertices = scanner.count("a vertex count");
  header.faces = scanner.count("a face count");  // an edge count may follow; OFF ignores it
  scanner.next_line();
  return header;
}

/// Moves to the next line with content, failing when the file ends before item `index` of `total`.
inline void expect_line(Text_scanner& scanner, const char* what, std::size_t index, std::size_t total) {
  scanner.skip_empty_lines();
  if (scanner.at_end())
    scanner.file().fail(join("the file ends after ", std::to_string(index), " of ", std::to_string(total),
                               " ", what, " that its header announces"));
}

/// Reads vertex line `i` of `count` into the 3 values at `xyz`.
template <std::floating_point T>
void read_off_vertex(Text_scanner& scanner, std::size_t i, std::size_t count, T* xyz) {
  expect_line(scanner, "vertices", i, count);
  read_xyz(scanner, "vertex", xyz);
  scanner.next_line();
}

/// Reads the vertex lines of an OFF text into `xyz`, which has room for `count` vertices.
template <std::floating_point T>
void read_off_vertices(Text_scanner& scanner, std::size_t count, T* xyz) {
  for (std::size_t i = 0; i < count; ++i) read_off_vertex(scanner, i, count, xyz + 3 * i);
}

/// Reads one face line "n i0 ... in-1 [colour]" of indices from 0, checked against `vertices`.
inline void read_off_face(Text_scanner& scanner, std::size_t vertices, const io::Mesh_read_options& options,
                          std::vector<std::uint32_t>& corners, io::Triangle_soup& soup) {
  const char* start = scanner.position();
  const std::size_t n = scanner.count("a face's vertex count");
  if (const std::string problem = polygon_problem(n, options); !problem.empty()) scanner.fail_at(start, problem);
  corners.clear();
  for (std::size_t k = 0; k < n; ++k) {
    scanner.skip_blanks();
    const char* where = scanner.position();
    if (scanner.at_line_end())
      scanner.fail_at(where, join("the face has ", std::to_string(k), " of its ", std::to_string(n), " indices"));
    const std::size_t index = scanner.count("a vertex index");
    if (index >= vertices)
      scanner.fail_at(where, join("vertex index ", std::to_string(index), " out of range [0, ",
                                    std::to_string(vertices), ")"));
    corners.push_back(static_cast<std::uint32_t>(index));
  }
  append_fan(corners, soup.triangles);
}

/// The fewest bytes of a vertex line ("0 0 0\n") and of a triangle's line ("3 0 1 2\n").
inline constexpr std::size_t min_off_vertex_bytes = 6;
inline constexpr std::size_t min_off_face_bytes = 8;

/// `count` lines of at least `line_bytes` bytes, or as many as the rest of the file can hold: a
/// header's count is trusted for an allocation only as far as the file's size allows, the file
/// then ending before the count does where the count was wrong.
inline std::size_t off_lines_that_fit(const Text_scanner& scanner, std::size_t count, std::size_t line_bytes) {
  const auto left = static_cast<std::size_t>(scanner.file().end() - scanner.position());
  return std::min(count, (left + 1) / line_bytes);  // the last line may lack its newline
}

/// Reads the vertices and faces of an OFF text.
inline io::Triangle_soup read_off_soup(const Text_file& file, const io::Mesh_read_options& options) {
  Text_scanner scanner(file);
  const Off_header header = read_off_header(scanner);
  if (header.vertices == 0) file.fail("no vertex: the mesh is empty");
  io::Triangle_soup soup;
  soup.points.reserve(3 * off_lines_that_fit(scanner, header.vertices, min_off_vertex_bytes));
  for (std::size_t i = 0; i < header.vertices; ++i) {
    std::array<double, 3> xyz;
    read_off_vertex(scanner, i, header.vertices, xyz.data());
    soup.points.insert(soup.points.end(), xyz.begin(), xyz.end());
  }
  soup.triangles.reserve(off_lines_that_fit(scanner, header.faces, min_off_face_bytes));
  std::vector<std::uint32_t> corners;
  for (std::size_t j = 0; j < header.faces; ++j) {
    expect_line(scanner, "faces", j, header.faces);
    read_off_face(scanner, header.vertices, options, corners, soup);
    scanner.next_line();
  }
  return soup;
}

/// Reads only the vertex positions of an OFF text into `xyz` (3 V values).
template <std::floating_point T>
void read_off_points(const Text_file& file, std::span<T> xyz) {
  Text_scanner scanner(file);
  const Off_header header = read_off_header(scanner);
  if (3 * header.vertices != xyz.size())
    file.fail(join("has ", std::to_string(header.vertices), " vertices instead of ",
                     std::to_string(xyz.size() / 3)));
  read_off_vertices(scanner, header.vertices, xyz.data());
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Reads an OFF mesh (text): its vertices and triangles.
///
/// The file starts with `OFF` (or `COFF`, `NOFF`, `CNOFF`), then the counts `V F E` (on the
/// keyword's line or the next), then one vertex per line (`x y z`, anything after the third number,
/// such as a colour or a normal, not read), then one face per line (`n i0 ... in-1`, indices from
/// 0, a colour after them not read). `#` comments and blank lines may come anywhere; LF and CRLF
/// endings are both read. Parsed in memory after one read of the whole file, like `read_obj`.
///
/// @param path the file to read.
/// @param options `triangulate` (default false): fan-triangulate faces of more than 3 vertices
/// instead of rejecting them.
/// @return the vertices and triangles in the order of the file.
/// @pre the file is a text OFF with at least one vertex, finite coordinates, and faces of 3
/// vertices (or more, with `triangulate`) whose indices are in `[0, V)`.
/// @throws invalid_input naming the file, and the line where there is one, when the file is
/// missing or unreadable, is not a text OFF, has a malformed or non-finite number, a vertex line
/// with fewer than 3 coordinates, a face that is not a triangle, an index out of range, fewer
/// lines than its header announces, or no vertex.
/// @par Complexity O(size of the file).
inline Triangle_soup read_off(const std::filesystem::path& path, const Mesh_read_options& options = {}) {
  const internal::Text_file file(path);
  return internal::read_off_soup(file, options);
}

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// OFF as `append_text_mesh` and `write_text_mesh` write it: the `OFF` line, a comment, the counts
/// `V F 0`, the vertices in index order and the triangles (`3 a b c`, 0-based indices).
inline constexpr Text_mesh_format off_format{.first_line = "OFF\n", .counts = true, .vertex_prefix = "",
                                             .face_prefix = "3 ", .first_index = 0};

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Writes frame `frame` of an animation as an OFF file, with one call.
///
/// The file holds the `OFF` line, a comment line, the counts `V F 0`, one `x y z` line per vertex
/// in index order and one `3 a b c` line per triangle in index order (0-based vertex indices, in
/// the order of `Deforming_mesh::triangles()`), so that `read_off` gives the same vertices and
/// triangles. Each coordinate is the shortest decimal text that reads back, as `Coordinate`, to
/// the same value.
///
/// @param animation the animation.
/// @param frame the frame to write, from 0.
/// @param file the file to write, replaced if it exists; its folder must exist.
/// @pre `frame < animation.num_frames()`.
/// @throws invalid_input naming `file` when `frame` is out of range or the file cannot be
/// written; no partial file is left then.
/// @par Complexity O(V + F).
/// @sa write_obj, write_ply, write_sequence
/// @par Example
/// @include write_off.cpp
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
void write_off(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
               const std::filesystem::path& file) {
  internal::write_text_mesh(animation, frame, file, internal::off_format);
}

}  // namespace deformseg::io
