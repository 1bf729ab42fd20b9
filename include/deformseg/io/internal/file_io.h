// The text lines of the mesh formats (OBJ, OFF), and the foundation's file helpers
// (deformseg/internal/file_io.h) by the names the readers and writers of io use.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace deformseg::io::internal {

using deformseg::internal::append_decimal;
using deformseg::internal::append_shortest;
using deformseg::internal::byte_position;
using deformseg::internal::create_folder;
using deformseg::internal::File_bytes;
using deformseg::internal::join;
using deformseg::internal::last_system_error;
using deformseg::internal::load_word;
using deformseg::internal::lower_extension;
using deformseg::internal::read_file_bytes;
using deformseg::internal::shortest_text;
using deformseg::internal::store_word;
using deformseg::internal::Streamed_file;
using deformseg::internal::write_file_bytes;

/// Appends a line per point of `xyz` (3 coordinates each): `prefix`, then its coordinates, each
/// the shortest text that reads back to it, separated by spaces. The vertex lines of OBJ ("v ")
/// and OFF (no prefix).
template <std::floating_point T>
void append_point_lines(std::string& out, std::span<const T> xyz, std::string_view prefix) {
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    out.append(prefix);
    for (std::size_t k = 0; k < 3; ++k) {
      if (k != 0) out.push_back(' ');
      append_shortest(out, xyz[i + k]);
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
      append_decimal(out, std::uint64_t{triangle[k]} + first_index);
    }
    out.push_back('\n');
  }
}

/// Throws invalid_input naming `path` unless `frame < num_frames`.
inline void check_frame_to_write(std::size_t frame, std::size_t num_frames, const std::filesystem::path& path) {
  if (frame >= num_frames)
    throw invalid_input(join("cannot write frame ", std::to_string(frame), " of an animation of ",
                             std::to_string(num_frames), " frames"),
                        {.file = path.string()});
}

}  // namespace deformseg::io::internal
