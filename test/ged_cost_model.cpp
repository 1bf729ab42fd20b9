#include <deformseg/ged/edit_cost.h>
#include <deformseg/ged/ged_policy.h>
#include <deformseg/ged/ged_result.h>

#include "ged_support.h"

#include <catch2/catch.hpp>

#include <string>

namespace {

using Graph = deformseg::test::Ged_graph;
using deformseg::test::make_graph;

// A user policy: maps node i to node i and charges the rest (an upper bound, never exact).
struct Identity_mapping_ged {
  template <class G, class C>
  deformseg::ged::Ged_result operator()(const G& a, const G& b, const C& costs) const {
    std::vector<int> mapping(boost::num_vertices(a), -1);
    for (std::size_t i = 0; i < mapping.size() && i < boost::num_vertices(b); ++i) mapping[i] = static_cast<int>(i);
    const double cost = deformseg::ged::edit_cost(a, b, mapping, costs);
    return {.distance = cost, .exact = false, .lower = 0, .upper = cost, .mapping = mapping};
  }
};

struct Double_costs : deformseg::ged::Unit_costs {
  double edge_deletion() const { return 2.0; }
};

struct Not_a_ged_policy {
  double operator()(const Graph&, const Graph&) const { return 0; }
};

}  // namespace

TEST_CASE("GED concepts accept models and reject non-models", "[ged][concepts]") {
  using namespace deformseg::ged;
  STATIC_REQUIRE(LabelledGraph<Graph>);
  STATIC_REQUIRE(LabelledGraph<boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, std::string>>);
  STATIC_REQUIRE(!LabelledGraph<boost::adjacency_list<boost::listS, boost::listS, boost::undirectedS, int>>);
  STATIC_REQUIRE(GedCostModel<Unit_costs, int>);
  STATIC_REQUIRE(GedCostModel<Double_costs, int>);
  STATIC_REQUIRE(!GedCostModel<int, int>);
  STATIC_REQUIRE(GedPolicy<Identity_mapping_ged, Graph, Unit_costs>);
  STATIC_REQUIRE(!GedPolicy<Not_a_ged_policy, Graph, Unit_costs>);
}

TEST_CASE("edit_cost: exact costs of given mappings", "[ged][edit_cost]") {
  using deformseg::ged::edit_cost;
  const Graph path = make_graph({1, 2, 1}, {{0, 1}, {1, 2}});
  const Graph triangle = make_graph({1, 2, 3}, {{0, 1}, {1, 2}, {0, 2}});
  CHECK(edit_cost(path, path, {0, 1, 2}) == 0.0);
  CHECK(edit_cost(path, path, {2, 1, 0}) == 0.0);                  // the automorphism
  CHECK(edit_cost(path, path, {1, 0, 2}) == 4.0);  // two relabels, edge 1-2 out, 0-2 in
  CHECK(edit_cost(path, triangle, {0, 1, 2}) == 2.0);              // relabel 1->3, insert edge 0-2
  CHECK(edit_cost(path, triangle, {-1, -1, -1}) == 3 + 2 + 3 + 3); // delete all, insert all
  CHECK(edit_cost(triangle, path, {0, 1, 2}) == 2.0);              // symmetric edit path
  CHECK(edit_cost(path, path, {0, 1, -1}, Double_costs{}) == 1 + 1 + 2 + 1);
  CHECK_THROWS_AS(edit_cost(path, path, {0, 0, 1}), deformseg::invalid_input);
  CHECK_THROWS_AS(edit_cost(path, path, {0, 1}), deformseg::invalid_input);
  CHECK_THROWS_AS(edit_cost(path, path, {0, 1, 3}), deformseg::invalid_input);
}

TEST_CASE("a user GED policy plugs in", "[ged][concepts]") {
  const Graph a = make_graph({1, 2}, {{0, 1}});
  const Graph b = make_graph({1, 2, 2}, {{0, 1}, {1, 2}});
  const auto r = Identity_mapping_ged{}(a, b, deformseg::ged::Unit_costs{});
  CHECK(r.distance == 2.0);  // insert node 2 and edge 1-2
  CHECK(r.mapping == std::vector<int>{0, 1});
}
