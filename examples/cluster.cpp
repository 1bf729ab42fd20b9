// deformseg::clustering::cluster runs any clustering policy on a distance matrix, and items at
// distance exactly 0 (say, graphs at graph edit distance 0) always get the same label, even when
// more clusters are asked for than there are distinct items.
#include <deformseg/clustering/agglomerative.h>
#include <deformseg/clustering/k_medoids.h>

#include <iostream>

namespace dc = deformseg::clustering;

int main() {
  // Items 0, 1 and 3 are the same (distance 0); items 2 and 4 are different.
  Eigen::MatrixXd distances(5, 5);
  distances << 0, 0, 3, 0, 8,
               0, 0, 3, 0, 8,
               3, 3, 0, 3, 6,
               0, 0, 3, 0, 8,
               8, 8, 6, 8, 0;
  const dc::Clustering pam = dc::cluster(distances, dc::K_medoids{.clusters = 4});
  const dc::Clustering tree = dc::cluster(distances, dc::Agglomerative{.clusters = 2});
  std::cout << "k-medoids, 4 asked:";
  for (const std::size_t l : pam.labels) std::cout << ' ' << l;  // 0 0 1 0 2: 3 distinct items
  std::cout << "\nagglomerative, 2:  ";
  for (const std::size_t l : tree.labels) std::cout << ' ' << l;  // 0 0 0 0 1
  std::cout << '\n';
  return pam.clusters == 3 && pam.labels[3] == pam.labels[0] && tree.labels[4] == 1 ? 0 : 1;
}
