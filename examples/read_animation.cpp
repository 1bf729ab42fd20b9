// The README's first program: make a synthetic animation, write it the ways users store theirs,
// read it back with read_animation, split a glTF clip's name off its file, and show what an error
// looks like.
//
//   read_animation [INPUT [TOPOLOGY]]   INPUT: a folder or "glob" of frames, or a .pc2/.mdd cache
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

using namespace deformseg;

void describe(const std::string& input, const mesh::Surface_mesh_animation& animation) {
  std::cout << input << " (" << io::animation_format(input) << "): " << animation.num_frames()
            << " frames, " << animation.num_vertices() << " vertices, " << animation.num_faces()
            << " triangles\n";
}

int main(int argc, char** argv) {
  if (argc > 1) {  // the user's own animation
    io::Animation_read_options options;
    if (argc > 2) options.topology = argv[2];
    describe(argv[1], io::read_animation(argv[1], options));
    return 0;
  }

  // A tube that bends by 90 degrees at its middle joint: rest, bend, hold, unbend.
  mesh::Bending_tube spec;
  spec.schedule = {{10, {0.0}}, {10, {std::numbers::pi / 2}}, {10, {}}, {10, {0.0}}};
  const auto tube = mesh::make_bending_tube(spec);

  // As a folder of OBJ frames, and as a point cache with its topology mesh.
  io::write_sequence(tube.animation, "tube_frames", {.format = io::Mesh_format::obj});
  io::write_obj(tube.animation, 0, "tube_topology.obj");
  io::write_pc2(tube.animation, "tube.pc2");

  const mesh::Surface_mesh_animation frames = io::read_animation("tube_frames");
  const mesh::Surface_mesh_animation cached = io::read_animation("tube.pc2", {.topology = "tube_topology.obj"});
  describe("tube_frames", frames);
  describe("tube.pc2", cached);
  std::cout << "frame 20, vertex 7: " << frames.frame_matrix(20).col(7).transpose() << '\n';

  // A glTF file's clip may be named after a '#', as the tool's commands take it.
  const auto [file, clip] = io::split_clip_suffix("Fox.glb#Walk");
  std::cout << "Fox.glb#Walk: file " << file << ", clip " << clip.value_or("(none)") << '\n';

  // Bad input is an invalid_input that says what and where.
  try {
    io::read_animation("tube.pc2");
  } catch (const invalid_input& e) {
    std::cout << "error: " << e.what() << "\n  file: " << e.where().file << "\n  message: " << e.message() << '\n';
  }
  return 0;
}
