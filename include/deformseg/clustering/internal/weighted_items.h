// The two entry points that every clustering policy of the library offers, written once: a
// distance matrix (each item a group of weight 1) and the weighted groups of `cluster`. Both
// resolve the threads before any work, check their input, and hand the policy the same view.
#pragma once

#include <deformseg/clustering/clustering.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <cstddef>
#include <numeric>
#include <vector>

namespace deformseg::clustering::internal {

// What a policy clusters, by reference: g groups, their g x g distances and weights, and the group
// of each item (the groups of `cluster`, or the items of a matrix, each its own group).
struct Weighted_items {
  const Eigen::MatrixXd& distances;
  const std::vector<double>& weights;
  const std::vector<std::size_t>& group_of_item;
};

// `solve(items, used)` on the items of `distances`, each of weight 1, `used` being `threads` as
// thread_count resolved it. `who` names the policy in the errors.
template <class Solve>
Clustering cluster_matrix(const Eigen::MatrixXd& distances, int threads, const char* who, const Solve& solve) {
  const int used = thread_count(threads, who);
  check_distance_matrix(distances, who);
  const auto n = std::size_t(distances.rows());
  const std::vector<double> weights(n, 1.0);
  std::vector<std::size_t> group_of_item(n);
  std::iota(group_of_item.begin(), group_of_item.end(), std::size_t{0});
  return solve(Weighted_items{distances, weights, group_of_item}, used);
}

// `solve(items, used)` on weighted groups, as `cluster_matrix`.
template <class Solve>
Clustering cluster_groups(const Grouped_items& groups, int threads, const char* who, const Solve& solve) {
  const int used = thread_count(threads, who);
  check_groups(groups, who);
  return solve(Weighted_items{groups.distances, groups.weights, groups.group_of_item}, used);
}

}  // namespace deformseg::clustering::internal
