// The exact graph edit distance by branch and bound, and what a node limit does to it.
#include <deformseg/ged/exact_ged.h>

#include <iostream>
#include <random>

int main() {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, int>;
  // Two random sparse graphs of 10 nodes with 3 node kinds, like the segment graphs of a mesh.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> kind(0, 2);
  std::bernoulli_distribution edge(0.3);
  Graph a(10), b(10);
  for (Graph* g : {&a, &b}) {
    for (std::size_t v = 0; v < 10; ++v) (*g)[v] = kind(rng);
    for (std::size_t u = 0; u < 10; ++u)
      for (std::size_t v = u + 1; v < 10; ++v)
        if (edge(rng)) boost::add_edge(u, v, *g);
  }
  const deformseg::ged::Ged_result exact = deformseg::ged::Exact_ged{}(a, b);
  std::cout << "graph edit distance " << exact.distance << (exact.exact ? " (exact)" : " (bounds only)")
            << "; mapping";
  for (std::size_t i = 0; i < exact.mapping.size(); ++i) std::cout << ' ' << i << "->" << exact.mapping[i];
  std::cout << '\n';
  // [limit]
  // With almost no search allowed, the answer says so and brackets the distance.
  const auto rough = deformseg::ged::Exact_ged{.max_expanded = 2}(a, b);
  std::cout << "after 2 expansions: " << rough.lower << " <= distance <= " << rough.upper
            << (rough.exact ? " (exact)" : " (not exact)") << '\n';
  // [limit]
  return exact.exact && rough.lower <= exact.distance && exact.distance <= rough.upper ? 0 : 1;
}
