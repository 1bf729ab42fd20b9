/// @file alignment/dtw.h
/// @brief `Dtw`: dynamic time warping, the global alignment of two sequences of least total
/// dissimilarity, with an optional Sakoe–Chiba window, its path in linear space on long
/// sequences; `Dtw::mean_cost` and `Dtw::score_and_length`, the cost and length of its path
/// without the path.
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw_mean_cost.h>
#include <deformseg/alignment/internal/alignment_grid.h>
#include <deformseg/alignment/internal/dtw_band.h>
#include <deformseg/alignment/internal/dtw_linear_space.h>
#include <deformseg/alignment/internal/dtw_value_pass.h>
#include <deformseg/exceptions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::alignment {

namespace internal {

// Trace byte of a cell, the predecessor of its cheapest path, as two bits set without branches
// (the choice is data, branches on it mispredict): bit 0 when up beat the diagonal, bit 1 when
// left beat both. So: left when bit 1, else up when bit 0, else the diagonal.
inline constexpr std::uint8_t dtw_up_bit = 1, dtw_left_bit = 2;

// One row as the pass walks along it.
template <bool Trace>
struct Dtw_row {
  const double* cost = nullptr;  // cost[j - 1]: d of cell j
  Trace_byte* trace = nullptr;
  double diagonal = dtw_unreachable, left = dtw_unreachable;

  // Cell j (1-based column): at[j] holds the row above's cumulative cost there and gets this
  // row's. On ties the diagonal is preferred, then up, then left.
  void step(std::size_t j, double* at) {
    const double up = at[j];
    const bool up_wins = up < diagonal;
    double best = std::min(diagonal, up);
    const bool left_wins = left < best;
    best = std::min(best, left);
    if constexpr (Trace) trace[j - 1] = Trace_byte(unsigned(up_wins) | unsigned(left_wins) << 1);
    diagonal = up;
    at[j] = left = best + cost[j - 1];
  }
};

// The cumulative costs of a rows x cols grid, rows outer: `at[1 + j]` ends as the last row's, and
// `end` is told each row's cost at the last column (on_last_col ends). The trace bytes when Trace.
// Without a band, `rows_at_once` rows at a time (walk_skewed); with one, a row at a time over its
// columns.
template <bool Trace, class D>
struct Dtw_pass {
  std::size_t rows, cols;
  const D& d;
  const Band& band;
  Dtw_ends ends;
  Trace_byte* trace;
  const char* who;

  // The cost of the best path and the cell where it ends (0-based).
  struct Result {
    double cost = dtw_unreachable;
    std::size_t row = 0, col = 0;
  };

  Result run() const {
    require_row_length(cols, who);
    const double start = ends.start_on_first_row ? 0.0 : dtw_unreachable;
    std::vector<double> at(cols + 1, start), cost(rows_at_once * cols);
    at[0] = 0;  // the virtual cell before (0, 0)
    Result best;
    std::size_t i = 0;
    if (band.windowed()) {
      for (; i < rows; ++i) banded_row(i, at.data(), cost.data());
    } else {
      for (; i + rows_at_once <= rows; i += rows_at_once)
        rows_together<rows_at_once>(i, at.data(), cost.data(), best);
      for (; i < rows; ++i) rows_together<1>(i, at.data(), cost.data(), best);
    }
    if (ends.end == Dtw_ends::End::corner) return {at[cols], rows - 1, cols - 1};
    if (ends.end == Dtw_ends::End::on_last_row) {
      const auto last = std::min_element(at.begin() + 1, at.end());
      return {*last, rows - 1, std::size_t(last - at.begin()) - 1};
    }
    return best;
  }

  template <std::size_t K>
  void rows_together(std::size_t first, double* at, double* cost, Result& best) const {
    std::array<Dtw_row<Trace>, K> row;
    const double before_column_0 = ends.start_on_first_col ? 0.0 : dtw_unreachable;
    for_each_index<K>([&](auto k) {
      read_row(d, first + k, 0, cols, cost + k * cols, who);
      row[k].cost = cost + k * cols;
      if constexpr (Trace) row[k].trace = trace + (first + k) * cols;
      row[k].diagonal = first + k == 0 ? 0.0 : before_column_0;
      row[k].left = before_column_0;
    });
    walk_skewed(row, cols, [&](auto& r, std::size_t, std::size_t j) { r.step(j, at); });
    for_each_index<K>([&](auto k) {
      if (row[k].left < best.cost) best = {row[k].left, first + k, cols - 1};
    });
  }

  // Row i over its band only; cells outside the band hold `dtw_unreachable` when read.
  void banded_row(std::size_t i, double* at, double* cost) const {
    const std::size_t lo = band.first(i), hi = band.last(i);
    read_row(d, i, lo, hi - lo + 1, cost + lo, who);
    Dtw_row<Trace> row;
    row.cost = cost;
    if constexpr (Trace) row.trace = trace + i * cols;
    row.diagonal = at[lo];
    for (std::size_t j = lo + 1; j <= hi + 1; ++j) row.step(j, at);
    at[lo] = dtw_unreachable;  // column lo - 1 is outside the band of every later row
  }
};

// The pairs of the path ending at (i, j), followed back through the trace bytes until it leaves
// the grid (through the virtual cell before (0, 0), or a free start).
inline std::vector<std::pair<std::size_t, std::size_t>> dtw_traceback(std::size_t i, std::size_t j, std::size_t cols,
                                                                       const Trace_byte* trace) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (;;) {
    pairs.emplace_back(i, j);
    const auto from = std::uint8_t(trace[i * cols + j]);
    const bool left = from & dtw_left_bit, up = !left && (from & dtw_up_bit);
    if ((!left && i == 0) || (!up && j == 0)) break;
    if (!left) --i;
    if (!up) --j;
  }
  std::reverse(pairs.begin(), pairs.end());
  return pairs;
}

// The path through a linear-space traceback (dtw_linear_space.h): the same pairs and score as
// the byte per cell. The end is the corner, or found first by a pass of the costs alone.
template <class D>
Alignment dtw_align_linear_space(std::size_t rows, std::size_t cols, const D& d, const Band& band, Dtw_ends ends,
                                 std::size_t max_trace_bytes, const char* who) {
  require_row_length(cols, who);
  require_row_length(rows, who);
  typename Dtw_pass<false, D>::Result end{dtw_unreachable, rows - 1, cols - 1};
  if (ends.end != Dtw_ends::End::corner) end = Dtw_pass<false, D>{rows, cols, d, band, ends, nullptr, who}.run();
  std::vector<double> top(end.col + 2, ends.start_on_first_row ? 0.0 : dtw_unreachable);
  top[0] = 0;  // the virtual cell before (0, 0)
  const std::vector<double> left(end.row + 1, ends.start_on_first_col ? 0.0 : dtw_unreachable);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  const double cost =
      Dtw_linear_path<D>(d, band, max_trace_bytes, who).trace({0, end.row, 0, end.col}, top, left, pairs);
  std::reverse(pairs.begin(), pairs.end());
  return {cost, std::move(pairs)};
}

// The path: through a byte per cell when the grid has at most max_trace_bytes cells, else in
// linear space.
template <class D>
Alignment dtw_align(std::size_t rows, std::size_t cols, const D& d, const Band& band, Dtw_ends ends,
                    std::size_t max_trace_bytes, const char* who) {
  if (rows > max_trace_bytes / cols)
    return dtw_align_linear_space(rows, cols, d, band, ends, max_trace_bytes, who);
  const auto trace = trace_matrix(rows, cols, who);
  const auto end = Dtw_pass<true, D>{rows, cols, d, band, ends, trace.get(), who}.run();
  return {end.cost, dtw_traceback(end.row, end.col, cols, trace.get())};
}

template <class D>
double dtw_cost(std::size_t rows, std::size_t cols, const D& d, const Band& band, Dtw_ends ends, const char* who) {
  return Dtw_pass<false, D>{rows, cols, d, band, ends, nullptr, who}.run().cost;
}

// dtw_align's score and number of pairs, by the value pass (never abandoned), in O(cols) memory.
template <class D>
Score_and_length dtw_score_and_length(std::size_t rows, std::size_t cols, const D& d, const Band& band,
                                      Dtw_ends ends, const char* who) {
  const Mean_cost_abandoning never(rows, cols, {});
  const Dtw_mean_cost value = Dtw_value_pass<D>(rows, cols, d, band, never, ends, who).run();
  return {value.score, value.length};
}

}  // namespace internal

/// @brief Alignment policy (models `AlignmentPolicy`): dynamic time warping, the warping path
/// from (0, 0) to (n - 1, m - 1), with steps (1, 0), (0, 1) and (1, 1), of least total
/// dissimilarity `sum of d(i, j)` over its cells. The score is that total cost: lower is better,
/// the opposite sense of Smith_waterman, as `higher_is_better == false` says.
///
/// Every element of both sequences is in at least one pair; `Alignment::pairs` is the path, from
/// (0, 0) to (n - 1, m - 1). On ties the path is followed back preferring a diagonal step, then a
/// step that leaves j (an element of B matched again), then one that leaves i.
///
/// `window` (default: none) is a Sakoe–Chiba band of half-width w: only the cells with
/// `|i (m - 1) - j (n - 1)| <= w min(n - 1, m - 1)` are used, those within w cells (counted along
/// the longer sequence) of the straight line from (0, 0) to (n - 1, m - 1); for n = m, `|i - j|
/// <= w`. `w = 0` with n = m is the diagonal alone. A window too narrow to connect the two corners
/// (which happens when w is below about half the ratio of the lengths) is an error whose message
/// gives the narrowest that does. Outside the window, d is neither read nor checked.
///
/// `max_trace_bytes` (default 2^25, 32 MiB) bounds the memory of `align`'s traceback: up to that
/// many cells, `align` keeps a byte per cell of the n x m grid; above, it finds the same path in
/// linear space (see `align`).
struct Dtw {
  std::optional<std::size_t> window{};  ///< Sakoe–Chiba half-width in cells; none by default
  /// @brief The most cells whose trace bytes `align` holds at once: the whole grid when
  /// `n m <= max_trace_bytes`, else blocks of at most that many cells (or one row) of a
  /// divide-and-conquer traceback. Default 2^25 (32 MiB: 5,792 x 5,792 frames); 0 makes every
  /// alignment use the divide and conquer. The result does not depend on it.
  std::size_t max_trace_bytes = std::size_t(1) << 25;

  /// @brief The score is a cost, to be minimised.
  static constexpr bool higher_is_better = false;

  /// @brief The least-cost warping path between A (n elements) and B (m elements) under `d`.
  ///
  /// When `n m > max_trace_bytes`, the path is found in linear space instead of through a byte per
  /// cell, with the same result (the same pairs, the same score bit for bit): the rows are split in
  /// two halves; one pass over the grid, carrying for each cell the column where its traceback
  /// would enter the top half's last row, tells where the path crosses into the top half; the
  /// bottom half's part of the path and the top half's are then found the same way, each over the
  /// rectangle that holds it (from the crossing to the right in the bottom half, up to it in the
  /// top half), which the costs kept along its top and left edges determine. A rectangle of at most
  /// `max_trace_bytes` cells, or of one row, is traced back through a byte per cell; one of at most
  /// twice that, by a pass of the costs down to its last `max_trace_bytes / width` rows, those
  /// traced back through a byte per cell, then the part of the path above them the same way.
  /// @param n, m the lengths: both 0 (cost 0, no pairs) or both at least 1.
  /// @param d the dissimilarity, each value finite and `>= 0`; read row by row, by `d.row` when
  /// it has one (`RowDissimilarity`), each row once through a byte per cell, a few times (about
  /// log2(n m / max_trace_bytes) + 2) in linear space.
  /// @return its total cost and its pairs, from (0, 0) to (n - 1, m - 1).
  /// @throws invalid_input when exactly one sequence is empty, when the window does not connect
  /// the corners, or when a value of d is not finite and `>= 0`.
  /// @par Complexity O(n m) time (O(n w + m w) cells with a window). Memory: up to
  /// `max_trace_bytes` cells, n m bytes plus O(m) doubles; above, `max_trace_bytes` bytes (or m)
  /// plus O(n + m log n) doubles, in at most about 3 n m cells (each rectangle's area is at most
  /// half its parent's) instead of n m (what it costs in time: @ref section_dtw_linear_space).
  /// @par Example
  /// @include dtw_linear_space.cpp
  template <Dissimilarity D>
  Alignment align(std::size_t n, std::size_t m, const D& d) const {
    if (n == 0 && m == 0) return {};
    const internal::Band band = checked_band(n, m);
    return internal::dtw_align(n, m, d, band, {}, max_trace_bytes, "Dtw");
  }

  /// @brief The cost of `align(n, m, d)` alone, computed over the shorter sequence's length.
  /// @throws invalid_input as `align`, but never for the size of the grid.
  /// @par Complexity O(n m) time (less with a window), O(min(n, m)) memory.
  template <Dissimilarity D>
  double score(std::size_t n, std::size_t m, const D& d) const {
    if (n == 0 && m == 0) return 0;
    const internal::Band band = checked_band(n, m);
    if (m > n) return internal::dtw_cost(m, n, internal::Transposed<D>{d}, internal::Band(m, n, window), {}, "Dtw");
    return internal::dtw_cost(n, m, d, band, {}, "Dtw");
  }

  /// @brief The cost and the length of `align(n, m, d)`'s path without the path, in O(m)
  /// memory and about 1.7 times `score`'s time (it carries a length per cell); optionally
  /// abandoned as soon as the mean cost `score / length` is proved to exceed a threshold (early
  /// abandoning for a nearest-neighbour search).
  ///
  /// Unless abandoned, `score` is `align(n, m, d).score` bit for bit (the same sums in the same
  /// order) and `length` is `align(n, m, d).pairs.size()`: the pass carries, per cell, the length
  /// of the path align's traceback would follow to it, with align's rule for ties. So the pass
  /// runs in the caller's orientation, never transposed: on ties the length depends on which
  /// sequence is A. The window applies as in `align`.
  ///
  /// With `options.abandon_above = tau`, the rows are read and walked `rows_at_once` (4) at a
  /// time, and after each such step (and after the last row) the pass stops, with
  /// `abandoned = true` and `rows_done` the rows finished, if every path the traceback could
  /// still follow is proved to have a mean cost above tau: the tracked cost and length to a cell
  /// of the row, plus what the rest costs at least (`options.row_bounds` of the rows below, 0
  /// without them) over the fewest and the most cells it can have. The test leaves a relative
  /// margin of about (2 n + m) 2^-50 for rounding, so it never abandons when `score / length <=
  /// tau`, and when it does not abandon the result is that without `abandon_above`. Rows after the
  /// stop are not read.
  /// @param n, m the lengths: both 0 (result {0, 0, false, 0}) or both at least 1.
  /// @param d the dissimilarity, each value finite and `>= 0`; read a row at a time, by `d.row`
  /// when it has one (`RowDissimilarity`).
  /// @param options when to abandon (default: never); see `Dtw_mean_cost_options`.
  /// @return the cost, the length, whether abandoned and how many rows were done.
  /// @throws invalid_input as `score` does, when `abandon_above` is NaN, when `row_bounds` is
  /// neither empty nor of n values, or when one of them is not finite and `>= 0`.
  /// @par Complexity O(n m) time (O(n w + m w) cells with a window), less when abandoned, plus
  /// O(m) per abandoning test (each stops at the first cell whose bound is not above tau);
  /// O(m) memory, plus O(n) for the row bounds' suffix sums.
  /// @par Example
  /// @include dtw_mean_cost.cpp
  template <Dissimilarity D>
  Dtw_mean_cost mean_cost(std::size_t n, std::size_t m, const D& d, const Dtw_mean_cost_options& options = {}) const {
    internal::check_mean_cost_options(n, options);
    if (n == 0 && m == 0) return {};
    const internal::Band band = checked_band(n, m);
    const internal::Mean_cost_abandoning abandoning(n, m, options);
    return internal::Dtw_value_pass<D>(n, m, d, band, abandoning).run();
  }

  /// @brief The cost of `align(n, m, d)`'s path, bit for bit, and its number of cells, without the
  /// path (`score_and_length(align(n, m, d))`): all that `similarity::Best_score_normalization`
  /// reads, one minus the mean dissimilarity along the path. `mean_cost` without abandoning.
  /// @param n, m, d as `align`.
  /// @throws invalid_input as `score`.
  /// @par Complexity as `mean_cost`: O(n m) time (less with a window), O(m) memory.
  /// @par Example
  /// @include dtw_mean_cost.cpp
  template <Dissimilarity D>
  Score_and_length score_and_length(std::size_t n, std::size_t m, const D& d) const {
    const Dtw_mean_cost value = mean_cost(n, m, d);
    return {value.score, value.length};
  }

private:
  internal::Band checked_band(std::size_t n, std::size_t m) const {
    if (n == 0 || m == 0)
      throw invalid_input("Dtw: cannot warp an empty sequence onto one of " + std::to_string(std::max(n, m)) +
                          " elements");
    const internal::Band band(n, m, window);
    if (band.connected()) return band;
    std::size_t narrow = *window, wide = std::max(n, m);  // not connected / connected
    while (wide - narrow > 1) {
      const std::size_t mid = narrow + (wide - narrow) / 2;
      (internal::Band(n, m, mid).connected() ? wide : narrow) = mid;
    }
    throw invalid_input("Dtw: the window " + std::to_string(*window) + " does not connect (0, 0) to (" +
                        std::to_string(n - 1) + ", " + std::to_string(m - 1) + "); the narrowest that does is " +
                        std::to_string(wide));
  }
};

}  // namespace deformseg::alignment
