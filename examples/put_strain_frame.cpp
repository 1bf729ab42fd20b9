// One frame of strain, and its principal directions, written into face property maps of a
// CGAL::Surface_mesh, as a CGAL algorithm downstream would read them.
#include <deformseg/strain/strain.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{8, {std::numbers::pi / 3}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto field = strain::compute_strain(tube.animation, {.principal_directions = true});

  // A copy of the connectivity, with two face properties.
  // [property_maps]
  mesh::Surface_mesh mesh = tube.animation.face_graph();
  auto strain = mesh.add_property_map<mesh::Surface_mesh::Face_index, float>("f:strain", 0.0f).first;
  auto direction =
      mesh.add_property_map<mesh::Surface_mesh::Face_index, mesh::Kernel::Vector_3>("f:stretch_direction").first;
  strain::put_strain_frame(field, 8, mesh, strain);
  strain::put_principal_directions(field, 8, mesh, direction);
  // [property_maps]

  std::size_t strained = 0;
  mesh::Surface_mesh::Face_index most = *faces(mesh).begin();
  for (auto f : faces(mesh)) {
    if (strain[f] > 0.1f) ++strained;
    if (strain[f] > strain[most]) most = f;
  }
  std::cout << strained << " of " << mesh.number_of_faces() << " faces have a normalised strain above 0.1 at frame 8\n";
  std::cout << "face " << most << ": strain " << strain[most] << ", stretched along " << direction[most] << '\n';
  return 0;
}
