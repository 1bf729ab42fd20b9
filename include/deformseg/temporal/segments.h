/// @file temporal/segments.h
/// @brief What temporal segmentation policies share: frame intervals, the threshold that sets
/// their granularity, and the `TemporalSegmentationPolicy` concept.
#pragma once

#include <deformseg/temporal/segment_cost.h>

#include <concepts>
#include <cstddef>
#include <vector>

namespace deformseg::temporal {

/// @brief The frames [first, last] of one temporal segment, both included.
struct Frame_interval {
  std::size_t first = 0;  ///< the first frame
  std::size_t last = 0;   ///< the last frame, `>= first`
  /// @brief Equal when both ends are.
  friend bool operator==(const Frame_interval&, const Frame_interval&) = default;
};

/// @brief A threshold on the within-segment dissimilarity `Ds`, given absolutely or relative to
/// the mean distance between two frames (`Segment_cost::mean_distance`), so that one value
/// serves animations whose strains differ in scale.
struct Segmentation_threshold {
  /// @brief The threshold, or its ratio to the mean frame distance.
  double value = 0.5;
  /// @brief Whether `value` is relative to the mean frame distance (default) or absolute.
  bool relative = true;

  /// @brief The absolute threshold for `cost`: `value`, times `cost.mean_distance()` when
  /// relative.
  double resolve(const Segment_cost& cost) const { return relative ? value * cost.mean_distance() : value; }
};

/// @brief A temporal segmentation policy: a copyable function object that partitions the frames
/// of a `Segment_cost` into intervals.
///
/// `policy(cost)` returns intervals that cover `[0, cost.num_frames() - 1]` without gap or
/// overlap, in any order (`segment_frames` sorts and checks them). The policy holds its own
/// parameters (threshold, number of segments, ...). Has models: `Optimal_partition` (the
/// default), `Binary_split`, `Thesis_greedy`, `Barbic_pca`.
/// @code
/// // Segments of a fixed length, a policy of one's own.
/// struct Fixed_length {
///   std::size_t length = 10;
///   std::vector<deformseg::temporal::Frame_interval> operator()(const deformseg::temporal::Segment_cost& cost) const {
///     std::vector<deformseg::temporal::Frame_interval> out;
///     for (std::size_t m = 0; m < cost.num_frames(); m += length)
///       out.push_back({m, std::min(m + length, cost.num_frames()) - 1});
///     return out;
///   }
/// };
/// @endcode
template <class P>
concept TemporalSegmentationPolicy = std::copy_constructible<P> && requires(const P& policy, const Segment_cost& cost) {
  { policy(cost) } -> std::same_as<std::vector<Frame_interval>>;
};

}  // namespace deformseg::temporal
