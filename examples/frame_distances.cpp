// The frame distance matrix of a tube that holds three poses, and the within-segment
// dissimilarity Ds of a few intervals, in O(1) each.
#include <deformseg/strain/frame_distances.h>
#include <deformseg/temporal/segment_cost.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube spec;
  spec.joints = {{.position = 0.3}, {.position = 0.7}};
  // Poses (0, 0), (90, 0), (0, 90) degrees at frames 0-9, 13-22, 26-35; transitions 10-13, 23-26.
  spec.schedule = {{9, {}}, {4, {right, 0.0}}, {9, {}}, {4, {0.0, right}}, {9, {}}};
  const auto field = strain::compute_strain(mesh::make_bending_tube(spec).animation);

  const Eigen::MatrixXf euclidean = frame_distances(field);
  const Eigen::MatrixXd cosine = frame_distances<double>(field, {.metric = strain::Frame_metric::cosine});
  std::cout << "frames " << euclidean.rows() << "; distance 0-5 " << euclidean(0, 5) << ", 0-20 " << euclidean(0, 20)
            << ", 20-30 " << euclidean(20, 30) << "; cosine 20-30 " << cosine(20, 30) << '\n';

  const temporal::Segment_cost cost(euclidean);
  std::cout << "mean distance " << cost.mean_distance() << "; Ds(0, 9) " << cost(0, 9) << ", Ds(13, 22) "
            << cost(13, 22) << ", Ds(5, 18) " << cost(5, 18) << " (across a transition)\n";
  return 0;
}
