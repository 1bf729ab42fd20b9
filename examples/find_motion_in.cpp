// find_motion_in: where a short motion occurs in a long animation, from the two descriptions as
// made once (a search over many queries describes the long animation only once; find_motion then
// re-describes each window it keeps). A tube bends and unbends; the long animation does it twice.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <cstdio>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  constexpr double right = std::numbers::pi / 2;
  const std::vector<mesh::Tube_phase> motion{{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}};
  mesh::Bending_tube query_spec, long_spec;
  query_spec.schedule = motion;
  long_spec.schedule = motion;  // frames 0-37, a hold of 20 frames, the motion again from frame 58
  long_spec.schedule.push_back({20, {}});
  long_spec.schedule.insert(long_spec.schedule.end(), motion.begin(), motion.end());

  const similarity::Motion_signature_similarity<> policy;
  const auto query = policy.describe(mesh::make_bending_tube(query_spec).animation);
  const auto long_animation = policy.describe(mesh::make_bending_tube(long_spec).animation);
  const std::vector<similarity::Motion_match> matches =
      similarity::find_motion_in(policy, query, long_animation, {.count = 2});
  for (const similarity::Motion_match& m : matches)
    std::printf("frames %zu to %zu: %.3f\n", m.first, m.last, m.value);
  return matches.size() == 2 && matches[0].first != matches[1].first ? 0 : 1;
}
