// Uses the algorithms alone (deformseg::deformseg): a one-triangle animation, stretched along x in
// its second frame, has no strain at rest and some once stretched.
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/strain/strain.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <utility>
#include <vector>

int main() {
  using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
  const std::vector<std::array<double, 3>> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}};
  std::vector<double> rest_then_stretched{0, 0, 0, 1, 0, 0, 0, 1, 0, /**/ 0, 0, 0, 2, 0, 0, 0, 1, 0};
  const deformseg::mesh::Deforming_mesh<Mesh> animation(deformseg::mesh::make_face_graph<Mesh>(points, triangles),
                                                  std::move(rest_then_stretched));
  const deformseg::strain::Strain_field<float> strain = deformseg::strain::compute_strain(animation);
  return animation.num_frames() == 2 && strain(0, 0) == 0 && strain(0, 1) > 0 ? 0 : 1;
}
