// The graph edit distance between every two graphs of a set, in parallel.
#include <deformseg/ged/ged_matrix.h>

#include <iostream>
#include <vector>

int main() {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, int>;
  // Paths of 2 to 5 nodes, all of kind 0: from a path of n nodes to one of m, |n - m| nodes and
  // |n - m| edges are inserted.
  std::vector<Graph> paths;
  for (std::size_t n = 2; n <= 5; ++n) {
    Graph g(n);
    for (std::size_t v = 0; v < n; ++v) g[v] = 0;
    for (std::size_t v = 1; v < n; ++v) boost::add_edge(v - 1, v, g);
    paths.push_back(g);
  }
  // [matrix]
  const Eigen::MatrixXd d = deformseg::ged::ged_matrix(paths);
  // [matrix]
  std::cout << "distances between paths of 2 to 5 nodes:\n" << d << '\n';
  // The same with Bipartite_ged, both directions, and a progress report.
  const auto r = deformseg::ged::ged_matrix_results(
      paths, deformseg::ged::Bipartite_ged{}, deformseg::ged::Unit_costs{},
      {.both_directions = true, .progress = [](std::size_t done, std::size_t total) {
         std::cout << "pair " << done << " of " << total << '\n';
         return true;
       }});
  return d(0, 3) == 6 && r.distance(0, 3) >= d(0, 3) ? 0 : 1;
}
