// The same animation type with CGAL::Polyhedron_3 connectivity, and make_deforming_mesh to copy
// any model of the DeformingMesh concept into contiguous storage of another coordinate type.
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <CGAL/Polyhedron_3.h>

#include <array>
#include <iostream>
#include <vector>

int main() {
  using namespace deformseg;
  using Polyhedron = CGAL::Polyhedron_3<mesh::Kernel>;
  const std::vector<std::array<double, 3>> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::array<int, 3>> triangles{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

  // [polyhedron]
  mesh::Deforming_mesh<Polyhedron> animation(mesh::make_face_graph<Polyhedron>(points, triangles));
  for (int t = 0; t < 5; ++t) {  // the tetrahedron sliding along x
    std::vector<double> frame;
    for (const auto& p : points) frame.insert(frame.end(), {p[0] + 0.1 * t, p[1], p[2]});
    animation.add_frame(std::span<const double>(frame));
  }
  static_assert(mesh::DeformingMesh<mesh::Deforming_mesh<Polyhedron>>);

  const mesh::Deforming_mesh<Polyhedron, float> compact = mesh::make_deforming_mesh<float>(animation);
  // [polyhedron]
  std::cout << compact.num_frames() << " frames; " << animation.memory_bytes() << " bytes as double, "
            << compact.memory_bytes() << " as float\n";
  std::cout << "frame 4, vertex 1: " << compact.frame_matrix(4).col(1).transpose() << '\n';
  return 0;
}
