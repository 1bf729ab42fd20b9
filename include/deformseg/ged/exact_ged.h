/// @file ged/exact_ged.h
/// @brief `Exact_ged`: the graph edit distance by depth-first branch and bound over node
/// mappings, with an assignment lower bound; a limit on the work makes it report bounds instead.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/ged/bipartite_ged.h>
#include <deformseg/ged/edit_cost.h>
#include <deformseg/ged/ged_policy.h>
#include <deformseg/ged/internal/ged_search.h>
#include <deformseg/threads.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::ged {

namespace internal {

// The nodes of A in the order the search maps them: the one of largest degree first, then always
// the one with most edges to those already ordered (ties: larger degree, then smaller index), so
// that each step meets its edges to done nodes early, where they are priced exactly.
inline std::vector<std::size_t> search_order(const Ged_instance& in) {
  std::vector<std::size_t> order, degree(in.n), links(in.n, 0);
  std::vector<char> placed(in.n, 0);
  for (std::size_t i = 0; i < in.n; ++i) degree[i] = count_bits(in.adjacency_a.row(i), in.adjacency_a.words());
  for (std::size_t step = 0; step < in.n; ++step) {
    std::size_t best = in.n;
    for (std::size_t i = 0; i < in.n; ++i) {
      if (placed[i]) continue;
      if (best == in.n || links[i] > links[best] || (links[i] == links[best] && degree[i] > degree[best])) best = i;
    }
    placed[best] = 1;
    order.push_back(best);
    for (std::size_t i = 0; i < in.n; ++i)
      if (in.adjacency_a.test(best, i)) ++links[i];
  }
  return order;
}

// Depth-first branch and bound: at each depth the next node of A in search order is mapped onto
// each open node of B or deleted; children are priced by cost so far plus the completion bound,
// visited cheapest first, and cut when they cannot beat the best mapping found.
class Exact_search {
public:
  Exact_search(const Ged_instance& in, std::size_t max_expanded, double max_seconds)
      : in_(in), state_(in), order_(search_order(in)), children_(in.n), current_(in.n, -1),
        max_expanded_(max_expanded), max_seconds_(max_seconds), start_(std::chrono::steady_clock::now()) {}

  // Searches below `upper` (the cost of `mapping`); returns the proven lower bound, which is the
  // distance found when the search ends by itself.
  double run(std::vector<int>& mapping, double& upper) {
    best_ = std::move(mapping);
    upper_ = upper;
    const double root = state_.completion_bound(lsap_, matrix_);
    if (in_.n > 0 && root < upper_) expand(0, 0.0, root);
    mapping = std::move(best_);
    upper = upper_;
    if (!stopped_) return upper_;
    return std::max(root, std::min(upper_, frontier_));
  }

  bool stopped() const { return stopped_; }

private:
  struct Child {
    double bound;  // cost so far plus the completion bound
    double cost;   // cost so far
    int image;     // node of B, or -1 for a deletion
  };

  bool out_of_budget() const {
    if (expanded_ >= max_expanded_) return true;
    if (max_seconds_ <= 0 || expanded_ % 64 != 0) return false;
    const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - start_;
    return spent.count() >= max_seconds_;
  }

  void expand(std::size_t depth, double cost, double bound) {
    if (stopped_ || out_of_budget()) {
      stopped_ = true;
      frontier_ = std::min(frontier_, bound);
      return;
    }
    ++expanded_;
    if (expanded_ % 64 == 0) interruption_point();  // a search can last seconds: Ctrl-C in Python
    const std::size_t v = order_[depth];
    std::vector<Child>& children = children_[depth];
    children.clear();
    for (int w = -1; w < static_cast<int>(in_.m); ++w) {
      if (w >= 0 && !state_.is_open_in_b(static_cast<std::size_t>(w))) continue;
      const double child_cost = cost + state_.step_cost(v, w);
      if (child_cost >= upper_) continue;
      state_.map(v, w);
      const double child_bound = child_cost + state_.completion_bound(lsap_, matrix_);
      state_.unmap(v, w);
      if (child_bound >= upper_) continue;
      if (depth + 1 == in_.n) {  // a complete mapping: its bound is its cost
        current_[v] = w;
        best_ = current_;
        upper_ = child_bound;
        current_[v] = -1;
      } else {
        children.push_back({child_bound, child_cost, w});
      }
    }
    std::stable_sort(children.begin(), children.end(),
                     [](const Child& x, const Child& y) { return x.bound < y.bound; });
    for (const Child& child : children) {
      if (stopped_) {
        frontier_ = std::min(frontier_, child.bound);
        continue;
      }
      if (child.bound >= upper_) break;
      current_[v] = child.image;
      state_.map(v, child.image);
      expand(depth + 1, child.cost, child.bound);
      state_.unmap(v, child.image);
      current_[v] = -1;
    }
  }

  const Ged_instance& in_;
  Partial_mapping state_;
  std::vector<std::size_t> order_;
  std::vector<std::vector<Child>> children_;  // per depth, reused
  std::vector<int> current_, best_;
  Lsap_workspace lsap_;
  std::vector<double> matrix_;
  double upper_ = 0;
  double frontier_ = std::numeric_limits<double>::infinity();
  bool stopped_ = false;
  std::size_t expanded_ = 0;
  std::size_t max_expanded_;
  double max_seconds_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace internal

/// @brief GED policy (models `GedPolicy`): the exact graph edit distance, by depth-first branch
/// and bound over node mappings.
///
/// The nodes of the smaller graph (A, or B when A has more nodes) are mapped in a fixed order
/// (largest degree first, then always the node with most edges to those already mapped), each
/// onto a free node of the other graph or deleted. The first upper
/// bound is Bipartite_ged's; each partial mapping is priced by its exact cost so far plus an
/// admissible bound on the rest: an optimal assignment of the open nodes (node costs, exact costs
/// of their pairs with mapped nodes, half the least cost of their edges among open nodes; see
/// Assignment_lower_bound, which is this bound at the root). Children are visited cheapest first
/// and cut when their bound reaches the best cost found. Adjacency is held in bit rows, so the
/// search makes no Boost.Graph call.
///
/// When the search ends by itself the result is exact: `exact == true`,
/// `distance == lower == upper`, and `mapping` an optimal edit path. When a limit stops it first,
/// `exact == false`, `distance == upper` is the cost of the best mapping found (never worse than
/// Bipartite_ged's) and `lower` a proven bound: the least bound over the partial mappings left
/// open, or the root bound when that is larger. The search never runs past its limits.
///
/// Options are aggregate members: `Exact_ged{.max_expanded = 10'000}(a, b)`.
/// @throws invalid_input when the cost model gives a negative or non-finite cost, or when
/// `max_seconds` is negative or not a number; cancelled when the calling thread's
/// `Interruption_check` stops the search (threads.h; checked every 64 expansions).
/// @par Complexity exponential in the worst case; each expanded partial mapping costs
/// m + 1 assignment problems of at most n x m (chapter 10 of the manual gives times).
struct Exact_ged {
  /// @brief The most partial mappings expanded (children generated) before the search stops and
  /// reports bounds. Default 200,000: enough for pairs of up to about 16 nodes, and a cap that
  /// keeps any pair to seconds (chapter 10 of the manual gives the measurements). 0: only
  /// Bipartite_ged's mapping and the root bound.
  std::size_t max_expanded = 200'000;
  /// @brief A time limit in seconds, checked every 64 expansions; 0 (the default): none. A time
  /// limit makes the result depend on the machine's speed; `max_expanded` does not.
  double max_seconds = 0;

  /// @brief Compares `a` to `b` under `costs`.
  template <LabelledGraph G, GedCostModel<label_t<G>> C = Unit_costs>
  Ged_result operator()(const G& a, const G& b, const C& costs = {}) const {
    if (!(max_seconds >= 0))
      throw invalid_input("Exact_ged: max_seconds = " + std::to_string(max_seconds) + " must be >= 0");
    const internal::Ged_instance instance = internal::make_instance(a, b, costs, "Exact_ged");
    Ged_result start = Bipartite_ged{}(a, b, costs);
    double upper = start.upper;
    std::vector<int> mapping = std::move(start.mapping);
    // The search maps the nodes of the smaller graph (depth n, m + 1 choices each): from B when
    // A is larger, which gives the same distance.
    const bool from_b = instance.n > instance.m;
    const internal::Ged_instance searched = from_b ? internal::reversed(instance) : internal::Ged_instance{};
    internal::Exact_search search(from_b ? searched : instance, max_expanded, max_seconds);
    if (from_b) mapping = internal::inverted(mapping, instance.m);
    const double lower = search.run(mapping, upper);
    if (from_b) mapping = internal::inverted(mapping, instance.n);
    upper = edit_cost(a, b, mapping, costs);  // the cost of the mapping as edit_cost sums it
    if (!search.stopped() || lower >= upper)  // a stopped search may still have closed the gap
      return {.distance = upper, .exact = true, .lower = upper, .upper = upper, .mapping = std::move(mapping)};
    return {.distance = upper, .exact = false, .lower = std::min(lower, upper), .upper = upper,
            .mapping = std::move(mapping)};
  }
};

}  // namespace deformseg::ged
