// Writes every frame of an animation into a folder, one file per frame with zero-padded names:
// PLY files coloured per frame by how far each triangle has moved, and OBJ files.
#include <deformseg/color/color.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/mesh/synthetic.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{15, {std::numbers::pi / 2}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& animation = tube.animation;

  // A face's colour at frame t: from white (still) to red (moved by a fifth of the tube's length
  // or more), by how far its first vertex has moved since frame 0.
  const auto moved = [&](std::size_t t) {
    std::vector<color::Rgb> colors;
    for (const auto& triangle : animation.triangles()) {
      const double distance =
          (animation.frame_matrix(t).col(triangle[0]) - animation.frame_matrix(0).col(triangle[0])).norm();
      const auto fade = static_cast<std::uint8_t>(255 * (1 - std::min(distance / 0.2, 1.0)));
      colors.push_back({255, fade, fade});
    }
    return colors;
  };

  // [write]
  const auto ply = io::write_sequence(animation, "tube_ply", {.face_colors = moved});
  const auto obj = io::write_sequence(animation, "tube_obj", {.format = io::Mesh_format::obj});
  // [write]
  // The name a frame gets: zero-padded so that plain and natural sorting agree.
  std::cout << "frame 7 of 16 is written as " << io::sequence_file_name(7, 16, {.format = io::Mesh_format::obj})
            << '\n';
  std::cout << ply.size() << " PLY files, " << ply.front().string() << " to " << ply.back().string() << '\n'
            << obj.size() << " OBJ files, " << obj.front().string() << " to " << obj.back().string() << '\n';
  return 0;
}
