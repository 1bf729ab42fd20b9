// The work of a cluster, in one process: the similarity matrix of eight tubes assembled from
// tiles of 3 x 3 clips (the tiles on and above the diagonal, the others their mirrors), and the
// k-nearest-neighbour graph from blocks of rows searched among blocks of candidates, merged per
// row. Both equal the in-process results, value for value.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/search/nearest_motions.h>
#include <deformseg/search/similarity_tile.h>
#include <deformseg/similarity/motion_similarity.h>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <vector>

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
  const std::size_t n = collection.size(), tile = 3;
  std::vector<search::Clip_range> blocks;
  for (std::size_t begin = 0; begin < n; begin += tile) blocks.push_back({begin, std::min(n, begin + tile)});

  // [tiles]
  Eigen::MatrixXd matrix(n, n);
  for (std::size_t r = 0; r < blocks.size(); ++r)
    for (std::size_t c = r; c < blocks.size(); ++c) {
      const Eigen::MatrixXd values = search::similarity_tile(collection, blocks[r], blocks[c]);
      matrix.block(blocks[r].begin, blocks[c].begin, values.rows(), values.cols()) = values;
      matrix.block(blocks[c].begin, blocks[r].begin, values.cols(), values.rows()) = values.transpose();
    }
  // [tiles]
  std::cout << "matrix from " << blocks.size() << " x " << blocks.size() << " tiles: "
            << (matrix == search::similarity_matrix(collection) ? "the same" : "differs") << "\n";

  // [knn]
  const std::size_t k = 2;
  std::vector<search::Nearest_motions> graph;
  for (const search::Clip_range rows : blocks) {
    std::vector<std::vector<search::Nearest_motions>> parts;  // per block of candidates, per row
    for (const search::Clip_range candidates : blocks)
      parts.push_back(search::knn_graph(collection, rows, {.k = k, .candidates = candidates}));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      std::vector<search::Nearest_motions> row;
      for (const auto& part : parts) row.push_back(part[r]);
      graph.push_back(search::merge_nearest(row, k));
    }
  }
  // [knn]
  const auto whole = search::knn_graph(collection, {.k = k});
  bool same = true;
  for (std::size_t i = 0; i < n; ++i) same = same && graph[i].neighbours == whole[i].neighbours;
  std::cout << "k-nearest-neighbour graph from tiles: " << (same ? "the same" : "differs") << "\n";
  std::cout << "tube 3's nearest: tube " << graph[3].neighbours[0].index << " (" << graph[3].neighbours[0].value
            << ")\n";
  return same && matrix == search::similarity_matrix(collection) ? 0 : 1;
}
