// matrix_dissimilarity: an n x m matrix computed beforehand (distances between the frames of two
// animations, between cluster medoids...) as the dissimilarity an alignment policy reads.
#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>

int main() {
  namespace al = deformseg::alignment;
  // Frame t of the first animation at height sin(t / 4), of the second at sin(t / 8): the same
  // motion at half the speed; the entries are the absolute differences.
  Eigen::MatrixXd distances(20, 40);
  for (Eigen::Index i = 0; i < distances.rows(); ++i)
    for (Eigen::Index j = 0; j < distances.cols(); ++j)
      distances(i, j) = std::abs(std::sin(double(i) / 4) - std::sin(double(j) / 8));
  const al::Alignment path = al::Dtw{}.align(20, 40, al::matrix_dissimilarity(distances));
  std::printf("DTW cost %.3f over %zu pairs; frame 10 of the first matches frames", path.score, path.pairs.size());
  bool twice_as_late = false;  // frame 10 with frame 20, where the second is at the same height
  for (const auto& [i, j] : path.pairs)
    if (i == 10) {
      std::printf(" %zu", j);
      twice_as_late = twice_as_late || j == 20;
    }
  std::printf(" of the second\n");
  return twice_as_late ? 0 : 1;
}
