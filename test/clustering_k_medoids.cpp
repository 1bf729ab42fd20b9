#include <deformseg/clustering/k_medoids.h>

#include "clustering_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <random>

using deformseg::clustering::cluster;
using deformseg::clustering::Clustering;
using deformseg::clustering::K_medoids;
using deformseg_clustering_test::make_blobs;
using deformseg_clustering_test::random_distances;

namespace {

// The total distance of the items to their nearest medoid.
double medoid_cost(const Eigen::MatrixXd& d, const std::vector<std::size_t>& medoids) {
  double sum = 0;
  for (Eigen::Index i = 0; i < d.rows(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const std::size_t m : medoids) nearest = std::min(nearest, d(i, Eigen::Index(m)));
    sum += nearest;
  }
  return sum;
}

// The least cost over all sets of k medoids.
double brute_force_cost(const Eigen::MatrixXd& d, std::size_t k) {
  const auto n = std::size_t(d.rows());
  double best = std::numeric_limits<double>::infinity();
  for (std::uint32_t set = 0; set < (1u << n); ++set) {  // every subset of the n <= 9 items
    if (std::size_t(std::popcount(set)) != k) continue;
    std::vector<std::size_t> medoids;
    for (std::size_t i = 0; i < n; ++i)
      if (set >> i & 1u) medoids.push_back(i);
    best = std::min(best, medoid_cost(d, medoids));
  }
  return best;
}

// Whether some single swap of a medoid for a non-medoid lowers the cost.
bool some_swap_improves(const Eigen::MatrixXd& d, std::vector<std::size_t> medoids) {
  const double cost = medoid_cost(d, medoids);
  for (std::size_t m = 0; m < medoids.size(); ++m)
    for (std::size_t h = 0; h < std::size_t(d.rows()); ++h) {
      if (std::find(medoids.begin(), medoids.end(), h) != medoids.end()) continue;
      std::vector<std::size_t> swapped = medoids;
      swapped[m] = h;
      if (medoid_cost(d, swapped) < cost - 1e-9) return true;
    }
  return false;
}

}  // namespace

TEST_CASE("K_medoids: far-apart blobs are recovered exactly", "[clustering][k_medoids]") {
  for (unsigned seed = 0; seed < 10; ++seed) {
    const auto blobs = make_blobs({8, 15, 5, 11, 9}, seed);
    INFO("seed " << seed);
    const Clustering given = K_medoids{.clusters = 5}(blobs.distances);
    CHECK(given.labels == blobs.truth);
    CHECK(given.clusters == 5);
    CHECK(given.converged);
    const Clustering chosen = K_medoids{}(blobs.distances);
    CHECK(chosen.labels == blobs.truth);
    CHECK(chosen.silhouette > 0.9);
    CHECK(cluster(blobs.distances, K_medoids{.seed = 3}).labels == blobs.truth);
  }
}

TEST_CASE("K_medoids: the medoids are items of their clusters, each item at its nearest medoid",
          "[clustering][k_medoids]") {
  std::mt19937 random(3);
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::MatrixXd d = random_distances(30, random, 20);
    const std::size_t k = 1 + std::size_t(trial % 6);
    const Clustering c = K_medoids{.clusters = k, .seed = std::uint64_t(trial)}(d);
    REQUIRE(c.medoids.size() == c.clusters);
    for (std::size_t m = 0; m < c.clusters; ++m) CHECK(c.labels[c.medoids[m]] == m);
    for (Eigen::Index i = 0; i < d.rows(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const std::size_t m : c.medoids) nearest = std::min(nearest, d(i, Eigen::Index(m)));
      CHECK(d(i, Eigen::Index(c.medoids[c.labels[std::size_t(i)]])) == nearest);
    }
  }
}

TEST_CASE("K_medoids: a local optimum never worse than BUILD, mostly the brute-force optimum",
          "[clustering][k_medoids]") {
  std::mt19937 random(7);
  int trials = 0, optimal = 0, with_swaps = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 3 + std::size_t(trial % 7);                   // 3..9 items
    const std::size_t k = 1 + std::size_t(trial / 7 % 3);               // 1..3 medoids
    const Eigen::MatrixXd d = random_distances(n, random, trial % 2 ? 1000 : 6);  // ties when 6
    INFO("trial " << trial << ": n " << n << ", k " << k);
    const K_medoids pam{.clusters = k, .seed = std::uint64_t(trial)};
    const Clustering c = pam(d);
    K_medoids build_only = pam;
    build_only.max_iterations = 0;
    const Clustering b = build_only(d);
    REQUIRE(c.medoids.size() == k);
    const double cost = medoid_cost(d, c.medoids), brute = brute_force_cost(d, k);
    CHECK(cost >= brute - 1e-9);
    CHECK(cost <= medoid_cost(d, b.medoids) + 1e-9);
    CHECK(c.converged);
    CHECK_FALSE(some_swap_improves(d, c.medoids));
    // BUILD alone stops converged exactly when SWAP had nothing to do.
    CHECK(b.converged == (c.iterations == 0));
    CHECK(b.iterations == 0);
    ++trials;
    optimal += cost <= brute + 1e-9;
    with_swaps += c.iterations > 0;
  }
  INFO(optimal << " of " << trials << " optimal, " << with_swaps << " with swaps");
  CHECK(optimal >= trials * 95 / 100);
  CHECK(with_swaps > 0);  // SWAP was exercised
}

TEST_CASE("K_medoids: same seed, same labels / the iteration bound is reported", "[clustering][k_medoids]") {
  std::mt19937 random(5);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::MatrixXd d = random_distances(60, random, 8);  // many ties
    const K_medoids policy{.clusters = 4, .seed = std::uint64_t(trial)};
    const Clustering a = policy(d), b = policy(d);
    CHECK(a.labels == b.labels);
    CHECK(a.medoids == b.medoids);
    const Clustering one_swap = K_medoids{.clusters = 4, .seed = std::uint64_t(trial), .max_iterations = 1}(d);
    CHECK(one_swap.iterations <= 1);
    CHECK(one_swap.converged == (a.iterations <= 1));
  }
}

TEST_CASE("K_medoids: options are checked", "[clustering][k_medoids]") {
  std::mt19937 random(1);
  const Eigen::MatrixXd d = random_distances(5, random);
  CHECK_THROWS_AS(K_medoids{.clusters = 0}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(K_medoids{.clusters = 6}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(K_medoids{.max_clusters = 1}(d), deformseg::invalid_input);
  CHECK(K_medoids{.clusters = 5}(d).clusters == 5);
  CHECK(K_medoids{}(Eigen::MatrixXd::Zero(1, 1)).clusters == 1);
  CHECK(K_medoids{}(Eigen::MatrixXd(0, 0)).clusters == 0);
}
