/// @file write_obj.h
/// @brief Writes one frame of an animation as a Wavefront OBJ file: `write_obj`.
#pragma once

#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>

#include <concepts>
#include <cstddef>
#include <filesystem>
#include <string>

namespace deformseg::internal {

/// Appends frame `frame` of `animation` to `text` as OBJ: a comment, the `v` lines of the
/// vertices in index order, the `f` lines of the triangles (1-based indices).
/// @pre `frame < animation.num_frames()`.
template <class Graph, class Coordinate>
void append_obj(const Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame, std::string& text) {
  // At most 25 characters a double and 11 an index: the appends below do not reallocate.
  text.reserve(text.size() + 64 + animation.num_vertices() * (2 + 3 * 25) + animation.num_faces() * (2 + 3 * 11));
  text.append("# deformseg: frame ");
  append_decimal(text, frame);
  text.append(" of ");
  append_decimal(text, animation.num_frames());
  text.push_back('\n');

  const auto xyz = animation.frame_positions(frame);
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    text.push_back('v');
    for (std::size_t k = 0; k < 3; ++k) {
      text.push_back(' ');
      append_shortest(text, xyz[i + k]);
    }
    text.push_back('\n');
  }
  for (const auto& triangle : animation.triangles()) {
    text.push_back('f');
    for (const std::uint32_t v : triangle) {
      text.push_back(' ');
      append_decimal(text, std::uint64_t{v} + 1);
    }
    text.push_back('\n');
  }
}

}  // namespace deformseg::internal

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
template <FaceGraph Graph, std::floating_point Coordinate>
void write_obj(const Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
               const std::filesystem::path& file) {
  internal::check_frame_to_write(frame, animation.num_frames(), file);
  std::string text;
  internal::append_obj(animation, frame, text);
  internal::write_file_bytes(file, text);
}

}  // namespace deformseg::io
