// Writes one frame of an animation as a PLY file with a colour per face, which MeshLab and
// ParaView show, in binary and in text; and the same frame as an OBJ file.
#include <deformseg/color/color.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/ply.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  // A tube bending at two joints; the generator says which joint moves each triangle.
  mesh::Bending_tube spec;
  spec.joints = {{.position = 0.3, .blend_width = 0.1}, {.position = 0.7, .blend_width = 0.1}};
  spec.schedule = {{10, {std::numbers::pi / 2, std::numbers::pi / 3}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& animation = tube.animation;

  // Grey for rigid triangles, red and blue for those of each joint.
  const std::vector<color::Rgb> palette{{200, 200, 200}, {220, 40, 40}, {40, 80, 220}};
  std::vector<color::Rgb> face_colors;
  for (const int joint : tube.face_joint) face_colors.push_back(palette[std::size_t(joint + 1)]);

  const std::size_t last = animation.num_frames() - 1;
  io::write_ply(animation, last, "tube_colored.ply", face_colors);
  io::write_ply(animation, last, "tube_colored_ascii.ply", face_colors, {.encoding = io::Ply_encoding::ascii});
  io::write_obj(animation, last, "tube.obj");
  std::cout << "frame " << last << ": " << animation.num_vertices() << " vertices, " << animation.num_faces()
            << " triangles, written to tube_colored.ply (binary), tube_colored_ascii.ply and tube.obj\n";
  return 0;
}
