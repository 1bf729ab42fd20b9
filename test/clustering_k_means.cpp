#include <deformseg/clustering/k_means.h>

#include "clustering_support.h"

#include <catch2/catch.hpp>

#include <limits>
#include <random>

using deformseg::clustering::cluster;
using deformseg::clustering::Clustering;
using deformseg::clustering::K_means;
using deformseg_clustering_test::make_blobs;
using deformseg_clustering_test::random_distances;

namespace {

// The centroid of each cluster of the embedding (the columns of x) and whether every point is
// nearest its own centroid: a fixed point of Lloyd's algorithm.
bool is_lloyd_fixed_point(const Eigen::MatrixXd& x, const Clustering& c) {
  Eigen::MatrixXd centroid = Eigen::MatrixXd::Zero(x.rows(), Eigen::Index(c.clusters));
  Eigen::VectorXd count = Eigen::VectorXd::Zero(Eigen::Index(c.clusters));
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    centroid.col(Eigen::Index(c.labels[std::size_t(i)])) += x.col(i);
    count(Eigen::Index(c.labels[std::size_t(i)])) += 1;
  }
  for (Eigen::Index k = 0; k < centroid.cols(); ++k) centroid.col(k) /= count(k);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const double own = (x.col(i) - centroid.col(Eigen::Index(c.labels[std::size_t(i)]))).squaredNorm();
    for (Eigen::Index k = 0; k < centroid.cols(); ++k)
      if ((x.col(i) - centroid.col(k)).squaredNorm() < own - 1e-9) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("K_means: far-apart blobs are recovered exactly", "[clustering][k_means]") {
  for (unsigned seed = 0; seed < 10; ++seed) {
    const auto blobs = make_blobs({8, 15, 5, 11, 9}, seed);
    INFO("seed " << seed);
    const Clustering given = K_means{.clusters = 5, .seed = seed}(blobs.distances);
    CHECK(given.labels == blobs.truth);
    CHECK(given.converged);
    CHECK(K_means{.seed = seed}(blobs.distances).labels == blobs.truth);
    CHECK(cluster(blobs.distances, K_means{.seed = seed}).labels == blobs.truth);
    // Five prototypes, one per blob, are enough to tell the blobs apart.
    std::vector<std::size_t> prototypes(5);
    for (std::size_t i = 0; i < blobs.truth.size(); ++i) prototypes[blobs.truth[i]] = i;
    CHECK(K_means{.clusters = 5, .prototypes = prototypes}(blobs.distances).labels == blobs.truth);
  }
}

TEST_CASE("K_means: same seed, same labels / each run ends at a fixed point of Lloyd", "[clustering][k_means]") {
  std::mt19937 random(9);
  int differ = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::MatrixXd d = random_distances(40, random, 50);
    const std::size_t k = 2 + std::size_t(trial % 5);
    const K_means policy{.clusters = k, .seed = std::uint64_t(trial), .restarts = 1};
    const Clustering a = policy(d), b = policy(d);
    CHECK(a.labels == b.labels);
    CHECK(a.converged);
    CHECK(is_lloyd_fixed_point(d, a));  // the embedding of all items is the matrix's columns
    K_means other = policy;
    other.seed += 1000;
    differ += other(d).labels != a.labels;
  }
  CHECK(differ > 0);  // the seed matters on data without clear clusters
}

TEST_CASE("K_means: restarts keep the best run, the iteration bound is reported", "[clustering][k_means]") {
  std::mt19937 random(4);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::MatrixXd d = random_distances(50, random, 100);
    const auto inertia = [&](const Clustering& c) {
      Eigen::MatrixXd centroid = Eigen::MatrixXd::Zero(d.rows(), Eigen::Index(c.clusters));
      Eigen::VectorXd count = Eigen::VectorXd::Zero(Eigen::Index(c.clusters));
      for (Eigen::Index i = 0; i < d.cols(); ++i) {
        centroid.col(Eigen::Index(c.labels[std::size_t(i)])) += d.col(i);
        count(Eigen::Index(c.labels[std::size_t(i)])) += 1;
      }
      double sum = 0;
      for (Eigen::Index i = 0; i < d.cols(); ++i) {
        const auto l = Eigen::Index(c.labels[std::size_t(i)]);
        sum += (d.col(i) - centroid.col(l) / count(l)).squaredNorm();
      }
      return sum;
    };
    const K_means one{.clusters = 4, .seed = std::uint64_t(trial), .restarts = 1};
    K_means five = one;
    five.restarts = 5;
    // The first of the five runs is the single run: the best of five is no worse.
    CHECK(inertia(five(d)) <= inertia(one(d)) + 1e-9);
    K_means bounded = one;
    bounded.max_iterations = 0;
    const Clustering b = bounded(d);
    CHECK(b.iterations == 0);
    CHECK_FALSE(b.converged);
  }
}

TEST_CASE("K_means: options are checked", "[clustering][k_means]") {
  std::mt19937 random(1);
  const Eigen::MatrixXd d = random_distances(6, random);
  CHECK_THROWS_AS(K_means{.clusters = 0}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(K_means{.clusters = 7}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(K_means{.max_clusters = 1}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(K_means{.restarts = 0}(d), deformseg::invalid_input);
  CHECK_THROWS_AS((K_means{.prototypes = {0, 6}}(d)), deformseg::invalid_input);
  CHECK(K_means{.clusters = 6}(d).clusters == 6);
  CHECK(K_means{}(Eigen::MatrixXd::Zero(1, 1)).clusters == 1);
}
