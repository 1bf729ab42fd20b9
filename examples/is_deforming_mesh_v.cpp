// is_deforming_mesh_v: one function for every DeformingMesh that reads a Deforming_mesh's stored
// positions straight from memory and any other model through its point maps, chosen at compile
// time. The other model here is a view of the same animation that only gives point maps.
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/mesh/synthetic.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <numbers>

namespace {

using namespace deformseg;

// A model of DeformingMesh that is not a Deforming_mesh: the animation seen through its point maps.
struct Point_map_view {
  using Face_graph = mesh::Surface_mesh;
  const mesh::Surface_mesh_animation* animation;
  const Face_graph& face_graph() const { return animation->face_graph(); }
  std::size_t num_frames() const { return animation->num_frames(); }
  auto frame_point_map(std::size_t t) const { return animation->frame_point_map(t); }
};

// The highest z of frame t.
template <mesh::DeformingMesh Mesh>
double top(const Mesh& animation, std::size_t t) {
  double z = -std::numeric_limits<double>::infinity();
  if constexpr (mesh::is_deforming_mesh_v<Mesh>) {  // x y z of every vertex, one after the other
    const auto xyz = animation.frame_positions(t);
    for (std::size_t i = 2; i < xyz.size(); i += 3) z = std::max(z, double(xyz[i]));
  } else {
    const auto points = animation.frame_point_map(t);
    for (const auto v : vertices(animation.face_graph())) z = std::max(z, double(get(points, v).z()));
  }
  return z;
}

}  // namespace

int main() {
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}};
  const auto tube = mesh::make_bending_tube(spec).animation;
  const Point_map_view view{&tube};
  static_assert(mesh::is_deforming_mesh_v<mesh::Surface_mesh_animation> && !mesh::is_deforming_mesh_v<Point_map_view>);
  std::printf("top of the last frame: %.4f from the stored positions, %.4f through the point maps\n",
              top(tube, tube.num_frames() - 1), top(view, tube.num_frames() - 1));
  return top(tube, tube.num_frames() - 1) == top(view, tube.num_frames() - 1) ? 0 : 1;
}
