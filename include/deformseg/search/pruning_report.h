/// @file search/pruning_report.h
/// @brief `Pruning_report`: what a search of a motion collection did with its candidates, how many each
/// lower bound ruled out and how many it aligned.
#pragma once

#include <cstddef>

namespace deformseg::search {

/// @brief What the search of one query (or, summed, of several) did with the collection's clips:
/// every candidate is counted once, in the first of these that decided it.
struct Pruning_report {
  std::size_t candidates = 0;         ///< the clips searched: the collection less the query itself
  std::size_t pruned_by_summary = 0;  ///< ruled out by the bound of their summaries (`lb_mean`)
  std::size_t pruned_by_rows = 0;     ///< ruled out by the bound of their rows (`lb_rows_columns`)
  std::size_t abandoned = 0;          ///< aligned in part: the alignment stopped once it could not win
  std::size_t aligned = 0;            ///< aligned whole: their value computed
  std::size_t rows_aligned = 0;       ///< rows the alignments of the abandoned ones went through
  std::size_t rows_abandoned = 0;     ///< rows of the abandoned ones, in all

  /// @brief The share of the candidates ruled out before a full alignment: 0 when there are none.
  double pruned_share() const { return candidates ? double(candidates - aligned) / double(candidates) : 0.0; }

  /// @brief Adds the counts of `other`.
  Pruning_report& operator+=(const Pruning_report& other) {
    candidates += other.candidates;
    pruned_by_summary += other.pruned_by_summary;
    pruned_by_rows += other.pruned_by_rows;
    abandoned += other.abandoned;
    aligned += other.aligned;
    rows_aligned += other.rows_aligned;
    rows_abandoned += other.rows_abandoned;
    return *this;
  }
  /// @brief Equal counts.
  bool operator==(const Pruning_report&) const = default;
};

}  // namespace deformseg::search
