// Helpers shared by the graph edit distance tests: seeded random labelled graphs, random
// relabellings, cost models, and the graph edit distance by definition (brute force).
#pragma once

#include <deformseg/ged/edit_cost.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace deformseg::test {

using Ged_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, int>;

inline Ged_graph random_labelled_graph(std::mt19937& rng, std::size_t nodes, int kinds, double edge_probability) {
  Ged_graph g(nodes);
  std::uniform_int_distribution<int> kind(0, kinds - 1);
  std::bernoulli_distribution edge(edge_probability);
  for (std::size_t v = 0; v < nodes; ++v) g[v] = kind(rng);
  for (std::size_t u = 0; u < nodes; ++u)
    for (std::size_t v = u + 1; v < nodes; ++v)
      if (edge(rng)) boost::add_edge(u, v, g);
  return g;
}

/// The graph of node labels `labels` and undirected `edges` (pairs of node indices).
inline Ged_graph make_graph(const std::vector<int>& labels, const std::vector<std::pair<int, int>>& edges) {
  Ged_graph g(labels.size());
  for (std::size_t v = 0; v < labels.size(); ++v) g[v] = labels[v];
  for (auto [u, v] : edges) boost::add_edge(static_cast<std::size_t>(u), static_cast<std::size_t>(v), g);
  return g;
}

/// The same graph with its nodes renumbered at random: isomorphic to `g`.
inline Ged_graph permuted(const Ged_graph& g, std::mt19937& rng) {
  const std::size_t n = boost::num_vertices(g);
  std::vector<std::size_t> p(n);
  std::iota(p.begin(), p.end(), std::size_t{0});
  std::shuffle(p.begin(), p.end(), rng);
  Ged_graph h(n);
  for (std::size_t v = 0; v < n; ++v) h[p[v]] = g[v];
  for (std::size_t u = 0; u < n; ++u)
    for (std::size_t v = u + 1; v < n; ++v)
      if (boost::edge(u, v, g).second) boost::add_edge(p[u], p[v], h);
  return h;
}

/// Costs that differ by operation and by label, asymmetric, and with keeping an edge dearer than
/// deleting and inserting it; all multiples of 1/8, so that every sum is exact.
struct Uneven_costs {
  double node_substitution(int a, int b) const { return a == b ? 0.0 : 0.375 + 0.25 * std::abs(a - b); }
  double node_insertion(int a) const { return 0.75 + 0.125 * a; }
  double node_deletion(int) const { return 1.5; }
  double edge_insertion() const { return 1.25; }
  double edge_deletion() const { return 0.5; }
  double edge_substitution() const { return 2.5; }
};

/// Dear node operations, cheap edges, a small cost for keeping an edge.
struct Node_heavy_costs {
  double node_substitution(int a, int b) const { return a == b ? 0.0 : 2.0; }
  double node_insertion(int) const { return 3.0; }
  double node_deletion(int) const { return 3.0; }
  double edge_insertion() const { return 0.5; }
  double edge_deletion() const { return 0.5; }
  double edge_substitution() const { return 0.125; }
};

namespace by_definition {
template <class C>
void all_mappings(const Ged_graph& a, const Ged_graph& b, const C& costs, std::vector<int>& mapping,
                  std::vector<char>& used, std::size_t i, double& best) {
  if (i == mapping.size()) {
    best = std::min(best, deformseg::ged::edit_cost(a, b, mapping, costs));
    return;
  }
  mapping[i] = -1;
  all_mappings(a, b, costs, mapping, used, i + 1, best);
  for (std::size_t j = 0; j < used.size(); ++j) {
    if (used[j]) continue;
    used[j] = 1;
    mapping[i] = static_cast<int>(j);
    all_mappings(a, b, costs, mapping, used, i + 1, best);
    used[j] = 0;
  }
}
}  // namespace by_definition

/// The graph edit distance by definition: the least edit cost over every injective partial map
/// of the nodes of `a` into those of `b` (the nodes left out are deleted or inserted).
template <class C = deformseg::ged::Unit_costs>
double brute_force_ged(const Ged_graph& a, const Ged_graph& b, const C& costs = {}) {
  std::vector<int> mapping(boost::num_vertices(a));
  std::vector<char> used(boost::num_vertices(b), 0);
  double best = std::numeric_limits<double>::infinity();
  by_definition::all_mappings(a, b, costs, mapping, used, 0, best);
  return best;
}

}  // namespace deformseg::test
