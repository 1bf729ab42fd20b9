/// @file io/obj.h
/// @brief Reads a Wavefront OBJ mesh: `read_obj`.
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
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::io::internal {

/// The statements of the OBJ specification that carry nothing deformseg reads.
inline bool is_ignored_obj_statement(std::string_view word) {
  static constexpr std::array<std::string_view, 42> ignored{
      "vn",     "vt",       "vp",       "o",          "g",         "s",         "l",
      "usemtl", "mtllib",   "p",        "mg",         "usemap",    "maplib",    "shadow_obj",
      "trace_obj", "lod",   "bevel",    "c_interp",   "d_interp",  "ctech",     "stech",
      "cstype", "deg",      "bmat",     "step",       "curv",      "curv2",     "surf",
      "parm",   "trim",     "hole",     "scrv",       "sp",        "end",       "con",
      "call",   "csh",      "res",      "bsp",        "bzp",       "cdc",       "cdp"};
  return std::find(ignored.begin(), ignored.end(), word) != ignored.end();
}

/// Reads the vertices and faces of an OBJ text.
///
/// A positive index may refer to a vertex defined further down (CGAL's reader accepts that too),
/// so it is checked once all vertices are known. To name the line of the first such index, the
/// text is parsed again knowing the vertex count: only files with that error pay for it.
class Obj_parser {
public:
  Obj_parser(const Text_file& file, const io::Mesh_read_options& options,
             std::optional<std::size_t> known_vertex_count = std::nullopt)
      : scanner_(file), options_(options), known_vertex_count_(known_vertex_count) {}

  io::Triangle_soup parse() {
    reserve_for(scanner_.file().size());
    while (!scanner_.at_end()) {
      parse_line();
      scanner_.next_line();
    }
    if (soup_.points.empty()) scanner_.file().fail("no vertex: the mesh is empty");
    if (static_cast<std::size_t>(largest_index_) > soup_.num_vertices()) {
      Obj_parser(scanner_.file(), options_, soup_.num_vertices()).parse();  // throws with the line
      scanner_.file().fail(join("vertex index ", std::to_string(largest_index_), " out of range"));
    }
    return std::move(soup_);
  }

private:
  // Reserving by guess rather than letting the vectors double: each doubling copies and faults in
  // fresh pages, up to a third of the time on a frame of a few hundred kilobytes. A vertex line
  // and the two faces a triangle mesh has per vertex take 60 bytes or more (the horse 91, the
  // samba dancer 63), hence 3 coordinates per 60 bytes; the faces, about 2 V, are reserved at the
  // first face, which comes after the vertices in practice.
  void reserve_for(std::size_t bytes) { soup_.points.reserve(bytes / 20); }
  void reserve_faces() {
    if (soup_.triangles.capacity() == 0) soup_.triangles.reserve(2 * soup_.num_vertices() + 16);
  }

  void parse_line() {
    scanner_.skip_blanks();
    const char first = scanner_.peek();
    if (first == 'v' && ends_token(scanner_.peek(1))) {
      scanner_.advance(1);
      std::array<double, 3> xyz;
      read_xyz(scanner_, "v", xyz.data());
      soup_.points.insert(soup_.points.end(), xyz.begin(), xyz.end());
    } else if (first == 'f' && ends_token(scanner_.peek(1))) {
      scanner_.advance(1);
      parse_face();
    } else if (!scanner_.at_line_end()) {
      const char* start = scanner_.position();
      if (!is_ignored_obj_statement(scanner_.word()))
        scanner_.fail_at(start, join("unknown OBJ statement \"", Text_scanner::token_at(start), "\""));
    }
  }

  void parse_face() {
    const char* start = scanner_.position();
    reserve_faces();
    corners_.clear();
    for (scanner_.skip_blanks(); !scanner_.at_line_end(); scanner_.skip_blanks())
      corners_.push_back(read_corner());
    if (corners_.size() == 3) [[likely]]
      soup_.triangles.push_back({corners_[0], corners_[1], corners_[2]});
    else
      add_polygon(start);
  }

  void add_polygon(const char* start) {
    if (const std::string problem = polygon_problem(corners_.size(), options_); !problem.empty())
      scanner_.fail_at(start, problem);
    append_fan(corners_, soup_.triangles);
  }

  // One corner, "i", "i/t", "i//n" or "i/t/n": its vertex index, 0-based. The texture and normal
  // indices are checked for their form only, as they are not used.
  std::uint32_t read_corner() {
    const char* start = scanner_.position();
    const std::int64_t index = scanner_.integer("a vertex index");
    for (int slashes = 0; slashes < 2 && scanner_.peek() == '/'; ++slashes) {
      scanner_.advance(1);
      if (scanner_.peek() == '-' && is_digit(scanner_.peek(1))) scanner_.advance(1);
      while (is_digit(scanner_.peek())) scanner_.advance(1);
    }
    if (!ends_token(scanner_.peek()))
      scanner_.fail_at(start, join("malformed face corner \"", Text_scanner::token_at(start), "\""));
    return resolve(index, start);
  }

  // OBJ counts vertices from 1; a negative index counts back from the last vertex read so far.
  std::uint32_t resolve(std::int64_t index, const char* where) {
    if (index > 0 && index <= largest_allowed_) [[likely]] {
      largest_index_ = std::max(largest_index_, index);
      return static_cast<std::uint32_t>(index - 1);
    }
    const auto defined = static_cast<std::int64_t>(soup_.num_vertices());
    if (index == 0) scanner_.fail_at(where, "vertex index 0: OBJ indices start at 1");
    if (index > 0)
      scanner_.fail_at(where, join("vertex index ", std::to_string(index), " out of range: the file has ",
                                     known_vertex_count_ ? std::to_string(*known_vertex_count_) : "fewer",
                                     " vertices"));
    if (-index > defined)
      scanner_.fail_at(where, join("relative vertex index ", std::to_string(index), " out of range: ",
                                     std::to_string(defined), " vertices before it"));
    return static_cast<std::uint32_t>(defined + index);
  }

  Text_scanner scanner_;
  io::Mesh_read_options options_;
  std::optional<std::size_t> known_vertex_count_;
  io::Triangle_soup soup_;
  std::vector<std::uint32_t> corners_;
  // Positive indices above this are errors: the vertex count when known, else the largest the
  // triangles can hold.
  std::int64_t largest_allowed_ = static_cast<std::int64_t>(
      known_vertex_count_.value_or(std::numeric_limits<std::uint32_t>::max()));
  std::int64_t largest_index_ = 0;  // the largest positive index read, 1-based
};

/// Reads only the vertex positions of an OBJ text into `xyz` (3 V values), skipping every line
/// that is not a `v` line without looking further than its first characters.
template <std::floating_point T>
void read_obj_points(const Text_file& file, std::span<T> xyz) {
  const std::size_t expected = xyz.size() / 3;
  std::size_t found = 0;
  for (Text_scanner scanner(file); !scanner.at_end(); scanner.next_line()) {
    scanner.skip_blanks();
    if (scanner.peek() != 'v' || !ends_token(scanner.peek(1))) continue;
    if (found < expected) {
      scanner.advance(1);
      read_xyz(scanner, "v", xyz.data() + 3 * found);
    }
    ++found;
  }
  if (found != expected)
    file.fail(join("has ", std::to_string(found), " vertices instead of ", std::to_string(expected)));
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Reads a Wavefront OBJ mesh: its vertices and triangles.
///
/// Reads `v x y z` lines (numbers after the third, as in `v x y z w` or `v x y z r g b`, are not
/// read) and `f` lines whose corners are `i`, `i/t`, `i//n` or `i/t/n`, with indices from 1 or
/// negative (relative to the last vertex read). Lines of the other statements of the format (`vn`,
/// `vt`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, ...), comments and blank lines are skipped; LF
/// and CRLF endings are both read, and the last line may lack its newline. The whole file is read
/// with one call and parsed in memory, without `std::istream`.
///
/// @param path the file to read.
/// @param options `triangulate` (default false): fan-triangulate faces of more than 3 vertices
/// instead of rejecting them.
/// @return the vertices and triangles in the order of the file.
/// @pre the file has at least one vertex; every coordinate is a finite decimal number; every face
/// has 3 vertices (or more, with `triangulate`) whose indices are in range.
/// @throws invalid_input naming the file, and the line where there is one, when the file is
/// missing or unreadable, a number is malformed or not finite, a `v` line has fewer than 3
/// coordinates, a face is not a triangle, an index is 0 or out of range, a statement is unknown,
/// or the file has no vertex.
/// @par Complexity O(size of the file).
inline Triangle_soup read_obj(const std::filesystem::path& path, const Mesh_read_options& options = {}) {
  const internal::Text_file file(path);
  return internal::Obj_parser(file, options).parse();
}

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// OBJ as `append_text_mesh` and `write_text_mesh` write it: a comment, the `v` lines of the
/// vertices in index order, the `f` lines of the triangles (1-based indices).
inline constexpr Text_mesh_format obj_format{.first_line = "", .counts = false, .vertex_prefix = "v ",
                                             .face_prefix = "f ", .first_index = 1};

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Writes frame `frame` of an animation as a Wavefront OBJ file, with one call.
///
/// The file holds a comment line, one `v x y z` line per vertex in index order, and one
/// `f a b c` line per triangle in index order (1-based vertex indices, in the order of
/// `Deforming_mesh::triangles()`), so that reading it back with deformseg's or CGAL's readers
/// gives the same vertices and triangles. Each coordinate is written as the shortest decimal
/// text that reads back, as `Coordinate`, to the same value (`std::to_chars`).
///
/// @param animation the animation.
/// @param frame the frame to write, from 0.
/// @param file the file to write, replaced if it exists; its folder must exist.
/// @pre `frame < animation.num_frames()`.
/// @throws invalid_input naming `file` when `frame` is out of range or the file cannot be
/// written (the path being the caller's input); no partial file is left then.
/// @par Complexity O(V + F).
/// @sa write_ply, write_sequence
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
void write_obj(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
               const std::filesystem::path& file) {
  internal::write_text_mesh(animation, frame, file, internal::obj_format);
}

}  // namespace deformseg::io
