#include "ged_support.h"

#include <deformseg/ged/bipartite_ged.h>

#include <catch2/catch.hpp>

#include <random>

namespace {

using Graph = deformseg::test::Ged_graph;
using deformseg::test::brute_force_ged;
using deformseg::test::random_labelled_graph;

}  // namespace

TEST_CASE("Bipartite_ged is an upper bound: never below brute force, its mapping costs it", "[ged][bipartite]") {
  STATIC_REQUIRE(deformseg::ged::GedPolicy<deformseg::ged::Bipartite_ged, Graph, deformseg::ged::Unit_costs>);
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::size_t> size(0, 5);
  int equal = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Graph a = random_labelled_graph(rng, size(rng), 3, 0.4);
    const Graph b = random_labelled_graph(rng, size(rng), 3, 0.4);
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
  const Graph a = random_labelled_graph(rng, 6, 2, 0.5);
  const auto edges = static_cast<double>(boost::num_edges(a));
  const auto to_empty = deformseg::ged::Bipartite_ged{}(a, Graph{});
  CHECK(to_empty.distance == 6 + edges);
  CHECK(to_empty.mapping == std::vector<int>(6, -1));
  CHECK(deformseg::ged::Bipartite_ged{}(Graph{}, a).distance == 6 + edges);
  CHECK(deformseg::ged::Bipartite_ged{}(Graph{}, Graph{}).distance == 0);
}
