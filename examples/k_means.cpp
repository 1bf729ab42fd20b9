// k-means on the graph embedding: each item becomes its vector of distances to the prototypes
// (by default all items), clustered by Lloyd's algorithm seeded by k-means++. Here the items are
// two rings of points in the plane, given only by their distances.
#include <deformseg/clustering/k_means.h>

#include <Eigen/Core>

#include <cmath>
#include <iostream>
#include <vector>

namespace dc = deformseg::clustering;

int main() {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 12; ++i) {
    const double angle = 0.5236 * i;
    const Eigen::Vector2d centre = i % 2 ? Eigen::Vector2d(30, 0) : Eigen::Vector2d(0, 0);
    points.push_back(centre + Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  const auto n = Eigen::Index(points.size());
  Eigen::MatrixXd distances(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) distances(i, j) = (points[std::size_t(i)] - points[std::size_t(j)]).norm();

  // [cluster]
  const dc::Clustering all = dc::cluster(distances, dc::K_means{.clusters = 2, .seed = 42});
  // Two prototypes are enough here: each item's distances to items 0 and 1.
  const dc::Clustering two = dc::cluster(distances, dc::K_means{.clusters = 2, .prototypes = {0, 1}});
  // [cluster]
  std::cout << "labels:";
  for (const std::size_t l : all.labels) std::cout << ' ' << l;  // 0 1 0 1 ...
  std::cout << "\nLloyd steps " << all.iterations << ", silhouette " << all.silhouette
            << "; with 2 prototypes the same labels: " << std::boolalpha << (two.labels == all.labels) << '\n';
  return two.labels == all.labels && all.labels[1] == 1 && all.labels[2] == 0 ? 0 : 1;
}
