// The strain histograms of a bending tube: each frame becomes the share of the tube's rest area
// that strains so much from the frame before, on 16 log-spaced bins from 0.05 to 1.
#include <deformseg/strain/strain_histograms.h>
#include <deformseg/mesh/synthetic.h>

#include <cstdio>
#include <numbers>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  const double right = std::numbers::pi / 2;
  spec.schedule = {{5, {}}, {10, {right}}, {5, {}}, {10, {0.0}}};  // rest, bend, hold, unbend
  const auto tube = mesh::make_bending_tube(spec).animation;

  const strain::Strain_histograms h = strain::strain_histograms(tube);  // T x (16 + 2), rows sum to 1
  const auto edges = strain::histogram_edges({});
  std::printf("%td frames, %td columns: rigid below %.2f, 16 log bins, overflow from %.0f\n", h.rows(), h.cols(),
              edges.front(), edges.back());
  for (Eigen::Index t : {0, 10, 18, 25})
    std::printf("frame %2td: rigid %.3f, deforming %.3f\n", t, h(t, 0), 1 - h(t, 0));

  // The same field binned otherwise, against the rest pose, with the areas as weights.
  const auto coarse = strain::strain_histograms(
      tube, {.strain = {.reference = strain::Strain_reference::rest_pose, .normalization = strain::No_normalization{}},
             .histogram = {.bins = 4, .min_strain = 1e-3}});
  std::printf("against the rest pose, frame 18 (bent): rigid %.3f\n", coarse(18, 0));
  return 0;
}
