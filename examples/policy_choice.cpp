// with_policy_choice: a similarity policy chosen by name, as a program's user gives it (here as
// arguments: POLICY [ALIGNMENT [UP]], e.g. `policy_choice histogram dtw`). With no argument, a
// tube bending and unbending is compared with another timing of the same bend by every policy
// with its own alignment, then by the motion signatures without their vertical rates; a bad name
// is refused before anything is computed.
#include <deformseg/exceptions.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/policy_choice.h>
#include <deformseg/mesh/synthetic.h>

#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

using namespace deformseg;

namespace {

mesh::Surface_mesh_animation tube(const std::vector<mesh::Tube_phase>& schedule) {
  mesh::Bending_tube spec;
  spec.schedule = schedule;
  return mesh::make_bending_tube(spec).animation;
}

}  // namespace

int main(int argc, char** argv) {
  constexpr double right = std::numbers::pi / 2;
  const auto a = tube({{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}});
  const auto b = tube({{5, {0.0}}, {3, {right}}, {22, {}}, {3, {0.0}}, {5, {}}});

  std::vector<similarity::Policy_choice> choices;
  if (argc > 1) {
    choices.push_back({.policy = argv[1], .alignment = argc > 2 ? argv[2] : "", .up = argc > 3 ? argv[3] : ""});
  } else {
    for (const auto name : similarity::policy_names) choices.push_back({.policy = std::string(name)});
    choices.push_back({.up = "none"});
    choices.push_back({.policy = "histogram", .up = "+z"});  // refused: the histograms have no up
  }
  for (const similarity::Policy_choice& choice : choices) {
    const std::string up = choice.up.empty() ? "" : ", up " + choice.up;
    const std::string name = choice.policy + ", " + similarity::alignment_name(choice) + up;
    try {
      const double value = similarity::with_policy_choice(
          choice, [&](const auto& policy) { return similarity::motion_similarity(a, b, policy).value; });
      std::printf("%-40s %.3f\n", name.c_str(), value);
    } catch (const invalid_input& e) {
      std::printf("%-40s refused: %s\n", name.c_str(), e.what());
    }
  }
}
