/// @file io/write_ply.h
/// @brief Writes a frame of an animation as a PLY mesh (text or binary, colours per face or not): `write_ply`.
#pragma once

#include <deformseg/color/color.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/mesh_writer.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <type_traits>

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
