// Progress: a long call reports its steps to a callback on the calling thread; the callback stops
// it by returning false, and the call then throws deformseg::cancelled. Here a similarity matrix
// of six animations, stopped once the animations are described.
#include <deformseg/exceptions.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/threads.h>

#include <cstddef>
#include <cstdio>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  std::vector<mesh::Surface_mesh_animation> animations;
  for (int k = 1; k <= 6; ++k) {
    mesh::Bending_tube spec;
    spec.shape.rings = 12;
    spec.schedule = {{4, {0.0}}, {8, {k * std::numbers::pi / 12}}, {4, {}}};
    animations.push_back(mesh::make_bending_tube(spec).animation);
  }
  const std::size_t n = animations.size();
  std::size_t last_done = 0;
  const Progress stop_after_descriptions = [&](std::size_t done, std::size_t total) {
    std::printf("%zu of %zu steps done\n", done, total);
    last_done = done;
    return done < n;  // the first n steps describe the animations; then come the pairs
  };
  try {
    similarity::similarity_matrix(animations, similarity::Default_similarity{}, stop_after_descriptions);
    std::printf("not stopped\n");
    return 1;
  } catch (const cancelled& e) {
    std::printf("stopped after %zu steps: %s\n", last_done, e.what());
  }
  return last_done == n ? 0 : 1;
}
