// Frame-to-frame distances between the strain histograms of two tubes of different shape doing the
// same bend, and of one doing it faster: the dissimilarity an alignment of the two would use.
#include <deformseg/strain/histogram_distance.h>
#include <deformseg/strain/strain_histograms.h>
#include <deformseg/mesh/synthetic.h>

#include <cstdio>
#include <numbers>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube slim;
  slim.schedule = {{4, {}}, {10, {right}}, {10, {0.0}}};
  mesh::Bending_tube thick = slim;
  thick.shape = {.radius = 0.2, .length = 1.5, .sectors = 24, .rings = 60};
  mesh::Bending_tube fast = slim;
  fast.schedule = {{4, {}}, {3, {right}}, {17, {0.0}}};

  const auto a = strain::strain_histograms(mesh::make_bending_tube(slim).animation);
  const auto b = strain::strain_histograms(mesh::make_bending_tube(thick).animation);
  const auto c = strain::strain_histograms(mesh::make_bending_tube(fast).animation);

  const Eigen::MatrixXd same = strain::histogram_distances(a, b);  // earth mover's, in [0, 1]
  const Eigen::MatrixXd faster = strain::histogram_distances(a, c);
  std::printf("frame 8 of the slim tube: to frame 8 of the thick one %.4f, of the fast one %.4f\n", same(8, 8),
              faster(8, 8));
  std::printf("mean over matching frames: same bend %.4f, faster bend %.4f\n", same.diagonal().mean(),
              faster.diagonal().mean());
  std::printf("total variation, frame 8: %.4f\n",
              strain::histogram_distance(a.row(8), b.row(8), strain::Histogram_metric::total_variation));
  return 0;
}
