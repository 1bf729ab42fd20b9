/// @file temporal/binary_split.h
/// @brief Temporal segmentation by recursive binary splitting: `Binary_split`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/temporal/segment_cost.h>
#include <deformseg/temporal/segments.h>

#include <cstddef>
#include <vector>

namespace deformseg::temporal {

/// @brief Temporal segmentation top-down: while a segment's `Ds` is above the threshold, split it
/// in two where the length-weighted cost `(k - h + 1) Ds(h, k) + (t - k) Ds(k + 1, t)` is least.
///
/// The method (@ref method_temporal) states the split on the plain sum `Ds(h, k) + Ds(k + 1, t)`;
/// weighting by length keeps it from favouring a cut that splits off a single frame (whose `Ds` is
/// 0), the degeneracy the method describes for the optimum. The split points do not depend on the threshold, which only
/// says where to stop, so lowering it never gives fewer segments.
/// @par Complexity O(T) queries per split, O(T^2) in all at worst.
struct Binary_split {
  /// @brief The largest `Ds` of a segment left whole. Default: 0.5 times the mean frame distance:
  /// a segment is split while its frames are, on average, more than half as far apart as any
  /// two frames of the animation.
  Segmentation_threshold threshold{};
  /// @brief The fewest frames of a segment (>= 1). Default: 1.
  std::size_t min_length = 1;

  /// @brief The segments of `cost`'s frames.
  /// @throws invalid_input when `min_length` is 0.
  std::vector<Frame_interval> operator()(const Segment_cost& cost) const {
    if (min_length == 0) throw invalid_input("Binary_split: min_length must be at least 1");
    const double limit = threshold.resolve(cost);
    std::vector<Frame_interval> segments;
    std::vector<Frame_interval> pending{{0, cost.num_frames() - 1}};
    while (!pending.empty()) {
      const auto [h, t] = pending.back();
      pending.pop_back();
      if (t - h + 1 < 2 * min_length || cost(h, t) <= limit) {
        segments.push_back({h, t});
        continue;
      }
      const std::size_t k = best_split(cost, h, t);
      pending.push_back({h, k});
      pending.push_back({k + 1, t});
    }
    return segments;
  }

private:
  // The k in [h + min_length - 1, t - min_length] of least weighted cost; the first of equals.
  std::size_t best_split(const Segment_cost& cost, std::size_t h, std::size_t t) const {
    std::size_t best = h + min_length - 1;
    double best_cost = cost.weighted(h, best) + cost.weighted(best + 1, t);
    for (std::size_t k = best + 1; k + min_length <= t; ++k) {
      const double c = cost.weighted(h, k) + cost.weighted(k + 1, t);
      if (c < best_cost) {
        best = k;
        best_cost = c;
      }
    }
    return best;
  }
};

}  // namespace deformseg::temporal
