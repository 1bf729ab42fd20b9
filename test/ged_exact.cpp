#include <deformseg/ged/exact_ged.h>

#include "ged_support.h"

#include <catch2/catch.hpp>

#include <random>

namespace {

using deformseg::ged::Exact_ged;
using deformseg::test::brute_force_ged;
using deformseg::test::Ged_graph;
using deformseg::test::make_graph;
using deformseg::test::random_labelled_graph;

template <class C>
void check_against_brute_force(unsigned seed, int pairs, const C& costs) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> size(0, 7);
  std::uniform_real_distribution<double> density(0.1, 0.7);
  for (int trial = 0; trial < pairs; ++trial) {
    const Ged_graph a = random_labelled_graph(rng, size(rng), 3, density(rng));
    const Ged_graph b = random_labelled_graph(rng, size(rng), 3, density(rng));
    const auto r = Exact_ged{}(a, b, costs);
    INFO("trial " << trial << ": " << boost::num_vertices(a) << " and " << boost::num_vertices(b) << " nodes");
    REQUIRE(r.exact);
    CHECK(r.distance == brute_force_ged(a, b, costs));
    CHECK(r.lower == r.distance);
    CHECK(r.upper == r.distance);
    CHECK(deformseg::ged::edit_cost(a, b, r.mapping, costs) == r.distance);
  }
}

}  // namespace

TEST_CASE("Exact_ged: equals brute force over all node mappings, unit costs", "[ged][exact]") {
  STATIC_REQUIRE(deformseg::ged::GedPolicy<Exact_ged, Ged_graph, deformseg::ged::Unit_costs>);
  check_against_brute_force(11, 300, deformseg::ged::Unit_costs{});
}

TEST_CASE("Exact_ged: equals brute force under non-unit cost models", "[ged][exact]") {
  check_against_brute_force(12, 150, deformseg::test::Uneven_costs{});
  check_against_brute_force(13, 150, deformseg::test::Node_heavy_costs{});
}

TEST_CASE("Exact_ged: textbook distances", "[ged][exact]") {
  const Ged_graph path = make_graph({1, 2, 1}, {{0, 1}, {1, 2}});
  const Ged_graph triangle = make_graph({1, 2, 3}, {{0, 1}, {1, 2}, {0, 2}});
  const Ged_graph star = make_graph({0, 0, 0, 0}, {{0, 1}, {0, 2}, {0, 3}});
  const Ged_graph path4 = make_graph({0, 0, 0, 0}, {{0, 1}, {1, 2}, {2, 3}});
  const Ged_graph ring4 = make_graph({0, 0, 0, 0}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  const Ged_graph ring5 = make_graph({0, 0, 0, 0, 0}, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}});
  CHECK(Exact_ged{}(path, triangle).distance == 2);   // relabel a node, insert an edge
  CHECK(Exact_ged{}(star, path4).distance == 2);      // move one edge
  CHECK(Exact_ged{}(ring4, ring5).distance == 4);     // a node, two edges in, one out
  CHECK(Exact_ged{}(ring5, Ged_graph{}).distance == 10);
  CHECK(Exact_ged{}(Ged_graph{}, triangle).distance == 6);
  const auto none = Exact_ged{}(Ged_graph{}, Ged_graph{});
  CHECK(none.exact);
  CHECK(none.distance == 0);
  CHECK(none.mapping.empty());
}

TEST_CASE("Exact_ged: symmetric, zero exactly between isomorphic graphs, triangle inequality", "[ged][exact]") {
  std::mt19937 rng(21);
  std::uniform_int_distribution<std::size_t> size(1, 8);
  for (int trial = 0; trial < 60; ++trial) {
    INFO("trial " << trial);
    const Ged_graph a = random_labelled_graph(rng, size(rng), 3, 0.35);
    const Ged_graph b = random_labelled_graph(rng, size(rng), 3, 0.35);
    const Ged_graph c = random_labelled_graph(rng, size(rng), 3, 0.35);
    const double ab = Exact_ged{}(a, b).distance;
    CHECK(Exact_ged{}(b, a).distance == ab);
    CHECK(ab <= Exact_ged{}(a, c).distance + Exact_ged{}(c, b).distance);
    const auto same = Exact_ged{}(a, deformseg::test::permuted(a, rng));
    CHECK(same.exact);
    CHECK(same.distance == 0);
  }
  const Ged_graph big = random_labelled_graph(rng, 12, 2, 0.25);
  const auto same = Exact_ged{}(big, deformseg::test::permuted(big, rng));
  CHECK(same.exact);
  CHECK(same.distance == 0);
}

TEST_CASE("Exact_ged: Bipartite_ged is never below it", "[ged][exact]") {
  std::mt19937 rng(31);
  std::uniform_int_distribution<std::size_t> size(0, 9);
  for (int trial = 0; trial < 100; ++trial) {
    const Ged_graph a = random_labelled_graph(rng, size(rng), 2, 0.3);
    const Ged_graph b = random_labelled_graph(rng, size(rng), 2, 0.3);
    const auto exact = Exact_ged{}(a, b);
    REQUIRE(exact.exact);
    CHECK(deformseg::ged::Bipartite_ged{}(a, b).distance >= exact.distance);
  }
}

TEST_CASE("Exact_ged: a limit that is hit gives bounds, not a false exact answer", "[ged][exact][limit]") {
  std::mt19937 rng(41);
  int stopped = 0, gap = 0;
  for (int trial = 0; trial < 30; ++trial) {
    INFO("trial " << trial);
    const Ged_graph a = random_labelled_graph(rng, 9, 3, 0.3);
    const Ged_graph b = random_labelled_graph(rng, 9, 3, 0.3);
    const double truth = Exact_ged{}(a, b).distance;
    for (std::size_t limit : {std::size_t{0}, std::size_t{1}, std::size_t{5}}) {
      const auto r = Exact_ged{.max_expanded = limit}(a, b);
      CHECK(r.lower <= truth);
      CHECK(truth <= r.upper);
      CHECK(r.distance == r.upper);
      CHECK(deformseg::ged::edit_cost(a, b, r.mapping) == r.upper);
      if (r.exact) {
        CHECK(r.distance == truth);
      } else {
        ++stopped;
        gap += r.lower < r.upper ? 1 : 0;
      }
    }
  }
  CHECK(stopped > 20);  // the limits do bite on these pairs
  CHECK(gap == stopped);
}

TEST_CASE("Exact_ged: a time limit stops the search / bad options and costs throw", "[ged][exact][limit]") {
  std::mt19937 rng(51);
  // Dense 30-node pairs are far beyond any search (the bounds differ by a factor of 5 after
  // 100,000 expansions), so the 50 ms limit always bites.
  const Ged_graph a = random_labelled_graph(rng, 30, 3, 0.5);
  const Ged_graph b = random_labelled_graph(rng, 30, 3, 0.5);
  const auto r = Exact_ged{.max_seconds = 0.05}(a, b);
  CHECK_FALSE(r.exact);
  CHECK(r.lower <= r.upper);
  CHECK(r.lower > 0);
  CHECK_THROWS_AS(Exact_ged{.max_seconds = -1}(a, b), deformseg::invalid_input);
  struct Negative_costs : deformseg::ged::Unit_costs {
    double edge_deletion() const { return -1.0; }
  };
  CHECK_THROWS_WITH(Exact_ged{}(a, b, Negative_costs{}), Catch::Contains("edge_deletion() = -1"));
}
