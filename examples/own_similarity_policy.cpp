// A similarity policy of one's own: each frame described by the fraction of its area that
// deforms (normalised previous-pose strain above 0.5), frames aligned by Smith-Waterman on the
// difference of those fractions.
#include <deformseg/mesh/face_areas.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/mesh/synthetic.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

struct Deformed_area_similarity {
  using Description = std::vector<double>;  // per frame, the share of the area that deforms

  template <deformseg::mesh::DeformingMesh Mesh>
  Description describe(const Mesh& animation) const {
    const auto strain =
        deformseg::strain::compute_strain(animation, {.reference = deformseg::strain::Strain_reference::previous_pose});
    const std::vector<double> areas = deformseg::mesh::face_areas(animation, 0);
    double total = 0;
    for (double a : areas) total += a;
    Description shares;
    for (std::size_t t = 0; t < strain.num_frames(); ++t) {
      double deformed = 0;
      for (std::size_t f = 0; f < areas.size(); ++f) deformed += strain.frame(t)[f] > 0.5f ? areas[f] : 0.0;
      shares.push_back(deformed / total);
    }
    return shares;
  }

  deformseg::similarity::Similarity compare(const Description& a, const Description& b) const {
    const deformseg::alignment::Smith_waterman sw;
    const auto d = [&](std::size_t i, std::size_t j) { return std::min(1.0, 10 * std::abs(a[i] - b[j])); };
    deformseg::alignment::Alignment aligned = sw.align(a.size(), b.size(), d);
    deformseg::similarity::Similarity s;
    s.value = deformseg::similarity::Best_score_normalization{}(sw, aligned, a.size(), b.size());
    s.score = aligned.score;
    s.alignment = std::move(aligned.pairs);
    s.compared = "the deformed share of the area, frame by frame";
    return s;
  }
};

static_assert(
    deformseg::similarity::SimilarityPolicy<Deformed_area_similarity, deformseg::mesh::Surface_mesh_animation>);

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}, {8, {}}, {10, {0.0}}, {5, {}}};
  const auto a = mesh::make_bending_tube(spec).animation;
  spec.shape.radius = 0.2;
  const auto b = mesh::make_bending_tube(spec).animation;
  std::cout << "own policy, thin against thick tube: "
            << similarity::motion_similarity(a, b, Deformed_area_similarity{}).value << '\n';
  return 0;
}
