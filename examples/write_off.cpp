// write_off: one frame of an animation as an OFF file, each coordinate as the shortest text that
// reads back to it; read_off then gives the same points and triangles.
#include <deformseg/io/off.h>
#include <deformseg/mesh/synthetic.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{10, {std::numbers::pi / 2}}};
  const auto animation = mesh::make_bending_tube(spec).animation;
  const std::size_t last = animation.num_frames() - 1;
  io::write_off(animation, last, "tube.off");

  std::ifstream file("tube.off");
  std::string line;
  for (int i = 0; i < 4 && std::getline(file, line); ++i) std::cout << line << '\n';  // OFF, comment, counts, vertex 0
  const io::Triangle_soup soup = io::read_off("tube.off");
  const bool same = std::ranges::equal(soup.points, animation.frame_positions(last)) &&
                    std::ranges::equal(soup.triangles, animation.triangles());
  std::cout << "read back: " << soup.num_vertices() << " vertices, " << soup.triangles.size() << " triangles, "
            << (same ? "the same" : "different") << '\n';
  return same ? 0 : 1;
}
