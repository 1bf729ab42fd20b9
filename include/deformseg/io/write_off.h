/// @file write_off.h
/// @brief Writes one frame of an animation as an OFF file: `write_off`.
#pragma once

#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>

#include <concepts>
#include <cstddef>
#include <filesystem>
#include <string>

namespace deformseg::internal {

/// Appends frame `frame` of `animation` to `text` as OFF: the `OFF` line, a comment, the counts,
/// the vertices in index order and the triangles (`3 a b c`, 0-based indices).
/// @pre `frame < animation.num_frames()`.
template <class Graph, class Coordinate>
void append_off(const Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame, std::string& text) {
  // At most 25 characters a double and 11 an index: the appends below do not reallocate.
  text.reserve(text.size() + 96 + animation.num_vertices() * (1 + 3 * 25) + animation.num_faces() * (2 + 3 * 11));
  text.append("OFF\n# deformseg: frame ");
  append_decimal(text, frame);
  text.append(" of ");
  append_decimal(text, animation.num_frames());
  text.push_back('\n');
  append_decimal(text, animation.num_vertices());
  text.push_back(' ');
  append_decimal(text, animation.num_faces());
  text.append(" 0\n");

  const auto xyz = animation.frame_positions(frame);
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (k != 0) text.push_back(' ');
      append_shortest(text, xyz[i + k]);
    }
    text.push_back('\n');
  }
  for (const auto& triangle : animation.triangles()) {
    text.push_back('3');
    for (const std::uint32_t v : triangle) {
      text.push_back(' ');
      append_decimal(text, v);
    }
    text.push_back('\n');
  }
}

}  // namespace deformseg::internal

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
template <FaceGraph Graph, std::floating_point Coordinate>
void write_off(const Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
               const std::filesystem::path& file) {
  internal::check_frame_to_write(frame, animation.num_frames(), file);
  std::string text;
  internal::append_off(animation, frame, text);
  internal::write_file_bytes(file, text);
}

}  // namespace deformseg::io
