/// @file io/ply.h
/// @brief Reads a PLY mesh (text or binary): `read_ply`; with io/write_ply.h, writes one: `write_ply`.
#pragma once

#include <deformseg/io/internal/ply_body.h>
#include <deformseg/io/triangle_soup.h>
#include <deformseg/io/write_ply.h>

#include <filesystem>

namespace deformseg::io {

/// @brief Reads a PLY mesh, text (`format ascii`) or binary (either byte order): its vertices and
/// triangles.
///
/// The vertices are the `vertex` element's `x`, `y`, `z` properties (float or double); the faces
/// are the `face` element's `vertex_indices` (or `vertex_index`) list, indices from 0. Other
/// properties (normals, colours, texture coordinates) and elements are passed over. The header
/// is checked whole before the body is read: its lines, types, and element counts against the
/// size of the file, so that nothing is allocated for counts the file cannot hold.
///
/// @param path the file to read.
/// @param options `triangulate` (default false): fan-triangulate faces of more than 3 vertices
/// instead of rejecting them.
/// @return the vertices and triangles in the order of the file.
/// @pre the file is a PLY with at least one vertex, finite coordinates, and faces of 3 vertices
/// (or more, with `triangulate`) whose indices are in `[0, V)`; the `vertex` element comes before
/// the `face` element.
/// @throws invalid_input naming the file (and the line of a text PLY's error; the element and
/// item of a value) when the file is missing or unreadable, is not a PLY, has a malformed header
/// (an unknown line or type, a property before any element, no x, y or z, no integer
/// vertex_indices list, counts more than the file holds), a truncated body, a malformed or
/// out-of-range value, a non-finite coordinate, a face that is not a triangle, an index out of
/// range, or no vertex.
/// @par Complexity O(size of the file).
inline Triangle_soup read_ply(const std::filesystem::path& path, const Mesh_read_options& options = {}) {
  return internal::read_ply_soup(path, options);
}

}  // namespace deformseg::io
