/// @file clustering/k_means.h
/// @brief k-means on the graph embedding of a distance matrix (each item as its vector of
/// distances to prototype items), seeded by k-means++: `K_means`.
#pragma once

#include <deformseg/clustering/clustering.h>
#include <deformseg/clustering/internal/weighted_items.h>
#include <deformseg/exceptions.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace deformseg::clustering {

namespace internal {

// The embedding, one column per group: its distances to the prototypes. All items as prototypes
// (none given): the distances to every group, coordinate j scaled by sqrt(w_j), which keeps the
// Euclidean geometry of the embedding of the items themselves.
inline Eigen::MatrixXd embedding(const Weighted_items& g, const std::vector<std::size_t>& prototypes) {
  if (prototypes.empty()) {
    Eigen::MatrixXd x = g.distances;
    for (Eigen::Index j = 0; j < x.rows(); ++j) x.row(j) *= std::sqrt(g.weights[std::size_t(j)]);
    return x;
  }
  Eigen::MatrixXd x(Eigen::Index(prototypes.size()), g.distances.cols());
  for (std::size_t p = 0; p < prototypes.size(); ++p) {
    if (prototypes[p] >= g.group_of_item.size())
      throw invalid_input("K_means: prototype " + std::to_string(prototypes[p]) + " is not one of the " +
                          std::to_string(g.group_of_item.size()) + " items");
    x.row(Eigen::Index(p)) = g.distances.row(Eigen::Index(g.group_of_item[prototypes[p]]));
  }
  return x;
}

// One k-means run on the columns of x: k-means++ seeding, then Lloyd steps, each assigning the
// points in parallel on `threads` threads.
class Lloyd {
public:
  Lloyd(const Eigen::MatrixXd& x, const std::vector<double>& w, int threads)
      : x_(x), w_(w), n_(std::size_t(x.cols())), threads_(threads) {}

  struct Run {
    std::vector<std::size_t> labels;
    double inertia = 0;  // the weighted sum of squared distances to the centres
    std::size_t iterations = 0;
    bool converged = false;
  };

  Run run(std::size_t k, std::size_t max_iterations, deformseg::internal::Random_engine& random) const {
    Eigen::MatrixXd centres = seed(k, random);
    Run r;
    r.labels.assign(n_, k);
    std::vector<double> distance(n_);
    for (;;) {
      const bool changed = assign(centres, r.labels, distance);
      const bool reseeded = update(centres, r.labels, distance);
      if (!changed && !reseeded) {
        r.converged = true;
        break;
      }
      if (r.iterations == max_iterations) break;
      ++r.iterations;
    }
    assign(centres, r.labels, distance);
    for (std::size_t i = 0; i < n_; ++i) r.inertia += w_[i] * distance[i];
    return r;
  }

private:
  double squared(Eigen::Index i, const Eigen::MatrixXd& centres, Eigen::Index c) const {
    return (x_.col(i) - centres.col(c)).squaredNorm();
  }

  // k-means++: the first centre drawn in proportion to the weights, each next one in proportion
  // to weight x squared distance to the nearest centre so far.
  Eigen::MatrixXd seed(std::size_t k, deformseg::internal::Random_engine& random) const {
    Eigen::MatrixXd centres(x_.rows(), Eigen::Index(k));
    std::vector<double> nearest(n_, 1.0);
    std::vector<char> chosen(n_, 0);
    for (std::size_t c = 0; c < k; ++c) {
      std::vector<double> mass(n_);
      for (std::size_t i = 0; i < n_; ++i) mass[i] = chosen[i] ? 0.0 : w_[i] * nearest[i];
      const std::size_t pick = draw(mass, random, chosen);
      chosen[pick] = 1;
      centres.col(Eigen::Index(c)) = x_.col(Eigen::Index(pick));
      for (std::size_t i = 0; i < n_; ++i)
        nearest[i] = std::min(c == 0 ? std::numeric_limits<double>::infinity() : nearest[i],
                              squared(Eigen::Index(i), centres, Eigen::Index(c)));
    }
    return centres;
  }

  // Index i with probability mass[i] / sum; when all mass is 0 (points coincide with the
  // centres), the first point not chosen yet.
  static std::size_t draw(const std::vector<double>& mass, deformseg::internal::Random_engine& random,
                          const std::vector<char>& chosen) {
    double total = 0;
    for (const double m : mass) total += m;
    const double target = deformseg::internal::uniform01(random) * total;
    double sum = 0;
    std::size_t last = mass.size();
    for (std::size_t i = 0; i < mass.size(); ++i) {
      if (mass[i] <= 0) continue;
      sum += mass[i];
      last = i;
      if (target < sum) return i;
    }
    if (last < mass.size()) return last;  // target rounded up to the total
    std::size_t i = 0;
    while (chosen[i]) ++i;
    return i;
  }

  // Each point to its nearest centre (ties to the least); whether any label changed.
  bool assign(const Eigen::MatrixXd& centres, std::vector<std::size_t>& labels, std::vector<double>& distance) const {
    std::vector<char> changed(n_, 0);
    deformseg::internal::parallel_for(n_, threads_, [&](std::size_t i) {
      std::size_t best = 0;
      double least = std::numeric_limits<double>::infinity();
      for (Eigen::Index c = 0; c < centres.cols(); ++c) {
        const double s = squared(Eigen::Index(i), centres, c);
        if (s < least) {
          least = s;
          best = std::size_t(c);
        }
      }
      changed[i] = labels[i] != best;
      labels[i] = best;
      distance[i] = least;
    }, deformseg::internal::cheap_steps);
    for (const char c : changed)
      if (c) return true;
    return false;
  }

  // Centres to the weighted means of their points; an empty cluster takes the point farthest from
  // its centre (the least such). Whether a cluster was empty.
  bool update(Eigen::MatrixXd& centres, const std::vector<std::size_t>& labels, std::vector<double>& distance) const {
    const auto k = std::size_t(centres.cols());
    centres.setZero();
    std::vector<double> mass(k, 0.0);
    for (std::size_t i = 0; i < n_; ++i) {
      centres.col(Eigen::Index(labels[i])) += w_[i] * x_.col(Eigen::Index(i));
      mass[labels[i]] += w_[i];
    }
    bool reseeded = false;
    for (std::size_t c = 0; c < k; ++c) {
      if (mass[c] > 0) {
        centres.col(Eigen::Index(c)) /= mass[c];
        continue;
      }
      std::size_t farthest = 0;
      for (std::size_t i = 1; i < n_; ++i)
        if (distance[i] > distance[farthest]) farthest = i;
      centres.col(Eigen::Index(c)) = x_.col(Eigen::Index(farthest));
      distance[farthest] = 0;
      reseeded = true;
    }
    return reseeded;
  }

  const Eigen::MatrixXd& x_;
  const std::vector<double>& w_;
  std::size_t n_;
  int threads_;
};

}  // namespace internal

/// @brief k-means on the graph embedding: each item becomes the vector of its distances to the
/// prototype items (@ref method_similarity; each graph as its vector of GEDs to the prototypes), and
/// these vectors are clustered by Lloyd's algorithm under the Euclidean distance.
///
/// Each of `restarts` runs is seeded by k-means++ from one `std::mt19937_64(seed)` stream (with
/// sampling written out, so that the draws are the same on every standard library) and makes
/// Lloyd steps until no label changes or `max_iterations` steps; the run of least weighted sum of
/// squared distances to the centres wins (ties: the first). A cluster left empty takes the point
/// farthest from its centre. The medoids reported are the medoids of the clusters in the distance
/// matrix, and the silhouette (also for choosing k) is that of the distance matrix, not of the
/// embedding. When the embedding has fewer than k distinct points, fewer clusters may come out.
///
/// A model of `WeightedClusteringPolicy`: a group of w items at distance 0 counts w times in the
/// means, and with all items as prototypes its coordinate counts w times in the norm, so that the
/// geometry is that of the items.
/// Called on a matrix directly, the policy does not merge items at distance 0 (more clusters than
/// distinct items split them); through `cluster` they always share a label.
///
/// Options, as aggregate members (`K_means{.clusters = 3, .seed = 7}`):
/// - `clusters`: k; default none: the k in 2..`max_clusters` of best mean silhouette.
/// - `max_clusters`: default 10. `prototypes`: default empty (all items).
/// - `seed`: default 0. `max_iterations`: default 100. `restarts`: default 3.
/// - `threads`: default 0 (all the hardware's threads); the result does not depend on it.
/// @par Complexity
/// O(restarts x (k n p + iterations x k n p)) time for n items and p prototypes (p = n by
/// default), plus O(n^2) for the silhouette; O(n p) memory; with k by silhouette, that for each k.
struct K_means {
  /// @brief The number of clusters k, or none (the default) for the best mean silhouette over
  /// k = 2..`max_clusters`. At most the number of items.
  std::optional<std::size_t> clusters{};
  /// @brief The largest k tried when `clusters` is not given (>= 2). Default: 10.
  std::size_t max_clusters = 10;
  /// @brief The prototype items (indices of rows of the distance matrix given to `cluster` or to
  /// the policy; repeats allowed): an item's coordinates are its distances to them. Default:
  /// empty, meaning all items.
  std::vector<std::size_t> prototypes{};
  /// @brief The seed of the k-means++ draws. Default: 0.
  std::uint64_t seed = 0;
  /// @brief The most Lloyd steps of one run. Default: 100.
  std::size_t max_iterations = 100;
  /// @brief The number of seeded runs, the best kept (>= 1). Default: 3.
  std::size_t restarts = 3;
  /// @brief The threads of the Lloyd steps' assignments, the medoids and the silhouettes: 0
  /// (default) for all the hardware's threads (`thread_count`), else 1 to `max_threads`. The
  /// result does not depend on it.
  int threads = 0;

  /// @brief Clusters the items of `distances`.
  /// @param distances an n x n distance matrix (see `check_distance_matrix`).
  /// @return the clustering; labels canonical.
  /// @throws invalid_input when `threads` is out of range (before any work), `distances` is not
  /// a distance matrix, `clusters` is 0 or more than n, `max_clusters` < 2, `restarts` is 0, or a
  /// prototype is not an item.
  Clustering operator()(const Eigen::MatrixXd& distances) const {
    return internal::cluster_matrix(distances, threads, "K_means", std::bind_front(&K_means::solve, this));
  }

  /// @brief Clusters weighted groups of items (one label per group), as `cluster` does;
  /// `prototypes` are items, mapped to their groups.
  /// @param groups the groups, their weights and distances.
  /// @return the clustering of the groups.
  /// @throws invalid_input as the other overload, or when the groups are inconsistent.
  Clustering operator()(const Grouped_items& groups) const {
    return internal::cluster_groups(groups, threads, "K_means", std::bind_front(&K_means::solve, this));
  }

private:
  // `used`: `threads` as thread_count resolved it.
  Clustering solve(const internal::Weighted_items& g, int used) const {
    if (restarts == 0) throw invalid_input("K_means: restarts must be at least 1");
    const Eigen::MatrixXd x = internal::embedding(g, prototypes);
    const internal::Lloyd lloyd(x, g.weights, used);
    return internal::given_or_best_k(g.weights.size(), g.group_of_item.size(), clusters, max_clusters, "K_means",
                                     [&](std::size_t k) { return best_of_runs(g, lloyd, k, used); });
  }

  Clustering best_of_runs(const internal::Weighted_items& g, const internal::Lloyd& lloyd, std::size_t k,
                          int used) const {
    Clustering c;
    if (k == 0) return c;
    deformseg::internal::Random_engine random(seed);
    internal::Lloyd::Run best;
    for (std::size_t r = 0; r < restarts; ++r) {
      internal::Lloyd::Run run = lloyd.run(k, max_iterations, random);
      if (r == 0 || run.inertia < best.inertia) best = std::move(run);
    }
    c.labels = std::move(best.labels);
    c.iterations = best.iterations;
    c.converged = best.converged;
    return internal::finish(g.distances, g.weights, std::move(c), used);
  }
};

}  // namespace deformseg::clustering
