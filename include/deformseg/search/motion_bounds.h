/// @file search/motion_bounds.h
/// @brief Lower bounds of the default policy's dissimilarity of two described motions, from small
/// fixed-size summaries (`Motion_summary`), and the pruning rule of an exact nearest-motion search.
///
/// The quantity bounded: for signatures A (n rows, the first argument of `compare`) and B (m rows),
/// `D(A, B) = S / L`, the mean frame dissimilarity along the path `alignment::Dtw::align` returns
/// for `d(i, j) = frame_dissimilarity(||a_i - b_j||^2, unit)`; the default policy's value is
/// `1 - D`. Every bound here is a lower bound of the least mean over **all** warping paths from
/// (0, 0) to (n - 1, m - 1), so it holds whatever path the tie rule picks and in both orientations
/// (the paths of (B, A) are those of (A, B) transposed). Proofs: each bound's comment, and
/// @ref section_motion_bounds with what each prunes on real clips.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/search/internal/motion_bounds.h>
#include <deformseg/signatures/motion_signature_view.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace deformseg::search {

/// @brief The number of floats of the summary of a view of `width` values per row with `chunks`
/// chunk boxes: `1 + 5 width + 2 chunks width`.
/// @par Complexity O(1).
constexpr std::size_t summary_width(std::size_t width, std::size_t chunks) {
  return 1 + 5 * width + 2 * chunks * width;
}

/// @brief The most rows a summary records (its row count is a float, exact up to 2^24).
inline constexpr std::size_t summary_max_rows = std::size_t(1) << 24;

/// @brief A read-only view of one motion's summary, a flat block of `summary_width(width, chunks)`
/// floats that it does not own (a `Motion_summary`'s, or a motion store's), read in place.
///
/// Layout, in this order (so that a search that stops after the cheap bounds reads only the
/// block's start): the row count n; per dimension the least value `lo`, the greatest `hi` and the
/// mean (accumulated in double, rounded once); the first row; the last row; then per chunk its
/// box, `width` lows then `width` highs. The rows are split into `chunks` contiguous chunks of
/// near-equal size (chunk c holds rows [c n / K, (c + 1) n / K)); with fewer rows than chunks,
/// chunk c < n is row c and the later ones repeat the last row.
class Motion_summary_view {
public:
  /// @brief The summary held by `floats`, of rows `width` values wide, with `chunks` chunk boxes.
  /// @throws invalid_input when `width` or `chunks` is 0, when `floats` does not hold exactly
  /// `summary_width(width, chunks)` floats, or when its row count is not a whole number in
  /// [1, 2^24] (the block is not a summary of this shape).
  /// @par Complexity O(1).
  Motion_summary_view(std::span<const float> floats, std::size_t width, std::size_t chunks)
      : floats_(floats), width_(width), chunks_(chunks) {
    if (width == 0 || chunks == 0)
      throw invalid_input("Motion_summary_view: the width and the chunks must be positive");
    if (floats.size() != summary_width(width, chunks))
      throw invalid_input("Motion_summary_view: a summary of width " + std::to_string(width) + " with " +
                          std::to_string(chunks) + " chunks has " + std::to_string(summary_width(width, chunks)) +
                          " floats, not " + std::to_string(floats.size()));
    const float n = floats[0];
    if (!(n >= 1 && n <= float(summary_max_rows) && n == std::floor(n)))
      throw invalid_input("Motion_summary_view: the row count " + std::to_string(n) +
                          " is not a whole number in [1, 2^24]: not a summary");
  }

  /// @brief The summary held by `floats`, unchecked: for a block known to be a summary of this
  /// shape, such as one `summarize` wrote (`Motion_collection` makes its views so, once per clip,
  /// from the summaries it made), where the checks of the constructor would be repeated for
  /// every clip of every search.
  /// @pre `width` and `chunks` positive, `floats.size() == summary_width(width, chunks)`, and
  /// `floats[0]` a whole number in [1, 2^24] (not checked).
  /// @par Complexity O(1).
  static Motion_summary_view unchecked(std::span<const float> floats, std::size_t width, std::size_t chunks) {
    return Motion_summary_view(floats, width, chunks, Unchecked{});
  }

  /// @brief The rows of the summarised view.
  std::size_t rows() const { return std::size_t(floats_[0]); }
  /// @brief The values per row.
  std::size_t width() const { return width_; }
  /// @brief The chunk boxes.
  std::size_t chunks() const { return chunks_; }
  /// @brief Per dimension, the least value over the rows.
  std::span<const float> lo() const { return part(0); }
  /// @brief Per dimension, the greatest value over the rows.
  std::span<const float> hi() const { return part(1); }
  /// @brief Per dimension, the mean over the rows, rounded to the nearest float.
  std::span<const float> mean() const { return part(2); }
  /// @brief The first row.
  std::span<const float> first_row() const { return part(3); }
  /// @brief The last row.
  std::span<const float> last_row() const { return part(4); }
  /// @brief Per dimension, the least value over chunk `c`'s rows. @pre `c < chunks()` (not checked).
  std::span<const float> chunk_lo(std::size_t c) const { return part(5 + 2 * c); }
  /// @brief Per dimension, the greatest value over chunk `c`'s rows. @pre `c < chunks()` (not checked).
  std::span<const float> chunk_hi(std::size_t c) const { return part(6 + 2 * c); }
  /// @brief The whole block.
  std::span<const float> floats() const { return floats_; }

private:
  struct Unchecked {};
  Motion_summary_view(std::span<const float> floats, std::size_t width, std::size_t chunks, Unchecked)
      : floats_(floats), width_(width), chunks_(chunks) {}
  std::span<const float> part(std::size_t p) const { return floats_.subspan(1 + p * width_, width_); }

  std::span<const float> floats_;
  std::size_t width_, chunks_;
};

/// @brief Writes the summary of `view` with `chunks` chunk boxes into `out` (layout: see
/// `Motion_summary_view`); for a store that writes summaries in place.
/// @param view the signatures, at least one row and one column.
/// @param chunks the chunk boxes (`summarize` uses 4).
/// @param out `summary_width(view.width, chunks)` floats.
/// @throws invalid_input when the view has no row or no column, more than 2^24 rows, `chunks` is
/// 0, or `out` does not hold exactly `summary_width(view.width, chunks)` floats.
/// @par Complexity O(rows width) time, no allocation.
inline void summarize_into(const signatures::Motion_signature_view& view, std::size_t chunks, std::span<float> out) {
  if (view.rows == 0 || view.width == 0) throw invalid_input("summarize: the signatures have no row or no column");
  if (view.rows > summary_max_rows) throw invalid_input("summarize: more than 2^24 rows");
  if (chunks == 0) throw invalid_input("summarize: the chunks must be positive");
  const std::size_t width = view.width, rows = view.rows;
  if (out.size() != summary_width(width, chunks))
    throw invalid_input("summarize: the output holds " + std::to_string(out.size()) + " floats, a summary " +
                        std::to_string(summary_width(width, chunks)));
  out[0] = float(rows);
  const auto part = [&](std::size_t p) { return out.subspan(1 + p * width, width); };
  for (std::size_t k = 0; k < width; ++k) {
    const float* column = view.values + k * rows;
    double sum = 0;
    for (std::size_t r = 0; r < rows; ++r) sum += column[r];
    part(0)[k] = *std::min_element(column, column + rows);
    part(1)[k] = *std::max_element(column, column + rows);
    part(2)[k] = float(sum / double(rows));
    part(3)[k] = column[0];
    part(4)[k] = column[rows - 1];
    for (std::size_t c = 0; c < chunks; ++c) {
      const auto [begin, end] = internal::summary_chunk_rows(rows, chunks, c);
      part(5 + 2 * c)[k] = *std::min_element(column + begin, column + end);
      part(6 + 2 * c)[k] = *std::max_element(column + begin, column + end);
    }
  }
}

/// @brief The summary of one motion's signatures, owning its floats; `view()` reads it.
struct Motion_summary {
  /// @brief The values per row of the summarised signatures.
  std::size_t width = 0;
  /// @brief The chunk boxes.
  std::size_t chunks = 0;
  /// @brief `summary_width(width, chunks)` floats, laid out as `Motion_summary_view` says.
  std::vector<float> floats;

  /// @brief A view of these floats (valid while this summary lives and is not changed).
  /// @throws invalid_input when the floats are not a summary of this width and chunks.
  Motion_summary_view view() const { return {floats, width, chunks}; }
};

/// @brief The summary of `view` with `chunks` chunk boxes.
/// @param view the signatures, at least one row and one column.
/// @param chunks the chunk boxes, default 4.
/// @throws invalid_input as `summarize_into`.
/// @par Complexity O(rows width) time, `summary_width(width, chunks)` floats.
inline Motion_summary summarize(const signatures::Motion_signature_view& view, std::size_t chunks = 4) {
  const std::size_t floats = summary_width(view.width, std::max<std::size_t>(chunks, 1));
  Motion_summary summary{view.width, chunks, std::vector<float>(floats)};
  summarize_into(view, chunks, summary.floats);
  return summary;
}

/// @brief Copies `summary`'s floats into `out` (a store's block).
/// @throws invalid_input when `out` does not hold exactly `summary.floats.size()` floats.
/// @par Complexity O(summary_width).
inline void write_summary(const Motion_summary& summary, std::span<float> out) {
  if (out.size() != summary.floats.size())
    throw invalid_input("write_summary: the output holds " + std::to_string(out.size()) + " floats, the summary " +
                        std::to_string(summary.floats.size()));
  std::copy(summary.floats.begin(), summary.floats.end(), out.begin());
}

/// @brief The summary held by `floats` (a store's block), copied and checked.
/// @throws invalid_input as `Motion_summary_view`'s constructor.
/// @par Complexity O(summary_width).
inline Motion_summary read_summary(std::span<const float> floats, std::size_t width, std::size_t chunks) {
  const Motion_summary_view checked(floats, width, chunks);
  return {width, chunks, std::vector<float>(checked.floats().begin(), checked.floats().end())};
}

namespace internal {

inline void require_same_width(const Motion_summary_view& a, const Motion_summary_view& b, const char* who) {
  if (a.width() != b.width())
    throw invalid_input(std::string(who) + ": summaries of different widths (" + std::to_string(a.width()) + " and " +
                        std::to_string(b.width()) + ")");
}

}  // namespace internal

/// @brief LB_box: `frame_dissimilarity(gap2(box A, box B), unit) <= D(A, B)`, gap2 the squared
/// distance between the two bounding boxes (`sum_k max(0, lo_A - hi_B, lo_B - hi_A)_k^2`).
///
/// Every cell has `||a_i - b_j||^2 >= gap2` and the frame dissimilarity increases with it, so every
/// cell, hence the mean along any path, is at least the bound.
/// @param a the summary of A, the rows (the first argument of `compare`).
/// @param b the summary of B, the columns; as wide as `a`.
/// @param unit `frame_dissimilarity_unit(width, scale)` of the policy.
/// @throws invalid_input when the widths differ.
/// @par Complexity O(width), reads lo and hi only.
inline double lb_box(const Motion_summary_view& a, const Motion_summary_view& b, double unit) {
  internal::require_same_width(a, b, "lb_box");
  return signatures::frame_dissimilarity(internal::box_gap2(a.lo(), a.hi(), b.lo(), b.hi()), unit);
}

/// @brief LB_mean, the Jensen and chord bound: `chi(max(G, g0)) <= D(A, B)`.
///
/// A path of L cells visits row i k_i >= 1 times; the path average of its rows a_i is
/// `(n/L) mu_A + (1 - n/L) h`, h in box A, so per dimension it lies in
/// `I_A = [lo + l (mu - lo), hi - l (hi - mu)]`, `l = n / (n + m - 1) <= n / L` (a larger l only
/// shrinks the interval toward mu); the same for B with `m / (n + m - 1)`. Jensen (||.||^2 is
/// convex): the path's mean squared distance is at least `G = sum_k gap(I_A, I_B)_k^2`. Every cell's
/// squared distance lies in `[g0, S]` (g0 the boxes' gap2, S their farthest squared distance) where
/// the concave frame dissimilarity lies above its chord chi, affine and increasing: mean d >=
/// mean chi(s) = chi(mean s) >= chi(max(G, g0)). So the bound is at least `lb_box`. Each interval is
/// widened by `2^-22 max(|lo|, |hi|)` each way, more than the rounding of mu (a double sum of at
/// most 2^24 rows, then one float rounding) and of the interval's ends.
/// @param a the summary of A, the rows (the first argument of `compare`).
/// @param b the summary of B, the columns; as wide as `a`.
/// @param unit `frame_dissimilarity_unit(width, scale)` of the policy.
/// @throws invalid_input when the widths differ.
/// @par Complexity O(width), reads lo, hi and mean only.
inline double lb_mean(const Motion_summary_view& a, const Motion_summary_view& b, double unit) {
  internal::require_same_width(a, b, "lb_mean");
  const double n = double(a.rows()), m = double(b.rows());
  const double share_a = n / (n + m - 1), share_b = m / (n + m - 1);
  // The interval of a path average of one side in dimension k.
  // The interval of a path average of one side in dimension k, widened by more than the rounding
  // of mu (double sum, one float rounding) and of its own ends.
  const auto average_interval = [](const Motion_summary_view& s, std::size_t k, double share) {
    const double lo = s.lo()[k], hi = s.hi()[k], mu = s.mean()[k];
    const double rounding = 0x1p-22 * std::max(std::abs(lo), std::abs(hi));
    return std::pair{std::max(lo, lo + share * (mu - lo) - rounding), std::min(hi, hi - share * (hi - mu) + rounding)};
  };
  double g0 = 0, g = 0, farthest = 0;
  for (std::size_t k = 0; k < a.width(); ++k) {
    const double a_lo = a.lo()[k], a_hi = a.hi()[k], b_lo = b.lo()[k], b_hi = b.hi()[k];
    const double box_gap = internal::interval_gap(a_lo, a_hi, b_lo, b_hi);
    const double far = std::max(a_hi - b_lo, b_hi - a_lo);
    const auto [ia_lo, ia_hi] = average_interval(a, k, share_a);
    const auto [ib_lo, ib_hi] = average_interval(b, k, share_b);
    const double average_gap = internal::interval_gap(ia_lo, ia_hi, ib_lo, ib_hi);
    g0 += box_gap * box_gap;
    g += average_gap * average_gap;
    farthest += far * far;
  }
  const double f0 = signatures::frame_dissimilarity(g0, unit);
  if (!(farthest > g0) || !(g > g0)) return f0;
  const double x = std::min(g, farthest);
  return f0 + (signatures::frame_dissimilarity(farthest, unit) - f0) * ((x - g0) / (farthest - g0));
}

/// @brief LB_rows_columns, the LB_Keogh analogue for a DTW without window whose value is a mean:
/// `max(rows bound, columns bound) <= D(A, B)`.
///
/// For row i of A in chunk c, `r_i = f(min_c' gap2(chunk box A_c, chunk box B_c')) <= min_j d(i, j)`
/// (f the frame dissimilarity). A path of L cells visits every row; counting the corner cells
/// (0, 0) and (n - 1, m - 1) exactly (d00, d_last, from the first and last rows), one cell of every
/// other row at its r_i, and the L - n remaining cells at `rho = min_i r_i`:
/// `sum >= R' + (L - n) rho`, `R' = d00 + d_last + sum_{0<i<n-1} r_i`; the mean is monotone in L, so
/// its least over `max(n, m) <= L <= n + m - 1` is at an end (for n = 1, L = m: `(d00 + d_last +
/// (m - 2) r_0) / m`; for n = m = 1, d00 exactly). The columns bound is the same with the roles of
/// A and B swapped. Their max, not their sum: f is concave, so LB_Improved's two-pass sum does not
/// carry over.
/// @param a the summary of A, the rows (the first argument of `compare`).
/// @param b the summary of B, the columns; as wide as `a`.
/// @param unit `frame_dissimilarity_unit(width, scale)` of the policy.
/// @param scratch at least `a.chunks() + b.chunks()` doubles, overwritten: with it, no allocation
/// (the search passes each thread's own).
/// @throws invalid_input when the widths differ or `scratch` is too short.
/// @par Complexity O(chunks_A chunks_B width + width) time; reads the first and last rows and the
/// chunk boxes.
inline double lb_rows_columns(const Motion_summary_view& a, const Motion_summary_view& b, double unit,
                              std::span<double> scratch) {
  internal::require_same_width(a, b, "lb_rows_columns");
  const std::size_t ka = a.chunks(), kb = b.chunks();
  if (scratch.size() < ka + kb)
    throw invalid_input("lb_rows_columns: the scratch holds " + std::to_string(scratch.size()) + " values, not " +
                        std::to_string(ka + kb));
  const std::span<double> row_gap = scratch.first(ka), column_gap = scratch.subspan(ka, kb);
  std::fill(scratch.begin(), scratch.begin() + std::ptrdiff_t(ka + kb), std::numeric_limits<double>::infinity());
  for (std::size_t ca = 0; ca < ka; ++ca)
    for (std::size_t cb = 0; cb < kb; ++cb) {
      const double g = internal::box_gap2(a.chunk_lo(ca), a.chunk_hi(ca), b.chunk_lo(cb), b.chunk_hi(cb));
      row_gap[ca] = std::min(row_gap[ca], g);
      column_gap[cb] = std::min(column_gap[cb], g);
    }
  for (double& g : row_gap) g = signatures::frame_dissimilarity(g, unit);
  for (double& g : column_gap) g = signatures::frame_dissimilarity(g, unit);
  const double d00 = signatures::frame_dissimilarity(internal::squared_distance(a.first_row(), b.first_row()), unit);
  const double d_last = signatures::frame_dissimilarity(internal::squared_distance(a.last_row(), b.last_row()), unit);
  const std::size_t n = a.rows(), m = b.rows();
  return std::max(internal::rows_side_bound(n, m, ka, row_gap, d00, d_last),
                  internal::rows_side_bound(m, n, kb, column_gap, d00, d_last));
}

/// @brief `lb_rows_columns(a, b, unit, scratch)` with a scratch of its own.
/// @throws invalid_input when the widths differ.
/// @par Complexity O(chunks_A chunks_B width + width) time, O(chunks_A + chunks_B) memory.
inline double lb_rows_columns(const Motion_summary_view& a, const Motion_summary_view& b, double unit) {
  std::vector<double> scratch(a.chunks() + b.chunks());
  return lb_rows_columns(a, b, unit, scratch);
}

/// @brief Per row i of `query`, `out[i] = f(min_c gap2(a_i, chunk box c of candidate)) <= min_j d(i, j)`:
/// a lower bound of every cell of row i against the candidate (f the frame dissimilarity), for
/// the early abandoning of an exact pass over the query's rows.
/// @param query the query's signatures (rows of A).
/// @param candidate the candidate's summary (B).
/// @param unit `frame_dissimilarity_unit(width, scale)` of the policy.
/// @param out `query.rows` doubles.
/// @param scratch at least `query.rows` doubles, overwritten: with it, no allocation (the search
/// passes each thread's own).
/// @throws invalid_input when the widths differ, `out` does not hold `query.rows` values or
/// `scratch` fewer.
/// @par Complexity O(query.rows chunks width) time.
inline void row_bounds(const signatures::Motion_signature_view& query, const Motion_summary_view& candidate,
                       double unit, std::span<double> out, std::span<double> scratch) {
  if (query.width != candidate.width())
    throw invalid_input("row_bounds: the query is " + std::to_string(query.width) + " wide, the candidate " +
                        std::to_string(candidate.width()));
  if (out.size() != query.rows || scratch.size() < query.rows)
    throw invalid_input("row_bounds: the output holds " + std::to_string(out.size()) + " values and the scratch " +
                        std::to_string(scratch.size()) + ", the query has " + std::to_string(query.rows) + " rows");
  const std::size_t n = query.rows;
  const std::span<double> gap2 = scratch.first(n);  // row i against the chunk at hand
  std::fill(out.begin(), out.end(), std::numeric_limits<double>::infinity());
  // Chunk by chunk, each row's gap2 summed over the dimensions in order, then its least kept.
  for (std::size_t c = 0; c < candidate.chunks(); ++c) {
    std::fill(gap2.begin(), gap2.end(), 0.0);
    for (std::size_t k = 0; k < query.width; ++k) {
      const float* column = query.values + k * n;
      const double lo = candidate.chunk_lo(c)[k], hi = candidate.chunk_hi(c)[k];
      for (std::size_t i = 0; i < n; ++i) {
        const double g = internal::interval_gap(column[i], column[i], lo, hi);
        gap2[i] += g * g;
      }
    }
    for (std::size_t i = 0; i < n; ++i) out[i] = std::min(out[i], gap2[i]);
  }
  for (double& r : out) r = signatures::frame_dissimilarity(r, unit);
}

/// @brief `row_bounds(query, candidate, unit, out, scratch)` with a scratch of its own.
/// @throws invalid_input when the widths differ or `out` does not hold `query.rows` values.
/// @par Complexity O(query.rows chunks width) time, O(query.rows) memory.
inline void row_bounds(const signatures::Motion_signature_view& query, const Motion_summary_view& candidate,
                       double unit, std::span<double> out) {
  std::vector<double> scratch(query.rows);
  row_bounds(query, candidate, unit, out, scratch);
}

/// @brief A lower bound made safe against rounding: `lower_bound (1 - 2^-10) - 2^-20`.
///
/// Why this covers the comparison kernel and the bounds' own rounding. The kernel's contract: every
/// cell `|d_kernel - f(s)| <= 2^-12 f(s) + 2^-22`, s the double squared distance of the float rows,
/// f the double reference `frame_dissimilarity`; it sums the cells of a path in double (relative
/// error at most (n + m) 2^-53). Its D is the mean along some path P of d_kernel >= (1 - 2^-12)
/// mean_P f - 2^-22 - (sum rounding) >= (1 - 2^-12) LB - 2^-22 - (n + m) 2^-53, LB any exact lower
/// bound of the least mean over all paths. The bounds here read exact floats and sum nonnegative
/// terms in double (width + chunks + 10 roundings at most, relative below 2^-40 for width + chunks
/// below 2^12), `expm1` errs by an ulp, and LB_mean's chord by at most `2^-51 unit S` absolute
/// (S the farthest squared distance; below 2^-31 while `unit S < 2^20`),
/// so the computed bound is at most `LB (1 + 2^-40) + 2^-31`. Then
/// `D_kernel - safe >= LB (2^-10 - 2^-12 - 2^-40 - (n + m) 2^-53) + 2^-20 - 2^-22 - 2^-31 > 0` for
/// n + m below 2^40: a gap of more than 2^-21 (5e-7), far above the rounding of `1 - x` in double.
/// @par Complexity O(1).
constexpr double safe_lower_bound(double lower_bound) { return lower_bound * (1 - 0x1p-10) - 0x1p-20; }

/// @brief The pruning rule of an exact search: false, the candidate may be skipped, only when
/// `1 - safe_lower_bound(lower_bound) < kth_value` (strictly); true, its value must be computed,
/// otherwise (also for a NaN bound, and for `kth_value = -infinity`, fewer than k results yet).
///
/// With `kth_value` a value the kernel computed, a skipped candidate's kernel value is strictly
/// below it (see `safe_lower_bound`), so it is not among the k best and does not tie the k-th:
/// the results and their order are those of the full computation.
/// @param lower_bound any of `lb_box`, `lb_mean`, `lb_rows_columns` (or their max).
/// @param kth_value the k-th best value found so far.
/// @par Complexity O(1).
constexpr bool may_beat(double lower_bound, double kth_value) {
  return !(1.0 - safe_lower_bound(lower_bound) < kth_value);
}

}  // namespace deformseg::search
