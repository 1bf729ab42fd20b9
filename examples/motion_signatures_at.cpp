// motion_signatures_at: the motion signature of an animation at instants of one's choosing (seconds
// from its first frame), between its frames too, from its raw positions and vertex weights. At a
// frame's own instant it is that frame's row of motion_signatures.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/signatures/procrustes_distances.h>

#include <cstdio>
#include <numbers>
#include <span>
#include <vector>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}, {5, {}}};
  const auto tube = mesh::make_bending_tube(spec).animation;  // 30 frames per second
  const std::span<const double> positions = tube.all_positions();
  const std::span<const double> first_frame = tube.frame_positions(0);
  const std::vector<double> weights =
      signatures::vertex_area_weights(first_frame, tube.triangles(), tube.num_vertices());

  // Frame 10's instant, a third of the way to frame 11, and frame 11's.
  const std::vector<double> instants{10.0 / 30, 31.0 / 90, 11.0 / 30};
  const Eigen::MatrixXd at = signatures::motion_signatures_at(
      positions, std::span<const double>(weights), {}, tube.frames_per_second(), std::span<const double>(instants));
  const Eigen::MatrixXd every_frame = signatures::motion_signatures(tube);
  // Column 4: the 5th of 8 quantiles of the speeds at the shortest lag (1/30 s), as log RMS radii per second.
  std::printf("median speed at 10/30 s %.4f, at 31/90 s %.4f, at 11/30 s %.4f\n", at(0, 4), at(1, 4), at(2, 4));
  std::printf("motion_signatures, frames 10 and 11:        %.4f, %.4f\n", every_frame(10, 4), every_frame(11, 4));
  return at.row(0) == every_frame.row(10) && at.row(2) == every_frame.row(11) ? 0 : 1;
}
