// Builds a one-triangle animation through the installed headers and checks what it reads back.
#include <deformseg/mesh/deforming_mesh.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <vector>

int main() {
  using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
  const std::vector<std::array<double, 3>> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}};
  deformseg::mesh::Deforming_mesh<Mesh> animation(deformseg::mesh::make_face_graph<Mesh>(points, triangles));
  animation.add_frame_from(get(CGAL::vertex_point, animation.face_graph()));
  return animation.num_frames() == 1 && animation.num_faces() == 1 ? 0 : 1;
}
