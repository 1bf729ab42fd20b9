// outlier_check: a vertex absurdly far for its mesh's own scale, as corrupt data gives it, found
// frame by frame (what the tool warns of, and refuses with --refuse-defects).
#include <deformseg/io/outlying_vertices.h>
#include <deformseg/mesh/synthetic.h>

#include <cstdio>
#include <numbers>
#include <span>
#include <vector>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{10, {0.0}}, {10, {std::numbers::pi / 2}}, {10, {}}, {10, {0.0}}};  // 41 frames
  const auto tube = mesh::make_bending_tube(spec).animation;
  const io::Outlier_check check(tube.frame_positions(0));
  std::printf("median radius %.3f\n", check.scale());
  std::size_t found = 0;
  for (std::size_t t = 0; t < tube.num_frames(); ++t) {
    std::vector<double> frame(tube.frame_positions(t).begin(), tube.frame_positions(t).end());
    if (t == 12) frame[3 * 40] = 1e20;  // a corrupted coordinate
    if (const auto outlier = check(std::span<const double>(frame), t)) {
      std::printf("%s\n", outlier->text().c_str());
      ++found;
    }
  }
  return found == 1 ? 0 : 1;
}
