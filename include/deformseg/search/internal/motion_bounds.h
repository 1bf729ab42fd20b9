/// @file search/internal/motion_bounds.h
/// @brief Details of search/motion_bounds.h: the chunks of a summary's rows, box gaps, and the
/// row bound of LB_rows / LB_cols.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>

namespace deformseg::search::internal {

// The rows [begin, end) whose box is chunk c of `chunks` over `rows` rows: contiguous chunks of
// near-equal size (sizes differ by at most one). With fewer rows than chunks, chunk c < rows is row
// c and every later chunk repeats the last row.
inline std::pair<std::size_t, std::size_t> summary_chunk_rows(std::size_t rows, std::size_t chunks, std::size_t c) {
  if (rows < chunks) return c < rows ? std::pair{c, c + 1} : std::pair{rows - 1, rows};
  return {c * rows / chunks, (c + 1) * rows / chunks};
}

// The rows that chunk c stands for when rows are counted: its own rows, none for a repeated chunk.
inline std::pair<std::size_t, std::size_t> summary_chunk_owned_rows(std::size_t rows, std::size_t chunks,
                                                                    std::size_t c) {
  if (rows < chunks && c >= rows) return {rows, rows};
  return summary_chunk_rows(rows, chunks, c);
}

// The gap between the intervals [a_lo, a_hi] and [b_lo, b_hi], 0 when they meet. Float
// differences are exact in double unless the exponents are far apart (then rounded once).
inline double interval_gap(double a_lo, double a_hi, double b_lo, double b_hi) {
  return std::max({0.0, a_lo - b_hi, b_lo - a_hi});
}

// sum_k gap_k^2 of two boxes: a lower bound of ||a - b||^2 for a in box a, b in box b.
inline double box_gap2(std::span<const float> a_lo, std::span<const float> a_hi, std::span<const float> b_lo,
                       std::span<const float> b_hi) {
  double sum = 0;
  for (std::size_t k = 0; k < a_lo.size(); ++k) {
    const double g = interval_gap(a_lo[k], a_hi[k], b_lo[k], b_hi[k]);
    sum += g * g;
  }
  return sum;
}

inline double squared_distance(std::span<const float> a, std::span<const float> b) {
  double sum = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double g = double(a[k]) - double(b[k]);
    sum += g * g;
  }
  return sum;
}

// One side of LB_rows_columns, rows of A against B (n rows, m columns): with r_i a lower bound of
// row i's cells (per chunk: `chunk_bound[c]`), d00 and d_last the exact corner cells, every path
// of L cells has sum >= R' + (L - n) rho, R' = d00 + d_last + sum_{0<i<n-1} r_i, rho = min_i r_i;
// the mean (R' + (L - n) rho) / L is monotone in L, so its least over max(n, m) <= L <= n + m - 1
// is at an end. For n = 1 row 0 holds all L = m cells: (d00 + d_last + (m - 2) r_0) / m.
inline double rows_side_bound(std::size_t n, std::size_t m, std::size_t chunks, std::span<const double> chunk_bound,
                              double d00, double d_last) {
  if (n == 1 && m == 1) return d00;
  if (n == 1) return (d00 + d_last + double(m - 2) * chunk_bound[0]) / double(m);
  double sum = d00 + d_last, rho = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < chunks; ++c) {
    rho = std::min(rho, chunk_bound[c]);
    const auto [begin, end] = summary_chunk_owned_rows(n, chunks, c);
    const std::size_t middle_begin = std::max<std::size_t>(begin, 1), middle_end = std::min(end, n - 1);
    if (middle_end > middle_begin) sum += double(middle_end - middle_begin) * chunk_bound[c];
  }
  const auto mean_at = [&](std::size_t length) { return (sum + double(length - n) * rho) / double(length); };
  return std::min(mean_at(std::max(n, m)), mean_at(n + m - 1));
}

}  // namespace deformseg::search::internal
