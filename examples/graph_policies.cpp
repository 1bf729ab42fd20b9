// The two evolving-graph policies on bending tubes: the thesis' method (Evolving_graph_similarity
// with its defaults, thesis_segmentation) and the settings tuned on game characters
// (character_graph_similarity, character_segmentation). A bend on a thin tube is compared with the
// same bend on a thicker tube and with two bends; each policy's segmentation is printed first.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_similarity.h>

#include <cstdio>
#include <numbers>
#include <vector>

using namespace deformseg;

namespace {

mesh::Surface_mesh_animation tube(const std::vector<mesh::Tube_phase>& schedule, const mesh::Tube_shape& shape = {}) {
  mesh::Bending_tube spec;
  spec.shape = shape;
  spec.schedule = schedule;
  return mesh::make_bending_tube(spec).animation;
}

void print(const char* name, const spatiotemporal::Spatiotemporal_options& o) {
  char sigma[32] = "each animation's own";
  if (o.sigma) std::snprintf(sigma, sizeof sigma, "%g", *o.sigma);
  std::printf("%s: sigma %s, threshold %g, segments of %zu frames and more, part links %s\n", name, sigma,
              o.threshold, o.min_frames, o.parts.contact_distance > 0 || o.parts.rigid_tolerance > 0 ? "on" : "off");
}

template <class Policy>
void compare(const char* name, const Policy& policy) {
  constexpr double right = std::numbers::pi / 2;
  const std::vector<mesh::Tube_phase> bend{{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}};
  const auto a = tube(bend);
  const auto thicker = tube(bend, {.radius = 0.16, .length = 1.5, .sectors = 12, .rings = 30, .caps = false});
  const auto twice = tube({{5, {0.0}}, {5, {right}}, {4, {}}, {5, {0.0}}, {5, {right}}, {4, {}}, {5, {0.0}}, {5, {}}});
  std::printf("%s: the same bend on a thicker tube %.3f, two bends %.3f\n", name,
              similarity::motion_similarity(a, thicker, policy).value,
              similarity::motion_similarity(a, twice, policy).value);
}

}  // namespace

int main() {
  print("the thesis' segmentation", similarity::thesis_segmentation());
  print("the characters' segmentation", similarity::character_segmentation());
  compare("the thesis' graph policy (Smith-Waterman)", similarity::Evolving_graph_similarity<>{});
  compare("tuned on game characters (DTW)", similarity::character_graph_similarity());
  return 0;
}
