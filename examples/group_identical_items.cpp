// group_identical_items: the items of a distance matrix at distance exactly 0 from one another
// (copies of one animation, say) merged into weighted groups, as cluster() hands them to a
// WeightedClusteringPolicy; check_distance_matrix first, as cluster() does.
#include <deformseg/clustering/clustering.h>

#include <Eigen/Core>

#include <cstdio>

int main() {
  using namespace deformseg;
  // Items 0 and 2 are the same animation, and so are 1, 3 and 4.
  Eigen::MatrixXd d(5, 5);
  d << 0, 1, 0, 1, 1,  //
      1, 0, 1, 0, 0,   //
      0, 1, 0, 1, 1,   //
      1, 0, 1, 0, 0,   //
      1, 0, 1, 0, 0;
  clustering::check_distance_matrix(d, "group_identical_items example");
  const clustering::Grouped_items groups = clustering::group_identical_items(d);
  for (std::size_t g = 0; g < groups.weights.size(); ++g)
    std::printf("group %zu: first item %zu, %.0f items\n", g, groups.first_item[g], groups.weights[g]);
  std::printf("distance between the groups: %.1f\n", groups.distances(0, 1));
  return groups.weights.size() == 2 && groups.group_of_item[4] == 1 ? 0 : 1;
}
