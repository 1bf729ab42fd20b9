/// @file clustering/clustering.h
/// @brief Clustering of items given by their distance matrix: the result `Clustering`, the
/// `ClusteringPolicy` concept, the mean `silhouette`, and `cluster`, which runs a policy so that
/// items at distance 0 always share a label.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/internal/random.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::clustering {

/// @brief A partition of n items into clusters.
///
/// Labels are canonical: numbered 0..k-1 in the order of their first appearance (item 0 has label
/// 0, the first item not in cluster 0 has label 1, ...), so that two equal partitions are equal
/// results.
struct Clustering {
  /// @brief The cluster of each item, in 0..clusters-1; one entry per item.
  std::vector<std::size_t> labels{};
  /// @brief The number of clusters k.
  std::size_t clusters = 0;
  /// @brief The representative of each cluster: an item of it whose summed distance to the items
  /// of its cluster is least (the medoid; for `K_medoids`, the medoids it found). One per cluster.
  std::vector<std::size_t> medoids{};
  /// @brief The mean silhouette of the partition (see `silhouette`), in [-1, 1].
  double silhouette = 0;
  /// @brief Iterations the policy ran (swaps of `K_medoids`, Lloyd steps of `K_means`; 0 for a
  /// policy without iterations).
  std::size_t iterations = 0;
  /// @brief False when an iterative policy stopped at its iteration bound rather than converging.
  bool converged = true;
};

/// @brief Items of a distance matrix merged into groups of items at distance 0, as `cluster`
/// hands them to a policy that models `WeightedClusteringPolicy`.
///
/// Groups are the connected components of the graph whose edges join items at distance exactly
/// 0, numbered in the order of their first item.
struct Grouped_items {
  /// @brief The g x g distances between groups: the mean distance between their items (for a
  /// metric, any item of one to any item of the other).
  Eigen::MatrixXd distances{};
  /// @brief The number of items in each group, as a weight (one per group).
  std::vector<double> weights{};
  /// @brief The group of each item of the original matrix (one per item).
  std::vector<std::size_t> group_of_item{};
  /// @brief The first (least) item of each group (one per group).
  std::vector<std::size_t> first_item{};
};

/// @brief How a clustering is computed from a distance matrix, checked at compile time.
///
/// A type `P` models it when it is copyable and `p(distances)`, for `const P& p` and a
/// `const Eigen::MatrixXd& distances` (n x n, symmetric, zero diagonal, non-negative, finite),
/// returns a `Clustering` with one label per item. See @ref ClusteringPolicyConcept.
/// @code
/// // Every item a cluster of its own: a policy of one's own.
/// struct Singletons {
///   deformseg::clustering::Clustering operator()(const Eigen::MatrixXd& d) const {
///     deformseg::clustering::Clustering c;
///     for (Eigen::Index i = 0; i < d.rows(); ++i) c.labels.push_back(std::size_t(i));
///     return c;
///   }
/// };
/// @endcode
template <class P>
concept ClusteringPolicy = std::copy_constructible<P> && requires(const P& policy, const Eigen::MatrixXd& distances) {
  { policy(distances) } -> std::same_as<Clustering>;
};

/// @brief A `ClusteringPolicy` that can also cluster weighted groups of items (`p(groups)` for a
/// `const Grouped_items& groups`, one label per group), as if each group were `weights[g]` items
/// at distance 0 from one another. `cluster` uses it when the matrix has items at distance 0.
template <class P>
concept WeightedClusteringPolicy = ClusteringPolicy<P> && requires(const P& policy, const Grouped_items& groups) {
  { policy(groups) } -> std::same_as<Clustering>;
};

/// @brief Checks that `distances` is a distance matrix as the clustering policies take it.
/// @param distances the matrix.
/// @param who the name of the caller, which starts the message.
/// @throws invalid_input naming the first offending entry `(i, j)`: when the matrix is not
/// square, an entry is not finite or negative, the diagonal is not 0, or `(i, j) != (j, i)`.
/// @par Complexity O(n^2).
/// @par Example
/// @include check_distance_matrix.cpp
inline void check_distance_matrix(const Eigen::MatrixXd& distances, std::string_view who) {
  const std::string prefix = std::string(who) + ": ";
  if (distances.rows() != distances.cols())
    throw invalid_input(prefix + "the distance matrix is " + std::to_string(distances.rows()) + " x " +
                        std::to_string(distances.cols()) + ", not square");
  const auto entry = [&](Eigen::Index i, Eigen::Index j) {
    std::ostringstream s;
    s << "distance (" << i << ", " << j << ") = " << distances(i, j);
    return s.str();
  };
  for (Eigen::Index j = 0; j < distances.cols(); ++j)
    for (Eigen::Index i = 0; i < distances.rows(); ++i) {
      const double d = distances(i, j);
      if (!std::isfinite(d)) throw invalid_input(prefix + entry(i, j) + " is not finite");
      if (d < 0) throw invalid_input(prefix + entry(i, j) + " is negative");
      if (i == j && d != 0) throw invalid_input(prefix + entry(i, j) + " is on the diagonal, which must be 0");
    }
  // Symmetry tile by tile, so that the transposed reads stay in cache.
  constexpr Eigen::Index tile = 64;
  for (Eigen::Index tj = 0; tj < distances.cols(); tj += tile)
    for (Eigen::Index ti = 0; ti <= tj; ti += tile)
      for (Eigen::Index j = tj; j < std::min(tj + tile, distances.cols()); ++j)
        for (Eigen::Index i = ti; i < std::min({ti + tile, j, distances.rows()}); ++i)
          if (distances(i, j) != distances(j, i))
            throw invalid_input(prefix + entry(j, i) + " but " + entry(i, j) + ": the matrix must be symmetric");
}

namespace internal {

inline std::size_t distinct_labels(const std::vector<std::size_t>& labels) {
  std::vector<char> seen;
  std::size_t count = 0;
  for (const std::size_t l : labels) {
    if (l >= seen.size()) seen.resize(l + 1, 0);
    if (!seen[l]) ++count;
    seen[l] = 1;
  }
  return count;
}

// Renumbers labels 0..k-1 by first appearance, in place; returns old label -> new label (size:
// the largest old label + 1; labels absent are mapped to k).
inline std::vector<std::size_t> canonicalize(std::vector<std::size_t>& labels) {
  std::size_t largest = 0;
  for (const std::size_t l : labels) largest = std::max(largest, l);
  std::vector<std::size_t> renumber(labels.empty() ? 0 : largest + 1, std::numeric_limits<std::size_t>::max());
  std::size_t next = 0;
  for (std::size_t& l : labels) {
    if (renumber[l] == std::numeric_limits<std::size_t>::max()) renumber[l] = next++;
    l = renumber[l];
  }
  for (std::size_t& r : renumber)
    if (r == std::numeric_limits<std::size_t>::max()) r = next;
  return renumber;
}

// Mean silhouette of weighted items: item i stands for weights[i] items at distance 0 from one
// another. labels are 0..k-1. With unit weights, Rousseeuw's silhouette; a cluster of one item
// scores 0, and one cluster scores 0 overall. Items in parallel on `threads` threads.
inline double weighted_silhouette(const Eigen::MatrixXd& d, const std::vector<double>& weights,
                                  const std::vector<std::size_t>& labels, std::size_t clusters, int threads) {
  const std::size_t n = labels.size();
  if (clusters < 2 || n == 0) return 0.0;
  std::vector<double> size(clusters, 0.0);
  for (std::size_t i = 0; i < n; ++i) size[labels[i]] += weights[i];
  std::vector<double> score(n, 0.0);
  deformseg::internal::parallel_for(n, threads, [&](std::size_t i) {
    std::vector<double> sum(clusters, 0.0);  // weighted distance from i to each cluster
    for (std::size_t j = 0; j < n; ++j) sum[labels[j]] += weights[j] * d(Eigen::Index(j), Eigen::Index(i));
    const std::size_t own = labels[i];
    if (size[own] <= 1.0) return;  // a singleton scores 0
    const double a = sum[own] / (size[own] - 1.0);
    double b = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < clusters; ++c)
      if (c != own && size[c] > 0) b = std::min(b, sum[c] / size[c]);
    const double larger = std::max(a, b);
    score[i] = larger > 0 ? (b - a) / larger : 0.0;
  }, deformseg::internal::cheap_steps);
  double total = 0, weight = 0;
  for (std::size_t i = 0; i < n; ++i) {
    total += weights[i] * score[i];
    weight += weights[i];
  }
  return total / weight;
}

// The medoid of each cluster: least weighted sum of distances to its cluster, ties to the least item.
inline std::vector<std::size_t> medoids_of(const Eigen::MatrixXd& d, const std::vector<double>& weights,
                                           const std::vector<std::size_t>& labels, std::size_t clusters,
                                           int threads) {
  const std::size_t n = labels.size();
  std::vector<double> within(n, 0.0);
  deformseg::internal::parallel_for(n, threads, [&](std::size_t i) {
    for (std::size_t j = 0; j < n; ++j)
      if (labels[j] == labels[i]) within[i] += weights[j] * d(Eigen::Index(j), Eigen::Index(i));
  }, deformseg::internal::cheap_steps);
  std::vector<std::size_t> medoid(clusters, n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t& m = medoid[labels[i]];
    if (m == n || within[i] < within[m]) m = i;
  }
  return medoid;
}

// A policy's result made canonical: labels renumbered, the policy's medoids kept when they fit
// (one per label 0..k-1, each in its cluster) or else computed, the silhouette computed, on
// `threads` threads.
inline Clustering finish(const Eigen::MatrixXd& d, const std::vector<double>& weights, Clustering c, int threads) {
  const std::size_t k = distinct_labels(c.labels);
  bool medoids_fit = c.medoids.size() == k;
  for (std::size_t m = 0; medoids_fit && m < k; ++m)
    medoids_fit = c.medoids[m] < c.labels.size() && c.labels[c.medoids[m]] == m;
  const std::vector<std::size_t> renumber = canonicalize(c.labels);
  c.clusters = k;
  if (medoids_fit) {
    std::vector<std::size_t> medoids(k);
    for (std::size_t m = 0; m < k; ++m) medoids[renumber[m]] = c.medoids[m];
    c.medoids = std::move(medoids);
  } else {
    c.medoids = medoids_of(d, weights, c.labels, k, threads);
  }
  c.silhouette = weighted_silhouette(d, weights, c.labels, k, threads);
  return c;
}

// Checks groups handed to a weighted policy directly: their matrix, a positive weight per group,
// a valid group for each item.
inline void check_groups(const Grouped_items& g, std::string_view who) {
  check_distance_matrix(g.distances, who);
  const auto groups = std::size_t(g.distances.rows());
  if (g.weights.size() != groups)
    throw invalid_input(std::string(who) + ": " + std::to_string(g.weights.size()) + " weights for " +
                        std::to_string(groups) + " groups");
  for (std::size_t i = 0; i < groups; ++i)
    if (!(g.weights[i] > 0) || !std::isfinite(g.weights[i]))
      throw invalid_input(std::string(who) + ": the weight of group " + std::to_string(i) + " is " +
                          std::to_string(g.weights[i]) + ", not positive and finite");
  for (std::size_t i = 0; i < g.group_of_item.size(); ++i)
    if (g.group_of_item[i] >= groups)
      throw invalid_input(std::string(who) + ": item " + std::to_string(i) + " is in group " +
                          std::to_string(g.group_of_item[i]) + " of " + std::to_string(groups));
}

// The number of clusters a policy is asked for: given (at most the items; more than the groups
// gives one cluster per group), or the k in 2..max_clusters (at most the groups) with the best
// mean silhouette, ties to the least k. run(k) clusters the groups into k clusters.
template <class Run>
Clustering given_or_best_k(std::size_t groups, std::size_t items, std::optional<std::size_t> clusters,
                           std::size_t max_clusters, std::string_view who, const Run& run) {
  if (clusters) {
    if (*clusters == 0 || *clusters > items)
      throw invalid_input(std::string(who) + ": " + std::to_string(*clusters) + " clusters asked of " +
                          std::to_string(items) + " items");
    return run(std::min(*clusters, groups));
  }
  if (max_clusters < 2) throw invalid_input(std::string(who) + ": max_clusters must be at least 2");
  if (groups < 2) return run(groups);
  Clustering best = run(2);
  for (std::size_t k = 3; k <= std::min(max_clusters, groups); ++k) {
    Clustering candidate = run(k);
    if (candidate.silhouette > best.silhouette) best = std::move(candidate);
  }
  return best;
}

// The groups of items at distance 0 (union-find over such pairs), without their distances.
inline Grouped_items zero_distance_groups(const Eigen::MatrixXd& distances) {
  const auto n = std::size_t(distances.rows());
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (distances(Eigen::Index(i), Eigen::Index(j)) == 0) {
        const std::size_t a = root(i), b = root(j);
        parent[std::max(a, b)] = std::min(a, b);  // the root stays the least item
      }
  Grouped_items g;
  g.group_of_item.resize(n);
  std::vector<std::size_t> group_of_root(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = root(i);
    if (group_of_root[r] == n) {
      group_of_root[r] = g.first_item.size();
      g.first_item.push_back(i);
      g.weights.push_back(0.0);
    }
    g.group_of_item[i] = group_of_root[r];
    g.weights[g.group_of_item[i]] += 1.0;
  }
  return g;
}

}  // namespace internal

/// @brief Merges the items at distance exactly 0 into groups (connected components of the
/// zero-distance graph), for a `WeightedClusteringPolicy`.
/// @param distances an n x n distance matrix.
/// @pre `distances` passes `check_distance_matrix` (not checked here).
/// @return the groups, their weights (sizes) and distances (mean over their items' pairs).
/// @par Complexity O(n^2) time, O(g^2) extra memory for g groups.
/// @par Example
/// @include group_identical_items.cpp
inline Grouped_items group_identical_items(const Eigen::MatrixXd& distances) {
  Grouped_items g = internal::zero_distance_groups(distances);
  const auto n = std::size_t(distances.rows());
  const auto groups = Eigen::Index(g.first_item.size());
  g.distances = Eigen::MatrixXd::Zero(groups, groups);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const auto a = Eigen::Index(g.group_of_item[i]), b = Eigen::Index(g.group_of_item[j]);
      if (a != b) g.distances(std::min(a, b), std::max(a, b)) += distances(Eigen::Index(i), Eigen::Index(j));
    }
  for (Eigen::Index b = 0; b < groups; ++b)
    for (Eigen::Index a = 0; a < b; ++a) {
      g.distances(a, b) /= g.weights[std::size_t(a)] * g.weights[std::size_t(b)];
      g.distances(b, a) = g.distances(a, b);
    }
  return g;
}

/// @brief The mean silhouette of a partition of the items of a distance matrix.
///
/// For item i in cluster A, a(i) is its mean distance to the other items of A, b(i) the least,
/// over the other clusters B, of its mean distance to the items of B, and
/// s(i) = (b(i) - a(i)) / max(a(i), b(i)) (0 when both are 0). Conventions: s(i) = 0 for an item
/// alone in its cluster (Rousseeuw's); with a single cluster (k = 1, or no items) the silhouette
/// is 0. The result is the mean of s(i) over the items, in [-1, 1].
/// @param distances an n x n distance matrix.
/// @param labels the cluster of each item (any values; they only say which items are together).
/// @param threads the threads of the items' scores: 0 (default) for all the hardware's threads
/// (`thread_count`), else 1 to `max_threads`. The result does not depend on it.
/// @pre `distances` passes `check_distance_matrix`; `labels.size() == n`.
/// @return the mean silhouette.
/// @throws invalid_input when a precondition is broken or `threads` is out of range.
/// @par Complexity O(n^2 + n k) time, O(n + k) extra memory (per thread).
inline double silhouette(const Eigen::MatrixXd& distances, const std::vector<std::size_t>& labels,
                         int threads = 0) {
  threads = thread_count(threads, "silhouette");
  check_distance_matrix(distances, "silhouette");
  if (labels.size() != std::size_t(distances.rows()))
    throw invalid_input("silhouette: " + std::to_string(labels.size()) + " labels for " +
                        std::to_string(distances.rows()) + " items");
  std::vector<std::size_t> canonical = labels;
  internal::canonicalize(canonical);
  return internal::weighted_silhouette(distances, std::vector<double>(labels.size(), 1.0), canonical,
                                       internal::distinct_labels(canonical), threads);
}

/// @brief Clusters the items of a distance matrix with `policy`, so that items at distance
/// exactly 0 always share a label.
///
/// The items at distance 0 (connected through such pairs) are merged first
/// (`group_identical_items`); a `WeightedClusteringPolicy` then clusters the groups, each weighted
/// by its size, which for the policies of deformseg is the same objective as on the items; any
/// other policy clusters the matrix of groups. Without such items the policy gets `distances`
/// itself. Each item then takes its group's label; labels are made canonical (see `Clustering`),
/// the policy's medoids are kept (as the first item of their group) or else computed, and the
/// silhouette is computed on `distances`. A number of clusters k larger than the number of
/// groups gives one cluster per group.
/// @tparam Policy a `ClusteringPolicy`: `K_medoids`, `Agglomerative`, `K_means`, or one's own.
/// @param distances an n x n distance matrix: symmetric, zero diagonal, non-negative, finite.
/// @param policy the policy with its options (its threads among them, for `K_medoids`, `K_means`
/// and `Agglomerative`).
/// @param threads the threads of `cluster`'s own loops (the medoids and the silhouette): 0
/// (default) for all the hardware's threads (`thread_count`), else 1 to `max_threads`. The result
/// does not depend on it.
/// @return the clustering of the n items.
/// @throws invalid_input when `threads` is out of range (before any work), when `distances` is
/// not a distance matrix (naming the entry), when the policy's options are invalid, or when the
/// policy returns the wrong number of labels.
/// @par Complexity O(n^2) plus the policy's on the groups.
template <ClusteringPolicy Policy>
Clustering cluster(const Eigen::MatrixXd& distances, const Policy& policy, int threads = 0) {
  threads = thread_count(threads, "cluster");
  check_distance_matrix(distances, "cluster");
  const auto n = std::size_t(distances.rows());
  if (internal::zero_distance_groups(distances).first_item.size() == n) {  // no items at distance 0
    Clustering c = policy(distances);
    if (c.labels.size() != n)
      throw invalid_input("cluster: the policy gave " + std::to_string(c.labels.size()) + " labels for " +
                          std::to_string(n) + " items");
    return internal::finish(distances, std::vector<double>(n, 1.0), std::move(c), threads);
  }
  const Grouped_items groups = group_identical_items(distances);
  const std::size_t g = groups.weights.size();
  Clustering c;
  if constexpr (WeightedClusteringPolicy<Policy>)
    c = policy(groups);
  else
    c = policy(groups.distances);
  if (c.labels.size() != g)
    throw invalid_input("cluster: the policy gave " + std::to_string(c.labels.size()) + " labels for " +
                        std::to_string(g) + " groups of items at distance 0");
  // Canonical on the groups first, so that the policy's medoids are checked and kept.
  c = internal::finish(groups.distances, groups.weights, std::move(c), threads);
  Clustering result{std::vector<std::size_t>(n), c.clusters, {}, 0.0, c.iterations, c.converged};
  for (std::size_t i = 0; i < n; ++i) result.labels[i] = c.labels[groups.group_of_item[i]];
  for (const std::size_t m : c.medoids) result.medoids.push_back(groups.first_item[m]);
  // Already canonical: groups are numbered by their first item, and their labels are canonical.
  result.silhouette =
      internal::weighted_silhouette(distances, std::vector<double>(n, 1.0), result.labels, c.clusters, threads);
  return result;
}

}  // namespace deformseg::clustering
