// check_distance_matrix: the checks the clustering policies make of a distance matrix (square,
// finite, not negative, zero diagonal, symmetric), for a policy or a front end of one's own; the
// message names the caller and the first entry at fault.
#include <deformseg/clustering/clustering.h>
#include <deformseg/exceptions.h>

#include <Eigen/Core>

#include <cstdio>

int main() {
  using namespace deformseg;
  Eigen::MatrixXd d(3, 3);
  d << 0, 2, 3,  //
      2, 0, 4,   //
      3, 4, 0;
  clustering::check_distance_matrix(d, "my_clustering");  // a distance matrix: no exception
  d(2, 1) = 5;                                           // no longer symmetric
  try {
    clustering::check_distance_matrix(d, "my_clustering");
  } catch (const invalid_input& e) {
    std::printf("%s\n", e.what());
    return 0;
  }
  return 1;
}
