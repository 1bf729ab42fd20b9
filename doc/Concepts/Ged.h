/// \page GedConcepts The GedCostModel and GedPolicy concepts
///
/// The graph edit distance compares two graphs whose vertices carry a label (the node kind): a
/// Boost.Graph undirected graph with `vecS` vertex storage whose bundled vertex property is the
/// label, checked by the C++20 concept deformseg::ged::LabelledGraph.
///
/// \section GedCostModelConcept GedCostModel
/// A type `C` is a model for labels of type `L` when, for `const C& c` and `const L& a, b`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `c.node_substitution(a, b)` | convertible to `double` | cost of relabelling a node of kind a into kind b |
/// | `c.node_insertion(a)` | convertible to `double` | cost of inserting a node of kind a |
/// | `c.node_deletion(a)` | convertible to `double` | cost of deleting a node of kind a |
/// | `c.edge_insertion()` | convertible to `double` | cost of inserting an edge |
/// | `c.edge_deletion()` | convertible to `double` | cost of deleting an edge |
/// | `c.edge_substitution()` | convertible to `double` | cost of keeping an edge between mapped nodes |
///
/// Costs are non-negative; `node_substitution(a, a)` should be 0.
/// Model: deformseg::ged::Unit_costs (the default; derive from it to change some costs).
///
/// \section GedPolicyConcept GedPolicy
/// A type `P` is a model for graphs `G` and costs `C` when, for `const P& p`, `const G& a, b` and
/// `const C& costs`, `p(a, b, costs)` returns a deformseg::ged::Ged_result whose `lower` and
/// `upper` bracket the graph edit distance and whose `mapping` costs `upper`
/// (deformseg::ged::edit_cost). The C++20 concept is deformseg::ged::GedPolicy, in
/// `ged/ged_policy.h`; each model's header includes it.
///
/// Models:
/// - deformseg::ged::Exact_ged: the exact distance by depth-first branch and bound
///   (`exact == true`), or, when its node or time limit is hit, the best mapping found and a
///   proven lower bound (`exact == false`, `lower < upper`).
/// - deformseg::ged::Bipartite_ged: Riesen & Bunke's assignment approximation, an upper bound
///   (`lower == 0`).
/// - deformseg::ged::Assignment_lower_bound: a lower bound only (`upper` is +infinity, `mapping`
///   empty), admissible for every cost model.
///
/// Any model plugs into deformseg::ged::ged_matrix and deformseg::ged::ged_matrix_results, the
/// pairwise matrix of a set of graphs.
///
/// \par A type that is not a model
/// is rejected at compile time: `static_assert(deformseg::ged::GedPolicy<P, G, C>)` names the
/// first requirement it misses.
