// What the mesh writers share: the check of the frame to write (OBJ, OFF, PLY), and the one writer
// of OBJ and OFF, both a frame's vertex lines then its triangle lines after a header, differing
// only in their prefixes, their first index and OFF's counts.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace deformseg::io::internal {

/// Appends a line per point of `xyz` (3 coordinates each): `prefix`, then its coordinates, each
/// the shortest text that reads back to it, separated by spaces. The vertex lines of OBJ ("v ")
/// and OFF (no prefix).
template <std::floating_point T>
void append_point_lines(std::string& out, std::span<const T> xyz, std::string_view prefix) {
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    out.append(prefix);
    for (std::size_t k = 0; k < 3; ++k) {
      if (k != 0) out.push_back(' ');
      deformseg::internal::append_shortest(out, xyz[i + k]);
    }
    out.push_back('\n');
  }
}

/// Appends a line per triangle: `prefix`, then its 3 vertex indices plus `first_index`, separated
/// by spaces. The face lines of OBJ ("f ", from 1) and OFF ("3 ", from 0).
template <class Triangle>
void append_triangle_lines(std::string& out, std::span<const Triangle> triangles, std::string_view prefix,
                           std::uint64_t first_index) {
  for (const Triangle& triangle : triangles) {
    out.append(prefix);
    for (std::size_t k = 0; k < 3; ++k) {
      if (k != 0) out.push_back(' ');
      deformseg::internal::append_decimal(out, std::uint64_t{triangle[k]} + first_index);
    }
    out.push_back('\n');
  }
}

/// Throws invalid_input naming `path` unless `frame < num_frames`.
inline void check_frame_to_write(std::size_t frame, std::size_t num_frames, const std::filesystem::path& path) {
  if (frame >= num_frames)
    throw invalid_input(deformseg::internal::join("cannot write frame ", std::to_string(frame), " of an animation of ",
                                                  std::to_string(num_frames), " frames"),
                        {.file = path.string()});
}

/// What sets a text mesh format apart (`obj_format` in io/obj.h, `off_format` in io/off.h).
struct Text_mesh_format {
  std::string_view first_line;     ///< before the comment line: OFF's keyword, or nothing
  bool counts;                     ///< whether the counts `V F 0` follow the comment line (OFF)
  std::string_view vertex_prefix;  ///< before a vertex's coordinates
  std::string_view face_prefix;    ///< before a triangle's indices
  std::uint64_t first_index;       ///< the index of the first vertex: 1 (OBJ) or 0 (OFF)
};

/// Appends frame `frame` of `animation` to `text` in `format`: its first line, the comment
/// "# deformseg: frame N of T", the counts if the format has them, the vertex lines in index
/// order and the triangle lines.
/// @pre `frame < animation.num_frames()`.
template <class Graph, class Coordinate>
void append_text_mesh(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
                      const Text_mesh_format& format, std::string& text) {
  // At most 25 characters a double and 11 an index: the appends below do not reallocate.
  text.reserve(text.size() + 96 + animation.num_vertices() * (format.vertex_prefix.size() + 3 * 25) +
               animation.num_faces() * (format.face_prefix.size() + 3 * 11));
  text.append(format.first_line);
  text.append("# deformseg: frame ");
  deformseg::internal::append_decimal(text, frame);
  text.append(" of ");
  deformseg::internal::append_decimal(text, animation.num_frames());
  text.push_back('\n');
  if (format.counts) {
    deformseg::internal::append_decimal(text, animation.num_vertices());
    text.push_back(' ');
    deformseg::internal::append_decimal(text, animation.num_faces());
    text.append(" 0\n");
  }
  append_point_lines(text, animation.frame_positions(frame), format.vertex_prefix);
  append_triangle_lines(text, animation.triangles(), format.face_prefix, format.first_index);
}

/// Writes frame `frame` of `animation` to `file` in `format`, with one call.
/// @throws invalid_input naming `file` when `frame` is out of range or the file cannot be
/// written; no partial file is left then.
template <class Graph, class Coordinate>
void write_text_mesh(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
                     const std::filesystem::path& file, const Text_mesh_format& format) {
  check_frame_to_write(frame, animation.num_frames(), file);
  std::string text;
  append_text_mesh(animation, frame, format, text);
  deformseg::internal::write_file_bytes(file, text);
}

}  // namespace deformseg::io::internal
