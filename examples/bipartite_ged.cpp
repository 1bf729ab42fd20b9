// The bipartite approximation of the graph edit distance (Riesen & Bunke): fast, an upper bound.
#include <deformseg/ged/bipartite_ged.h>

#include <iostream>

int main() {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, int>;
  Graph star(4), path(4);  // node kinds: 0 for the centre, 1 for the others
  for (std::size_t v = 0; v < 4; ++v) star[v] = path[v] = v == 0 ? 0 : 1;
  for (std::size_t v = 1; v < 4; ++v) boost::add_edge(0, v, star);
  for (std::size_t v = 1; v < 4; ++v) boost::add_edge(v - 1, v, path);
  const deformseg::ged::Ged_result r = deformseg::ged::Bipartite_ged{}(star, path);
  std::cout << "star -> path: at most " << r.upper << " edits; mapping";
  for (std::size_t i = 0; i < r.mapping.size(); ++i) std::cout << ' ' << i << "->" << r.mapping[i];
  std::cout << '\n';
  return r.upper >= 2.0 ? 0 : 1;  // at least one edge out and one in
}
