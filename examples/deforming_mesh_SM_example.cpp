// Builds an animation from a reference mesh and per-frame position arrays, with CGAL::Surface_mesh
// connectivity, and reads it back three ways: raw coordinates, an Eigen matrix, a point map.
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <array>
#include <iostream>
#include <vector>

int main() {
  using namespace deformseg;
  // The reference mesh: a square made of two triangles, counter-clockwise seen from +z.
  const std::vector<std::array<double, 3>> points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  const mesh::Surface_mesh reference = mesh::make_face_graph<mesh::Surface_mesh>(points, triangles);

  // Three frames, one block of 3 x V coordinates each: the square, the square stretched along x,
  // the square lifted along z.
  std::vector<double> positions;
  const std::array<std::pair<double, double>, 3> stretch_and_lift{{{1.0, 0.0}, {1.5, 0.0}, {1.0, 1.0}}};
  for (const auto& [stretch, lift] : stretch_and_lift)
    for (const auto& p : points) positions.insert(positions.end(), {stretch * p[0], p[1], p[2] + lift});

  mesh::Surface_mesh_animation animation(reference, positions);
  // Frames can also be appended one at a time, here from the reference mesh's own points.
  animation.add_frame_from(get(CGAL::vertex_point, reference));

  std::cout << animation.num_frames() << " frames, " << animation.num_vertices() << " vertices, "
            << animation.num_faces() << " triangles\n";
  std::cout << "frame 1, vertex 2 (raw):      " << animation.frame_positions(1)[6] << ' '
            << animation.frame_positions(1)[7] << ' ' << animation.frame_positions(1)[8] << '\n';
  std::cout << "frame 1, vertex 2 (Eigen):    " << animation.frame_matrix(1).col(2).transpose() << '\n';
  const auto points_at_1 = animation.frame_point_map(1);
  std::cout << "frame 1, vertex 2 (point map): " << get(points_at_1, animation.vertex_descriptors()[2]) << '\n';
  std::cout << "triangle 1: " << animation.triangles()[1][0] << ' ' << animation.triangles()[1][1] << ' '
            << animation.triangles()[1][2] << '\n';
  return 0;
}
