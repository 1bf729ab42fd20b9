/// @file ged/cost_model.h
/// @brief Edit costs of the graph edit distance: the `GedCostModel` concept and the default
/// `Unit_costs`, and the `LabelledGraph` concept of the graphs compared.
#pragma once

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graph_traits.hpp>

#include <concepts>
#include <type_traits>

namespace deformseg::ged {

/// @brief A Boost.Graph undirected graph whose vertices are numbered 0..n-1 (`vecS` vertex
/// storage) and whose bundled vertex property `g[v]` is the vertex label (the node kind),
/// compared with `==`.
///
/// Example: `boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, int>`.
template <class G>
concept LabelledGraph = requires(const G& g, typename boost::graph_traits<G>::vertex_descriptor v) {
  { boost::num_vertices(g) } -> std::convertible_to<std::size_t>;
  { boost::edge(v, v, g).second } -> std::convertible_to<bool>;
  { boost::out_degree(v, g) } -> std::convertible_to<std::size_t>;
  { g[v] == g[v] } -> std::convertible_to<bool>;
} && std::is_same_v<typename boost::graph_traits<G>::vertex_descriptor, std::size_t>;

/// @brief The label type of a `LabelledGraph`.
template <LabelledGraph G>
using label_t = std::remove_cvref_t<decltype(std::declval<const G&>()[std::size_t{}])>;

/// @brief Costs of the six edit operations on graphs with vertex labels of type `Label`: node
/// insertion, deletion and substitution (which may look at the labels), edge insertion, deletion
/// and substitution (edges carry no label, so substitution is the cost of keeping an edge).
///
/// Costs must be non-negative, and `node_substitution(a, a)` should be 0 for the distance of a
/// graph to itself to be 0.
template <class C, class Label>
concept GedCostModel = requires(const C& c, const Label& a, const Label& b) {
  { c.node_substitution(a, b) } -> std::convertible_to<double>;
  { c.node_insertion(a) } -> std::convertible_to<double>;
  { c.node_deletion(a) } -> std::convertible_to<double>;
  { c.edge_insertion() } -> std::convertible_to<double>;
  { c.edge_deletion() } -> std::convertible_to<double>;
  { c.edge_substitution() } -> std::convertible_to<double>;
};

/// @brief The default costs (@ref method_similarity): inserting or deleting a node or an edge costs
/// 1; substituting a node costs 0 for equal labels and 1 otherwise; keeping an edge costs 0.
struct Unit_costs {
  /// @brief 0 when the labels are equal, else 1.
  template <class Label>
  double node_substitution(const Label& a, const Label& b) const { return a == b ? 0.0 : 1.0; }
  /// @brief 1 for any label.
  template <class Label>
  double node_insertion(const Label&) const { return 1.0; }
  /// @brief 1 for any label.
  template <class Label>
  double node_deletion(const Label&) const { return 1.0; }
  /// @brief 1.
  double edge_insertion() const { return 1.0; }
  /// @brief 1.
  double edge_deletion() const { return 1.0; }
  /// @brief 0: an edge kept between mapped nodes costs nothing.
  double edge_substitution() const { return 0.0; }
};

}  // namespace deformseg::ged
