// An animation of one's own on OpenMesh: a TriMesh for the connectivity (a FaceGraph through CGAL's
// graph traits for OpenMesh) and one vector of points per frame, read through per-frame point
// maps. It models DeformingMesh, so the algorithms take it as it is: here the strain and the
// temporal segmentation of a bending tube, the same to the last bit as on the default model.
// Built when CMake finds OpenMesh (Debian: libopenmesh-dev).
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/strain/strain.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <numbers>
#include <utility>
#include <vector>

// [own mesh type]
// OpenMesh with double points (its default traits hold floats).
struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
using Tri_mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// The positions of one frame, by vertex handle: a readable Boost property map.
class Frame_points {
public:
  using key_type = boost::graph_traits<Tri_mesh>::vertex_descriptor;
  using value_type = Tri_mesh::Point;
  using reference = const Tri_mesh::Point&;
  using category = boost::readable_property_map_tag;

  explicit Frame_points(const std::vector<Tri_mesh::Point>& points) : points_(&points) {}
  friend reference get(const Frame_points& map, key_type v) { return (*map.points_)[std::size_t(v.idx())]; }

private:
  const std::vector<Tri_mesh::Point>* points_;
};

// An animation: the connectivity once, the points of each frame in OpenMesh's vertex order.
struct Open_mesh_animation {
  using Face_graph = Tri_mesh;
  Tri_mesh mesh;
  std::vector<std::vector<Tri_mesh::Point>> frames;

  const Tri_mesh& face_graph() const { return mesh; }
  std::size_t num_frames() const { return frames.size(); }
  Frame_points frame_point_map(std::size_t t) const { return Frame_points(frames.at(t)); }
};
static_assert(deformseg::mesh::DeformingMesh<Open_mesh_animation>);
// [own mesh type]

int main() {
  using namespace deformseg;
  // A tube bending by a right angle, holding, and straightening, made on OpenMesh's TriMesh.
  mesh::Bending_tube spec;
  spec.shape = {.sectors = 12, .rings = 30};
  const double right = std::numbers::pi / 2;
  spec.schedule = {{6, {0.0}}, {6, {right}}, {6, {}}, {6, {0.0}}, {6, {}}};
  const auto tube = mesh::make_bending_tube<Tri_mesh>(spec).animation;

  // Its frames as vectors of OpenMesh points, vertex i at index i.
  Open_mesh_animation animation{tube.face_graph(), {}};
  for (std::size_t t = 0; t < tube.num_frames(); ++t) {
    const auto xyz = tube.frame_positions(t);
    std::vector<Tri_mesh::Point> points;
    for (std::size_t i = 0; i < tube.num_vertices(); ++i) points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    animation.frames.push_back(std::move(points));
  }

  // [algorithms]
  const strain::Strain_field<float> field = strain::compute_strain(animation);
  const temporal::Temporal_segmentation segments = temporal::temporal_segmentation(animation);
  // [algorithms]
  const auto largest = *std::max_element(field.values().begin(), field.values().end());
  std::cout << animation.num_frames() << " frames of " << animation.mesh.n_vertices() << " vertices and "
            << animation.mesh.n_faces() << " triangles; largest strain " << largest << '\n';
  std::cout << "segments:";
  for (const auto& s : segments.segments) std::cout << ' ' << s.first << '-' << s.last;
  std::cout << '\n';

  // The same field, to the last bit, as on the default model (Surface_mesh connectivity).
  const auto on_default = strain::compute_strain(mesh::make_bending_tube(spec).animation);
  const bool same = std::ranges::equal(field.values(), on_default.values());
  std::cout << (same ? "the same strain as on a Surface_mesh\n" : "a strain other than on a Surface_mesh\n");
  return same ? 0 : 1;
}
