// Self_similarity_matching: motion similarity through each animation's own frame x frame
// Procrustes distances, so no correspondence between the two meshes is needed. With no argument,
// a tube bending and unbending is compared with the same motion on another, moved and scaled
// tube, and with other motions; each value is printed with its z-score against frame-shuffled
// copies and the frames aligned.
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/mesh/synthetic.h>

#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

mesh::Surface_mesh_animation tube(const std::vector<mesh::Tube_phase>& schedule, const mesh::Tube_shape& shape = {},
                            const mesh::Placement& placement = {}) {
  mesh::Bending_tube spec;
  spec.shape = shape;
  spec.schedule = schedule;
  spec.placement = placement;
  return mesh::make_bending_tube(spec).animation;
}

}  // namespace

int main() {
  constexpr double right = std::numbers::pi / 2;
  const std::vector<mesh::Tube_phase> bend_hold_unbend{{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}};
  const mesh::Tube_shape thick{.radius = 0.16, .length = 1.5, .sectors = 12, .rings = 30, .caps = false};
  const mesh::Placement moved{.scale = 3, .translation = Eigen::Vector3d(1, 2, 3)};

  const similarity::Self_similarity_matching<> policy;  // window 30 frames, 16 quantiles, tolerance 0.3
  const auto query = policy.describe(tube(bend_hold_unbend));
  struct Candidate {
    const char* name;
    mesh::Surface_mesh_animation animation;
  };
  const Candidate candidates[] = {
      {"the same motion, another tube, moved and scaled", tube(bend_hold_unbend, thick, moved)},
      {"a quick bend, a long hold", tube({{5, {0.0}}, {3, {right}}, {22, {}}, {3, {0.0}}, {5, {}}}, thick)},
      {"a third of the bend", tube({{5, {0.0}}, {10, {right / 3}}, {8, {}}, {10, {0.0}}, {5, {}}}, thick)},
      {"standing still", tube({{38, {0.0}}}, thick)},
  };
  std::mt19937 random(1);  // for the z-scores against 20 frame-shuffled copies
  for (const Candidate& c : candidates) {
    const auto described = policy.describe(c.animation);
    const similarity::Similarity s = policy.compare(query, described);
    const double z = similarity::self_similarity_significance(policy, query, described, 20, random);
    std::printf("%-50s value %.3f, z %5.1f, %zu frames aligned\n", c.name, s.value, z, s.alignment.size());
  }
  return 0;
}
