/// @file io/read_mesh.h
/// @brief Reads a mesh file of any format deformseg knows, chosen by its extension: `read_mesh`,
/// and its vertex positions only: `read_mesh_points`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/text_scanner.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/off.h>
#include <deformseg/io/ply.h>
#include <deformseg/io/triangle_soup.h>

#include <algorithm>
#include <cctype>
#include <concepts>
#include <filesystem>
#include <span>
#include <string>

namespace deformseg::io::internal {

/// The mesh formats deformseg reads.
enum class Mesh_format { obj, off, ply };

/// The format of `path` by its extension, in any case; throws invalid_input for another one.
inline Mesh_format mesh_format(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return Mesh_format::obj;
  if (extension == ".off") return Mesh_format::off;
  if (extension == ".ply") return Mesh_format::ply;
  throw invalid_input(join("unknown mesh format \"", path.extension().string(),
                             "\": deformseg reads .obj, .off and .ply files"),
                      {.file = path.string()});
}

/// Reads the vertex positions of a mesh file into `xyz`, in the coordinate type of `xyz`.
template <std::floating_point T>
void read_points_as(const std::filesystem::path& path, std::span<T> xyz) {
  if (xyz.size() % 3 != 0)
    throw invalid_input(join("room for ", std::to_string(xyz.size()),
                               " coordinates given, not a multiple of 3"),
                        {.file = path.string()});
  switch (mesh_format(path)) {
    case Mesh_format::obj: return read_obj_points(Text_file(path), xyz);
    case Mesh_format::off: return read_off_points(Text_file(path), xyz);
    case Mesh_format::ply: return read_ply_points(path, xyz);
  }
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Reads a mesh file, choosing the reader by the file's extension (in any case): `.obj`
/// (`read_obj`), `.off` (`read_off`) or `.ply` (`read_ply`).
///
/// @param path the file to read.
/// @param options `triangulate` (default false): fan-triangulate faces of more than 3 vertices
/// instead of rejecting them.
/// @return the vertices and triangles in the order of the file.
/// @pre the extension is one of the three; the file meets the preconditions of its reader.
/// @throws invalid_input naming the file for another extension, and as the reader does.
/// @par Complexity O(size of the file).
/// @sa read_obj, read_off, read_ply, read_mesh_points
inline Triangle_soup read_mesh(const std::filesystem::path& path, const Mesh_read_options& options = {}) {
  switch (internal::mesh_format(path)) {
    case internal::Mesh_format::obj: return read_obj(path, options);
    case internal::Mesh_format::off: return read_off(path, options);
    case internal::Mesh_format::ply: return read_ply(path, options);
  }
  return {};  // not reached: mesh_format throws for any other format
}

/// @brief Reads only the vertex positions of a mesh file, by extension as `read_mesh`, into
/// `xyz`: x, y, z of vertex 0, then of vertex 1, ...
///
/// Made for the frames of an animation after the first, whose connectivity is known: an OBJ's
/// lines other than `v` lines are skipped without being parsed, so faces are neither read nor
/// checked; an OFF's reading stops after its vertices. A PLY is read whole (see `read_ply`).
///
/// @param path the file to read.
/// @param xyz where to write the coordinates: its size, `3 V`, says how many vertices the file
/// must have.
/// @pre the file has exactly `xyz.size() / 3` vertices, all with finite coordinates;
/// `xyz.size()` is a multiple of 3.
/// @throws invalid_input naming the file (and the line, for a malformed or non-finite number in
/// an OBJ or OFF) when it is missing or unreadable, has another vertex count ("has N vertices
/// instead of V"), a `v` line with fewer than 3 coordinates, a malformed or non-finite number, or
/// an unknown extension. `xyz` may then be partly written.
/// @par Complexity O(size of the file); for OBJ faster than `read_obj`, which parses every line
/// (@ref section_reading_speed).
/// @sa read_mesh
inline void read_mesh_points(const std::filesystem::path& path, std::span<double> xyz) {
  internal::read_points_as(path, xyz);
}

/// @brief Reads only the vertex positions of a mesh file into `float` coordinates: as the
/// `double` overload, each number of a text file rounded once, straight to the nearest `float`.
/// @param path the file to read.
/// @param xyz where to write the coordinates; its size, `3 V`, says how many vertices the file
/// must have.
/// @pre as the `double` overload; every coordinate is also within the range of `float`.
/// @throws invalid_input as the `double` overload, and for a number out of the range of `float`.
/// @par Complexity O(size of the file).
inline void read_mesh_points(const std::filesystem::path& path, std::span<float> xyz) {
  internal::read_points_as(path, xyz);
}

}  // namespace deformseg::io
