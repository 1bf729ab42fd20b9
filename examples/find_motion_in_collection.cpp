// find_motion_in_collection: where a motion occurs in a library of clips. Four tubes are described
// once into a Motion_collection: three bend once, each at its own pace, one holds still, then
// bends. A query, a bend at the pace of clip 1, is looked for in all of them; the best windows
// over all the clips come back with their clip, frames and values (from the descriptions as
// stored, as find_motion_in gives them for each clip alone).
#include <deformseg/mesh/synthetic.h>
#include <deformseg/search/find_motion_in_collection.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <cstdio>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  constexpr double right = std::numbers::pi / 2;
  const auto bend = [](std::size_t pace) {
    return std::vector<mesh::Tube_phase>{{5, {0.0}}, {pace, {right}}, {8, {}}, {pace, {0.0}}, {5, {}}};
  };
  const similarity::Motion_signature_similarity<> policy;
  search::Motion_collection library;
  for (const std::size_t pace : {std::size_t(6), std::size_t(10), std::size_t(16)}) {
    mesh::Bending_tube spec;
    spec.schedule = bend(pace);
    library.add(policy.describe(mesh::make_bending_tube(spec).animation));
  }
  mesh::Bending_tube late;  // still for 20 frames, then the bend of clip 1
  late.schedule = {{20, {0.0}}};
  for (const mesh::Tube_phase& phase : bend(10)) late.schedule.push_back(phase);
  library.add(policy.describe(mesh::make_bending_tube(late).animation));

  mesh::Bending_tube query;
  query.schedule = bend(10);
  // [find]
  const std::vector<search::Clip_match> found =
      search::find_motion_in_collection(policy.describe(mesh::make_bending_tube(query).animation), library,
                                            {.count = 3});
  // [find]
  for (const search::Clip_match& c : found)
    std::printf("clip %zu, frames %zu to %zu: %.3f\n", c.clip, c.match.first, c.match.last, c.match.value);
  return !found.empty() && found.front().clip == 1 ? 0 : 1;
}
