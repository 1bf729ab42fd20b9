/// @file evaluation/correlation.h
/// @brief Pearson and Spearman correlation between two lists of values, to compare computed
/// similarities with given scores such as human ratings (@ref method_similarity, validation).
#pragma once

#include <deformseg/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <span>
#include <string>
#include <vector>

namespace deformseg::evaluation {

namespace internal {

inline void check_correlation_input(std::span<const double> x, std::span<const double> y, const char* who) {
  if (x.size() != y.size())
    throw invalid_input(std::string(who) + ": " + std::to_string(x.size()) + " values against " +
                        std::to_string(y.size()));
  if (x.size() < 2) throw invalid_input(std::string(who) + ": needs at least 2 pairs of values, not " +
                                        std::to_string(x.size()));
  for (std::size_t k = 0; k < x.size(); ++k)
    if (!std::isfinite(x[k]) || !std::isfinite(y[k]))
      throw invalid_input(std::string(who) + ": value " + std::to_string(k) + " is not finite");
  const auto constant = [](std::span<const double> v) {
    return std::all_of(v.begin(), v.end(), [&](double e) { return e == v[0]; });
  };
  if (constant(x) || constant(y))
    throw invalid_input(std::string(who) + ": the " + (constant(x) ? "first" : "second") +
                        " list of values is constant, so the correlation is undefined");
}

// Pearson's r of checked input (neither list constant).
inline double pearson_of(std::span<const double> x, std::span<const double> y, const char* who) {
  const double count = static_cast<double>(x.size());
  const double mean_x = std::accumulate(x.begin(), x.end(), 0.0) / count;
  const double mean_y = std::accumulate(y.begin(), y.end(), 0.0) / count;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double dx = x[k] - mean_x, dy = y[k] - mean_y;
    sxy += dx * dy;
    sxx += dx * dx;
    syy += dy * dy;
  }
  if (sxx == 0 || syy == 0)  // values so close that their deviations underflow
    throw invalid_input(std::string(who) + ": the values do not vary enough for a correlation");
  return std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
}

// The ranks of the values from 1, ties given the mean of the ranks they share.
inline std::vector<double> average_ranks(std::span<const double> values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> rank(values.size());
  for (std::size_t first = 0; first < order.size();) {
    std::size_t last = first;
    while (last + 1 < order.size() && values[order[last + 1]] == values[order[first]]) ++last;
    const double shared = 0.5 * static_cast<double>(first + last) + 1.0;
    for (std::size_t k = first; k <= last; ++k) rank[order[k]] = shared;
    first = last + 1;
  }
  return rank;
}

}  // namespace internal

/// @brief Pearson's correlation coefficient r between `x` and `y`: their covariance over the
/// product of their standard deviations.
/// @param x, y paired values (x[k] with y[k]), as many of each, finite.
/// @return r in [-1, 1]: 1 when y grows linearly with x, -1 when it falls linearly.
/// @throws invalid_input when the sizes differ, there are fewer than 2 pairs, a value is not
/// finite, or either list is constant (r undefined).
/// @par Complexity O(n).
inline double pearson_correlation(std::span<const double> x, std::span<const double> y) {
  internal::check_correlation_input(x, y, "pearson_correlation");
  return internal::pearson_of(x, y, "pearson_correlation");
}

/// @brief Spearman's rank correlation coefficient between `x` and `y`: Pearson's r of their ranks,
/// tied values sharing the mean of their ranks. Unchanged by any strictly increasing transform of
/// either list.
/// @param x, y paired values (x[k] with y[k]), as many of each, finite.
/// @return the coefficient in [-1, 1]: 1 when y grows with x (in any way), -1 when it falls.
/// @throws invalid_input when the sizes differ, there are fewer than 2 pairs, a value is not
/// finite, or either list is constant.
/// @par Complexity O(n log n).
inline double spearman_correlation(std::span<const double> x, std::span<const double> y) {
  internal::check_correlation_input(x, y, "spearman_correlation");
  const std::vector<double> rank_x = internal::average_ranks(x), rank_y = internal::average_ranks(y);
  return internal::pearson_of(rank_x, rank_y, "spearman_correlation");
}

}  // namespace deformseg::evaluation
