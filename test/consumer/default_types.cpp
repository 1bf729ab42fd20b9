// Uses the algorithms on the default animation type (mesh::Surface_mesh_animation) with their default
// policies, as deformseg::compiled holds them: prints every result in hexadecimal floating point,
// so that a build against the compiled library and a header-only build compare to the last bit.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>
#include <deformseg/strain/strain.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <cstddef>
#include <iostream>
#include <numbers>
#include <vector>

using namespace deformseg;

namespace {

// A tube bending at its middle joint and back; `speed` bends faster.
mesh::Surface_mesh_animation bending_tube(std::size_t speed) {
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {20 / speed, {std::numbers::pi / 2}}, {10, {}}, {20 / speed, {0.0}}};
  return mesh::make_bending_tube(spec).animation;
}

}  // namespace

int main() {
  const std::vector<mesh::Surface_mesh_animation> tubes{bending_tube(1), bending_tube(2)};
  std::cout << std::hexfloat;
  for (const float value : strain::compute_strain(tubes[0]).values()) std::cout << value << ' ';
  std::cout << '\n';
  for (const double value : strain::compute_strain<double>(tubes[1]).values()) std::cout << value << ' ';
  std::cout << '\n';
  for (const temporal::Temporal_segment& s : temporal::temporal_segmentation(tubes[0]).segments)
    std::cout << "segment " << s.first << ' ' << s.last << ' ' << s.cost << '\n';
  const similarity::Similarity alike = similarity::motion_similarity(tubes[0], tubes[1]);
  std::cout << "similarity " << alike.value << ' ' << alike.score << ' ' << alike.alignment.size() << '\n';
  std::cout << "matrix " << similarity::similarity_matrix(tubes, similarity::Default_similarity{}, {}, 1) << '\n';
  const spatiotemporal::Spatiotemporal_segmentation parts = spatiotemporal::spatiotemporal_segmentation(tubes[0]);
  std::cout << "spatio-temporal segments " << parts.num_segments() << '\n';
  for (const spatiotemporal::Key_frame& key : spatiotemporal::evolving_graph(tubes[0]))
    std::cout << "key frame " << key.first_frame << ' ' << key.last_frame << ' ' << num_vertices(key.graph) << '\n';
  return 0;
}
