// A cheap lower bound on the graph edit distance, admissible for any cost model.
#include <deformseg/ged/exact_ged.h>
#include <deformseg/ged/lower_bound.h>

#include <iostream>
#include <string>

int main() {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, std::string>;
  Graph body(4), robot(5);  // a torso with three limbs; a torso with four
  body[0] = robot[0] = "torso";
  for (std::size_t v = 1; v < 4; ++v) body[v] = "limb", boost::add_edge(0, v, body);
  for (std::size_t v = 1; v < 5; ++v) robot[v] = "limb", boost::add_edge(0, v, robot);
  robot[4] = "wheel";
  // [bound]
  const auto bound = deformseg::ged::Assignment_lower_bound{}(body, robot);
  const auto exact = deformseg::ged::Exact_ged{}(body, robot);
  // [bound]
  std::cout << "lower bound " << bound.lower << ", exact distance " << exact.distance << '\n';
  return bound.lower <= exact.distance && bound.lower == 2 ? 0 : 1;  // insert the wheel and its edge
}
