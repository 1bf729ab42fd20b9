// motion_signatures_streamed: the motion signatures of a point cache read frame by frame, holding
// only the frames within the longest lag of the rows being computed, equal to the last bit to those
// of the whole animation read into memory.
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signature_stream.h>
#include <deformseg/signatures/motion_signatures.h>

#include <cstdio>
#include <cstring>
#include <numbers>
#include <span>
#include <vector>

int main() {
  using namespace deformseg;
  // A tube bending and unbending for 400 frames (13 s at 30 fps), as a PC2 cache and its topology.
  mesh::Bending_tube spec;
  for (int k = 0; k < 8; ++k) spec.schedule.push_back({50, {k % 2 == 0 ? std::numbers::pi / 2 : 0.0}});
  const auto tube = mesh::make_bending_tube(spec).animation;
  io::write_pc2(tube, "tube.pc2");
  io::write_obj(tube, 0, "tube.obj");

  // [stream]
  io::Point_cache_frame_source source("tube.pc2", {.topology = "tube.obj", .fps = 30});
  const std::vector<double> instants = signatures::frame_instants(source.num_frames(), source.frames_per_second());
  const signatures::Motion_signature_options options;  // lags of 1, 4, 16 and 128 thirtieths of a second
  const Eigen::MatrixXd streamed =
      signatures::motion_signatures_streamed(source, options, std::span<const double>(instants));
  const std::size_t ring = signatures::streamed_ring_frames(options, 30, source.num_frames(),
                                                            std::span<const double>(instants));
  // [stream]
  std::printf("%td signatures of %td values; %zu of %zu frames held at once\n", streamed.rows(), streamed.cols(),
              ring, source.num_frames());

  // The same cache read whole: the same signatures, bit for bit.
  const auto whole = io::read_animation("tube.pc2", {.topology = "tube.obj"});
  const Eigen::MatrixXd in_memory = signatures::motion_signatures(whole, options);
  const bool same = in_memory.rows() == streamed.rows() && in_memory.cols() == streamed.cols() &&
                    std::memcmp(in_memory.data(), streamed.data(), sizeof(double) * std::size_t(streamed.size())) == 0;
  std::printf("equal to the in-memory signatures: %s\n", same ? "yes" : "no");
  return same ? 0 : 1;
}
