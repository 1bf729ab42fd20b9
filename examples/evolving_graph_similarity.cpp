// The thesis' similarity with other plug-ins: exact graph edit distance under unit costs on the
// node kinds alone, agglomerative clustering into three labels, labels scored by the distance of
// their medoids, and dynamic time warping.
#include <deformseg/alignment/dtw.h>
#include <deformseg/clustering/agglomerative.h>
#include <deformseg/ged/exact_ged.h>
#include <deformseg/motion_similarity.h>
#include <deformseg/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  Bending_tube once, twice;
  once.schedule = {{5, {0.0}}, {10, {right}, Easing::linear}, {8, {}}, {10, {0.0}, Easing::linear}, {5, {}}};
  twice.schedule = {{5, {0.0}}, {5, {right}, Easing::linear}, {4, {}}, {5, {0.0}, Easing::linear},
                    {5, {right}, Easing::linear}, {4, {}}, {5, {0.0}, Easing::linear}, {5, {}}};
  const auto a = make_bending_tube(once).animation;
  const auto b = make_bending_tube(twice).animation;

  // [policy]
  Evolving_graph_similarity<ged::Exact_ged, Segment_costs, clustering::Agglomerative, alignment::Dtw> policy;
  policy.segmentation.threshold = 0.01;  // the tube's whole blend zone deforms while it moves
  policy.costs.area_weight = 0;          // unit costs on the kinds, as METHOD.md's default
  policy.clustering.clusters = 3;
  policy.labels = Label_dissimilarity::medoids;
  // [policy]
  const Similarity s = motion_similarity(a, b, policy);
  std::cout << "one bend against two: " << s.value << " (DTW cost " << s.score << ")\n" << s.compared << '\n';
  std::cout << "one bend against itself: " << motion_similarity(a, a, policy).value << '\n';
}
