/// @file clustering/k_medoids.h
/// @brief k-medoids clustering by Partitioning Around Medoids (Kaufman & Rousseeuw's PAM:
/// BUILD, then SWAP until no swap improves): `K_medoids`.
#pragma once

#include <deformseg/clustering/clustering.h>
#include <deformseg/clustering/internal/weighted_items.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace deformseg::clustering {

namespace internal {

// Each item's nearest and second nearest medoid (slots of `medoids`), ties to the least slot;
// a medoid is its own nearest.
struct Nearest_medoids {
  std::vector<std::size_t> slot;
  std::vector<double> first, second;

  Nearest_medoids(const Eigen::MatrixXd& d, const std::vector<std::size_t>& medoids) {
    const auto n = std::size_t(d.rows());
    constexpr double infinity = std::numeric_limits<double>::infinity();
    slot.assign(n, 0);
    first.assign(n, infinity);
    second.assign(n, infinity);
    for (std::size_t m = 0; m < medoids.size(); ++m)
      for (std::size_t i = 0; i < n; ++i) {
        const double x = i == medoids[m] ? -1.0 : d(Eigen::Index(i), Eigen::Index(medoids[m]));
        if (x < first[i]) {
          second[i] = first[i];
          first[i] = x;
          slot[i] = m;
        } else if (x < second[i]) {
          second[i] = x;
        }
      }
    for (double& x : first) x = std::max(x, 0.0);  // the -1 that made a medoid its own nearest
  }

  double cost(const std::vector<double>& weights) const {
    double sum = 0;
    for (std::size_t i = 0; i < first.size(); ++i) sum += weights[i] * first[i];
    return sum;
  }
};

// BUILD: the medoid of least total distance, then, k - 1 times, the item that lowers the total
// distance most. Candidates are scanned in `order`, so that ties go to the first in it. Gains in
// parallel on `threads` threads.
inline std::vector<std::size_t> pam_build(const Eigen::MatrixXd& d, const std::vector<double>& w, std::size_t k,
                                          const std::vector<std::size_t>& order, int threads) {
  const auto n = std::size_t(d.rows());
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  std::vector<char> is_medoid(n, 0);
  std::vector<std::size_t> medoids;
  std::vector<double> gain(n);
  while (medoids.size() < k) {
    // The gain of j as a medoid (the first one: minus its total distance).
    deformseg::internal::parallel_for(n, threads, [&](std::size_t j) {
      double g = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double x = d(Eigen::Index(i), Eigen::Index(j));
        g += medoids.empty() ? -w[i] * x : w[i] * std::max(0.0, nearest[i] - x);
      }
      gain[j] = g;
    }, deformseg::internal::cheap_steps);
    std::size_t best = n;
    for (const std::size_t j : order)
      if (!is_medoid[j] && (best == n || gain[j] > gain[best])) best = j;
    medoids.push_back(best);
    is_medoid[best] = 1;
    for (std::size_t i = 0; i < n; ++i) nearest[i] = std::min(nearest[i], d(Eigen::Index(i), Eigen::Index(best)));
  }
  return medoids;
}

// The best swap of a medoid for the non-medoid h, in O(n + k) (the FastPAM1 decomposition): the
// change of cost when h replaces slot m is common + correction[m], where common is the gain of
// the items that move to h and correction[m] accounts for the items whose nearest medoid is m.
struct Swap {
  double delta = std::numeric_limits<double>::infinity();
  std::size_t slot = 0;
};

inline Swap best_swap_for(const Eigen::MatrixXd& d, const std::vector<double>& w, const Nearest_medoids& near,
                          std::size_t k, std::size_t h) {
  std::vector<double> correction(k, 0.0);
  double common = 0;
  for (std::size_t i = 0; i < near.slot.size(); ++i) {
    const double x = d(Eigen::Index(i), Eigen::Index(h));
    const double moved = std::min(x - near.first[i], 0.0);
    common += w[i] * moved;
    correction[near.slot[i]] += w[i] * (std::min(x, near.second[i]) - near.first[i] - moved);
  }
  Swap best;
  for (std::size_t m = 0; m < k; ++m)
    if (common + correction[m] < best.delta) best = {common + correction[m], m};
  return best;
}

}  // namespace internal

/// @brief k-medoids clustering by PAM (Kaufman & Rousseeuw): BUILD picks k medoids greedily,
/// then SWAP replaces a medoid by a non-medoid while the best such swap lowers the total distance
/// of the items to their nearest medoid; each item joins its nearest medoid.
///
/// The result is a local optimum for single swaps (`converged`), or where `max_iterations` swaps
/// stopped it (`converged == false`); `iterations` is the number of swaps made. The medoids are in
/// `Clustering::medoids`. A model of `WeightedClusteringPolicy`: a group of w items at distance 0
/// counts w times in the total distance.
/// Called on a matrix directly, the policy does not merge items at distance 0 (more clusters than
/// distinct items split them); through `cluster` they always share a label.
///
/// Options, as aggregate members for designated initializers
/// (`K_medoids{.clusters = 4}`):
/// - `clusters`: k; default none: the k in 2..`max_clusters` of best mean silhouette.
/// - `max_clusters`: default 10.
/// - `seed`: the order in which ties are broken; default 0. The result is the same for a seed.
/// - `max_iterations`: the most swaps; default 100.
/// - `threads`: default 0 (all the hardware's threads); the result does not depend on it.
/// @par Complexity
/// O(k n^2) for BUILD and O(n^2 + k n) per swap, O(n + k) memory besides the matrix (per
/// thread); with k by silhouette, that for each k in 2..max_clusters.
struct K_medoids {
  /// @brief The number of clusters k, or none (the default) for the best mean silhouette over
  /// k = 2..`max_clusters`. At most the number of items; more than the number of distinct items
  /// gives one cluster per distinct item.
  std::optional<std::size_t> clusters{};
  /// @brief The largest k tried when `clusters` is not given (>= 2). Default: 10.
  std::size_t max_clusters = 10;
  /// @brief The seed of the order in which ties between equally good medoids are broken.
  /// Default: 0.
  std::uint64_t seed = 0;
  /// @brief The most swaps SWAP makes (0: BUILD only). Default: 100.
  std::size_t max_iterations = 100;
  /// @brief The threads of BUILD's gains, SWAP's candidates and the silhouettes: 0 (default) for
  /// all the hardware's threads (`thread_count`), else 1 to `max_threads`. The result does not
  /// depend on it.
  int threads = 0;

  /// @brief Clusters the items of `distances`.
  /// @param distances an n x n distance matrix (see `check_distance_matrix`).
  /// @return the clustering, with its medoids; labels canonical.
  /// @throws invalid_input when `threads` is out of range (before any work), `distances` is not
  /// a distance matrix, `clusters` is 0 or more than n, or `max_clusters` < 2.
  Clustering operator()(const Eigen::MatrixXd& distances) const {
    return internal::cluster_matrix(distances, threads, "K_medoids", std::bind_front(&K_medoids::solve, this));
  }

  /// @brief Clusters weighted groups of items (one label per group), as `cluster` does.
  /// @param groups the groups, their weights and distances.
  /// @return the clustering of the groups.
  /// @throws invalid_input as the other overload, or when the groups are inconsistent.
  Clustering operator()(const Grouped_items& groups) const {
    return internal::cluster_groups(groups, threads, "K_medoids", std::bind_front(&K_medoids::solve, this));
  }

private:
  // `used`: `threads` as thread_count resolved it.
  Clustering solve(const internal::Weighted_items& g, int used) const {
    return internal::given_or_best_k(g.weights.size(), g.group_of_item.size(), clusters, max_clusters, "K_medoids",
                                     [&](std::size_t k) {
                                       Clustering c = pam(g.distances, g.weights, k, used);
                                       return internal::finish(g.distances, g.weights, std::move(c), used);
                                     });
  }

  Clustering pam(const Eigen::MatrixXd& d, const std::vector<double>& w, std::size_t k, int used) const {
    const auto n = std::size_t(d.rows());
    Clustering c;
    if (k == 0) return c;
    const std::vector<std::size_t> order = deformseg::internal::shuffled_indices(n, seed);
    c.medoids = internal::pam_build(d, w, k, order, used);
    internal::Nearest_medoids near(d, c.medoids);
    std::vector<char> is_medoid(n, 0);
    for (const std::size_t m : c.medoids) is_medoid[m] = 1;
    std::vector<internal::Swap> swaps(n);
    for (;;) {
      deformseg::internal::parallel_for(n, used, [&](std::size_t h) {
        swaps[h] = is_medoid[h] ? internal::Swap{} : internal::best_swap_for(d, w, near, k, h);
      }, deformseg::internal::cheap_steps);
      std::size_t best = n;
      for (const std::size_t h : order)
        if (best == n || swaps[h].delta < swaps[best].delta) best = h;
      // An improvement below rounding is none, so that SWAP cannot cycle.
      if (!(swaps[best].delta < -1e-12 * near.cost(w))) break;
      if (c.iterations == max_iterations) {
        c.converged = false;
        break;
      }
      std::size_t& replaced = c.medoids[swaps[best].slot];
      is_medoid[replaced] = 0;
      is_medoid[best] = 1;
      replaced = best;
      near = internal::Nearest_medoids(d, c.medoids);
      ++c.iterations;
    }
    c.labels = near.slot;
    return c;
  }
};

}  // namespace deformseg::clustering
