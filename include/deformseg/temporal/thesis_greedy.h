/// @file temporal/thesis_greedy.h
/// @brief The reconstruction of the thesis' Algorithm 4-1: `Thesis_greedy`.
#pragma once

#include <deformseg/temporal/segment_cost.h>
#include <deformseg/temporal/segments.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace deformseg::temporal {

/// @brief Temporal segmentation by the thesis' Algorithm 4-1, as deformseg reconstructs it
/// (@ref method_temporal): in the frames [h, t], take the longest window [m, n] whose `Ds(m, n)` is at most the threshold
/// (of equally long ones, the smallest `Ds`, then the earliest), make it a segment, and segment
/// [h, m - 1] and [n + 1, t] the same way.
///
/// A segment of one frame (`Ds = 0`) always qualifies, so it always ends. Lowering the threshold
/// does not always give more segments: a window that qualifies no more may leave remainders that
/// split differently.
/// @par Complexity
/// O(T^2) queries of `Ds` in the worst case for each interval searched (every shorter window
/// tried after the longer ones fail); O(T) when long windows qualify.
struct Thesis_greedy {
  /// @brief The largest `Ds` of a segment. Default: 0.2 times the mean frame distance. A window
  /// mixing two poses at distance d in shares p and 1 - p has `Ds = 2 p (1 - p) d`: with d about
  /// the mean distance, 0.2 admits about 1 frame in 9 of another pose, and a looser threshold lets
  /// the longest window reach across a transition (@ref section_partition_choice).
  Segmentation_threshold threshold{.value = 0.2, .relative = true};

  /// @brief The segments of `cost`'s frames.
  std::vector<Frame_interval> operator()(const Segment_cost& cost) const {
    const double limit = threshold.resolve(cost);
    std::vector<Frame_interval> segments;
    std::vector<Frame_interval> pending{{0, cost.num_frames() - 1}};
    while (!pending.empty()) {
      const Frame_interval range = pending.back();
      pending.pop_back();
      const Frame_interval window = longest_window(cost, range, limit);
      segments.push_back(window);
      if (window.first > range.first) pending.push_back({range.first, window.first - 1});
      if (window.last < range.last) pending.push_back({window.last + 1, range.last});
    }
    return segments;
  }

private:
  static Frame_interval longest_window(const Segment_cost& cost, Frame_interval range, double limit) {
    for (std::size_t length = range.last - range.first + 1; length > 1; --length) {
      std::optional<Frame_interval> best;
      double best_cost = 0;
      for (std::size_t m = range.first; m + length - 1 <= range.last; ++m) {
        const double c = cost(m, m + length - 1);
        if (c <= limit && (!best || c < best_cost)) {
          best = Frame_interval{m, m + length - 1};
          best_cost = c;
        }
      }
      if (best) return *best;
    }
    return {range.first, range.first};
  }
};

}  // namespace deformseg::temporal
