// DTW's path in memory linear in the lengths: the same pairs and score as the full traceback of
// dtw.h, found by divide and conquer over rectangles of the grid (Dtw::max_trace_bytes).
//
// A cell's cumulative cost depends only on the cells above and to its left, so a rectangle of the
// grid is computed exactly from its boundary: the costs of the row above it and of the column
// before it. The traceback's choice at a cell depends only on its predecessors' costs, so a
// forward pass can carry, per cell, where its traceback will enter a chosen middle row. One pass
// over a rectangle thus tells where the path crosses the middle row; the path is then that of the
// bottom part (its boundary: the middle row, kept, and the column before the crossing, computed)
// followed back into that of the top part (its boundary: a part of the rectangle's own). A
// rectangle small enough is traced back through a byte per cell, as dtw.h does for the whole grid;
// one of at most twice that, by its bottom rows so, after a pass of the costs above them, then the
// rest of the path above them.
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/internal/alignment_grid.h>
#include <deformseg/alignment/internal/dtw_band.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace deformseg::alignment::internal {

// Rows r0..r1 and columns c0..c1 of the grid, inclusive.
struct Dtw_rect {
  std::size_t r0, r1, c0, c1;
  std::size_t height() const { return r1 - r0 + 1; }
  std::size_t width() const { return c1 - c0 + 1; }
};

// The path ending at a cell, followed back through a rectangle whose boundary costs are given:
// `top[k]` the cost of (r0 - 1, c0 - 1 + k) for k = 0..width, `left[k]` that of (r0 + k, c0 - 1)
// for k < height; virtual cells (row or column -1) are the free or forbidden starts.
template <class D>
class Dtw_linear_path {
public:
  using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

  // max_trace_bytes: the largest rectangle (in cells) traced back through a byte per cell; a
  // rectangle of one row is always.
  Dtw_linear_path(const D& d, const Band& band, std::size_t max_trace_bytes, const char* who)
      : d_(d), band_(band), block_(max_trace_bytes), who_(who) {}

  // The pairs, last first, of the path ending at (r1, c1) up to where it leaves `rect`; returns
  // the cumulative cost of (r1, c1).
  double trace(const Dtw_rect& rect, std::span<const double> top, std::span<const double> left, Pairs& pairs) const {
    const std::size_t area = rect.height() * rect.width();
    if (rect.height() == 1 || area <= block_) return trace_block(rect, top, left, pairs).cost;
    if (area / 2 <= block_) return trace_tail(rect, top, left, pairs);
    return trace_split(rect, top, left, pairs);
  }

private:
  const D& d_;
  const Band& band_;
  std::size_t block_;
  const char* who_;

  // Row i over columns c0..c0 + width - 1: `cur[k]` becomes the cost of (i, c0 - 1 + k) for
  // k = 1..width, from `above` (the row above, k = 0..width) and `cur[0]` (the column before).
  // The same operations as Dtw_row::step, in the same order, so the same bits; cells outside the
  // band cost +inf and are not read. visit(k, up_wins, left_wins) is told each cell's choice.
  template <class Visit>
  void sweep_row(std::size_t i, std::size_t c0, std::size_t width, const double* above, double* cur,
                 std::vector<double>& row, const Visit& visit) const {
    const std::size_t lo = std::max(c0, band_.first(i)), hi = std::min(c0 + width - 1, band_.last(i));
    if (lo > hi) {
      std::fill(cur + 1, cur + width + 1, dtw_unreachable);
      return;
    }
    std::fill(cur + 1, cur + (lo - c0) + 1, dtw_unreachable);
    read_row(d_, i, lo, hi - lo + 1, row.data(), who_);
    double diagonal = above[lo - c0], left = cur[lo - c0];
    for (std::size_t k = lo - c0 + 1, end = hi - c0 + 1; k <= end; ++k) {
      const double up = above[k];
      const bool up_wins = up < diagonal;
      double best = std::min(diagonal, up);
      const bool left_wins = left < best;
      best = std::min(best, left);
      visit(k, up_wins, left_wins);
      diagonal = up;
      cur[k] = left = best + row[k - 1 - (lo - c0)];
    }
    std::fill(cur + (hi - c0) + 2, cur + width + 1, dtw_unreachable);
  }

  // The costs of row `last` of `rect` (columns c0 - 1..c1), from its edges, a row at a time.
  std::vector<double> costs_down_to(std::size_t last, const Dtw_rect& rect, std::span<const double> top,
                                    std::span<const double> left) const {
    const std::size_t width = rect.width();
    std::vector<double> above(top.begin(), top.end()), cur(width + 1), row(width);
    for (std::size_t i = rect.r0; i <= last; ++i) {
      cur[0] = left[i - rect.r0];
      sweep_row(i, rect.c0, width, above.data(), cur.data(), row, [](std::size_t, bool, bool) {});
      std::swap(above, cur);
    }
    return above;
  }

  // How a traceback left a rectangle: the cost of its end, and whether it stepped into the row
  // above inside the rectangle's columns, at `column` (rather than into the column before it).
  struct Exit {
    double cost;
    bool through_top;
    std::size_t column;
  };

  // A small rectangle: a byte per cell, then the traceback as dtw_traceback does it.
  Exit trace_block(const Dtw_rect& rect, std::span<const double> top, std::span<const double> left,
                   Pairs& pairs) const {
    const std::size_t width = rect.width();
    std::vector<std::uint8_t> choice(rect.height() * width);  // 0 diagonal, 1 up, 2 left
    std::vector<double> above(top.begin(), top.end()), cur(width + 1), row(width);
    for (std::size_t i = rect.r0; i <= rect.r1; ++i) {
      std::uint8_t* out = choice.data() + (i - rect.r0) * width;
      cur[0] = left[i - rect.r0];
      sweep_row(i, rect.c0, width, above.data(), cur.data(), row,
                [&](std::size_t k, bool up_wins, bool left_wins) { out[k - 1] = left_wins ? 2 : up_wins ? 1 : 0; });
      std::swap(above, cur);
    }
    std::size_t i = rect.r1, j = rect.c1;
    for (;;) {
      pairs.emplace_back(i, j);
      const std::uint8_t from = choice[(i - rect.r0) * width + (j - rect.c0)];
      if (from != 2 && i == rect.r0) {
        const bool inside = from == 1 || j > rect.c0;
        return {above[width], inside, inside ? j - (from == 0) : 0};
      }
      if (from != 1 && j == rect.c0) return {above[width], false, 0};
      if (from != 2) --i;
      if (from != 1) --j;
    }
  }

  // A rectangle of at most twice the block: the costs of the rows above its last
  // `block_ / width` ones, those traced back through a byte per cell, then the part of the path
  // above them (at most a block).
  double trace_tail(const Dtw_rect& rect, std::span<const double> top, std::span<const double> left,
                    Pairs& pairs) const {
    const std::size_t last_top = rect.r1 - block_ / rect.width();
    const std::vector<double> above = costs_down_to(last_top, rect, top, left);
    const std::size_t top_rows = last_top + 1 - rect.r0;
    const Exit exit = trace_block({last_top + 1, rect.r1, rect.c0, rect.c1}, above, left.subspan(top_rows), pairs);
    if (exit.through_top)
      trace({rect.r0, last_top, rect.c0, exit.column}, top.first(exit.column - rect.c0 + 2), left.first(top_rows),
            pairs);
    return exit.cost;
  }

  // Splits the rows in two halves and finds where the path crosses the last row of the top one.
  double trace_split(const Dtw_rect& rect, std::span<const double> top, std::span<const double> left,
                     Pairs& pairs) const {
    const std::size_t width = rect.width(), mid = rect.r0 + rect.height() / 2 - 1;
    std::vector<double> above = costs_down_to(mid, rect, top, left), cur(width + 1), row(width);
    const std::vector<double> middle = above;  // the costs of row mid, columns c0 - 1..c1
    // crossing[k]: where the traceback from (i, c0 - 1 + k) enters row mid, as k there; 0 when it
    // leaves the rectangle through its left side first (column c0 - 1 is not in the rectangle).
    std::vector<std::size_t> crossing(width + 1), next(width + 1);
    for (std::size_t k = 0; k <= width; ++k) crossing[k] = k;
    next[0] = 0;
    for (std::size_t i = mid + 1; i <= rect.r1; ++i) {
      cur[0] = left[i - rect.r0];
      sweep_row(i, rect.c0, width, above.data(), cur.data(), row, [&](std::size_t k, bool up_wins, bool left_wins) {
        next[k] = left_wins ? next[k - 1] : up_wins ? crossing[k] : crossing[k - 1];
      });
      std::swap(above, cur);
      std::swap(crossing, next);
    }
    const double cost = above[width];
    const std::size_t x = crossing[width];
    const std::span<const double> bottom_left = left.subspan(mid + 1 - rect.r0);
    if (x == 0) {  // the path does not reach row mid inside the rectangle
      trace({mid + 1, rect.r1, rect.c0, rect.c1}, middle, bottom_left, pairs);
      return cost;
    }
    const std::size_t column = rect.c0 - 1 + x;  // the path's last cell in row mid is (mid, column)
    const std::vector<double> before = column_before(mid, rect, column, middle, bottom_left);
    trace({mid + 1, rect.r1, column, rect.c1}, std::span(middle).subspan(x - 1), before, pairs);
    trace({rect.r0, mid, rect.c0, column}, top.first(x + 1), left.first(mid + 1 - rect.r0), pairs);
    return cost;
  }

  // The costs of column `column - 1` in rows mid + 1..r1, the left boundary of the bottom part.
  std::vector<double> column_before(std::size_t mid, const Dtw_rect& rect, std::size_t column,
                                    const std::vector<double>& middle, std::span<const double> left) const {
    if (column == rect.c0) return {left.begin(), left.end()};
    const std::size_t width = column - rect.c0;
    std::vector<double> above(middle.begin(), middle.begin() + std::ptrdiff_t(width) + 1), cur(width + 1), row(width),
        costs;
    costs.reserve(rect.r1 - mid);
    for (std::size_t i = mid + 1; i <= rect.r1; ++i) {
      cur[0] = left[i - mid - 1];
      sweep_row(i, rect.c0, width, above.data(), cur.data(), row, [](std::size_t, bool, bool) {});
      costs.push_back(cur[width]);
      std::swap(above, cur);
    }
    return costs;
  }
};

}  // namespace deformseg::alignment::internal
