// with_positions_and_weights: a per-frame measure of one's own over any DeformingMesh, from its
// contiguous positions (T x 3V) and its vertices' shares of the first frame's area. Here the height
// of the surface's area-weighted centroid, frame by frame, as a tube bends over.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signatures.h>

#include <cstddef>
#include <cstdio>
#include <numbers>
#include <span>
#include <vector>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}, {5, {}}};
  const auto tube = mesh::make_bending_tube(spec).animation;  // upright along z, 1 long

  const std::vector<double> heights =
      signatures::with_positions_and_weights(tube, [](auto positions, std::span<const double> weights) {
        const std::size_t vertices = weights.size(), frames = positions.size() / (3 * vertices);
        std::vector<double> height(frames, 0.0);
        for (std::size_t t = 0; t < frames; ++t)
          for (std::size_t v = 0; v < vertices; ++v) height[t] += weights[v] * positions[3 * (t * vertices + v) + 2];
        return height;
      });
  std::printf("centroid height: frame 0 %.3f, frame 10 %.3f, frame %zu %.3f\n", heights[0], heights[10],
              heights.size() - 1, heights.back());
  return heights.back() < heights[0] ? 0 : 1;  // the upper half now lies sideways
}
