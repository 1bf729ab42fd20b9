#include <deformseg/ged/bipartite_ged.h>

#include <catch2/catch.hpp>

#include <random>

namespace {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, int>;

Graph random_graph(std::mt19937& rng, std::size_t nodes, int kinds, double edge_probability) {
  Graph g(nodes);
  std::uniform_int_distribution<int> kind(0, kinds - 1);
  std::bernoulli_distribution edge(edge_probability);
  for (std::size_t v = 0; v < nodes; ++v) g[v] = kind(rng);
  for (std::size_t u = 0; u < nodes; ++u)
    for (std::size_t v = u + 1; v < nodes; ++v)
      if (edge(rng)) boost::add_edge(u, v, g);
  return g;
}

// The graph edit distance by definition: the least edit cost over every partial injective map.
void all_mappings(const Graph& a, const Graph& b, std::vector<int>& mapping, std::vector<char>& used,
                  std::size_t i, double& best) {
  if (i == mapping.size()) {
    best = std::min(best, deformseg::ged::edit_cost(a, b, mapping));
    return;
  }
  mapping[i] = -1;
  all_mappings(a, b, mapping, used, i + 1, best);
  for (std::size_t j = 0; j < used.size(); ++j) {
    if (used[j]) continue;
    used[j] = 1;
    mapping[i] = static_cast<int>(j);
    all_mappings(a, b, mapping, used, i + 1, best);
    used[j] = 0;
  }
}

double brute_force_ged(const Graph& a, const Graph& b) {
  std::vector<int> mapping(boost::num_vertices(a));
  std::vector<char> used(boost::num_vertices(b), 0);
  double best = std::numeric_limits<double>::infinity();
  all_mappings(a, b, mapping, used, 0, best);
  return best;
}

}  // namespace

TEST_CASE("Bipartite_ged is an upper bound: never below brute force, its mapping costs it", "[ged][bipartite]") {
  STATIC_REQUIRE(deformseg::ged::GedPolicy<deformseg::ged::Bipartite_ged, Graph, deformseg::ged::Unit_costs>);
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::size_t> size(0, 5);
  int equal = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Graph a = random_graph(rng, size(rng), 3, 0.4);
    const Graph b = random_graph(rng, size(rng), 3, 0.4);
    const auto r = deformseg::ged::Bipartite_ged{}(a, b);
    INFO("trial " << trial);
    CHECK_FALSE(r.exact);
    CHECK(r.distance == r.upper);
    CHECK(r.upper == deformseg::ged::edit_cost(a, b, r.mapping));
    const double exact = brute_force_ged(a, b);
    CHECK(r.upper >= exact);
    equal += r.upper == exact ? 1 : 0;
  }
  CHECK(equal > 100);  // a useful approximation: most small pairs come out exact
}

TEST_CASE("Bipartite_ged: exact answers where the mapping is forced", "[ged][bipartite]") {
  std::mt19937 rng(3);
  const Graph a = random_graph(rng, 6, 2, 0.5);
  const auto edges = static_cast<double>(boost::num_edges(a));
  const auto to_empty = deformseg::ged::Bipartite_ged{}(a, Graph{});
  CHECK(to_empty.distance == 6 + edges);
  CHECK(to_empty.mapping == std::vector<int>(6, -1));
  CHECK(deformseg::ged::Bipartite_ged{}(Graph{}, a).distance == 6 + edges);
  CHECK(deformseg::ged::Bipartite_ged{}(Graph{}, Graph{}).distance == 0);
}
