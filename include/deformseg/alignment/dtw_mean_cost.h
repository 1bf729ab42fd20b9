/// @file alignment/dtw_mean_cost.h
/// @brief What `Dtw::mean_cost` takes (`Dtw_mean_cost_options`) and returns (`Dtw_mean_cost`): the
/// cost and length of DTW's warping path without the path, with optional early abandoning.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace deformseg::alignment {

/// @brief When `Dtw::mean_cost` may stop early. By default it never does.
struct Dtw_mean_cost_options {
  /// @brief A threshold tau on the mean cost `score / length` (a dissimilarity, not a sum): the
  /// pass stops, `abandoned`, as soon as it has proved that the mean cost of the path `align`
  /// returns exceeds tau, and only then. Not NaN. Default: none, never abandon.
  std::optional<double> abandon_above{};
  /// @brief Empty (the default), or n values: `row_bounds[i]` a lower bound of `min_j d(i, j)`,
  /// finite and `>= 0`, that lets the pass abandon earlier (a bound of the rows still to come).
  /// Only that they are finite and `>= 0` is checked: a value above the row's least cell may make
  /// the pass abandon a path whose mean cost is at most tau. Referred to during the call only.
  std::span<const double> row_bounds{};
};

/// @brief The value of a DTW alignment without its path: `Dtw::mean_cost`'s result.
struct Dtw_mean_cost {
  /// @brief The cost of `Dtw::align`'s path, bit for bit its `score`; 0 when abandoned.
  double score = 0;
  /// @brief The number of cells of that path, `Dtw::align(...).pairs.size()`; 0 when abandoned.
  std::size_t length = 0;
  /// @brief Whether the pass stopped because the mean cost was proved above `abandon_above`.
  bool abandoned = false;
  /// @brief How many rows (elements of the first sequence) the pass finished: n unless it stopped
  /// early (it may also abandon after the last row, then `rows_done == n`).
  std::size_t rows_done = 0;

  /// @brief The mean cost `score / length` along the path: 0 when `length == 0` (empty sequences,
  /// or abandoned).
  double mean() const { return length == 0 ? 0.0 : score / double(length); }
};

}  // namespace deformseg::alignment
