// Colours for normalised strain, one per face of a frame: what deformseg::io::write_ply takes as
// face colours to show a frame coloured by strain.
#include <deformseg/strain/strain.h>
#include <deformseg/color/strain_colors.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  std::cout << "the map, from 0 to 1:";
  for (double v = 0; v <= 1.0; v += 0.25) {
    const color::Rgb c = color::strain_color(v);
    std::cout << "  " << v << " -> (" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ")";
  }
  std::cout << '\n';

  mesh::Bending_tube spec;
  spec.schedule = {{6, {std::numbers::pi / 2}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto field = strain::compute_strain(tube.animation);
  // [colors]
  const std::vector<color::Rgb> colors = color::strain_colors(field.frame(6));
  // io::write_ply(tube.animation, 6, "frame_6.ply", colors) writes it as a coloured mesh.
  // [colors]
  std::size_t not_darkest = 0;
  for (const color::Rgb& c : colors) not_darkest += c == color::strain_colormap.front() ? 0 : 1;
  std::cout << colors.size() << " face colours for frame 6, " << not_darkest << " of them above the colour of 0\n";
  return 0;
}
