// Tests of histogram_distance and histogram_distances: hand values, one-hot shifts, the metric
// axioms on random histograms, the earth mover's distance against a transport by hand, the
// matrix against the pairwise calls, and bad input.
#include <catch2/catch.hpp>

#include <deformseg/strain/histogram_distance.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace deformseg;

namespace {

constexpr strain::Histogram_metric metrics[] = {strain::Histogram_metric::total_variation,
                                                strain::Histogram_metric::earth_movers};

Eigen::MatrixXd random_histograms(std::mt19937& rng, Eigen::Index count, Eigen::Index bins) {
  std::uniform_real_distribution<double> mass(0, 1);
  std::bernoulli_distribution empty(0.3);
  Eigen::MatrixXd h(count, bins);
  for (Eigen::Index i = 0; i < count; ++i) {
    for (Eigen::Index k = 0; k < bins; ++k) h(i, k) = empty(rng) ? 0.0 : mass(rng);
    if (h.row(i).sum() == 0) h(i, 0) = 1;
    h.row(i) /= h.row(i).sum();
  }
  return h;
}

// The earth mover's work by moving mass greedily from the left, which is optimal on a line, over
// the largest work n - 1.
double transported(const Eigen::RowVectorXd& from, const Eigen::RowVectorXd& to) {
  Eigen::RowVectorXd supply = from, demand = to;
  double work = 0;
  for (Eigen::Index i = 0, j = 0; i < supply.size() && j < demand.size();) {
    const double moved = std::min(supply[i], demand[j]);
    work += moved * double(std::abs(i - j));
    supply[i] -= moved;
    demand[j] -= moved;
    if (supply[i] <= 1e-15) ++i;
    if (demand[j] <= 1e-15) ++j;
  }
  return work / double(from.size() - 1);
}

Eigen::RowVectorXd one_hot(Eigen::Index bins, Eigen::Index at) {
  Eigen::RowVectorXd h = Eigen::RowVectorXd::Zero(bins);
  h[at] = 1;
  return h;
}

}  // namespace

TEST_CASE("histogram_distance: hand values", "[histogram_distance]") {
  const Eigen::RowVector4d a(0.5, 0.5, 0, 0), b(0, 0.5, 0.5, 0), c(0, 0, 0, 1);
  CHECK(strain::histogram_distance(a, b, strain::Histogram_metric::total_variation) == Approx(0.5));
  CHECK(strain::histogram_distance(a, b, strain::Histogram_metric::earth_movers) ==
        Approx(1.0 / 3));  // half the mass, one bin
  CHECK(strain::histogram_distance(a, c, strain::Histogram_metric::total_variation) == Approx(1.0));
  CHECK(strain::histogram_distance(a, c, strain::Histogram_metric::earth_movers) == Approx((0.5 * 3 + 0.5 * 2) / 3));
  CHECK(strain::histogram_distance(a, b) ==
        strain::histogram_distance(a, b, strain::Histogram_metric::earth_movers));  // the default
  // Column vectors and float work alike; one bin is always at distance 0.
  CHECK(strain::histogram_distance(Eigen::Vector4f(0.5f, 0.5f, 0, 0), Eigen::Vector4f(0, 0.5f, 0.5f, 0)) ==
        Approx(1.0 / 3));
  for (auto metric : metrics)
    CHECK(strain::histogram_distance(Eigen::VectorXd::Ones(1), Eigen::VectorXd::Ones(1), metric) == 0);
}

TEST_CASE("histogram_distance: earth mover's of shifted one-hot histograms is proportional to the shift",
          "[histogram_distance]") {
  const Eigen::Index bins = 18;
  for (Eigen::Index i = 0; i < bins; ++i)
    for (Eigen::Index j = 0; j < bins; ++j) {
      CHECK(strain::histogram_distance(one_hot(bins, i), one_hot(bins, j)) ==
            Approx(double(std::abs(i - j)) / double(bins - 1)).margin(1e-15));
      CHECK(strain::histogram_distance(one_hot(bins, i), one_hot(bins, j), strain::Histogram_metric::total_variation) ==
            (i == j ? 0.0 : 1.0));
    }
}

TEST_CASE("histogram_distance: earth mover's agrees with a greedy transport on random histograms",
          "[histogram_distance]") {
  std::mt19937 rng(11);
  for (Eigen::Index bins : {2, 3, 7, 18}) {
    const Eigen::MatrixXd h = random_histograms(rng, 30, bins);
    for (Eigen::Index i = 0; i + 1 < h.rows(); ++i)
      CHECK(strain::histogram_distance(h.row(i), h.row(i + 1)) ==
            Approx(transported(h.row(i), h.row(i + 1))).margin(1e-12));
  }
}

TEST_CASE("histogram_distances: symmetric, zero on the diagonal, in [0, 1], triangle inequality",
          "[histogram_distance]") {
  std::mt19937 rng(5);
  const Eigen::MatrixXd h = random_histograms(rng, 40, 18);
  for (auto metric : metrics) {
    const Eigen::MatrixXd d = strain::histogram_distances(h, h, metric);
    REQUIRE(d.rows() == 40);
    REQUIRE(d.cols() == 40);
    CHECK(d == d.transpose());
    CHECK(d.diagonal().isZero(0));
    CHECK(d.minCoeff() >= 0);
    CHECK(d.maxCoeff() <= 1);
    for (Eigen::Index i = 0; i < d.rows(); ++i)
      for (Eigen::Index j = 0; j < d.rows(); ++j)
        for (Eigen::Index k = 0; k < d.rows(); ++k) REQUIRE(d(i, k) <= d(i, j) + d(j, k) + 1e-12);
  }
}

TEST_CASE("histogram_distances: each entry is the pairwise distance, for any thread count", "[histogram_distance]") {
  std::mt19937 rng(3);
  const Eigen::MatrixXd a = random_histograms(rng, 23, 9), b = random_histograms(rng, 31, 9);
  for (auto metric : metrics) {
    const Eigen::MatrixXd d = strain::histogram_distances(a, b, metric);
    REQUIRE(d.rows() == 23);
    REQUIRE(d.cols() == 31);
    for (Eigen::Index i = 0; i < d.rows(); ++i)
      for (Eigen::Index j = 0; j < d.cols(); ++j)
        REQUIRE(d(i, j) == strain::histogram_distance(a.row(i), b.row(j), metric));
    CHECK(strain::histogram_distances(a, b, metric, 1) == d);
    CHECK(strain::histogram_distances(a, b, metric, 2) == d);
  }
  CHECK(strain::histogram_distances(a.topRows(0), b).size() == 0);
}

TEST_CASE("histogram_distance: bad input is rejected, naming the problem", "[histogram_distance]") {
  const Eigen::RowVector3d good(0.2, 0.3, 0.5);
  CHECK_THROWS_WITH(strain::histogram_distance(good, Eigen::RowVector2d(0.5, 0.5)), Catch::Contains("same size"));
  CHECK_THROWS_WITH(strain::histogram_distance(good, Eigen::RowVector3d(0.2, 0.3, 0.6)), Catch::Contains("sums to"));
  CHECK_THROWS_WITH(strain::histogram_distance(good, Eigen::RowVector3d(-0.2, 0.7, 0.5)), Catch::Contains("bin 0"));
  CHECK_THROWS_AS(
      strain::histogram_distance(good, Eigen::RowVector3d(std::numeric_limits<double>::quiet_NaN(), 0.5, 0.5)),
      invalid_input);
  CHECK_THROWS_AS(strain::histogram_distance(Eigen::RowVectorXd(0), Eigen::RowVectorXd(0)), invalid_input);
  CHECK_THROWS_AS(strain::histogram_distance(Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Identity()), invalid_input);
  const Eigen::MatrixXd a = good.replicate(3, 1);
  Eigen::MatrixXd broken = a;
  broken(2, 1) = 0.9;
  CHECK_THROWS_WITH(strain::histogram_distances(a, broken), Catch::Contains("second argument: histogram 2"));
  CHECK_THROWS_WITH(strain::histogram_distances(a, Eigen::MatrixXd::Ones(3, 1)), Catch::Contains("3 and 1 bins"));
  CHECK_THROWS_AS(strain::histogram_distances(a, a, strain::Histogram_metric::earth_movers, -1), invalid_input);
}
