// Motion_signature_dissimilarity: the frame dissimilarities of two described animations, computed
// when an alignment asks for them (a cell or a row at a time) by the float kernel of the default
// policy. Here two tubes bending at different paces are described, one row and one cell are read,
// and DTW over the lazy dissimilarity gives the policy's own compare value.
#include <deformseg/alignment/dtw.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signature_kernel.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <cstdio>
#include <numbers>
#include <vector>

using namespace deformseg;

namespace {

mesh::Surface_mesh_animation tube(const std::vector<mesh::Tube_phase>& schedule) {
  mesh::Bending_tube spec;
  spec.schedule = schedule;
  return mesh::make_bending_tube(spec).animation;
}

}  // namespace

int main() {
  constexpr double right = std::numbers::pi / 2;
  const similarity::Motion_signature_similarity<> policy;
  const auto a = policy.describe(tube({{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}}));
  const auto b = policy.describe(tube({{5, {0.0}}, {20, {right}}, {4, {}}, {20, {0.0}}, {5, {}}}));

  // The dissimilarity refers to the descriptions' floats (similarity::view); 1 / (64 scale^2) by default.
  const signatures::Motion_signature_dissimilarity d(
      similarity::view(a), similarity::view(b),
      signatures::frame_dissimilarity_unit(std::size_t(a.signatures.cols()), policy.scale));
  std::vector<double> row(d.cols());
  d.row(20, 0, d.cols(), row.data());  // frame 20 of a (held bent) against every frame of b
  std::printf("frame 20 of a against b's frames 0, 25, 50: %.3f %.3f %.3f\n", row[0], row[25], row[50]);
  const bool same_cell = d(20, 25) == row[25];  // a cell read alone is the value read in its row

  // DTW over the lazy dissimilarity: the value 1 - mean along the path is compare's.
  const alignment::Alignment path = alignment::Dtw{}.align(d.rows(), d.cols(), d);
  const double value = 1.0 - path.score / double(path.pairs.size());
  std::printf("DTW over %zu x %zu frames: value %.4f (compare: %.4f)\n", d.rows(), d.cols(), value,
              policy.compare(a, b).value);
  return same_cell && value == policy.compare(a, b).value ? 0 : 1;
}
