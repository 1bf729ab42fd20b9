/// @file ply.h
/// @brief Reads a PLY mesh (text or binary): `read_ply`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/text_scanner.h>
#include <deformseg/io/triangle_soup.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::internal {

/// Fails unless `path` names a readable file that starts with PLY's magic word, so that the
/// common mistakes get a message of their own rather than CGAL's bare "false".
inline void check_ply_magic(const std::filesystem::path& path) {
  const File_bytes start = read_file_bytes(path, 4);
  const std::string_view magic(start.begin(), start.size);
  if (magic.size() != 4 || !magic.starts_with("ply") || !(magic[3] == '\n' || magic[3] == '\r'))
    throw invalid_input("not a PLY file: it does not start with the line \"ply\"", {.file = path.string()});
}

/// Reads a PLY file with CGAL into points and polygons, with deformseg's messages.
inline io::Triangle_soup read_ply_soup(const std::filesystem::path& path, const io::Mesh_read_options& options) {
  check_ply_magic(path);
  const auto fail = [&](const std::string& message) { throw invalid_input(message, {.file = path.string()}); };
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_PLY(path.string(), points, polygons, CGAL::parameters::verbose(false)))
    fail("cannot read as a PLY polygon mesh: a malformed header, a truncated body, or no "
         "vertex_indices list in its faces (CGAL::IO::read_PLY failed)");
  if (points.empty()) fail("no vertex: the mesh is empty");

  io::Triangle_soup soup;
  soup.points.reserve(3 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(points[i][k]))
        fail(join("vertex ", std::to_string(i), " has a non-finite coordinate"));
      soup.points.push_back(points[i][k]);
    }
  std::vector<std::uint32_t> corners;
  soup.triangles.reserve(polygons.size());
  for (std::size_t j = 0; j < polygons.size(); ++j) {
    if (const std::string problem = polygon_problem(polygons[j].size(), options); !problem.empty())
      fail(join("face ", std::to_string(j), ": ", problem));
    corners.clear();
    for (const std::size_t index : polygons[j]) {
      if (index >= points.size())
        fail(join("face ", std::to_string(j), " has vertex index ", std::to_string(index),
                    " out of range [0, ", std::to_string(points.size()), ")"));
      corners.push_back(static_cast<std::uint32_t>(index));
    }
    append_fan(corners, soup.triangles);
  }
  return soup;
}

/// Reads only the vertex positions of a PLY file into `xyz` (3 V values). PLY is read whole by
/// CGAL, faces included: this is as slow as `read_ply`.
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

}  // namespace deformseg::internal

namespace deformseg::io {

/// @brief Reads a PLY mesh, text (`format ascii`) or binary (either byte order): its vertices and
/// triangles.
///
/// The vertices are the `vertex` element's `x`, `y`, `z` properties (float or double); the faces
/// are the `face` element's `vertex_indices` (or `vertex_index`) list, indices from 0. Other
/// properties (normals, colours, texture coordinates) and elements are not read. The parsing is
/// CGAL's (`CGAL::IO::read_PLY`), wrapped with deformseg's checks and messages.
///
/// @param path the file to read.
/// @param options `triangulate` (default false): fan-triangulate faces of more than 3 vertices
/// instead of rejecting them.
/// @return the vertices and triangles in the order of the file.
/// @pre the file is a PLY with at least one vertex, finite coordinates, and faces of 3 vertices
/// (or more, with `triangulate`) whose indices are in `[0, V)`.
/// @throws invalid_input naming the file (and the face or vertex; binary PLY has no lines) when
/// the file is missing or unreadable, is not a PLY, cannot be parsed, has a non-finite coordinate,
/// a face that is not a triangle, an index out of range, or no vertex.
/// @par Complexity O(size of the file).
inline Triangle_soup read_ply(const std::filesystem::path& path, const Mesh_read_options& options = {}) {
  return internal::read_ply_soup(path, options);
}

}  // namespace deformseg::io
