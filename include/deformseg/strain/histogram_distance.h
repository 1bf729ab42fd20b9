/// @file strain/histogram_distance.h
/// @brief Distances between histograms (total variation, earth mover's on the bin index), of two
/// histograms or of every frame of one animation to every frame of another:
/// `histogram_distance`, `histogram_distances`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace deformseg::strain {

/// @brief How two histograms h, g of n bins (each summing to 1) are compared. Both are metrics
/// with values in [0, 1].
///
/// The default of `histogram_distance(s)` is `earth_movers`: on strain histograms it tells motions
/// apart with a wider margin than total variation (@ref section_histogram_defaults), because a
/// strain slightly larger is near, not as far as any other.
enum class Histogram_metric {
  /// @brief The total variation distance `0.5 sum_k |h_k - g_k|`: the share of the mass that sits
  /// in other bins. 1 when no bin is shared; blind to how far apart the bins are.
  total_variation,
  /// @brief The earth mover's distance on the bin index, `sum_(k < n-1) |H_k - G_k| / (n - 1)`
  /// with H, G the cumulative sums: the least work to move h onto g, a unit of mass over one bin
  /// costing 1, divided by the largest possible work (all mass from the first bin to the last,
  /// n - 1). Moving all mass by m bins costs `m / (n - 1)`. 0 when n = 1.
  earth_movers,
};

namespace internal {

// Rows in contiguous memory, for the inner loop of the distances.
using Histogram_rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Histograms must be distributions, up to this much rounding of their sum.
inline constexpr double histogram_sum_tolerance = 1e-6;

template <class Derived>
void check_histograms(const Eigen::MatrixBase<Derived>& rows, const char* what) {
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    double sum = 0;
    for (Eigen::Index k = 0; k < rows.cols(); ++k) {
      const double h = double(rows(i, k));
      if (!(std::isfinite(h) && h >= 0))
        throw invalid_input(std::string(what) + ": histogram " + std::to_string(i) + " has bin " +
                            std::to_string(k) + " not finite and >= 0: " + std::to_string(h));
      sum += h;
    }
    if (!(std::abs(sum - 1) <= histogram_sum_tolerance))
      throw invalid_input(std::string(what) + ": histogram " + std::to_string(i) + " sums to " +
                          std::to_string(sum) + ", not 1");
  }
}

// Both metrics are a factor times the L1 distance of a transform of the rows: the rows themselves
// (total variation) or their cumulative sums without the last, which is 1 (earth mover's).
template <class Derived>
Histogram_rows metric_rows(const Eigen::MatrixBase<Derived>& rows, Histogram_metric metric) {
  Histogram_rows h = rows.template cast<double>();
  if (metric == Histogram_metric::total_variation) return h;
  Histogram_rows cumulative(h.rows(), std::max<Eigen::Index>(h.cols() - 1, 0));
  for (Eigen::Index i = 0; i < h.rows(); ++i) {
    double sum = 0;
    for (Eigen::Index k = 0; k < cumulative.cols(); ++k) cumulative(i, k) = sum += h(i, k);
  }
  return cumulative;
}

inline double metric_factor(Histogram_metric metric, Eigen::Index bins) {
  if (metric == Histogram_metric::total_variation) return 0.5;
  return bins > 1 ? 1.0 / double(bins - 1) : 0.0;
}

// factor * sum_k |u(i, k) - v(j, k)|, in order, clamped to [0, 1] against rounding.
inline double scaled_l1(const Histogram_rows& u, Eigen::Index i, const Histogram_rows& v, Eigen::Index j,
                        double factor) {
  double sum = 0;
  for (Eigen::Index k = 0; k < u.cols(); ++k) sum += std::abs(u(i, k) - v(j, k));
  return std::clamp(factor * sum, 0.0, 1.0);
}

}  // namespace internal

/// @brief The distance between two histograms of the same bins.
/// @tparam Derived1, Derived2 Eigen vector expressions (a row of `Strain_histograms`, a
/// `VectorXd`, ...).
/// @param h1 the first histogram, n >= 1 bins.
/// @param h2 the second, n bins.
/// @param metric earth mover's (default) or total variation, see `Histogram_metric`.
/// @return the distance in [0, 1]: 0 for equal histograms, symmetric, with the triangle
/// inequality; equal to the matching entry of `histogram_distances`.
/// @pre both are vectors of the same size n >= 1, with entries finite and >= 0 summing to 1
/// (within 1e-6).
/// @throws invalid_input naming the broken precondition.
/// @par Complexity O(n).
template <class Derived1, class Derived2>
double histogram_distance(const Eigen::MatrixBase<Derived1>& h1, const Eigen::MatrixBase<Derived2>& h2,
                          Histogram_metric metric = Histogram_metric::earth_movers) {
  if (!(h1.rows() == 1 || h1.cols() == 1) || !(h2.rows() == 1 || h2.cols() == 1) || h1.size() != h2.size() ||
      h1.size() == 0)
    throw invalid_input("histogram_distance: expected two vectors of the same size >= 1, got " +
                        std::to_string(h1.rows()) + " x " + std::to_string(h1.cols()) + " and " +
                        std::to_string(h2.rows()) + " x " + std::to_string(h2.cols()));
  const Eigen::RowVectorXd a = h1.reshaped().transpose().template cast<double>();
  const Eigen::RowVectorXd b = h2.reshaped().transpose().template cast<double>();
  internal::check_histograms(a, "histogram_distance");
  internal::check_histograms(b, "histogram_distance");
  return internal::scaled_l1(internal::metric_rows(a, metric), 0, internal::metric_rows(b, metric), 0,
                             internal::metric_factor(metric, a.size()));
}

/// @brief The `Ta x Tb` matrix of distances between every histogram (row) of `a` and every
/// histogram of `b`: the frame dissimilarity `d(i, j)` of an alignment of two animations, each in
/// [0, 1].
///
/// Rows of the result are computed in parallel, each entry in a fixed order, so the result is the
/// same for any number of threads, and entry (i, j) equals `histogram_distance(a.row(i),
/// b.row(j), metric)` exactly.
/// @tparam DerivedA, DerivedB Eigen matrix expressions (typically `Strain_histograms`).
/// @param a `Ta x n` histograms, one per row.
/// @param b `Tb x n` histograms, the same bins.
/// @param metric earth mover's (default) or total variation, see `Histogram_metric`.
/// @param threads threads (0, the default: all the hardware's threads (`thread_count`)).
/// @return the `Ta x Tb` distances (an empty matrix when `a` or `b` has no row).
/// @pre both have the same number n >= 1 of columns; every row finite, >= 0 and summing to 1
/// (within 1e-6); `threads` from 0 to `max_threads`.
/// @throws invalid_input naming the broken precondition (the matrix and row).
/// @par Complexity O(Ta Tb n) time, O((Ta + Tb) n + Ta Tb) memory (chapter 10 of the manual gives
/// times).
template <class DerivedA, class DerivedB>
Eigen::MatrixXd histogram_distances(const Eigen::MatrixBase<DerivedA>& a, const Eigen::MatrixBase<DerivedB>& b,
                                    Histogram_metric metric = Histogram_metric::earth_movers,
                                    int threads = 0) {
  if (a.cols() != b.cols() || a.cols() == 0)
    throw invalid_input("histogram_distances: the histograms have " + std::to_string(a.cols()) + " and " +
                        std::to_string(b.cols()) + " bins; expected the same number, at least 1");
  thread_count(threads, "histogram_distances");
  internal::check_histograms(a, "histogram_distances, first argument");
  internal::check_histograms(b, "histogram_distances, second argument");
  const internal::Histogram_rows u = internal::metric_rows(a, metric), v = internal::metric_rows(b, metric);
  const double factor = internal::metric_factor(metric, a.cols());
  Eigen::MatrixXd distances(a.rows(), b.rows());
  deformseg::internal::parallel_for(std::size_t(a.rows()), threads, [&](std::size_t i) {
    for (Eigen::Index j = 0; j < b.rows(); ++j)
      distances(Eigen::Index(i), j) = internal::scaled_l1(u, Eigen::Index(i), v, j, factor);
  });
  return distances;
}

}  // namespace deformseg::strain
