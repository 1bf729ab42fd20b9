// The thesis' similarity with other plug-ins: exact graph edit distance under unit costs on the
// node kinds alone, agglomerative clustering into three labels, labels scored by the distance of
// their medoids, and dynamic time warping.
#include <deformseg/alignment/dtw.h>
#include <deformseg/clustering/agglomerative.h>
#include <deformseg/ged/exact_ged.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube once, twice;
  once.schedule = {
      {5, {0.0}}, {10, {right}, mesh::Easing::linear}, {8, {}}, {10, {0.0}, mesh::Easing::linear}, {5, {}}};
  twice.schedule = {{5, {0.0}}, {5, {right}, mesh::Easing::linear}, {4, {}}, {5, {0.0}, mesh::Easing::linear},
                    {5, {right}, mesh::Easing::linear}, {4, {}}, {5, {0.0}, mesh::Easing::linear}, {5, {}}};
  const auto a = mesh::make_bending_tube(once).animation;
  const auto b = mesh::make_bending_tube(twice).animation;

  // [policy]
  similarity::Evolving_graph_similarity<ged::Exact_ged, similarity::Segment_costs, clustering::Agglomerative,
                                        alignment::Dtw>
      policy;
  policy.segmentation.threshold = 0.01;  // the tube's whole blend zone deforms while it moves
  policy.costs.area_weight = 0;          // unit costs on the kinds, as METHOD.md's default
  policy.clustering.clusters = 3;
  policy.labels = similarity::Label_dissimilarity::medoids;
  // [policy]
  const similarity::Similarity s = similarity::motion_similarity(a, b, policy);
  std::cout << "one bend against two: " << s.value << " (DTW cost " << s.score << ")\n" << s.compared << '\n';
  std::cout << "one bend against itself: " << similarity::motion_similarity(a, a, policy).value << '\n';
  return 0;
}
