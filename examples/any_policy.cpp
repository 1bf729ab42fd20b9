// Any_policy and visit_policy: similarity policies of different types held alike, as a program
// holds the one its user picks at run time, and used as any policy, by one function written once
// for all. A tube bending and unbending is compared with another timing of the same bend by each.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/any_policy.h>
#include <deformseg/similarity/motion_similarity.h>

#include <cstdio>
#include <numbers>
#include <utility>
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
  const auto a = tube({{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}});
  const auto b = tube({{5, {0.0}}, {3, {right}}, {22, {}}, {3, {0.0}}, {5, {}}});

  similarity::Motion_signature_similarity<alignment::Smith_waterman> speeds;  // speeds alone, aligned locally
  speeds.signatures.up = std::nullopt;
  const std::vector<std::pair<const char*, similarity::Any_policy>> policies{
      {"motion signatures, DTW (the default)", similarity::Default_similarity{}},
      {"motion signatures: speeds, Smith-Waterman", speeds},
      {"strain histograms, DTW", similarity::Strain_distribution_similarity<alignment::Dtw>{}},
      {"self-similarity", similarity::Self_similarity_matching<>{}},
      {"evolving graphs (the thesis')", similarity::Graph_similarity<alignment::Smith_waterman>{}},
      {"evolving graphs (characters)", similarity::character_graph_similarity()},
  };
  for (const auto& [name, policy] : policies) {
    const similarity::Similarity s =
        similarity::visit_policy(policy, [&](const auto& p) { return similarity::motion_similarity(a, b, p); });
    std::printf("%-42s %.3f (%zu aligned pairs)\n", name, s.value, s.alignment.size());
  }
  return 0;
}
