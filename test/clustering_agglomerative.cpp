#include <deformseg/clustering/agglomerative.h>

#include "clustering_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>

using deformseg::clustering::Agglomerative;
using deformseg::clustering::cluster;
using deformseg::clustering::Linkage;
using deformseg_clustering_test::make_blobs;
using deformseg_clustering_test::on_a_line;

namespace {

std::vector<std::size_t> canonical(std::vector<std::size_t> labels) {
  std::vector<std::size_t> renumber(labels.size() + 1, labels.size());
  std::size_t next = 0;
  for (std::size_t& l : labels) {
    if (renumber[l] == labels.size()) renumber[l] = next++;
    l = renumber[l];
  }
  return labels;
}

// The textbook algorithm, straight from the definition: merge the two clusters whose linkage
// (mean or largest distance between their items) is least, until k are left. O(n^4), for small n.
std::vector<std::size_t> brute_force_cut(const Eigen::MatrixXd& d, Linkage linkage, std::size_t k) {
  std::vector<std::vector<std::size_t>> clusters;
  for (std::size_t i = 0; i < std::size_t(d.rows()); ++i) clusters.push_back({i});
  const auto link = [&](const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
    double sum = 0, largest = 0;
    for (const std::size_t i : a)
      for (const std::size_t j : b) {
        sum += d(Eigen::Index(i), Eigen::Index(j));
        largest = std::max(largest, d(Eigen::Index(i), Eigen::Index(j)));
      }
    return linkage == Linkage::average ? sum / double(a.size() * b.size()) : largest;
  };
  while (clusters.size() > k) {
    std::size_t best_a = 0, best_b = 1;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < clusters.size(); ++a)
      for (std::size_t b = a + 1; b < clusters.size(); ++b)
        if (link(clusters[a], clusters[b]) < best) {
          best = link(clusters[a], clusters[b]);
          best_a = a;
          best_b = b;
        }
    clusters[best_a].insert(clusters[best_a].end(), clusters[best_b].begin(), clusters[best_b].end());
    clusters.erase(clusters.begin() + std::ptrdiff_t(best_b));
  }
  std::vector<std::size_t> labels(std::size_t(d.rows()));
  for (std::size_t c = 0; c < clusters.size(); ++c)
    for (const std::size_t i : clusters[c]) labels[i] = c;
  return canonical(labels);
}


}  // namespace

TEST_CASE("Agglomerative: a textbook example where average and complete linkage differ",
          "[clustering][agglomerative]") {
  // Points 0, 2, 5, 9.5 on a line. Both linkages first merge {0, 2} at 2. Then:
  //  average:  {0,2}-5 = (5 + 3) / 2 = 4,  {0,2}-9.5 = 8.5,  5-9.5 = 4.5: merge {0, 2, 5} at 4,
  //            last at (9.5 + 7.5 + 4.5) / 3 = 7.17;
  //  complete: {0,2}-5 = 5,  {0,2}-9.5 = 9.5,  5-9.5 = 4.5: merge {5, 9.5} at 4.5, last at 9.5.
  const Eigen::MatrixXd d = on_a_line({0, 2, 5, 9.5});
  const Agglomerative average{.linkage = Linkage::average};
  const Agglomerative complete{.linkage = Linkage::complete};
  const auto labels = [&](Agglomerative p) { return p(d).labels; };
  using L = std::vector<std::size_t>;
  auto a = average, c = complete;
  a.clusters = c.clusters = 3;
  CHECK(labels(a) == L{0, 0, 1, 2});
  CHECK(labels(c) == L{0, 0, 1, 2});
  a.clusters = c.clusters = 2;
  CHECK(labels(a) == L{0, 0, 0, 1});
  CHECK(labels(c) == L{0, 0, 1, 1});
  a.clusters = c.clusters = 1;
  CHECK(labels(a) == L{0, 0, 0, 0});
  a.clusters = c.clusters = 4;
  CHECK(labels(c) == L{0, 1, 2, 3});
  // Cut by height: a merge at a linkage <= height is made.
  a.clusters = c.clusters = std::nullopt;
  a.height = c.height = 1.9;
  CHECK(labels(a) == L{0, 1, 2, 3});
  a.height = c.height = 2.0;
  CHECK(labels(a) == L{0, 0, 1, 2});
  a.height = c.height = 4.2;
  CHECK(labels(a) == L{0, 0, 0, 1});
  CHECK(labels(c) == L{0, 0, 1, 2});
  a.height = c.height = 4.5;
  CHECK(labels(c) == L{0, 0, 1, 1});
  a.height = c.height = 7.2;
  CHECK(labels(a) == L{0, 0, 0, 0});
  CHECK(labels(c) == L{0, 0, 1, 1});
  a.height = c.height = 9.5;
  CHECK(labels(c) == L{0, 0, 0, 0});
}

TEST_CASE("Agglomerative: every cut equals the textbook algorithm on random matrices", "[clustering][agglomerative]") {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> distance(1.0, 10.0);  // not metric: any symmetric matrix
  for (int trial = 0; trial < 60; ++trial) {
    const auto n = Eigen::Index(2 + trial % 11);
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < i; ++j) d(i, j) = d(j, i) = distance(random);
    for (const Linkage linkage : {Linkage::average, Linkage::complete})
      for (std::size_t k = 1; k <= std::size_t(n); ++k) {
        INFO("trial " << trial << ", n " << n << ", k " << k << ", complete " << (linkage == Linkage::complete));
        CHECK(Agglomerative{.linkage = linkage, .clusters = k}(d).labels == brute_force_cut(d, linkage, k));
      }
  }
}

TEST_CASE("Agglomerative: items at distance 0 weigh as items in the average", "[clustering][agglomerative]") {
  // Groups of copies handed to the policy with their weights give the cuts of the textbook
  // algorithm on all the items (for k at most the number of distinct items).
  std::mt19937 random(23);
  for (int trial = 0; trial < 30; ++trial) {
    // Offsets 2^p / 1000 make the distances between distinct points all different: no ties.
    std::vector<double> x;
    std::uniform_int_distribution<int> position(0, 40), copies(1, 3);
    for (int p = 0; p < 6; ++p)
      x.insert(x.end(), std::size_t(copies(random)), position(random) + 0.001 * double(1 << p));
    const Eigen::MatrixXd d = on_a_line(x);
    for (const Linkage linkage : {Linkage::average, Linkage::complete})
      for (std::size_t k = 1; k <= 6; ++k) {
        INFO("trial " << trial << ", k " << k);
        CHECK(cluster(d, Agglomerative{.linkage = linkage, .clusters = k}).labels == brute_force_cut(d, linkage, k));
      }
  }
}

TEST_CASE("Agglomerative: far-apart blobs are recovered by k, by height, by silhouette",
          "[clustering][agglomerative]") {
  for (unsigned seed = 0; seed < 10; ++seed) {
    const auto blobs = make_blobs({8, 15, 5, 11, 9, 1}, seed);
    INFO("seed " << seed);
    for (const Linkage linkage : {Linkage::average, Linkage::complete}) {
      CHECK(Agglomerative{.linkage = linkage, .clusters = 6}(blobs.distances).labels == blobs.truth);
      // Within a blob at most 2 apart, between blobs at least 18.
      CHECK(Agglomerative{.linkage = linkage, .height = 5.0}(blobs.distances).labels == blobs.truth);
      CHECK(Agglomerative{.linkage = linkage}(blobs.distances).labels == blobs.truth);
      CHECK(cluster(blobs.distances, Agglomerative{.linkage = linkage}).labels == blobs.truth);
    }
  }
}

TEST_CASE("Agglomerative: options are checked", "[clustering][agglomerative]") {
  const Eigen::MatrixXd d = on_a_line({0, 1, 5});
  CHECK_THROWS_AS((Agglomerative{.clusters = 2, .height = 1.0}(d)), deformseg::invalid_input);
  CHECK_THROWS_AS(Agglomerative{.height = -1.0}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(Agglomerative{.height = std::numeric_limits<double>::infinity()}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(Agglomerative{.clusters = 0}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(Agglomerative{.clusters = 4}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(Agglomerative{.max_clusters = 1}(d), deformseg::invalid_input);
  CHECK(Agglomerative{.height = 0.0}(d).clusters == 3);
  CHECK(Agglomerative{}(Eigen::MatrixXd::Zero(1, 1)).clusters == 1);
}
