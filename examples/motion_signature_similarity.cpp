// Motion_signature_similarity, the default policy: each frame as the area-weighted quantiles of how
// fast its vertices move, and how fast up or down, at lags of 1, 4, 16 and 128 thirtieths of a
// second (motion_signatures: rates per second at the animation's frame rate), frames aligned by DTW.
// With no argument, a tube bending and unbending is compared with the same motion on another,
// moved and scaled tube, and with other motions; each value is printed with its z-score against
// frame-shuffled copies (similarity_significance).
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/significance.h>
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

  // The signature of one frame in the middle of the bend, 8 quantiles per lag: the speeds, as log
  // RMS radii per second (30 fps); then the rates up (+Y), as asinh(rate / 9e-3), weighted by sqrt(0.2).
  const Eigen::MatrixXd signatures = signatures::motion_signatures(tube(bend_hold_unbend));
  std::printf("frame 10 of %zu, lag 1, speeds:     ", std::size_t(signatures.rows()));
  for (Eigen::Index q = 0; q < 8; ++q) std::printf(" %5.2f", signatures(10, q));
  std::printf("\nframe 10 of %zu, lag 1, rates up:   ", std::size_t(signatures.rows()));
  const Eigen::Index rates_up = signatures.cols() / 2;  // the speeds of every lag come first
  for (Eigen::Index q = rates_up; q < rates_up + 8; ++q) std::printf(" %5.2f", signatures(10, q));
  std::printf("\n\n");

  const similarity::Motion_signature_similarity<>
      policy;  // lags 1, 4, 16, 128 / 30 s; 8 quantiles; up +Y; scale 1.77; DTW
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
    std::printf("%-48s %.3f  (z-score %5.1f, %zu frame pairs)\n", c.name, s.value,
                similarity::similarity_significance(policy, query, described, 20, random), s.alignment.size());
  }
  return 0;
}
