// procrustes_distance and centred_weighted_frames: the weighted Procrustes distance of two frames
// (the smallest distance over rotations, no reflection) that procrustes_distances computes for
// every pair of frames of an animation. Frame 1 is frame 0 turned by 90 degrees about z, frame 2
// its mirror image.
#include <deformseg/signatures/procrustes_distances.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

int main() {
  using namespace deformseg;
  // Four points of an L, x y z each, in three frames.
  const std::vector<double> positions{0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 1,     // frame 0
                                      0, 0, 0, 0, 2, 0, -1, 0, 0, 0, 0, 1,    // turned about z
                                      0, 0, 0, -2, 0, 0, 0, 1, 0, 0, 0, 1};   // mirrored in x
  const std::vector<double> weights(4, 0.25);
  // Rows 3t..3t+2: frame t centred, weighted and scaled to the animation's RMS radius.
  const Eigen::MatrixXd rows = signatures::centred_weighted_frames(positions, weights, 3);
  const auto distance = [&](Eigen::Index a, Eigen::Index b) {
    const Eigen::MatrixXd x = rows.middleRows(3 * a, 3), y = rows.middleRows(3 * b, 3);
    return signatures::procrustes_distance(x * y.transpose(), x.squaredNorm(), y.squaredNorm());
  };
  const Eigen::MatrixXd all = signatures::procrustes_distances(positions, weights);
  std::printf("turned: %.6f, mirrored: %.6f (procrustes_distances: %.6f, %.6f)\n", distance(0, 1), distance(0, 2),
              all(0, 1), all(0, 2));
  return distance(0, 1) < 1e-6 && distance(0, 2) > 0.1 && std::abs(distance(0, 2) - all(0, 2)) < 1e-9 ? 0 : 1;
}
