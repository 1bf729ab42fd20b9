/// @file ged/lower_bound.h
/// @brief `Assignment_lower_bound`: a cheap lower bound on the graph edit distance, from an
/// assignment of node labels and degrees; admissible for every cost model.
#pragma once

#include <deformseg/ged/edit_cost.h>
#include <deformseg/ged/ged_policy.h>
#include <deformseg/ged/internal/ged_search.h>

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace deformseg::ged {

/// @brief GED policy (models `GedPolicy`): a lower bound on the graph edit distance, for pruning
/// and clustering thresholds, and the bound at the root of `Exact_ged`'s search.
///
/// Each node of A is substituted by a distinct node of B or deleted, each node of B left over is
/// inserted; every choice is priced with its node cost (`node_substitution`, `node_deletion`,
/// `node_insertion`) plus half of the least cost of its incident edges: with degrees d and d',
/// min(d, d') edges kept at min(`edge_substitution`, `edge_deletion` + `edge_insertion`) each, the
/// other |d - d'| deleted or inserted. The optimal assignment of those costs (with deletions and
/// insertions, solved exactly) is the bound. Every edit path pays at least this (each edge has two
/// ends, each charged half), so the bound is admissible for any cost model with non-negative
/// costs: no further property is needed. Under `Unit_costs` it is at least both the
/// label-multiset bound and the degree-sequence bound.
///
/// The result: `lower == distance` is the bound, `upper` is +infinity and `mapping` empty, and
/// `exact == false`, except when one graph has no node: then the bound is the distance (delete or
/// insert everything), `exact == upper == lower` and `mapping` is all -1.
/// @throws invalid_input when the cost model gives a negative or non-finite cost.
/// @par Complexity O(n m) cost evaluations and O(min(n,m)^2 max(n,m)) for the assignment, n and
/// m the node counts.
struct Assignment_lower_bound {
  /// @brief Bounds the graph edit distance from `a` to `b` under `costs` from below.
  template <LabelledGraph G, GedCostModel<label_t<G>> C = Unit_costs>
  Ged_result operator()(const G& a, const G& b, const C& costs = {}) const {
    const internal::Ged_instance instance = internal::make_instance(a, b, costs, "Assignment_lower_bound");
    internal::Partial_mapping root(instance);
    internal::Lsap_workspace lsap;
    std::vector<double> matrix;
    const double bound = root.completion_bound(lsap, matrix);
    if (instance.n == 0 || instance.m == 0) {  // nothing to choose: the bound is the distance
      std::vector<int> mapping(instance.n, -1);
      const double distance = edit_cost(a, b, mapping, costs);
      return {.distance = distance, .exact = true, .lower = distance, .upper = distance, .mapping = std::move(mapping)};
    }
    return {.distance = bound, .exact = false, .lower = bound,
            .upper = std::numeric_limits<double>::infinity(), .mapping = {}};
  }
};

}  // namespace deformseg::ged
