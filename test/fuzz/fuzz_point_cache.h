// The topology the point cache harnesses read their inputs with: a tetrahedron (4 vertices).
#pragma once

#include <deformseg/mesh/default_mesh.h>

#include <array>
#include <vector>

namespace deformseg::fuzz {

inline const mesh::Surface_mesh& tetrahedron() {
  static const mesh::Surface_mesh mesh = mesh::make_face_graph<mesh::Surface_mesh>(
      std::vector<std::array<double, 3>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  return mesh;
}

}  // namespace deformseg::fuzz
