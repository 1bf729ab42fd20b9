/// @file ged/ged_matrix.h
/// @brief The graph edit distance between every two graphs of a set: `ged_matrix`, and
/// `ged_matrix_results` with each pair's bounds and mapping. Parallel, symmetric, deterministic.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/ged/exact_ged.h>
#include <deformseg/ged/ged_policy.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::ged {

/// @brief Options of ged_matrix and ged_matrix_results.
struct Ged_matrix_options {
  /// @brief Threads (0: all the hardware's threads (`thread_count`)), at most `max_threads`. The result is the same for
  /// any number, for a
  /// deterministic policy (Exact_ged without `max_seconds`, Bipartite_ged,
  /// Assignment_lower_bound).
  int threads = 0;
  /// @brief false (the default): pair {i, j}, i < j, is `policy(graphs[i], graphs[j], costs)`.
  /// true: `policy(graphs[j], graphs[i], costs)` too, and the two are combined: the larger lower
  /// bound, the smaller upper bound (with its mapping, turned round when it came from j -> i), exact
  /// when either is. Better bounds for twice the work; only meaningful for a symmetric cost model
  /// (insertion costs equal to deletion costs, symmetric substitution costs).
  bool both_directions = false;
  /// @brief Called on the calling thread with the pairs done and their total (see `Progress`),
  /// after each parallel batch of pairs (about 5 % of them, at least 16); returning false stops
  /// the work, which then throws `cancelled`. Empty (the default): no call.
  Progress progress{};
};

/// @brief The pairwise comparison of a set of graphs: matrices of distances and bounds, and each
/// pair's Ged_result.
struct Ged_matrix_result {
  Eigen::MatrixXd distance;       ///< k x k, symmetric, zero diagonal: each pair's `distance`
  Eigen::MatrixXd lower;          ///< k x k, symmetric: each pair's proven lower bound
  Eigen::MatrixXd upper;          ///< k x k, symmetric: each pair's upper bound (may be +infinity)
  std::vector<Ged_result> pairs;  ///< pair {i, j}, i < j, at index pair_index(i, j): graph i -> graph j
  bool exact = true;              ///< whether every pair's distance is exact

  /// @brief The index in `pairs` of pair {i, j} (i != j, either order): pairs are stored row by
  /// row of the upper triangle.
  std::size_t pair_index(std::size_t i, std::size_t j) const {
    if (i > j) std::swap(i, j);
    const auto k = static_cast<std::size_t>(distance.rows());
    return i * k - i * (i + 1) / 2 + (j - i - 1);
  }
};

namespace internal {

// The mapping of graph j -> graph i turned into one of graph i (n nodes) -> graph j.
inline std::vector<int> inverse_mapping(const std::vector<int>& reverse, std::size_t n) {
  std::vector<int> forward(n, -1);
  for (std::size_t k = 0; k < reverse.size(); ++k)
    if (reverse[k] >= 0) forward[static_cast<std::size_t>(reverse[k])] = static_cast<int>(k);
  return forward;
}

// Both directions of a pair as one result (symmetric costs): the tighter bound of each side.
inline Ged_result combined(Ged_result forward, Ged_result reverse, std::size_t n) {
  Ged_result r;
  r.lower = std::max(forward.lower, reverse.lower);
  if (reverse.upper < forward.upper) {
    r.upper = reverse.upper;
    r.mapping = inverse_mapping(reverse.mapping, n);
  } else {
    r.upper = forward.upper;
    r.mapping = std::move(forward.mapping);
  }
  r.exact = forward.exact || reverse.exact || r.lower >= r.upper;
  if (r.exact) r.lower = r.upper;
  r.distance = std::isinf(r.upper) ? r.lower : r.upper;
  return r;
}

}  // namespace internal

/// @brief Compares every two graphs of `graphs` with `policy` under `costs`, in parallel: the
/// distance matrix with each pair's bounds and Ged_result.
///
/// Pair {i, j} with i < j is computed once, as `policy(graphs[i], graphs[j], costs)` (see
/// Ged_matrix_options::both_directions for the alternative), and mirrored, so the matrices are
/// symmetric whatever the policy; the diagonal is 0. Pairs are shared among threads dynamically
/// but each is computed alone, so the result does not depend on the number of threads.
/// @tparam Graphs a random-access range (`std::vector`, `std::span`, ...) of a `LabelledGraph`
/// type.
/// @param graphs the k graphs; k may be 0 or 1.
/// @param policy a `GedPolicy`; default Exact_ged{} (its default node limit).
/// @param costs a `GedCostModel`; default Unit_costs.
/// @param options threads, both directions, a progress callback that can stop the work.
/// @return k x k matrices and k (k - 1) / 2 pair results.
/// @throws invalid_input or whatever the policy throws (the exception of the first failing pair
/// in pair order; the pairs after it are not started); invalid_input for `threads` out of [0,
/// `max_threads`]; cancelled when `options.progress` or the calling thread's
/// `Interruption_check` (threads.h) returned false.
/// @par Complexity k (k - 1) / 2 policy calls (twice that with both directions).
template <std::ranges::random_access_range Graphs, class Policy = Exact_ged,
          class Costs = Unit_costs>
  requires GedPolicy<Policy, std::ranges::range_value_t<Graphs>, Costs>
Ged_matrix_result ged_matrix_results(const Graphs& graphs, const Policy& policy = {}, const Costs& costs = {},
                                     const Ged_matrix_options& options = {}) {
  const auto k = static_cast<std::size_t>(std::ranges::size(graphs));
  std::vector<std::pair<std::size_t, std::size_t>> todo;
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j) todo.emplace_back(i, j);
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<Ged_result> pairs(todo.size(), Ged_result{.distance = infinity, .exact = false, .lower = 0,
                                                        .upper = infinity, .mapping = {}});
  const int threads = thread_count(options.threads, "ged_matrix");
  const std::size_t total = todo.size();
  deformseg::internal::parallel_for_reporting(total, threads, options.progress, 0, total, [&](std::size_t at) {
    const auto [i, j] = todo[at];
    const auto& a = graphs[static_cast<std::ranges::range_difference_t<Graphs>>(i)];
    const auto& b = graphs[static_cast<std::ranges::range_difference_t<Graphs>>(j)];
    Ged_result forward = policy(a, b, costs);
    pairs[at] = options.both_directions
                    ? internal::combined(std::move(forward), policy(b, a, costs), boost::num_vertices(a))
                    : std::move(forward);
  });
  Ged_matrix_result result{
      .distance = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)),
      .lower = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)),
      .upper = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)),
      .pairs = {},
      .exact = true};
  for (std::size_t at = 0; at < todo.size(); ++at) {
    const auto i = static_cast<Eigen::Index>(todo[at].first), j = static_cast<Eigen::Index>(todo[at].second);
    const Ged_result& r = pairs[at];
    result.distance(i, j) = result.distance(j, i) = r.distance;
    result.lower(i, j) = result.lower(j, i) = r.lower;
    result.upper(i, j) = result.upper(j, i) = r.upper;
    result.exact = result.exact && r.exact;
  }
  result.pairs = std::move(pairs);
  return result;
}

/// @brief The symmetric k x k matrix of graph edit distances between every two graphs of
/// `graphs` (zero diagonal): `ged_matrix_results(graphs, policy, costs, options).distance`.
///
/// With the default Exact_ged, an entry is exact unless the pair hit the node limit; then it is
/// the best upper bound found (ged_matrix_results tells which).
/// @param graphs the k graphs, a random-access range of one `LabelledGraph` type.
/// @param policy a `GedPolicy`; default Exact_ged{}.
/// @param costs a `GedCostModel`; default Unit_costs.
/// @param options threads, both directions, a progress callback that can stop the work.
/// @throws invalid_input or whatever the policy throws; cancelled as `ged_matrix_results`.
/// @par Complexity k (k - 1) / 2 policy calls.
template <std::ranges::random_access_range Graphs, class Policy = Exact_ged,
          class Costs = Unit_costs>
  requires GedPolicy<Policy, std::ranges::range_value_t<Graphs>, Costs>
Eigen::MatrixXd ged_matrix(const Graphs& graphs, const Policy& policy = {}, const Costs& costs = {},
                           const Ged_matrix_options& options = {}) {
  return ged_matrix_results(graphs, policy, costs, options).distance;
}

}  // namespace deformseg::ged
