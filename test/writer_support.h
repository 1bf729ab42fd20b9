// What the writers' tests (io_obj.cpp, io_off_ply.cpp, io_frame_sequence.cpp) share: a drifting
// tetrahedron whose coordinates have long decimal expansions, the face lines a writer gives, and
// CGAL's reading of the files back.
#pragma once

#include "tetrahedron.h"

#include <deformseg/color/color.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

namespace deformseg::test {

/// The points and polygons CGAL's readers give.
using Point_3 = CGAL::Simple_cartesian<double>::Point_3;
using Polygons = std::vector<std::vector<std::size_t>>;

/// Frame t moves vertex i by (t / 10, t / 3, -t i / 7): values with long decimal expansions.
template <class Coordinate>
std::vector<Coordinate> drifting_positions(std::size_t frames) {
  std::vector<Coordinate> xyz;
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t i = 0; i < 4; ++i) {
      const double d = double(t);
      xyz.push_back(Coordinate(tetra_points[i][0] + d / 10));
      xyz.push_back(Coordinate(tetra_points[i][1] + d / 3));
      xyz.push_back(Coordinate(tetra_points[i][2] - d * double(i) / 7));
    }
  return xyz;
}

template <class Graph, class Coordinate = double>
mesh::Deforming_mesh<Graph, Coordinate> drifting_tetrahedron(std::size_t frames) {
  return mesh::Deforming_mesh<Graph, Coordinate>(tetrahedron<Graph>(), drifting_positions<Coordinate>(frames));
}

/// A path for a file a writer test writes, in a folder of its own, emptied first.
inline std::filesystem::path writer_output(const std::string& test, const std::string& name) {
  return fresh_dir("writers/" + test) / name;
}

/// The triangles of a polygon soup, each rotated to start at its smallest index, as the
/// animation's triangle table may start each cycle anywhere.
inline std::vector<std::array<std::size_t, 3>> canonical_triangles(const Polygons& polygons) {
  std::vector<std::array<std::size_t, 3>> triangles;
  for (const auto& polygon : polygons) {
    REQUIRE(polygon.size() == 3);
    std::array<std::size_t, 3> triangle{polygon[0], polygon[1], polygon[2]};
    std::rotate(triangle.begin(), std::min_element(triangle.begin(), triangle.end()), triangle.end());
    triangles.push_back(triangle);
  }
  return triangles;
}

inline Polygons tetra_polygons() {
  Polygons polygons;
  for (const auto& t : tetra_triangles) polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  return polygons;
}

/// Checks the points read back against frame `frame` of the animation, exactly.
template <class Animation>
void check_points(const std::vector<Point_3>& points, const Animation& animation, std::size_t frame) {
  REQUIRE(points.size() == animation.num_vertices());
  const auto xyz = animation.frame_positions(frame);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(points[i][k] == double(xyz[3 * i + k]));
}

/// The face lines the animation's triangle table gives, with a suffix each (colours).
template <class Animation>
std::string face_lines(const Animation& animation, const char* prefix, int base,
                       const std::vector<std::string>& suffixes) {
  std::string lines;
  for (std::size_t j = 0; j < animation.num_faces(); ++j) {
    lines += prefix;
    for (const auto v : animation.triangles()[j]) lines.append(" ").append(std::to_string(v + base));
    if (!suffixes.empty()) lines.append(suffixes[j]);
    lines.append("\n");
  }
  return lines;
}

/// Reads a PLY file with CGAL, face colours included (CGAL wants both colour iterators of one type).
inline bool read_ply_colored(const std::filesystem::path& file, std::vector<Point_3>& points, Polygons& polygons,
                             std::vector<CGAL::IO::Color>& face_colors) {
  std::vector<CGAL::IO::Color> vertex_colors;
  return CGAL::IO::read_PLY(file.string(), points, polygons,
                            CGAL::parameters::face_color_output_iterator(std::back_inserter(face_colors))
                                .vertex_color_output_iterator(std::back_inserter(vertex_colors)));
}

inline const std::vector<color::Rgb> four_colors{{255, 0, 0}, {0, 128, 0}, {0, 0, 255}, {12, 34, 56}};

}  // namespace deformseg::test
