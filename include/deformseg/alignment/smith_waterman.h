/// @file alignment/smith_waterman.h
/// @brief `Smith_waterman`: the best local alignment of two sequences, with linear or affine gap
/// costs (Gotoh), under a substitution score made from a dissimilarity.
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/exceptions.h>
#include <deformseg/alignment/internal/alignment_grid.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::alignment {

namespace internal {

// Trace byte of a cell, set without branches (the choices are data, branches on them
// mispredict). Where H came from: bit 0 when the diagonal beat 0, bit 1 when the vertical gap beat
// both, bit 2 when the horizontal gap beat all three; so the highest bit set tells, none meaning
// a fresh start. Bit 3 when the vertical gap state F extended a gap (else it opened one from H
// above), bit 4 the same for the horizontal state E.
inline constexpr std::uint8_t sw_diagonal_bit = 1, sw_vertical_bit = 2, sw_horizontal_bit = 4;
inline constexpr std::uint8_t sw_vertical_extends = 8, sw_horizontal_extends = 16;

struct Sw_scores {
  double match, spread, open, extend;  // substitution = match - spread * d
};

struct Sw_end {
  double score = 0;
  std::size_t row = 0, col = 0;  // 1-based grid cell where the best alignment ends; 0: none
  std::size_t pairs = 0;         // the pairs of its traceback, when counted
};

// Per column, the pairs of the tracebacks from the row above's H and F (the vertical gap state)
// there, when the pass counts them: h[j], vertical[j] as the pass's h and vertical_gap.
struct Sw_counts {
  std::size_t* h = nullptr;
  std::size_t* vertical = nullptr;
};

// One row of the grid as the pass walks along it: the scores of its cells against the row
// above, its running values, its best cell so far. With Count, beside each state's score the
// number of pairs of the traceback from it (the predecessor its trace bits name, one more pair
// for a diagonal step, none for a fresh start), so that the best cell's is that of align's pairs.
template <bool Affine, bool Trace, bool Count = false>
struct Sw_row {
  const double* substitution = nullptr;  // substitution[j - 1]: score of cell j
  Trace_byte* trace = nullptr;           // this row's trace bytes, when Trace
  double diagonal = 0, left = 0, horizontal_gap = -std::numeric_limits<double>::infinity();
  double best = 0;
  std::size_t best_col = 0;
  std::size_t diagonal_pairs = 0, left_pairs = 0, horizontal_pairs = 0, best_pairs = 0;  // with Count

  // Cell j (1-based): h[j] and vertical_gap[j] hold the row above's H and F there, and get this
  // row's (counts.h[j], counts.vertical[j] their pairs, with Count). On ties H prefers, in order:
  // stopping (0), the diagonal, the vertical gap, the horizontal gap; a gap state prefers opening.
  void step(std::size_t j, double* h, double* vertical_gap, Sw_counts counts, const Sw_scores& sc) {
    const double up = h[j];
    double vertical = up - sc.open, horizontal = left - sc.open;
    std::size_t up_pairs = 0, vertical_pairs = 0, horizontal_from = 0;
    if constexpr (Count) {
      up_pairs = vertical_pairs = counts.h[j];
      horizontal_from = left_pairs;
    }
    unsigned gap_bits = 0;
    if constexpr (Affine) {
      const double vertical_extended = vertical_gap[j] - sc.extend;
      const bool vertical_extends = vertical_extended > vertical;
      gap_bits |= vertical_extends ? sw_vertical_extends : 0;
      vertical = std::max(vertical, vertical_extended);
      vertical_gap[j] = vertical;
      const double horizontal_extended = horizontal_gap - sc.extend;
      const bool horizontal_extends = horizontal_extended > horizontal;
      gap_bits |= horizontal_extends ? sw_horizontal_extends : 0;
      horizontal = std::max(horizontal, horizontal_extended);
      horizontal_gap = horizontal;
      if constexpr (Count) {
        vertical_pairs = counts.vertical[j] = vertical_extends ? counts.vertical[j] : vertical_pairs;
        horizontal_from = horizontal_pairs = horizontal_extends ? horizontal_pairs : horizontal_from;
      }
    }
    double v = diagonal + substitution[j - 1];
    const unsigned diagonal_wins = v > 0.0;
    v = std::max(v, 0.0);
    const unsigned vertical_wins = vertical > v;
    v = std::max(v, vertical);
    const unsigned horizontal_wins = horizontal > v;
    v = std::max(v, horizontal);
    if constexpr (Trace)
      trace[j - 1] = Trace_byte(diagonal_wins | vertical_wins << 1 | horizontal_wins << 2 | gap_bits);
    std::size_t pairs = 0;
    if constexpr (Count) {
      // The traceback's order: the horizontal gap, else the vertical gap, else the diagonal.
      pairs = horizontal_wins ? horizontal_from
              : vertical_wins ? vertical_pairs
              : diagonal_wins ? diagonal_pairs + 1
                              : 0;
      diagonal_pairs = up_pairs;
      counts.h[j] = left_pairs = pairs;
    }
    diagonal = up;
    h[j] = left = v;
    if (v > best) {
      best = v;
      best_col = j;
      if constexpr (Count) best_pairs = pairs;
    }
  }
};

// K consecutive rows from `first` (1-based), walked together (walk_skewed).
template <std::size_t K, bool Affine, bool Trace, bool Count, class D>
void sw_rows(std::size_t first, std::size_t cols, const D& d, const Sw_scores sc, double* h, double* vertical_gap,
             Sw_counts counts, double* substitution, Trace_byte* trace, Sw_end& end) {
  std::array<Sw_row<Affine, Trace, Count>, K> rows;
  for_each_index<K>([&](auto k) {
    double* s = substitution + k * cols;
    read_row(d, first + k - 1, 0, cols, s, "Smith_waterman");
    for (std::size_t j = 0; j < cols; ++j) s[j] = sc.match - sc.spread * s[j];
    rows[k].substitution = s;
    if constexpr (Trace) rows[k].trace = trace + (first + k - 1) * cols;
  });
  walk_skewed(rows, cols, [&](auto& row, std::size_t, std::size_t j) { row.step(j, h, vertical_gap, counts, sc); });
  for_each_index<K>([&](auto k) {
    if (rows[k].best > end.score) end = {rows[k].best, first + k, rows[k].best_col, rows[k].best_pairs};
  });
}

// The whole rows x cols grid, rows outer, `rows_at_once` rows at a time: the best local score and
// where it ends (the first best cell in row-major order), the trace bytes when Trace, the number
// of its traceback's pairs when Count.
template <bool Affine, bool Trace, bool Count = false, class D>
Sw_end sw_pass(std::size_t rows, std::size_t cols, const D& d, const Sw_scores& sc, Trace_byte* trace) {
  require_row_length(cols, "Smith_waterman");
  std::vector<double> h(cols + 1, 0.0), substitution(rows_at_once * cols);
  std::vector<double> vertical_gap(Affine ? cols + 1 : 0, -std::numeric_limits<double>::infinity());
  std::vector<std::size_t> h_pairs(Count ? cols + 1 : 0, 0), vertical_pairs(Count && Affine ? cols + 1 : 0, 0);
  const Sw_counts counts{h_pairs.data(), vertical_pairs.data()};
  Sw_end end;
  std::size_t i = 1;
  double* const gap = vertical_gap.data();
  for (; i + rows_at_once <= rows + 1; i += rows_at_once)
    sw_rows<rows_at_once, Affine, Trace, Count>(i, cols, d, sc, h.data(), gap, counts, substitution.data(), trace,
                                                end);
  for (; i <= rows; ++i)
    sw_rows<1, Affine, Trace, Count>(i, cols, d, sc, h.data(), gap, counts, substitution.data(), trace, end);
  return end;
}

// The pairs of the alignment ending at `end`, followed back through the trace bytes until a cell
// that started afresh (score 0).
inline std::vector<std::pair<std::size_t, std::size_t>> sw_traceback(const Sw_end& end, std::size_t cols,
                                                                      const Trace_byte* trace) {
  enum class State { h, vertical, horizontal } state = State::h;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::size_t i = end.row, j = end.col;
  while (i > 0 && j > 0) {
    const auto t = std::uint8_t(trace[(i - 1) * cols + (j - 1)]);
    if (state == State::vertical) {
      state = t & sw_vertical_extends ? State::vertical : State::h;
      --i;
    } else if (state == State::horizontal) {
      state = t & sw_horizontal_extends ? State::horizontal : State::h;
      --j;
    } else {
      if (t & sw_horizontal_bit) {
        state = State::horizontal;
      } else if (t & sw_vertical_bit) {
        state = State::vertical;
      } else if (t & sw_diagonal_bit) {
        pairs.emplace_back(i - 1, j - 1);
        --i;
        --j;
      } else {
        break;  // a fresh start
      }
    }
  }
  std::reverse(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace internal

/// @brief Alignment policy (models `AlignmentPolicy`): the best local alignment of Smith and
/// Waterman (1981), with affine gaps by Gotoh's recursion (1982). The score is to be maximised
/// (`higher_is_better`).
///
/// Element i of A against element j of B scores `match - (match - mismatch) * d(i, j)`: `match`
/// for d = 0, `mismatch` for d = 1, in between (or beyond) for a continuous dissimilarity such as
/// the distance between two frames or between two cluster medoids. A gap of length L (L
/// consecutive elements of one sequence against none of the other) costs
/// `gap_open + (L - 1) * gap_extend`: linear gaps when the two are equal (the defaults, the method's
/// +1 / -1 / -1), affine otherwise. The score is the largest total over all pairs of contiguous
/// parts of A and B, so never below 0; the empty alignment scores 0.
///
/// Ties are broken deterministically: the alignment returned ends at the first best cell in
/// row-major order (smallest i, then smallest j), and is followed back preferring, at each cell,
/// to stop (when the score there is 0), then a pair, then a gap in B (an element of A left out),
/// then a gap in A; a gap state prefers to open rather than extend. So it is the shortest among
/// the tied alignments ending there.
///
/// The defaults: `match = 1`, `mismatch = -1`, `gap_open = 1`, `gap_extend = 1`.
struct Smith_waterman {
  double match = 1;       ///< score of a pair at dissimilarity 0
  double mismatch = -1;   ///< score of a pair at dissimilarity 1, `<= match`
  double gap_open = 1;    ///< cost (`>= 0`) of a gap's first element
  double gap_extend = 1;  ///< cost of each further element of a gap, `0 <= gap_extend <= gap_open`

  /// @brief The score is to be maximised.
  static constexpr bool higher_is_better = true;

  /// @brief The best local alignment of A (n elements) and B (m elements) under `d`.
  /// @param n, m the lengths; either may be 0 (score 0, no pairs).
  /// @param d the dissimilarity, each value finite and `>= 0`.
  /// @return the best score and the pairs of the local part, in increasing order.
  /// @throws invalid_input when the scores are invalid (not finite, `mismatch > match`, a gap
  /// cost negative, `gap_extend > gap_open`) or a value of d is not finite and `>= 0`, or when an
  /// n x m byte matrix cannot be addressed.
  /// @par Complexity O(n m) time, O(n m) bytes for the traceback plus O(m) doubles.
  template <Dissimilarity D>
  Alignment align(std::size_t n, std::size_t m, const D& d) const {
    const internal::Sw_scores sc = checked_scores();
    const auto trace = internal::trace_matrix(n, m, "Smith_waterman");
    const internal::Sw_end end = affine() ? internal::sw_pass<true, true>(n, m, d, sc, trace.get())
                                          : internal::sw_pass<false, true>(n, m, d, sc, trace.get());
    return {end.score, internal::sw_traceback(end, m, trace.get())};
  }

  /// @brief The score of `align(n, m, d)` alone, computed over the shorter sequence's length.
  /// @throws invalid_input as `align`, but never for the size of the grid.
  /// @par Complexity O(n m) time, O(min(n, m)) memory.
  template <Dissimilarity D>
  double score(std::size_t n, std::size_t m, const D& d) const {
    const internal::Sw_scores sc = checked_scores();
    if (m > n) {
      const internal::Transposed<D> t{d};
      return affine() ? internal::sw_pass<true, false>(m, n, t, sc, nullptr).score
                      : internal::sw_pass<false, false>(m, n, t, sc, nullptr).score;
    }
    return affine() ? internal::sw_pass<true, false>(n, m, d, sc, nullptr).score
                    : internal::sw_pass<false, false>(n, m, d, sc, nullptr).score;
  }

  /// @brief The score of `align(n, m, d)`, bit for bit, and its number of pairs, without the pairs
  /// (`score_and_length(align(n, m, d))`): `align`'s pass over the same grid, carrying per cell
  /// and gap state the number of pairs of the traceback from there, with `align`'s ties.
  /// `similarity::Best_score_normalization` reads only the score; the count serves a
  /// normalisation of one's own.
  /// @param n, m, d as `align`.
  /// @throws invalid_input as `score`.
  /// @par Complexity O(n m) time, O(m) memory.
  template <Dissimilarity D>
  Score_and_length score_and_length(std::size_t n, std::size_t m, const D& d) const {
    const internal::Sw_scores sc = checked_scores();
    const internal::Sw_end end = affine() ? internal::sw_pass<true, false, true>(n, m, d, sc, nullptr)
                                          : internal::sw_pass<false, false, true>(n, m, d, sc, nullptr);
    return {end.score, end.pairs};
  }

private:
  bool affine() const { return gap_open != gap_extend; }

  internal::Sw_scores checked_scores() const {
    constexpr const char* who = "Smith_waterman";
    internal::require_finite(match, who, "match");
    internal::require_finite(mismatch, who, "mismatch");
    internal::require_finite(gap_open, who, "gap_open");
    internal::require_finite(gap_extend, who, "gap_extend");
    if (mismatch > match)
      throw invalid_input("Smith_waterman: mismatch = " + std::to_string(mismatch) + " is above match = " +
                          std::to_string(match));
    if (gap_extend < 0 || gap_extend > gap_open)
      throw invalid_input("Smith_waterman: the gap costs need 0 <= gap_extend <= gap_open, not gap_open = " +
                          std::to_string(gap_open) + ", gap_extend = " + std::to_string(gap_extend));
    return {match, match - mismatch, gap_open, gap_extend};
  }
};

}  // namespace deformseg::alignment
