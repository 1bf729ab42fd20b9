// The nearest motions of a query among a collection of described tubes: each tube bends on its
// own schedule, each is described once into a Motion_collection, and the search gives the 3 most
// similar with their values (those similarity_matrix gives) and how many it never had to align.
// Then every tube's 2 nearest others: the k-nearest-neighbour graph.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/search/nearest_motions.h>
#include <deformseg/similarity/motion_similarity.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const similarity::Default_similarity policy;
  search::Motion_collection collection;
  // Tube i bends to a right angle in 2 + i frames, holds, unbends, and rests.
  for (std::size_t i = 0; i < 12; ++i) {
    mesh::Bending_tube spec;
    spec.schedule = {{5, {0.0}}, {2 + i, {std::numbers::pi / 2}}, {6, {}}, {2 + i, {0.0}}, {5, {}}};
    collection.add(policy.describe(mesh::make_bending_tube(spec).animation));
  }
  // [search]
  const auto found = search::nearest_motions(collection.view(5), collection, {.k = 3});
  // [search]
  std::cout << "nearest to tube 5:";
  for (const auto& n : found.neighbours) std::cout << " tube " << n.index << " (" << n.value << ")";
  std::cout << "\nof " << found.pruning.candidates << " candidates, " << found.pruning.aligned
            << " aligned whole\n";

  // [graph]
  const auto graph = search::knn_graph(collection, {.k = 2});
  // [graph]
  for (std::size_t i = 0; i < graph.size(); ++i) {
    std::cout << "tube " << i << ":";
    for (const auto& n : graph[i].neighbours) std::cout << ' ' << n.index;
    std::cout << '\n';
  }
  return 0;
}
