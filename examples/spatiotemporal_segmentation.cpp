// Spatio-temporal segments of a tube that bends and straightens: which triangles deform, in
// which frames, as one segment per movement.
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{10, {}}, {10, {std::numbers::pi / 2}}, {10, {}}, {10, {0.0}}};  // rest, bend, hold, unbend
  const auto animation = mesh::make_bending_tube(spec).animation;

  // The defaults: previous-pose strain above 0.5 is deformed; segments of fewer than 10
  // triangles or 2 frames removed; rigid islands of up to 30 triangles absorbed.
  const spatiotemporal::Spatiotemporal_segmentation segments = spatiotemporal::spatiotemporal_segmentation(animation);
  std::cout << segments.num_segments() << " segments\n";
  for (std::size_t k = 0; k < segments.num_segments(); ++k) {
    const auto& e = segments.extent(k);
    std::cout << "segment " << k << ": frames " << e.first_frame << "-" << e.last_frame << ", " << e.cells
              << " triangle-frames, at most " << e.largest_slice << " triangles in a frame\n";
  }
  std::size_t deformed_at_15 = 0;
  for (std::int32_t label : segments.frame_labels(15))
    deformed_at_15 += label != spatiotemporal::Spatiotemporal_segmentation::rigid;
  std::cout << "frame 15: " << deformed_at_15 << " deformed triangles\n";

  // Rest-pose strain, without clean-up: deformed while away from the rest pose.
  const auto pose = spatiotemporal::spatiotemporal_segmentation(
      animation,
      {.reference = strain::Strain_reference::rest_pose, .min_triangles = 1, .min_frames = 1, .max_island = 0});
  std::cout << "against the rest pose, without clean-up: " << pose.num_segments() << " segments\n";
  return 0;
}
