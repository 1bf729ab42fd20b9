/// @file ged/bipartite_ged.h
/// @brief `Bipartite_ged`: the graph edit distance approximated by an assignment problem
/// (Riesen & Bunke 2009); its answer is the true cost of an edit path, so an upper bound.
#pragma once

#include <deformseg/ged/assignment.h>
#include <deformseg/ged/edit_cost.h>
#include <deformseg/ged/ged_policy.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace deformseg::ged {

namespace internal {

// Cheapest way to match d1 unlabelled incident edges to d2: keep min(d1, d2), delete or insert
// the rest.
template <class C>
double local_edge_cost(std::size_t d1, std::size_t d2, const C& costs) {
  const double kept = static_cast<double>(std::min(d1, d2)) * costs.edge_substitution();
  if (d1 >= d2) return kept + static_cast<double>(d1 - d2) * costs.edge_deletion();
  return kept + static_cast<double>(d2 - d1) * costs.edge_insertion();
}

// The (n + m) x (n + m) matrix: substitutions top left, deletions on the diagonal top right,
// insertions on the diagonal bottom left, zeros bottom right. Forbidden cells get a cost above
// that of deleting everything and inserting everything, so no optimum uses them.
template <class G, class C>
Eigen::MatrixXd bipartite_cost_matrix(const G& a, const G& b, const C& costs) {
  const std::size_t n = boost::num_vertices(a), m = boost::num_vertices(b);
  std::vector<double> deletion(n), insertion(m);
  double delete_and_insert_all = 0;
  for (std::size_t i = 0; i < n; ++i) {
    deletion[i] = costs.node_deletion(a[i]) + local_edge_cost(boost::out_degree(i, a), 0, costs);
    delete_and_insert_all += deletion[i];
  }
  for (std::size_t j = 0; j < m; ++j) {
    insertion[j] = costs.node_insertion(b[j]) + local_edge_cost(0, boost::out_degree(j, b), costs);
    delete_and_insert_all += insertion[j];
  }
  const auto size = static_cast<Eigen::Index>(n + m);
  Eigen::MatrixXd cost = Eigen::MatrixXd::Zero(size, size);
  const double forbidden = delete_and_insert_all + 1;
  cost.topRightCorner(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n)).setConstant(forbidden);
  cost.bottomLeftCorner(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m)).setConstant(forbidden);
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    for (std::size_t j = 0; j < m; ++j)
      cost(r, static_cast<Eigen::Index>(j)) =
          costs.node_substitution(a[i], b[j]) +
          local_edge_cost(boost::out_degree(i, a), boost::out_degree(j, b), costs);
    cost(r, static_cast<Eigen::Index>(m + i)) = deletion[i];
  }
  for (std::size_t j = 0; j < m; ++j)
    cost(static_cast<Eigen::Index>(n + j), static_cast<Eigen::Index>(j)) = insertion[j];
  return cost;
}

}  // namespace internal

/// @brief GED policy (models `GedPolicy`): the bipartite approximation of Riesen & Bunke. Each
/// node substitution, deletion and insertion is priced with the cheapest matching of its incident
/// edges; the optimal assignment of that (n + m) x (n + m) matrix (solve_assignment) gives a node
/// mapping, whose true edit cost (edit_cost) is returned.
///
/// The result is never exact (`exact == false`, `lower == 0`): `distance == upper` is the cost of
/// a real edit path, so never below the graph edit distance.
/// @par Complexity O((n + m)^3), n and m the node counts.
struct Bipartite_ged {
  /// @brief Compares `a` to `b` under `costs`.
  template <LabelledGraph G, GedCostModel<label_t<G>> C = Unit_costs>
  Ged_result operator()(const G& a, const G& b, const C& costs = {}) const {
    const std::size_t n = boost::num_vertices(a), m = boost::num_vertices(b);
    const Assignment assignment = solve_assignment(internal::bipartite_cost_matrix(a, b, costs));
    std::vector<int> mapping(n, -1);
    for (std::size_t i = 0; i < n; ++i)
      if (assignment.row_to_column[i] < static_cast<int>(m)) mapping[i] = assignment.row_to_column[i];
    const double cost = edit_cost(a, b, mapping, costs);
    return {.distance = cost, .exact = false, .lower = 0, .upper = cost, .mapping = std::move(mapping)};
  }
};

}  // namespace deformseg::ged
