// What the tests of the alignment policies share: warping paths enumerated one by one (the brute
// force the DTW policies are checked against), path checks, random dissimilarity matrices and
// shapes, the check of score_and_length against align.
#pragma once

#include <deformseg/alignment/alignment.h>

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace deformseg::alignment_test {

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

/// The dissimilarity |x[i] - y[j]| of two sequences of numbers.
inline Eigen::MatrixXd absolute_differences(const std::vector<double>& x, const std::vector<double>& y) {
  Eigen::MatrixXd d(static_cast<Eigen::Index>(x.size()), static_cast<Eigen::Index>(y.size()));
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < y.size(); ++j) d(Eigen::Index(i), Eigen::Index(j)) = std::abs(x[i] - y[j]);
  return d;
}

inline double entry(const Eigen::MatrixXd& d, std::size_t i, std::size_t j) {
  return d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
}

// The least sum of d over every warping path from (0, first_col) to (n - 1, last_col) whose
// cells all satisfy `allowed`, found by walking each path (steps (1, 0), (0, 1), (1, 1)); +inf when
// there is none.
inline double brute_force_warping(const Eigen::MatrixXd& d, std::size_t first_col, std::size_t last_col,
                                  const std::function<bool(std::size_t, std::size_t)>& allowed) {
  const std::size_t n = std::size_t(d.rows());
  double best = std::numeric_limits<double>::infinity();
  std::function<void(std::size_t, std::size_t, double)> walk = [&](std::size_t i, std::size_t j, double sum) {
    if (i >= n || j > last_col || !allowed(i, j)) return;
    sum += entry(d, i, j);
    if (i == n - 1 && j == last_col) {
      best = std::min(best, sum);
      return;
    }
    walk(i + 1, j, sum);
    walk(i, j + 1, sum);
    walk(i + 1, j + 1, sum);
  };
  walk(0, first_col, 0.0);
  return best;
}

// Checks that `pairs` is a warping path from (0, first_col) to (n - 1, last_col) with steps
// (1, 0), (0, 1), (1, 1) and returns the sum of d over it.
inline double check_warping_path(const Pairs& pairs, const Eigen::MatrixXd& d, std::size_t first_col,
                                 std::size_t last_col) {
  REQUIRE(!pairs.empty());
  CHECK(pairs.front() == std::pair<std::size_t, std::size_t>(0, first_col));
  CHECK(pairs.back() == std::pair<std::size_t, std::size_t>(std::size_t(d.rows()) - 1, last_col));
  double sum = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    REQUIRE(pairs[k].first < std::size_t(d.rows()));
    REQUIRE(pairs[k].second < std::size_t(d.cols()));
    if (k > 0) {
      const std::size_t di = pairs[k].first - pairs[k - 1].first, dj = pairs[k].second - pairs[k - 1].second;
      REQUIRE(di <= 1);
      REQUIRE(dj <= 1);
      REQUIRE(di + dj >= 1);
    }
    sum += entry(d, pairs[k].first, pairs[k].second);
  }
  return sum;
}

// An n x m matrix of random dissimilarities: |x - y| between integers 0 to 2 on even trials (so
// with many ties), uniform values in [0, 1) on odd ones.
inline Eigen::MatrixXd random_dissimilarities(std::size_t n, std::size_t m, int trial, std::mt19937& random) {
  Eigen::MatrixXd d(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  if (trial % 2 == 0) {
    std::vector<int> a(n), b(m);
    for (auto& x : a) x = int(random() % 3);
    for (auto& x : b) x = int(random() % 3);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < m; ++j) d(Eigen::Index(i), Eigen::Index(j)) = std::abs(a[i] - b[j]);
  } else {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (Eigen::Index k = 0; k < d.size(); ++k) d(k) = unit(random);
  }
  return d;
}

// A grid's shape for `trial`: up to 13 x 13, with 60 to 66 rows or columns on a trial in 20.
inline std::pair<std::size_t, std::size_t> small_shape(int trial, std::mt19937& random) {
  std::size_t n = 1 + random() % 13, m = 1 + random() % 13;
  if (trial % 40 == 5) n = 60 + random() % 7;
  if (trial % 40 == 6) m = 60 + random() % 7;
  return {n, m};
}

// `value`, a policy's score_and_length, is `path`'s, its align's: the score bit for bit, and the
// number of pairs.
inline void check_score_and_length(const alignment::Score_and_length& value, const alignment::Alignment& path) {
  CHECK(std::bit_cast<std::uint64_t>(value.score) == std::bit_cast<std::uint64_t>(path.score));
  CHECK(value.length == path.pairs.size());
}

}  // namespace deformseg::alignment_test
