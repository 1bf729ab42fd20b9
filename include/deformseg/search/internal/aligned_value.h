/// @file search/internal/aligned_value.h
/// The value of the default policy for two clips by the value pass of DTW, which a search abandons
/// once a clip cannot win, and the unit of the frame dissimilarity a search uses: what
/// `nearest_motions` and `similarity_tile` share.
#pragma once

#include <deformseg/alignment/dtw.h>
#include <deformseg/exceptions.h>
#include <deformseg/search/pruning_report.h>
#include <deformseg/signatures/motion_signature_kernel.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <span>
#include <string>

namespace deformseg::search::internal {

// The value of the default policy for clips a (rows of the alignment) and b, computed by the
// value pass that gives align's own score and path length; std::nullopt when the pass was
// abandoned, proven below `at_least`. Counts the rows of an abandoned pass in `report`.
inline std::optional<double> aligned_value(signatures::Motion_signature_view a, signatures::Motion_signature_view b,
                                           double unit, std::optional<double> at_least,
                                           std::span<const double> row_bounds, Pruning_report& report) {
  alignment::Dtw_mean_cost_options options;
  if (at_least) options.abandon_above = 1.0 - *at_least;
  options.row_bounds = row_bounds;
  const auto pass =
      alignment::Dtw{}.mean_cost(a.rows, b.rows, signatures::Motion_signature_dissimilarity{a, b, unit}, options);
  if (pass.abandoned) {
    ++report.abandoned;
    report.rows_aligned += pass.rows_done;
    report.rows_abandoned += a.rows;
    return std::nullopt;
  }
  ++report.aligned;
  return std::clamp(1.0 - pass.score / double(pass.length), 0.0, 1.0);
}

// The unit of the frame dissimilarity of `policy` for signatures of `width` values; refuses what
// the search's bounds do not cover.
inline double search_unit(const similarity::Motion_signature_similarity<>& policy, std::size_t width,
                          const char* who) {
  if (policy.alignment.window)
    throw invalid_input(std::string(who) + ": the search aligns without a window (its bounds assume none)");
  if (!(policy.scale > 0)) throw invalid_input(std::string(who) + ": the scale must be positive");
  return signatures::frame_dissimilarity_unit(width, policy.scale);
}

}  // namespace deformseg::search::internal
