/// @file ged/edit_cost.h
/// @brief The cost of the edit path that a node mapping induces between two labelled graphs.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/ged/cost_model.h>

#include <cstddef>
#include <string>
#include <vector>

namespace deformseg::ged {

/// @brief The total cost of turning graph `a` into graph `b` when node i of `a` becomes node
/// `mapping[i]` of `b` (or is deleted when `mapping[i] == -1`): node substitutions and deletions,
/// insertion of the nodes of `b` nobody maps to, and for each pair of nodes an edge deletion,
/// insertion or substitution as the edges on both sides say.
///
/// Every mapping's cost is an upper bound on the graph edit distance; the distance is the minimum
/// over mappings.
/// @pre `mapping.size() == num_vertices(a)`, entries in [-1, num_vertices(b)), no node of `b`
/// used twice; else `invalid_input`.
/// @par Complexity O((n + m)^2) edge look-ups, n and m the node counts.
template <LabelledGraph G, GedCostModel<label_t<G>> C = Unit_costs>
double edit_cost(const G& a, const G& b, const std::vector<int>& mapping, const C& costs = {}) {
  const std::size_t n = boost::num_vertices(a), m = boost::num_vertices(b);
  if (mapping.size() != n)
    throw invalid_input("edit_cost: the mapping has " + std::to_string(mapping.size()) +
                        " entries for a graph of " + std::to_string(n) + " nodes");
  std::vector<int> preimage(m, -1);
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int j = mapping[i];
    if (j < -1 || j >= static_cast<int>(m) || (j >= 0 && preimage[static_cast<std::size_t>(j)] != -1))
      throw invalid_input("edit_cost: mapping[" + std::to_string(i) + "] = " + std::to_string(j) +
                          " is out of range or maps a second node to the same node");
    if (j < 0) {
      total += costs.node_deletion(a[i]);
      continue;
    }
    preimage[static_cast<std::size_t>(j)] = static_cast<int>(i);
    total += costs.node_substitution(a[i], b[static_cast<std::size_t>(j)]);
  }
  for (std::size_t j = 0; j < m; ++j)
    if (preimage[j] < 0) total += costs.node_insertion(b[j]);
  // Edges of a: kept when both ends map onto an edge of b, else deleted.
  for (std::size_t u = 0; u < n; ++u)
    for (std::size_t v = u + 1; v < n; ++v) {
      if (!boost::edge(u, v, a).second) continue;
      const int mu = mapping[u], mv = mapping[v];
      const bool kept = mu >= 0 && mv >= 0 &&
                        boost::edge(static_cast<std::size_t>(mu), static_cast<std::size_t>(mv), b).second;
      total += kept ? costs.edge_substitution() : costs.edge_deletion();
    }
  // Edges of b not the image of an edge of a are inserted.
  for (std::size_t x = 0; x < m; ++x)
    for (std::size_t y = x + 1; y < m; ++y) {
      if (!boost::edge(x, y, b).second) continue;
      const int px = preimage[x], py = preimage[y];
      const bool image = px >= 0 && py >= 0 &&
                         boost::edge(static_cast<std::size_t>(px), static_cast<std::size_t>(py), a).second;
      if (!image) total += costs.edge_insertion();
    }
  return total;
}

}  // namespace deformseg::ged
