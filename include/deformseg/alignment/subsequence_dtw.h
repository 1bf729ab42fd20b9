/// @file alignment/subsequence_dtw.h
/// @brief `Subsequence_dtw`: dynamic time warping of a whole query sequence against the best
/// contiguous part of another (open begin and end).
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw.h>
#include <deformseg/exceptions.h>
#include <deformseg/alignment/internal/alignment_grid.h>

#include <cstddef>
#include <string>
#include <utility>

namespace deformseg::alignment {

/// @brief Which sequence `Subsequence_dtw` matches whole.
enum class Subsequence_query {
  first,   ///< A, the first sequence (the default)
  shorter  ///< the shorter of the two (A when they are equally long)
};

/// @brief Alignment policy (models `AlignmentPolicy`): subsequence dynamic time warping. The whole
/// query sequence is warped onto the contiguous part of the other sequence that costs least: the
/// path may start at any element of the other sequence and end at any later one (open begin and
/// end), with steps (1, 0), (0, 1) and (1, 1). The score is the path's total dissimilarity, lower
/// is better (`higher_is_better == false`).
///
/// It stands in for the "mDTW" the thesis compares with (@ref method_similarity), whose definition
/// we lack: of the usual DTW variants, the one whose open ends suit a motion found inside a
/// longer one.
///
/// Every element of the query is in at least one pair. On ties the path ends at the first
/// (smallest-index) best element of the other sequence, is followed back preferring a diagonal
/// step, then a step that repeats the other sequence's element, then one that repeats the
/// query's, and starts afresh rather than extend a start at no cost.
struct Subsequence_dtw {
  /// @brief The sequence matched whole; default the first.
  Subsequence_query query = Subsequence_query::first;
  /// @brief The most cells whose trace bytes `align` holds at once, as `Dtw::max_trace_bytes`:
  /// above, the same path is found in linear space. Default 2^25 (32 MiB); 0: always.
  std::size_t max_trace_bytes = std::size_t(1) << 25;

  /// @brief The score is a cost, to be minimised.
  static constexpr bool higher_is_better = false;

  /// @brief The least-cost warping of the query onto a contiguous part of the other sequence.
  /// @param n, m the lengths of A and B: both 0 (cost 0, no pairs) or both at least 1.
  /// @param d the dissimilarity between A and B, each value finite and `>= 0`.
  /// @return its cost and its pairs (i of A, j of B), in increasing order.
  /// @throws invalid_input when exactly one sequence is empty, or when a value of d is not finite
  /// and `>= 0`.
  /// @par Complexity O(n m) time, O(n m) bytes for the traceback plus O(n + m) doubles; when
  /// `n m > max_trace_bytes`, `Dtw::align`'s linear-space traceback (after a pass of the costs
  /// alone, to find the end): `max_trace_bytes` bytes plus O(n + m log n) doubles.
  template <Dissimilarity D>
  Alignment align(std::size_t n, std::size_t m, const D& d) const {
    if (check_lengths(n, m)) return {};
    if (query == Subsequence_query::first || n <= m)
      return internal::dtw_align(n, m, d, internal::Band(n, m, {}), query_along_rows(), max_trace_bytes,
                                 "Subsequence_dtw");
    // The query is B: the grid with B along the rows, then the pairs turned back.
    Alignment a = internal::dtw_align(m, n, internal::Transposed<D>{d}, internal::Band(m, n, {}),
                                      query_along_rows(), max_trace_bytes, "Subsequence_dtw");
    for (auto& [i, j] : a.pairs) std::swap(i, j);
    return a;
  }

  /// @brief The cost of `align(n, m, d)` alone, computed over the shorter sequence's length.
  /// @throws invalid_input as `align`, but never for the size of the grid.
  /// @par Complexity O(n m) time, O(min(n, m)) memory.
  template <Dissimilarity D>
  double score(std::size_t n, std::size_t m, const D& d) const {
    if (check_lengths(n, m)) return 0;
    const bool query_is_a = query == Subsequence_query::first || n <= m;
    // Rows over the longer sequence, so that the one row kept is as short as can be.
    if (n >= m)
      return internal::dtw_cost(n, m, d, internal::Band(n, m, {}), query_is_a ? query_along_rows() : query_along_cols(),
                                "Subsequence_dtw");
    return internal::dtw_cost(m, n, internal::Transposed<D>{d}, internal::Band(m, n, {}),
                              query_is_a ? query_along_cols() : query_along_rows(), "Subsequence_dtw");
  }

  /// @brief The cost of `align(n, m, d)`'s path, bit for bit, and its number of pairs, without the
  /// path (`score_and_length(align(n, m, d))`): a pass over the same grid as `align` (the query
  /// along its rows) carrying, per cell, the length of the path the traceback would follow to it,
  /// with `align`'s ties. What `similarity::Best_score_normalization` reads.
  /// @param n, m, d as `align`.
  /// @throws invalid_input as `score`.
  /// @par Complexity O(n m) time; O(m) memory when the query is A, O(n) when it is B.
  template <Dissimilarity D>
  Score_and_length score_and_length(std::size_t n, std::size_t m, const D& d) const {
    if (check_lengths(n, m)) return {};
    if (query == Subsequence_query::first || n <= m)
      return internal::dtw_score_and_length(n, m, d, internal::Band(n, m, {}), query_along_rows(),
                                            "Subsequence_dtw");
    return internal::dtw_score_and_length(m, n, internal::Transposed<D>{d}, internal::Band(m, n, {}),
                                          query_along_rows(), "Subsequence_dtw");
  }

private:
  // True when both are empty; throws when one is.
  static bool check_lengths(std::size_t n, std::size_t m) {
    if ((n == 0) != (m == 0))
      throw invalid_input("Subsequence_dtw: cannot warp an empty sequence onto one of " +
                          std::to_string(n + m) + " elements");
    return n == 0;
  }
  // The query along the rows: the path starts anywhere in row 0 and ends anywhere in the last.
  static internal::Dtw_ends query_along_rows() { return {false, true, internal::Dtw_ends::End::on_last_row}; }
  // The query along the columns: it starts anywhere in column 0 and ends anywhere in the last.
  static internal::Dtw_ends query_along_cols() { return {true, false, internal::Dtw_ends::End::on_last_col}; }
};

}  // namespace deformseg::alignment
