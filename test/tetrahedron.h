// The tetrahedron (oriented outwards) that the mesh, reader and writer tests build, read and
// write: its points and triangles in the forms those tests compare, and as a face graph.
#pragma once

#include "test_support.h"

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/mesh/default_mesh.h>

#include <array>
#include <concepts>
#include <string>
#include <vector>

namespace deformseg::test {

inline const std::vector<std::array<double, 3>> tetra_points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
inline const std::vector<std::array<int, 3>> tetra_triangles{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

/// The same points, x y z after x y z, and triangles, as a reader's triangle soup holds them.
inline const std::vector<double> tetrahedron_points{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
inline const Triangles tetrahedron_triangles{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

/// The tetrahedron as a face graph of type `Graph`.
template <class Graph>
Graph tetrahedron() {
  return mesh::make_face_graph<Graph>(tetra_points, tetra_triangles);
}

/// A short name of the face graph type, for the names of the files a test writes.
template <class Graph>
std::string graph_name() {
  return std::same_as<Graph, mesh::Surface_mesh> ? "surface_mesh" : "polyhedron";
}

}  // namespace deformseg::test
