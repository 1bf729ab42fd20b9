// The quantity that search/motion_bounds.h bounds, by brute force, for its test and its bench:
// the frame dissimilarities of two float views by the double reference, the mean along the path
// alignment::Dtw::align returns, and the least mean over all paths (exhaustive, small grids).
#pragma once

#include <deformseg/alignment/dtw.h>
#include <deformseg/signatures/motion_signature_view.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace deformseg::test {

// d(i, j) = frame_dissimilarity(||a_i - b_j||^2, unit), the squared distance summed in double over
// the dimensions in order.
inline Eigen::MatrixXd reference_dissimilarities(const signatures::Motion_signature_view& a,
                                                 const signatures::Motion_signature_view& b, double unit) {
  Eigen::MatrixXd d(a.rows, b.rows);
  for (std::size_t i = 0; i < a.rows; ++i)
    for (std::size_t j = 0; j < b.rows; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < a.width; ++k) {
        const double g = double(a(i, k)) - double(b(j, k));
        s += g * g;
      }
      d(Eigen::Index(i), Eigen::Index(j)) = signatures::frame_dissimilarity(s, unit);
    }
  return d;
}

// D = score / pairs, the mean along Dtw's (tie-broken) path: 1 - the default policy's value.
inline double dtw_mean(const Eigen::MatrixXd& d) {
  const auto at = [&](std::size_t i, std::size_t j) { return d(Eigen::Index(i), Eigen::Index(j)); };
  const auto aligned = alignment::Dtw{}.align(std::size_t(d.rows()), std::size_t(d.cols()), at);
  return aligned.score / double(aligned.pairs.size());
}

// min over every warping path p of sum_p d / |p|: least sums per (cell, path length), O(n m (n + m)).
inline double least_mean_over_paths(const Eigen::MatrixXd& d) {
  const std::size_t n = std::size_t(d.rows()), m = std::size_t(d.cols()), lengths = n + m;
  constexpr double none = std::numeric_limits<double>::infinity();
  std::vector<double> best(n * m * lengths, none);  // best[(i m + j) lengths + L]
  const auto at = [&](std::size_t i, std::size_t j, std::size_t length) -> double& {
    return best[(i * m + j) * lengths + length];
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t length = 1; length <= i + j + 1; ++length) {
        double before = i == 0 && j == 0 && length == 1 ? 0.0 : none;
        if (length > 1) {
          if (i > 0) before = std::min(before, at(i - 1, j, length - 1));
          if (j > 0) before = std::min(before, at(i, j - 1, length - 1));
          if (i > 0 && j > 0) before = std::min(before, at(i - 1, j - 1, length - 1));
        }
        at(i, j, length) = before + d(Eigen::Index(i), Eigen::Index(j));
      }
  double least = none;
  for (std::size_t length = std::max(n, m); length < lengths; ++length)
    least = std::min(least, at(n - 1, m - 1, length) / double(length));
  return least;
}

}  // namespace deformseg::test
