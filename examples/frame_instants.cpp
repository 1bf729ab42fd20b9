// frame_instants: the instants of an animation's frames, t / fps seconds. The same bend sampled at 30
// and at 60 frames per second has, at the same instants, the same motion signatures (up to the
// interpolation between frames): the 60 fps clip is described at the 30 fps clip's frame instants.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signatures.h>

#include <cstdio>
#include <numbers>
#include <span>
#include <vector>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube at_30;
  at_30.schedule = {{5, {0.0}}, {15, {right}}, {10, {}}};
  mesh::Bending_tube at_60 = at_30;  // the same phases in twice the frames
  at_60.schedule = {{10, {0.0}}, {30, {right}}, {20, {}}};
  const auto slow = mesh::make_bending_tube(at_30).animation;
  auto fine = mesh::make_bending_tube(at_60).animation;
  fine.set_frames_per_second(60);

  const std::vector<double> instants = signatures::frame_instants(slow.num_frames(), slow.frames_per_second());
  std::printf("%zu frames at 30 fps: instants 0, %.4f, %.4f, ..., %.4f s\n", instants.size(), instants[1],
              instants[2], instants.back());

  const Eigen::MatrixXd reference = signatures::motion_signatures(slow);
  const Eigen::MatrixXd same_instants = signatures::with_positions_and_weights(fine, [&](auto positions, auto weights) {
    return signatures::motion_signatures_at(positions, weights, {}, fine.frames_per_second(),
                                            std::span<const double>(instants));
  });
  // Frame t of the 60 fps clip is at t / 60 s: row by row, its first frames are the first half-second only.
  const Eigen::MatrixXd same_frames = signatures::motion_signatures(fine).topRows(reference.rows());
  const double at_instants = (same_instants - reference).cwiseAbs().maxCoeff();
  const double at_frames = (same_frames - reference).cwiseAbs().maxCoeff();
  std::printf("largest difference from the 30 fps signatures: at its instants %.3f, frame by frame %.3f\n",
              at_instants, at_frames);
  return at_instants < at_frames / 4 ? 0 : 1;
}
