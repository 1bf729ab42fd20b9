// A clip's nearest others in its own collection: eight tubes bend on schedules of their own, each
// is described once into a Motion_collection, and tube 3's two nearest other tubes are found, with
// the values similarity_matrix gives them (tube 3 itself is no candidate). Row 3 of knn_graph is
// the same search, so it gives the same neighbours.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/search/nearest_motions.h>
#include <deformseg/similarity/motion_similarity.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const similarity::Default_similarity policy;
  search::Motion_collection collection;
  // Tube i bends to a right angle in 2 + 2 i frames, holds, unbends, and rests.
  for (std::size_t i = 0; i < 8; ++i) {
    mesh::Bending_tube spec;
    spec.schedule = {{5, {0.0}}, {2 + 2 * i, {std::numbers::pi / 2}}, {6, {}}, {2 + 2 * i, {0.0}}, {5, {}}};
    collection.add(policy.describe(mesh::make_bending_tube(spec).animation));
  }
  // [others]
  const auto found = search::nearest_others(collection, 3, {.k = 2});
  // [others]
  std::cout << "nearest to tube 3:";
  for (const auto& n : found.neighbours) std::cout << " tube " << n.index << " (" << n.value << ")";
  std::cout << "\nof " << found.pruning.candidates << " other tubes, " << found.pruning.aligned << " aligned whole\n";
  const auto graph = search::knn_graph(collection, {.k = 2});
  std::cout << (graph[3].neighbours == found.neighbours ? "row 3 of the graph is the same\n" : "differs\n");
  return graph[3].neighbours == found.neighbours ? 0 : 1;
}
