// The mean silhouette of a partition: near 1 when items are much nearer their own cluster than
// any other, near 0 for overlapping clusters, below 0 for a wrong partition.
#include <deformseg/clustering/clustering.h>

#include <cmath>
#include <iostream>

namespace dc = deformseg::clustering;

int main() {
  const double x[] = {0, 1, 5, 6, 7};
  Eigen::MatrixXd distances(5, 5);
  for (Eigen::Index i = 0; i < 5; ++i)
    for (Eigen::Index j = 0; j < 5; ++j) distances(i, j) = std::abs(x[i] - x[j]);

  const double good = dc::silhouette(distances, {0, 0, 1, 1, 1});
  const double wrong = dc::silhouette(distances, {0, 1, 1, 1, 0});
  const double one = dc::silhouette(distances, {0, 0, 0, 0, 0});  // one cluster: 0 by convention
  std::cout << "{0 1} {5 6 7}: " << good << "\n{0 7} {1 5 6}: " << wrong << "\none cluster: " << one << '\n';
  return good > 0.7 && wrong < 0 && one == 0 ? 0 : 1;
}
