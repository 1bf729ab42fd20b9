/// @file clustering/agglomerative.h
/// @brief Hierarchical agglomerative clustering with average or complete linkage, cut by a
/// number of clusters, by a height, or by the best silhouette: `Agglomerative`.
#pragma once

#include <deformseg/clustering/clustering.h>
#include <deformseg/clustering/internal/weighted_items.h>
#include <deformseg/exceptions.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace deformseg::clustering {

/// @brief The distance between two clusters in `Agglomerative`.
enum class Linkage {
  /// @brief The mean distance between their items (UPGMA), the default.
  average,
  /// @brief The largest distance between their items.
  complete,
};

namespace internal {

// One merge of the dendrogram: the clusters whose first items are `kept` and `removed` join at
// `height`.
struct Merge {
  std::size_t kept = 0, removed = 0;
  double height = 0;
};

// The n - 1 merges of the dendrogram, in order of height (a merge after those it builds on), by
// the nearest-neighbour chain: follow nearest neighbours until two clusters are each other's
// nearest, merge them, and go on from the rest of the chain. Exact for reducible linkages, of
// which average and complete are. Ties go to the previous link of the chain, then the least index.
inline std::vector<Merge> dendrogram(Eigen::MatrixXd d, std::vector<double> size, Linkage linkage) {
  const auto n = std::size_t(d.rows());
  std::vector<char> active(n, 1);
  std::vector<double> reached(n, 0.0);  // the height at which each cluster was made
  std::vector<Merge> merges;
  std::vector<std::size_t> chain;
  std::size_t first_active = 0;
  while (merges.size() + 1 < n) {
    if (chain.empty()) {
      while (!active[first_active]) ++first_active;
      chain.push_back(first_active);
    }
    const std::size_t a = chain.back();
    const bool has_previous = chain.size() > 1;
    std::size_t nearest = has_previous ? chain[chain.size() - 2] : n;
    double distance =
        has_previous ? d(Eigen::Index(nearest), Eigen::Index(a)) : std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < n; ++c)
      if (active[c] && c != a && d(Eigen::Index(c), Eigen::Index(a)) < distance) {
        nearest = c;
        distance = d(Eigen::Index(c), Eigen::Index(a));
      }
    if (!has_previous || nearest != chain[chain.size() - 2]) {
      chain.push_back(nearest);
      continue;
    }
    chain.resize(chain.size() - 2);
    const std::size_t kept = std::min(a, nearest), removed = std::max(a, nearest);
    // Rounding in the average's update can dent the heights' order: keep them monotone.
    const double height = std::max({distance, reached[kept], reached[removed]});
    for (std::size_t c = 0; c < n; ++c) {
      if (!active[c] || c == kept || c == removed) continue;
      const auto ci = Eigen::Index(c), ki = Eigen::Index(kept), ri = Eigen::Index(removed);
      const double joined = linkage == Linkage::complete
                                ? std::max(d(ci, ki), d(ci, ri))
                                : (size[kept] * d(ci, ki) + size[removed] * d(ci, ri)) / (size[kept] + size[removed]);
      d(ci, ki) = d(ki, ci) = joined;
    }
    size[kept] += size[removed];
    active[removed] = 0;
    reached[kept] = height;
    merges.push_back({kept, removed, height});
  }
  std::stable_sort(merges.begin(), merges.end(), [](const Merge& x, const Merge& y) { return x.height < y.height; });
  return merges;
}

// The partition made by the first `count` merges (labels: each item's cluster root).
inline Clustering cut(const std::vector<Merge>& merges, std::size_t n, std::size_t count) {
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t m = 0; m < count; ++m) parent[root(merges[m].removed)] = root(merges[m].kept);
  Clustering c;
  c.labels.resize(n);
  for (std::size_t i = 0; i < n; ++i) c.labels[i] = root(i);
  return c;
}

}  // namespace internal

/// @brief Hierarchical agglomerative clustering: starting from one cluster per item, the two
/// clusters of least linkage are merged until one is left; the dendrogram is then cut.
///
/// The cut: into `clusters` clusters (the last k - 1 merges undone) when given; else at `height`
/// when given (every merge at a linkage <= height is kept); else at the k in 2..`max_clusters`
/// of best mean silhouette. The dendrogram is built by the nearest-neighbour chain algorithm,
/// which for average and complete linkage gives the merges of the textbook algorithm (ties
/// apart). A model of `WeightedClusteringPolicy`: a group of w items at distance 0 is a cluster
/// of w items from the start (for average linkage, w items in the means).
/// Called on a matrix directly, the policy does not merge items at distance 0 (more clusters than
/// distinct items split them); through `cluster` they always share a label.
///
/// Options, as aggregate members (`Agglomerative{.linkage = Linkage::complete, .height = 2.0}`):
/// - `linkage`: default `Linkage::average`.
/// - `clusters`: default none. `height`: default none. At most one of them.
/// - `max_clusters`: default 10.
/// - `threads`: default 0 (all the hardware's threads); the result does not depend on it.
/// @par Complexity
/// O(n^2) time for the dendrogram, O(n) per cut, plus O(n^2) per silhouette with k by silhouette;
/// O(n^2) memory (a copy of the matrix).
struct Agglomerative {
  /// @brief How the distance between clusters is measured. Default: `Linkage::average`.
  Linkage linkage = Linkage::average;
  /// @brief The number of clusters k, when given (at most the number of items; more than the
  /// number of distinct items gives one cluster per distinct item). Default: none.
  std::optional<std::size_t> clusters{};
  /// @brief The cut height, when given: clusters whose linkage is at most this are merged
  /// (>= 0, finite). Default: none.
  std::optional<double> height{};
  /// @brief The largest k tried when neither `clusters` nor `height` is given (>= 2). Default: 10.
  std::size_t max_clusters = 10;
  /// @brief The threads of the medoids and the silhouettes (the dendrogram is built on the calling
  /// thread): 0 (default) for all the hardware's threads (`thread_count`), else 1 to
  /// `max_threads`. The result does not depend on it.
  int threads = 0;

  /// @brief Clusters the items of `distances`.
  /// @param distances an n x n distance matrix (see `check_distance_matrix`).
  /// @return the clustering; labels canonical.
  /// @throws invalid_input when `threads` is out of range (before any work), `distances` is not
  /// a distance matrix, both `clusters` and `height` are given, `clusters` is 0 or more than n,
  /// `height` is negative or not finite, or `max_clusters` < 2.
  Clustering operator()(const Eigen::MatrixXd& distances) const {
    return internal::cluster_matrix(distances, threads, "Agglomerative", std::bind_front(&Agglomerative::solve, this));
  }

  /// @brief Clusters weighted groups of items (one label per group), as `cluster` does.
  /// @param groups the groups, their weights and distances.
  /// @return the clustering of the groups.
  /// @throws invalid_input as the other overload, or when the groups are inconsistent.
  Clustering operator()(const Grouped_items& groups) const {
    return internal::cluster_groups(groups, threads, "Agglomerative", std::bind_front(&Agglomerative::solve, this));
  }

private:
  // `used`: `threads` as thread_count resolved it.
  Clustering solve(const internal::Weighted_items& g, int used) const {
    const Eigen::MatrixXd& d = g.distances;
    const std::vector<double>& w = g.weights;
    if (clusters && height) throw invalid_input("Agglomerative: give clusters or height, not both");
    if (height && !(*height >= 0 && std::isfinite(*height)))
      throw invalid_input("Agglomerative: height " + std::to_string(*height) + " is not a finite number >= 0");
    const std::size_t n = w.size();
    const std::vector<internal::Merge> merges = internal::dendrogram(d, w, linkage);
    if (height) {
      const auto below = std::upper_bound(merges.begin(), merges.end(), *height,
                                          [](double h, const internal::Merge& m) { return h < m.height; });
      return internal::finish(d, w, internal::cut(merges, n, std::size_t(below - merges.begin())), used);
    }
    const std::size_t items = g.group_of_item.size();
    return internal::given_or_best_k(n, items, clusters, max_clusters, "Agglomerative", [&](std::size_t k) {
      return internal::finish(d, w, internal::cut(merges, n, n - k), used);
    });
  }
};

}  // namespace deformseg::clustering
