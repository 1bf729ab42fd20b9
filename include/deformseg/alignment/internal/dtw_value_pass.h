// The value pass of Dtw::mean_cost: DTW's forward pass that carries, beside each cell's cumulative
// cost, the length of the path the traceback would follow to it, so that the cost and length of
// Dtw::align's path come out in O(m) memory; with early abandoning on a lower bound of the mean.
#pragma once

#include <deformseg/alignment/dtw_mean_cost.h>
#include <deformseg/alignment/internal/alignment_grid.h>
#include <deformseg/alignment/internal/dtw_band.h>
#include <deformseg/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace deformseg::alignment::internal {

// One row as the value pass walks along it. The cost is Dtw_row's, operation for operation (so
// bit for bit); the length follows the predecessor that Dtw_row's trace byte names: left if it
// beat both, else up if it beat the diagonal, else the diagonal. The prefix of a traced path is
// the traced path to its cell, so the length of the corner's is that of align's pairs.
struct Dtw_length_row {
  const double* cost = nullptr;  // cost[j - 1]: d of cell j
  double diagonal = dtw_unreachable, left = dtw_unreachable;
  std::size_t diagonal_length = 0, left_length = 0;

  // Cell j (1-based column): at[j], length[j] hold the row above's there and get this row's.
  void step(std::size_t j, double* at, std::size_t* length) {
    const double up = at[j];
    const std::size_t up_length = length[j];
    const bool up_wins = up < diagonal;
    double best = std::min(diagonal, up);
    const bool left_wins = left < best;
    best = std::min(best, left);
    // Selected by masks, not by ?: which the compiler may turn into branches that mispredict.
    std::size_t from = diagonal_length;
    from ^= (from ^ up_length) & (std::size_t(0) - std::size_t(up_wins));
    from ^= (from ^ left_length) & (std::size_t(0) - std::size_t(left_wins));
    diagonal = up;
    diagonal_length = up_length;
    at[j] = left = best + cost[j - 1];
    length[j] = left_length = from + 1;
  }
};

// Lower bounds of what a path still costs below row i: the sum of the row bounds r of the rows
// after i (every one is visited), and the least of them (any further cell costs at least that).
// Summed from the last row up, so each sum has the relative rounding error of a sum of
// nonnegative terms (a total minus a prefix would not). Both 0 without row bounds.
class Rows_below {
public:
  explicit Rows_below(std::span<const double> r) : sums_(r.size() + 1, 0.0), least_(r.size() + 1, dtw_unreachable) {
    for (std::size_t i = r.size(); i-- > 0;) {
      sums_[i] = r[i] + sums_[i + 1];
      least_[i] = std::min(r[i], least_[i + 1]);
    }
  }
  double sum(std::size_t i) const { return i + 1 < sums_.size() ? sums_[i + 1] : 0.0; }
  // Only for a row with rows below it.
  double least(std::size_t i) const { return i + 1 < least_.size() ? least_[i + 1] : 0.0; }

private:
  std::vector<double> sums_, least_;
};

// The abandoning test. After row i, align's path leaves row i at some cell (i, j) of the row, and
// its part up to there is the tracked one: cost C = C(i, j), length l = l(i, j). The rest has lambda
// cells, all below row i, max(a, b) <= lambda <= a + b (a = n - 1 - i rows and b = m - 1 - j
// columns to go), and costs at least R + (lambda - a) rho (R, rho: Rows_below). So the mean cost D
// is at least B(j) = min over lambda of (C + R + (lambda - a) rho) / (l + lambda), a
// linear-fractional function of lambda whose least value is at an end of the interval. When every
// B(j) of the row exceeds tau, D > tau.
//
// Rounding: D is computed as fl(S / L), S from C by lambda rounded additions of nonnegative terms,
// so D >= (1 - u)^(lambda + 1) (C + rest) / L, u = 2^-53; B is computed with at most n + 4 roundings
// (R summed over at most n - 1 terms, then +, *, +, /), each of relative error <= u, so
// B_computed <= B (1 + u)^(n + 4). Hence D >= B_computed (1 - K u) with K = lambda + n + 5
// <= 2 n + m + 5, and B_computed > tau (1 + 2 K u) implies D > tau for tau >= 0 (K u << 1). The
// threshold uses 8 (2 n + m + 8) u, four times that, which also covers rounding the threshold
// itself, and adds 2^-1000 against subnormal quotients, whose error is absolute, not relative.
class Mean_cost_abandoning {
public:
  Mean_cost_abandoning(std::size_t n, std::size_t m, const Dtw_mean_cost_options& options)
      : n_(n), m_(m), tau_(options.abandon_above), below_(options.row_bounds) {
    if (!tau_) return;
    const double slack = double(2 * n + m + 8) * 0x1p-50;
    threshold_ = std::isfinite(*tau_) ? *tau_ + std::abs(*tau_) * slack + 0x1p-1000 : *tau_;
  }
  bool enabled() const { return tau_.has_value(); }

  // Whether, after row i < n - 1 whose columns lo..hi hold cost at[1 + j] and length length[1 + j],
  // every path is proved to have a mean cost above tau. Stops at the first column that is not.
  bool proven_above(std::size_t i, std::size_t lo, std::size_t hi, const double* at, const std::size_t* length) const {
    const double rest = below_.sum(i), least = below_.least(i);
    const std::size_t a = n_ - 1 - i;
    for (std::size_t j = lo; j <= hi; ++j) {
      const std::size_t b = m_ - 1 - j, shortest = std::max(a, b);
      const double base = at[1 + j] + rest, l = double(length[1 + j]);
      if (!(bound(base, l, shortest, shortest - a, least) > threshold_)) return false;
      if (!(bound(base, l, a + b, b, least) > threshold_)) return false;
    }
    return true;
  }

  // After the last row the mean cost is known: it is D itself.
  bool final_above(double score, std::size_t length) const { return tau_ && score / double(length) > *tau_; }

private:
  static double bound(double base, double l, std::size_t lambda, std::size_t extra, double least) {
    return (base + double(extra) * least) / (l + double(lambda));
  }

  std::size_t n_, m_;
  std::optional<double> tau_;
  Rows_below below_;
  double threshold_ = 0;
};

// The value pass over an n x m grid, rows outer, paths from (0, 0) to the far corner, or with the
// free starts and the end in the last row of `ends` (Subsequence_dtw's query along the rows; not
// the end in the last column, nor with a band): without a band rows_at_once rows at a time
// (walk_skewed), with one a row at a time over its columns; the abandoning test (paths to the
// corner only) after every rows_at_once rows and after the last. A free start is a virtual cell
// of cost 0 and length 0, as the traceback leaves the grid there.
template <class D>
class Dtw_value_pass {
public:
  Dtw_value_pass(std::size_t n, std::size_t m, const D& d, const Band& band, const Mean_cost_abandoning& abandoning,
                 Dtw_ends ends = {}, const char* who = "Dtw")
      : n_(n), m_(m), d_(d), band_(band), abandoning_(abandoning), ends_(ends), who_(who) {
    require_row_length(m, who);
    at_.assign(m + 1, ends.start_on_first_row ? 0.0 : dtw_unreachable);
    at_[0] = 0;  // the virtual cell before (0, 0)
    length_.assign(m + 1, 0);
    cost_.resize(rows_at_once * m);
  }

  Dtw_mean_cost run() {
    std::size_t i = 0;
    while (i < n_) {
      const std::size_t step = band_.windowed() ? 1 : n_ - i >= rows_at_once ? rows_at_once : 1;
      if (band_.windowed())
        banded_row(i);
      else if (step == rows_at_once)
        rows_together<rows_at_once>(i);
      else
        rows_together<1>(i);
      i += step;
      if (i < n_ && i % rows_at_once == 0 && abandons_after(i - 1)) return {0, 0, true, i};
    }
    std::size_t end = m_;  // the corner, or the first least cell of the last row, as Dtw_pass's
    if (ends_.end != Dtw_ends::End::corner)
      end = std::size_t(std::min_element(at_.begin() + 1, at_.end()) - at_.begin());
    if (abandoning_.final_above(at_[end], length_[end])) return {0, 0, true, n_};
    return {at_[end], length_[end], false, n_};
  }

private:
  bool abandons_after(std::size_t i) const {
    if (!abandoning_.enabled()) return false;
    const std::size_t lo = band_.windowed() ? band_.first(i) : 0, hi = band_.windowed() ? band_.last(i) : m_ - 1;
    return abandoning_.proven_above(i, lo, hi, at_.data(), length_.data());
  }

  template <std::size_t K>
  void rows_together(std::size_t first) {
    std::array<Dtw_length_row, K> row;
    const double before_column_0 = ends_.start_on_first_col ? 0.0 : dtw_unreachable;
    for_each_index<K>([&](auto k) {
      read_row(d_, first + k, 0, m_, cost_.data() + k * m_, who_);
      row[k].cost = cost_.data() + k * m_;
      row[k].diagonal = first + k == 0 ? 0.0 : before_column_0;
      row[k].left = before_column_0;
    });
    double* at = at_.data();
    std::size_t* length = length_.data();
    walk_skewed(row, m_, [&](auto& r, std::size_t, std::size_t j) { r.step(j, at, length); });
  }

  // Row i over its band only; cells outside the band hold dtw_unreachable when read.
  void banded_row(std::size_t i) {
    const std::size_t lo = band_.first(i), hi = band_.last(i);
    read_row(d_, i, lo, hi - lo + 1, cost_.data() + lo, who_);
    Dtw_length_row row;
    row.cost = cost_.data();
    row.diagonal = at_[lo];
    row.diagonal_length = length_[lo];
    for (std::size_t j = lo + 1; j <= hi + 1; ++j) row.step(j, at_.data(), length_.data());
    at_[lo] = dtw_unreachable;  // column lo - 1 is outside the band of every later row
  }

  std::size_t n_, m_;
  const D& d_;
  const Band& band_;
  const Mean_cost_abandoning& abandoning_;
  Dtw_ends ends_;
  const char* who_;
  std::vector<double> at_, cost_;
  std::vector<std::size_t> length_;
};

// Throws unless the options are usable for an n-row pass.
inline void check_mean_cost_options(std::size_t n, const Dtw_mean_cost_options& options) {
  if (options.abandon_above && std::isnan(*options.abandon_above))
    throw invalid_input("Dtw::mean_cost: abandon_above is NaN");
  const auto& r = options.row_bounds;
  if (!r.empty() && r.size() != n)
    throw invalid_input("Dtw::mean_cost: " + std::to_string(r.size()) + " row bounds for " + std::to_string(n) +
                        " rows (give one per row, or none)");
  for (std::size_t i = 0; i < r.size(); ++i)
    if (!(r[i] >= 0.0 && r[i] <= std::numeric_limits<double>::max()))
      throw invalid_input("Dtw::mean_cost: the row bound " + std::to_string(i) + " = " + std::to_string(r[i]) +
                          " is not a finite value >= 0");
}

}  // namespace deformseg::alignment::internal
