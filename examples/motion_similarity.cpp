// How alike two tubes move: the same schedule on a thin and on a thick tube, against another
// schedule on the thin one, by the default policy (motion signatures), by strain histograms and by
// the thesis' policy (evolving graphs).
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/strain_distribution_similarity.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube thin, thick, other;
  thin.schedule = {{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}};  // bend, hold, unbend
  thick = thin;
  thick.shape = {.radius = 0.16, .length = 1.5, .sectors = 12, .rings = 30, .caps = false};
  other.schedule = {{5, {0.0}}, {3, {right}}, {22, {}}, {3, {0.0}}, {5, {}}};  // a quick bend, a long hold
  const auto a = mesh::make_bending_tube(thin).animation;
  const auto b = mesh::make_bending_tube(thick).animation;
  const auto c = mesh::make_bending_tube(other).animation;

  const similarity::Similarity same =
      similarity::motion_similarity(a, b);  // Default_similarity: motion signatures, DTW
  std::cout << "same schedule, thin and thick tube: " << same.value << " (" << same.alignment.size()
            << " frame pairs aligned)\n";
  std::cout << "other schedule, same tube:          " << similarity::motion_similarity(a, c).value << '\n';
  std::cout << "compared: " << same.compared << "\n\n";

  const similarity::Strain_distribution_similarity<> strain;
  std::cout << "strain histograms, thin and thick:   " << similarity::motion_similarity(a, b, strain).value
            << "\nstrain histograms, other schedule:   " << similarity::motion_similarity(a, c, strain).value << "\n\n";

  const similarity::Evolving_graph_similarity<> thesis;
  const similarity::Similarity graphs = similarity::motion_similarity(a, b, thesis);
  std::cout << "thesis' policy, thin and thick:      " << graphs.value << "\nframe labels of the thin tube:";
  for (std::size_t label : graphs.labels_a) std::cout << ' ' << label;
  std::cout << "\nthesis' policy, other schedule:      " << similarity::motion_similarity(a, c, thesis).value << "\n\n";

  // The thin tube's first phase alone (standing still): Smith-Waterman's local alignment measured
  // against the shorter sequence (the default normalisation) finds it whole in the thin tube;
  // against the longer, the rest counts too.
  mesh::Bending_tube still = thin;
  still.schedule = {thin.schedule.front()};
  const auto d = mesh::make_bending_tube(still).animation;
  similarity::Strain_distribution_similarity<> by_longer;
  by_longer.normalization.length = similarity::Normalize_by::longer;
  std::cout << "standing still against the thin tube, by the shorter: "
            << similarity::motion_similarity(d, a, strain).value
            << ", by the longer: " << similarity::motion_similarity(d, a, by_longer).value << '\n';
  return 0;
}
