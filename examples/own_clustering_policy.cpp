// A clustering policy of one's own: any copyable type whose call operator takes the distance
// matrix and returns a deformseg::clustering::Clustering models the ClusteringPolicy concept and
// runs through cluster(), which makes its labels canonical and adds medoids and silhouette.
#include <deformseg/clustering/clustering.h>

#include <iostream>
#include <numeric>
#include <vector>

namespace dc = deformseg::clustering;

// Single-link clusters at a threshold: connected components of "closer than `threshold`".
struct Threshold_components {
  double threshold = 1.0;

  dc::Clustering operator()(const Eigen::MatrixXd& d) const {
    const auto n = std::size_t(d.rows());
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    const auto root = [&](std::size_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (d(Eigen::Index(i), Eigen::Index(j)) < threshold) parent[root(i)] = root(j);
    dc::Clustering c;
    for (std::size_t i = 0; i < n; ++i) c.labels.push_back(root(i));  // any values: cluster() renumbers
    return c;
  }
};
static_assert(dc::ClusteringPolicy<Threshold_components>);

int main() {
  const double x[] = {5.0, 0.0, 0.5, 5.4, 1.0, 9.0};
  Eigen::MatrixXd distances(6, 6);
  for (Eigen::Index i = 0; i < 6; ++i)
    for (Eigen::Index j = 0; j < 6; ++j) distances(i, j) = std::abs(x[i] - x[j]);
  const dc::Clustering c = dc::cluster(distances, Threshold_components{.threshold = 0.8});
  std::cout << c.clusters << " clusters, labels:";
  for (const std::size_t l : c.labels) std::cout << ' ' << l;  // 0 1 1 0 1 2
  std::cout << ", medoids:";
  for (const std::size_t m : c.medoids) std::cout << ' ' << m;  // 0 2 5
  std::cout << '\n';
  return c.labels == std::vector<std::size_t>{0, 1, 1, 0, 1, 2} ? 0 : 1;
}
