// A whole first program: reads two animations (or, given none, makes two bending tubes), then
// prints the strain of the first, its temporal segments and how alike the two move.
//   first_program A B     A and B: glTF clips as FILE.glb#CLIP (a file of one clip: FILE.glb), frame folders, globs
#include <deformseg/io/read_animation.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/strain/strain.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <exception>
#include <iostream>
#include <numbers>

using namespace deformseg;

// A tube bending at its middle joint: rest, bend, hold, unbend; `speed` bends faster.
mesh::Surface_mesh_animation bending_tube(std::size_t speed) {
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {20 / speed, {std::numbers::pi / 2}}, {10, {}}, {20 / speed, {0.0}}};
  return mesh::make_bending_tube(spec).animation;
}

int main(int argc, char** argv) try {
  const bool given = argc == 3;
  const mesh::Surface_mesh_animation a = given ? io::read_animation(argv[1]) : bending_tube(1);
  const mesh::Surface_mesh_animation b = given ? io::read_animation(argv[2]) : bending_tube(2);
  std::cout << "A: " << a.num_frames() << " frames of " << a.num_faces() << " triangles\n";

  // The normalised strain of every triangle of A at every frame, against frame 0.
  const strain::Strain_field<float> field = strain::compute_strain(a);
  std::cout << "strain of triangle 0 at the last frame: " << field(0, a.num_frames() - 1) << '\n';

  // Intervals of similar poses of A.
  const temporal::Temporal_segmentation poses = temporal::temporal_segmentation(a);
  for (const temporal::Temporal_segment& segment : poses.segments)
    std::cout << "segment: frames " << segment.first << " to " << segment.last << '\n';

  // How alike A and B move: 1 for the same motion, whatever the shape, size or frame rate; a faster
  // motion (as B's quicker bend) is another motion.
  const similarity::Similarity alike = similarity::motion_similarity(a, b);
  std::cout << "similarity of A and B: " << alike.value << '\n';
  return 0;
} catch (const std::exception& error) {  // deformseg::invalid_input names the file, line or frame
  std::cerr << "error: " << error.what() << '\n';
  return 1;
}
