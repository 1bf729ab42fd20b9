#include <deformseg/ged/lower_bound.h>

#include "ged_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace {

using deformseg::ged::Assignment_lower_bound;
using deformseg::test::brute_force_ged;
using deformseg::test::Ged_graph;
using deformseg::test::random_labelled_graph;

// The classic bound under unit costs: labels that cannot be matched, and the edge count difference.
double multiset_bound(const Ged_graph& a, const Ged_graph& b) {
  std::vector<int> la, lb;
  for (std::size_t v = 0; v < boost::num_vertices(a); ++v) la.push_back(a[v]);
  for (std::size_t v = 0; v < boost::num_vertices(b); ++v) lb.push_back(b[v]);
  std::sort(la.begin(), la.end());
  std::sort(lb.begin(), lb.end());
  std::vector<int> common;
  std::set_intersection(la.begin(), la.end(), lb.begin(), lb.end(), std::back_inserter(common));
  const double nodes = static_cast<double>(std::max(la.size(), lb.size()) - common.size());
  const double edges = std::abs(static_cast<double>(boost::num_edges(a)) - static_cast<double>(boost::num_edges(b)));
  return nodes + edges;
}

template <class C>
void check_admissible(unsigned seed, int pairs, const C& costs) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> size(1, 6);
  std::uniform_real_distribution<double> density(0.1, 0.7);
  int tight = 0;
  for (int trial = 0; trial < pairs; ++trial) {
    const Ged_graph a = random_labelled_graph(rng, size(rng), 3, density(rng));
    const Ged_graph b = random_labelled_graph(rng, size(rng), 3, density(rng));
    const auto r = Assignment_lower_bound{}(a, b, costs);
    INFO("trial " << trial);
    CHECK_FALSE(r.exact);
    CHECK(r.distance == r.lower);
    CHECK(std::isinf(r.upper));
    CHECK(r.mapping.empty());
    const double exact = brute_force_ged(a, b, costs);
    CHECK(r.lower >= 0);
    CHECK(r.lower <= exact);
    tight += r.lower == exact ? 1 : 0;
  }
  CHECK(tight > pairs / 10);  // not a trivial bound
}

}  // namespace

TEST_CASE("Assignment_lower_bound: never above brute force, for any cost model", "[ged][lower_bound]") {
  STATIC_REQUIRE(deformseg::ged::GedPolicy<Assignment_lower_bound, Ged_graph, deformseg::ged::Unit_costs>);
  check_admissible(61, 200, deformseg::ged::Unit_costs{});
  check_admissible(62, 150, deformseg::test::Uneven_costs{});
  check_admissible(63, 150, deformseg::test::Node_heavy_costs{});
}

TEST_CASE("Assignment_lower_bound: at least the label-multiset and edge-count bound", "[ged][lower_bound]") {
  std::mt19937 rng(64);
  std::uniform_int_distribution<std::size_t> size(1, 12);
  for (int trial = 0; trial < 200; ++trial) {
    const Ged_graph a = random_labelled_graph(rng, size(rng), 3, 0.3);
    const Ged_graph b = random_labelled_graph(rng, size(rng), 3, 0.3);
    INFO("trial " << trial);
    CHECK(Assignment_lower_bound{}(a, b).lower >= multiset_bound(a, b));
  }
}

TEST_CASE("Assignment_lower_bound: exact answers", "[ged][lower_bound]") {
  Ged_graph zeros(3), ones(2);
  for (std::size_t v = 0; v < 3; ++v) zeros[v] = 0;
  for (std::size_t v = 0; v < 2; ++v) ones[v] = 1;
  CHECK(Assignment_lower_bound{}(zeros, ones).lower == 3);  // two relabels, one deletion
  std::mt19937 rng(65);
  const Ged_graph g = random_labelled_graph(rng, 7, 3, 0.4);
  CHECK(Assignment_lower_bound{}(g, g).lower == 0);
  const auto to_empty = Assignment_lower_bound{}(g, Ged_graph{});
  CHECK(to_empty.exact);
  CHECK(to_empty.lower == static_cast<double>(7 + boost::num_edges(g)));
  CHECK(to_empty.upper == to_empty.lower);
  CHECK(to_empty.mapping == std::vector<int>(7, -1));
  CHECK(Assignment_lower_bound{}(Ged_graph{}, g).exact);
  struct Bad_costs : deformseg::ged::Unit_costs {
    double node_insertion(int) const { return std::nan(""); }
  };
  CHECK_THROWS_AS(Assignment_lower_bound{}(g, g, Bad_costs{}), deformseg::invalid_input);
}
