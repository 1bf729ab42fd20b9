// Hierarchical agglomerative clustering of points on a line: average and complete linkage
// disagree on where the point 5 belongs, and the dendrogram can be cut by k or by height.
#include <deformseg/clustering/agglomerative.h>

#include <cmath>
#include <iostream>

namespace dc = deformseg::clustering;

namespace {

void print(const char* what, const dc::Clustering& c) {
  std::cout << what << ":";
  for (const std::size_t l : c.labels) std::cout << ' ' << l;
  std::cout << "  (" << c.clusters << " clusters)\n";
}

}  // namespace

int main() {
  const double x[] = {0.0, 2.0, 5.0, 9.5};
  Eigen::MatrixXd distances(4, 4);
  for (Eigen::Index i = 0; i < 4; ++i)
    for (Eigen::Index j = 0; j < 4; ++j) distances(i, j) = std::abs(x[i] - x[j]);

  // {0, 2} merge first; then 5 is at a mean distance 4 of them but 4.5 from 9.5 (average joins
  // it to {0, 2}), and at most 5 from them (complete joins it to 9.5 instead).
  // [linkage]
  const auto average = dc::cluster(distances, dc::Agglomerative{.linkage = dc::Linkage::average, .clusters = 2});
  const auto complete = dc::cluster(distances, dc::Agglomerative{.linkage = dc::Linkage::complete, .clusters = 2});
  const auto cut = dc::cluster(distances, dc::Agglomerative{.linkage = dc::Linkage::complete, .height = 3.0});
  // [linkage]
  print("average, k = 2 ", average);    // 0 0 0 1
  print("complete, k = 2", complete);   // 0 0 1 1
  print("complete, h = 3", cut);        // 0 0 1 2
  return average.labels[2] == 0 && complete.labels[2] == 1 && cut.clusters == 3 ? 0 : 1;
}
