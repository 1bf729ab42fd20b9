// coordinate_buffer: positions sized first, then each frame written once into its block (as the
// readers parse frames in parallel), becoming an animation's without a copy.
#include <deformseg/mesh/coordinate_buffer.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

int main() {
  using namespace deformseg;
  // A square of two triangles that stretches along x over 4 frames.
  const std::vector<std::array<double, 3>> rest{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<std::array<std::uint32_t, 3>> triangles{{0, 1, 2}, {0, 2, 3}};
  const std::size_t frames = 4, block = 3 * rest.size();

  mesh::Coordinate_buffer<double> positions(frames * block);  // unwritten: no pass of zeros
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t v = 0; v < rest.size(); ++v)
      for (std::size_t k = 0; k < 3; ++k)
        positions[t * block + 3 * v + k] = rest[v][k] * (k == 0 ? 1.0 + 0.5 * t : 1.0);
  const double* storage = positions.data();

  const mesh::Surface_mesh_animation animation(mesh::make_face_graph<mesh::Surface_mesh>(rest, triangles),
                                               std::move(positions));
  std::printf("%zu frames of %zu vertices; vertex 1 of the last frame at x = %.1f; storage %s\n",
              animation.num_frames(), animation.num_vertices(), animation.frame_positions(3)[3],
              animation.all_positions().data() == storage ? "taken, not copied" : "copied");
  return animation.all_positions().data() == storage && animation.frame_positions(3)[3] == 2.5 ? 0 : 1;
}
