// k-medoids (PAM) on a distance matrix: three groups of points on a line, clustered with k given
// and with k chosen by the best mean silhouette. Each cluster has a medoid, one of its items.
#include <deformseg/clustering/k_medoids.h>

#include <cmath>
#include <iostream>

namespace dc = deformseg::clustering;

int main() {
  const double x[] = {0.0, 0.4, 10.0, 0.2, 10.3, 20.0, 9.8, 20.5, 0.1};
  const Eigen::Index n = 9;
  Eigen::MatrixXd distances(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) distances(i, j) = std::abs(x[i] - x[j]);

  // [cluster]
  const dc::Clustering given = dc::cluster(distances, dc::K_medoids{.clusters = 3});
  const dc::Clustering chosen = dc::cluster(distances, dc::K_medoids{});  // k by silhouette, 2..10
  // [cluster]
  std::cout << "labels:";
  for (const std::size_t l : given.labels) std::cout << ' ' << l;  // 0 0 1 0 1 2 1 2 0
  std::cout << "\nmedoids:";
  for (const std::size_t m : given.medoids) std::cout << " item " << m << " (x = " << x[m] << ")";
  std::cout << "\nk by silhouette: " << chosen.clusters << ", mean silhouette " << chosen.silhouette
            << ", swaps " << chosen.iterations << '\n';
  return given.labels == chosen.labels && chosen.clusters == 3 ? 0 : 1;
}
