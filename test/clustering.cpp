#include <deformseg/clustering/agglomerative.h>
#include <deformseg/clustering/clustering.h>
#include <deformseg/clustering/k_means.h>
#include <deformseg/clustering/k_medoids.h>
#include <deformseg/threads.h>

#include "clustering_support.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>
#include <string>

using deformseg::clustering::Agglomerative;
using deformseg::clustering::check_distance_matrix;
using deformseg::clustering::cluster;
using deformseg::clustering::Clustering;
using deformseg::clustering::ClusteringPolicy;
using deformseg::clustering::group_identical_items;
using deformseg::clustering::Grouped_items;
using deformseg::clustering::K_means;
using deformseg::clustering::K_medoids;
using deformseg::clustering::Linkage;
using deformseg::clustering::silhouette;
using deformseg::clustering::WeightedClusteringPolicy;
using deformseg::test::Scoped_variable;
using deformseg_clustering_test::make_blobs;
using deformseg_clustering_test::on_a_line;

namespace {


// A policy of one's own: the items within `radius` of item 0 form one cluster, the rest another.
struct Near_the_first {
  double radius = 5;
  Clustering operator()(const Eigen::MatrixXd& d) const {
    Clustering c;
    for (Eigen::Index i = 0; i < d.rows(); ++i) c.labels.push_back(d(0, i) <= radius ? 0 : 1);
    return c;
  }
};

// Labels items by index parity: would split items at distance 0 if it saw them.
struct By_parity {
  Clustering operator()(const Eigen::MatrixXd& d) const {
    Clustering c;
    for (Eigen::Index i = 0; i < d.rows(); ++i) c.labels.push_back(std::size_t(i % 2));
    return c;
  }
};

struct Too_few_labels {
  Clustering operator()(const Eigen::MatrixXd&) const { return {}; }
};

struct Not_a_clustering_policy {};
struct Returns_labels_only {
  std::vector<std::size_t> operator()(const Eigen::MatrixXd& d) const {
    return std::vector<std::size_t>(std::size_t(d.rows()));
  }
};
struct Takes_a_vector {
  Clustering operator()(const std::vector<double>&) const { return {}; }
};
struct Not_const_callable {
  Clustering operator()(const Eigen::MatrixXd&) { return {}; }
};

bool share_label_at_distance_zero(const Eigen::MatrixXd& d, const Clustering& c) {
  for (Eigen::Index i = 0; i < d.rows(); ++i)
    for (Eigen::Index j = 0; j < d.cols(); ++j)
      if (d(i, j) == 0 && c.labels[std::size_t(i)] != c.labels[std::size_t(j)]) return false;
  return true;
}

// A policy of the library on `threads` threads, through `cluster` on as many.
template <class Policy>
Clustering on_threads(const Eigen::MatrixXd& d, Policy policy, int threads) {
  policy.threads = threads;
  return cluster(d, policy, threads);
}

bool is_canonical(const Clustering& c) {
  std::size_t next = 0;
  for (const std::size_t l : c.labels) {
    if (l > next) return false;
    if (l == next) ++next;
  }
  return next == c.clusters && c.medoids.size() == c.clusters;
}

}  // namespace

static_assert(ClusteringPolicy<K_medoids> && ClusteringPolicy<Agglomerative> && ClusteringPolicy<K_means>);
static_assert(WeightedClusteringPolicy<K_medoids> && WeightedClusteringPolicy<Agglomerative> &&
              WeightedClusteringPolicy<K_means>);
static_assert(ClusteringPolicy<Near_the_first> && !WeightedClusteringPolicy<Near_the_first>);
static_assert(!ClusteringPolicy<Not_a_clustering_policy>);
static_assert(!ClusteringPolicy<Returns_labels_only>);
static_assert(!ClusteringPolicy<Takes_a_vector>);
static_assert(!ClusteringPolicy<Not_const_callable>);

TEST_CASE("silhouette: a hand-computed example", "[clustering][silhouette]") {
  // 0 1 | 5 6 7. Item 0: a = 1, b = (5 + 6 + 7) / 3 = 6, s = 5/6. Item 1: a = 1, b = 5, s = 4/5.
  // Item 5: a = (1 + 2) / 2, b = (5 + 4) / 2, s = 2/3. Item 6: a = 1, b = 5.5, s = 9/11.
  // Item 7: a = 1.5, b = 6.5, s = 10/13.
  const Eigen::MatrixXd d = on_a_line({0, 1, 5, 6, 7});
  const double expected = (5.0 / 6 + 4.0 / 5 + 2.0 / 3 + 9.0 / 11 + 10.0 / 13) / 5;
  CHECK(silhouette(d, {0, 0, 1, 1, 1}) == Approx(expected).epsilon(1e-14));
  CHECK(silhouette(d, {7, 7, 3, 3, 3}) == Approx(expected).epsilon(1e-14));  // any label values
  // Splitting off 7 as a singleton: it scores 0; item 0: b = min(5.5, 7), s = 9/11; item 1:
  // b = min(4.5, 6), s = 7/9; item 5: a = 1, b = min(4.5, 2), s = 1/2; item 6: a = b = 1, s = 0.
  CHECK(silhouette(d, {0, 0, 1, 1, 2}) == Approx((9.0 / 11 + 7.0 / 9 + 1.0 / 2 + 0 + 0) / 5).epsilon(1e-14));
  // A wrong partition scores below 0: 0 and 7 together.
  CHECK(silhouette(d, {0, 1, 1, 1, 0}) < 0);
}

TEST_CASE("silhouette: conventions for one cluster, singletons, no items", "[clustering][silhouette]") {
  const Eigen::MatrixXd d = on_a_line({0, 1, 5});
  CHECK(silhouette(d, {0, 0, 0}) == 0.0);
  CHECK(silhouette(d, {0, 1, 2}) == 0.0);
  CHECK(silhouette(Eigen::MatrixXd(0, 0), {}) == 0.0);
  // Two items at distance 0 in a cluster: a = 0, so they score 1.
  CHECK(silhouette(on_a_line({0, 0, 4}), {0, 0, 1}) == Approx(2.0 / 3));
  CHECK_THROWS_AS(silhouette(d, {0, 1}), deformseg::invalid_input);
}

TEST_CASE("check_distance_matrix: names the offending entry", "[clustering]") {
  const Eigen::MatrixXd good = on_a_line({0, 1, 3});
  CHECK_NOTHROW(check_distance_matrix(good, "test"));
  const auto message = [](const Eigen::MatrixXd& d) {
    try {
      check_distance_matrix(d, "test");
    } catch (const deformseg::invalid_input& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  CHECK_THAT(message(Eigen::MatrixXd::Zero(2, 3)), Catch::Contains("2 x 3, not square"));
  Eigen::MatrixXd d = good;
  d(1, 2) = d(2, 1) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(message(d), Catch::StartsWith("test: distance (2, 1)") && Catch::Contains("not finite"));
  d = good;
  d(0, 2) = d(2, 0) = -1;
  CHECK_THAT(message(d), Catch::Contains("(2, 0)") && Catch::Contains("negative"));
  d = good;
  d(1, 1) = 0.5;
  CHECK_THAT(message(d), Catch::Contains("(1, 1)") && Catch::Contains("diagonal"));
  d = good;
  d(0, 1) = 1.5;
  CHECK_THAT(message(d), Catch::Contains("(1, 0)") && Catch::Contains("(0, 1)") && Catch::Contains("symmetric"));
  CHECK_THROWS_AS(cluster(d, K_medoids{}), deformseg::invalid_input);
  CHECK_THROWS_AS(K_means{}(d), deformseg::invalid_input);
  CHECK_THROWS_AS(Agglomerative{}(d), deformseg::invalid_input);
}

TEST_CASE("group_identical_items: components of the zero-distance graph", "[clustering]") {
  // Items 0 and 2 coincide, 3 and 4 too; 1 alone.
  const Eigen::MatrixXd d = on_a_line({0, 3, 0, 10, 10});
  const Grouped_items g = group_identical_items(d);
  CHECK(g.group_of_item == std::vector<std::size_t>{0, 1, 0, 2, 2});
  CHECK(g.first_item == std::vector<std::size_t>{0, 1, 3});
  CHECK(g.weights == std::vector<double>{2, 1, 2});
  CHECK(g.distances.isApprox(on_a_line({0, 3, 10})));
  // Not transitive: 0 ~ 1 and 1 ~ 2 at distance 0, but 0 and 2 at distance 2: one group, whose
  // distance to item 3 is the mean over its items.
  Eigen::MatrixXd chain(4, 4);
  chain << 0, 0, 2, 4,
           0, 0, 0, 5,
           2, 0, 0, 6,
           4, 5, 6, 0;
  const Grouped_items c = group_identical_items(chain);
  CHECK(c.group_of_item == std::vector<std::size_t>{0, 0, 0, 1});
  CHECK(c.distances(0, 1) == 5.0);
}

TEST_CASE("cluster: items at distance 0 always share a label", "[clustering]") {
  // Three copies of the point 0, then 10 and 20. Asked for 4 clusters, PAM on the matrix itself
  // must put a medoid on a second copy of 0 and so split the copies; cluster() does not.
  const Eigen::MatrixXd d = on_a_line({0, 0, 10, 0, 20});
  const Clustering naive = K_medoids{.clusters = 4}(d);
  CHECK(naive.clusters == 4);
  CHECK_FALSE(share_label_at_distance_zero(d, naive));
  for (const Clustering& c : {cluster(d, K_medoids{.clusters = 4}), cluster(d, Agglomerative{.clusters = 4}),
                              cluster(d, K_means{.clusters = 4}), cluster(d, By_parity{})}) {
    CHECK(share_label_at_distance_zero(d, c));
    CHECK(is_canonical(c));
  }
  CHECK(cluster(d, K_medoids{.clusters = 4}).labels == std::vector<std::size_t>{0, 0, 1, 0, 2});
  CHECK(cluster(d, K_medoids{.clusters = 4}).medoids == std::vector<std::size_t>{0, 2, 4});
  // By_parity sees the three groups {0, 1, 3}, {2}, {4}: groups 0 and 2 even, group 1 odd.
  CHECK(cluster(d, By_parity{}).labels == std::vector<std::size_t>{0, 0, 1, 0, 0});
  CHECK_THROWS_AS(cluster(d, K_medoids{.clusters = 6}), deformseg::invalid_input);

  // A chain of zeros that is not transitive still shares one label.
  Eigen::MatrixXd chain(4, 4);
  chain << 0, 0, 2, 9,
           0, 0, 0, 9,
           2, 0, 0, 9,
           9, 9, 9, 0;
  for (const Clustering& c : {cluster(chain, K_medoids{.clusters = 3}), cluster(chain, Agglomerative{.clusters = 3}),
                              cluster(chain, K_means{.clusters = 3})})
    CHECK(c.labels == std::vector<std::size_t>{0, 0, 0, 1});
}

TEST_CASE("cluster: random duplicates never split, by every policy", "[clustering]") {
  std::mt19937 random(11);
  for (int trial = 0; trial < 30; ++trial) {
    auto blobs = make_blobs({6, 5, 7}, unsigned(trial));
    // Copy some points exactly: the copies are at distance 0 from their originals.
    std::uniform_int_distribution<std::size_t> pick(0, blobs.points.size() - 1);
    for (int copy = 0; copy < 8; ++copy) blobs.points.push_back(blobs.points[pick(random)]);
    const Eigen::MatrixXd d = deformseg_clustering_test::euclidean_distances(blobs.points);
    const std::size_t k = 2 + std::size_t(trial % 6);
    INFO("trial " << trial << ", k " << k);
    for (const Clustering& c :
         {cluster(d, K_medoids{.clusters = k}), cluster(d, K_medoids{}), cluster(d, Agglomerative{.clusters = k}),
          cluster(d, Agglomerative{.linkage = Linkage::complete}), cluster(d, K_means{.clusters = k, .seed = 3}),
          cluster(d, K_means{})}) {
      CHECK(share_label_at_distance_zero(d, c));
      CHECK(is_canonical(c));
      CHECK(c.silhouette == Approx(silhouette(d, c.labels)));
    }
  }
}

TEST_CASE("cluster: duplicates weigh in the result as items", "[clustering]") {
  // One cluster of 0, 4, 10: its medoid is 4 (total distance 10); with two more copies of 10
  // it is 10 (total 16 against 22 for 4).
  const Eigen::MatrixXd plain = on_a_line({0, 4, 10});
  CHECK(cluster(plain, K_medoids{.clusters = 1}).medoids == std::vector<std::size_t>{1});
  const Eigen::MatrixXd copies = on_a_line({0, 4, 10, 10, 10});
  CHECK(cluster(copies, K_medoids{.clusters = 1}).medoids == std::vector<std::size_t>{2});
  // Average linkage: 4 is nearer 0 (4) than 10 (6), whatever the copies.
  CHECK(cluster(copies, Agglomerative{.clusters = 2}).labels == std::vector<std::size_t>{0, 0, 1, 1, 1});
}

TEST_CASE("cluster: a policy of one's own compiles and runs", "[clustering]") {
  const auto blobs = make_blobs({10, 12}, 5);
  const Clustering c = cluster(blobs.distances, Near_the_first{});
  CHECK(c.labels == blobs.truth);
  CHECK(c.clusters == 2);
  CHECK(c.silhouette > 0.8);
  CHECK(c.silhouette == Approx(silhouette(blobs.distances, c.labels)));
  CHECK(is_canonical(c));
  CHECK_THROWS_AS(cluster(blobs.distances, Too_few_labels{}), deformseg::invalid_input);
}

TEST_CASE("cluster: the same result on 1, 2 or all threads", "[clustering]") {
  auto blobs = make_blobs({40, 50, 30, 45}, 2, 3.0);  // overlapping blobs: close calls
  const Eigen::MatrixXd& d = blobs.distances;
  // With copies of items, `cluster` hands the policies weighted groups: their other overload.
  for (std::size_t i = 0; i < 20; ++i) blobs.points.push_back(blobs.points[7 * i]);
  const Eigen::MatrixXd with_copies = deformseg_clustering_test::euclidean_distances(blobs.points);
  const auto check = [&](auto policy, const char* name) {
    for (const Eigen::MatrixXd* m : {&d, &with_copies}) {
      INFO(name << (m == &d ? "" : ", with copies"));
      const Clustering one = on_threads(*m, policy, 1);
      for (const int threads : {2, 0}) {
        INFO("threads " << threads);
        const Clustering other = on_threads(*m, policy, threads);
        CHECK(other.labels == one.labels);
        CHECK(other.medoids == one.medoids);
        CHECK(other.silhouette == one.silhouette);  // bit-identical
        CHECK(other.iterations == one.iterations);
        CHECK(other.converged == one.converged);
        CHECK(silhouette(*m, one.labels, threads) == silhouette(*m, one.labels, 1));
      }
    }
  };
  check(K_medoids{}, "K_medoids");
  check(Agglomerative{}, "Agglomerative");
  check(Agglomerative{.linkage = Linkage::complete, .clusters = 6}, "Agglomerative, complete, 6 clusters");
  check(K_means{}, "K_means");
  check(K_means{.clusters = 7, .seed = 9}, "K_means, 7 clusters");
}

TEST_CASE("cluster: every loop runs on the count given, none on the environment's", "[clustering]") {
  const Eigen::MatrixXd d = make_blobs({40, 50, 30, 45}, 2, 3.0).distances;  // loops long enough to share
  // Only a count of 0 reads the environment, and refuses this value: any loop left on 0 throws.
  const Scoped_variable unreadable("DEFORMSEG_NUM_THREADS", "many");
  const auto check = [&](auto policy, const char* name) {
    INFO(name);
    for (const int threads : {1, 2}) CHECK_NOTHROW(on_threads(d, policy, threads));
    const std::string refused = "DEFORMSEG_NUM_THREADS is 'many'";
    CHECK_THROWS_WITH(on_threads(d, policy, 0), Catch::Contains(refused));
    policy.threads = 2;
    CHECK_THROWS_WITH(cluster(d, policy), Catch::Contains(refused));  // cluster's own count
    policy.threads = 0;
    CHECK_THROWS_WITH(cluster(d, policy, 2), Catch::Contains(refused));  // the policy's
  };
  check(K_medoids{}, "K_medoids");
  check(Agglomerative{}, "Agglomerative");
  check(K_means{}, "K_means");
  std::vector<std::size_t> halves(std::size_t(d.rows()), 0);
  std::fill(halves.begin() + d.rows() / 2, halves.end(), 1);
  CHECK_NOTHROW(silhouette(d, halves, 2));
}

TEST_CASE("cluster and the policies: a thread count out of range is refused before any work", "[clustering]") {
  Eigen::MatrixXd asymmetric = on_a_line({0, 1, 3});
  asymmetric(0, 1) = 1.5;  // refused too, but after the count
  const Grouped_items groups = group_identical_items(on_a_line({0, 1, 3}));
  for (const int threads : {-1, deformseg::max_threads + 1}) {
    const auto refused = [&](const std::string& who) {
      return who + ": threads must be 0 (the default) to " + std::to_string(deformseg::max_threads) + ", not " +
             std::to_string(threads);
    };
    CHECK_THROWS_WITH(K_medoids{.threads = threads}(asymmetric), refused("K_medoids"));
    CHECK_THROWS_WITH(K_medoids{.threads = threads}(groups), refused("K_medoids"));
    CHECK_THROWS_WITH(Agglomerative{.threads = threads}(asymmetric), refused("Agglomerative"));
    CHECK_THROWS_WITH(Agglomerative{.threads = threads}(groups), refused("Agglomerative"));
    CHECK_THROWS_WITH(K_means{.threads = threads}(asymmetric), refused("K_means"));
    CHECK_THROWS_WITH(K_means{.threads = threads}(groups), refused("K_means"));
    CHECK_THROWS_WITH(cluster(asymmetric, K_medoids{}, threads), refused("cluster"));
    CHECK_THROWS_WITH(cluster(on_a_line({0, 1, 3}), K_means{.threads = threads}), refused("K_means"));
    CHECK_THROWS_WITH(silhouette(asymmetric, {0, 0, 1}, threads), refused("silhouette"));
  }
}
