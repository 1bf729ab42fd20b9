// Temporal segmentation of a tube that holds three poses, by each policy, and by a policy of
// one's own.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <string>

namespace {

void print(const std::string& name, const deformseg::temporal::Temporal_segmentation& result) {
  std::cout << name << ":";
  for (const auto& s : result.segments) std::cout << " [" << s.first << ", " << s.last << "]";
  std::cout << '\n';
}

// [policy]
// Segments of a fixed length: a policy of one's own, a model of TemporalSegmentationPolicy.
struct Fixed_length {
  std::size_t length = 10;
  std::vector<deformseg::temporal::Frame_interval> operator()(const deformseg::temporal::Segment_cost& cost) const {
    std::vector<deformseg::temporal::Frame_interval> out;
    for (std::size_t m = 0; m < cost.num_frames(); m += length)
      out.push_back({m, std::min(m + length, cost.num_frames()) - 1});
    return out;
  }
};
// [policy]

}  // namespace

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube spec;
  spec.joints = {{.position = 0.3}, {.position = 0.7}};
  // Poses held at frames 0-19, 23-42 and 46-65; transitions 20-23 and 43-46.
  spec.schedule = {{19, {}}, {4, {right, 0.0}}, {19, {}}, {4, {0.0, right}}, {19, {}}};
  const auto animation = mesh::make_bending_tube(spec).animation;

  // From the animation: normalised rest-pose strain, Euclidean frame distances, the optimum.
  print("optimal partition", temporal::temporal_segmentation(animation));

  // From a strain field, with other policies; the distances once, for all of them.
  // [policies]
  const temporal::Segment_cost cost(frame_distances(strain::compute_strain(animation)));
  print("3 segments", temporal::segment_frames(cost, temporal::Optimal_partition{.segments = 3}));
  print("binary split", temporal::segment_frames(cost, temporal::Binary_split{}));
  print("thesis greedy", temporal::segment_frames(cost, temporal::Thesis_greedy{.threshold = {.value = 0.1}}));
  print("Barbic PCA", temporal::segment_frames(cost, temporal::Barbic_pca{}));
  // [policies]
  // [use]
  const auto own = temporal::segment_frames(cost, Fixed_length{.length = 22});
  print("fixed length", own);
  // [use]
  std::cout << "frame 30 is in segment " << own.segment_of(30) << ", of cost " << own.segments[own.segment_of(30)].cost
            << '\n';
  return 0;
}
