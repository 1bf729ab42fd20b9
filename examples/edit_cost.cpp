// The cost of the edit path a node mapping induces between two labelled graphs, with the default
// unit costs and with a cost model of one's own: deformseg::ged::edit_cost.
#include <deformseg/ged/edit_cost.h>

#include <iostream>

// [costs]
struct Expensive_edges : deformseg::ged::Unit_costs {  // a user cost model: edges cost 3
  double edge_insertion() const { return 3.0; }
  double edge_deletion() const { return 3.0; }
};
// [costs]

int main() {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, int>;
  Graph path(3), triangle(3);
  for (std::size_t v = 0; v < 3; ++v) path[v] = triangle[v] = int(v);
  boost::add_edge(0, 1, path);
  boost::add_edge(1, 2, path);
  boost::add_edge(0, 1, triangle);
  boost::add_edge(1, 2, triangle);
  boost::add_edge(0, 2, triangle);
  const std::vector<int> identity{0, 1, 2};
  const double unit = deformseg::ged::edit_cost(path, triangle, identity);
  // [use]
  const double custom = deformseg::ged::edit_cost(path, triangle, identity, Expensive_edges{});
  // [use]
  std::cout << "path -> triangle by the identity: " << unit << " with unit costs, " << custom
            << " with expensive edges\n";  // one edge inserted: 1 and 3
  return unit == 1.0 && custom == 3.0 ? 0 : 1;
}
