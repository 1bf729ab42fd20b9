// find_motion: where a short motion occurs in a long animation. With no argument, a tube that
// bends, holds and unbends (39 frames) is looked for in a long animation of another tube that does
// it twice, among other motions; the two windows are printed with their values.
#include <deformseg/similarity/find_motion.h>
#include <deformseg/mesh/synthetic.h>

#include <cstdio>
#include <numbers>
#include <vector>

using namespace deformseg;

int main() {
  constexpr double right = std::numbers::pi / 2;
  const std::vector<mesh::Tube_phase> motion{{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}};
  mesh::Bending_tube query_spec, long_spec;
  query_spec.schedule = motion;
  long_spec.shape = {.radius = 0.16, .length = 1.5, .sectors = 12, .rings = 30, .caps = false};
  // Half bends (frames 0-12), the motion (12-50), a hold, half bends, the motion (80-118), a hold.
  long_spec.schedule = {{6, {right / 2}}, {6, {0.0}}};
  long_spec.schedule.insert(long_spec.schedule.end(), motion.begin(), motion.end());
  long_spec.schedule.insert(long_spec.schedule.end(), {{18, {}}, {6, {right / 2}}, {6, {0.0}}});
  long_spec.schedule.insert(long_spec.schedule.end(), motion.begin(), motion.end());
  long_spec.schedule.push_back({10, {}});
  const auto query = mesh::make_bending_tube(query_spec).animation;
  const auto long_animation = mesh::make_bending_tube(long_spec).animation;

  // The three best non-overlapping windows, by the default policy (motion signatures).
  for (const similarity::Motion_match& m : similarity::find_motion(query, long_animation, {.count = 3}))
    std::printf("frames %3zu to %3zu of %zu: %.3f (%zu frame pairs)\n", m.first, m.last,
                long_animation.num_frames(), m.value, m.alignment.size());
  return 0;
}
