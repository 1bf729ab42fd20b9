/// @file temporal/optimal_partition.h
/// @brief The exact optimum of the length-weighted segmentation cost, by dynamic programming:
/// `Optimal_partition`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/temporal/segment_cost.h>
#include <deformseg/temporal/segments.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace deformseg::temporal {

/// @brief The partition of the frames into segments of at least `min_length` frames that
/// minimises `sum over segments (n - m + 1) Ds(m, n)`, plus a penalty per segment, or with
/// exactly `segments` segments; found exactly by dynamic programming.
///
/// Why the weight: `Ds` is an average, and a one-frame segment has `Ds = 0`, so the plain sum of
/// `Ds` is least when single frames are cut off (@ref method_temporal, @ref section_partition_choice).
/// Weighted by length, the cost is the sum over segments of their frames' mean distance to the
/// other frames of their segment: the kernel change-point cost.
///
/// With `segments` unset, the number of segments is free and each costs `penalty`: relative to
/// the cost of the whole animation as one segment, `T Ds(0, T - 1)`, about `T` times the mean
/// frame distance, so that 0.03 (the default) adds a segment only where it lowers that cost by at
/// least 3 %. A larger penalty never gives more segments; the default splits a gallop into its
/// phases, where a slightly larger one may leave a motion whose poses recur one segment
/// (@ref section_partition_choice).
/// @par Complexity
/// O(T^2) time for a penalty, O(K T^2) for K segments; O(T) memory (O(K T) for K segments).
struct Optimal_partition {
  /// @brief The cost of each segment: relative (default) to `T Ds(0, T - 1)`, or absolute.
  /// Default: 0.03, relative.
  Segmentation_threshold penalty{.value = 0.03, .relative = true};
  /// @brief The number of segments, when given; then `penalty` is not used. Default: none.
  std::optional<std::size_t> segments{};
  /// @brief The fewest frames of a segment (>= 1). Default: 1.
  std::size_t min_length = 1;

  /// @brief The optimal segments of `cost`'s frames.
  /// @throws invalid_input when `min_length` is 0, `segments` is 0, or the frames cannot be cut
  /// into `segments` segments of `min_length` frames.
  std::vector<Frame_interval> operator()(const Segment_cost& cost) const {
    const std::size_t frames = cost.num_frames();
    if (min_length == 0) throw invalid_input("Optimal_partition: min_length must be at least 1");
    if (segments && (*segments == 0 || *segments * min_length > frames))
      throw invalid_input("Optimal_partition: " + std::to_string(frames) + " frames cannot make " +
                          std::to_string(*segments) + " segments of at least " + std::to_string(min_length) +
                          " frames");
    if (segments) return with_count(cost, *segments);
    const double scale = double(frames) * cost(0, frames - 1);
    return with_penalty(cost, penalty.relative ? penalty.value * scale : penalty.value);
  }

private:
  static constexpr double infinity = std::numeric_limits<double>::infinity();

  // best[n]: the least cost of frames [0, n); start[n]: where its last segment starts.
  std::vector<Frame_interval> with_penalty(const Segment_cost& cost, double per_segment) const {
    const std::size_t frames = cost.num_frames();
    std::vector<double> best(frames + 1, infinity);
    std::vector<std::size_t> start(frames + 1, 0);
    best[0] = 0;
    for (std::size_t n = min_length; n <= frames; ++n)
      for (std::size_t m = 0; m + min_length <= n; ++m) {
        const double c = best[m] + cost.weighted(m, n - 1) + per_segment;
        if (c < best[n]) {
          best[n] = c;
          start[n] = m;
        }
      }
    return trace_back(start, frames);
  }

  // Row k of `best`: the least cost of frames [0, n) in k + 1 segments, computed row by row.
  std::vector<Frame_interval> with_count(const Segment_cost& cost, std::size_t count) const {
    const std::size_t frames = cost.num_frames();
    std::vector<double> previous(frames + 1, infinity), current(frames + 1, infinity);
    std::vector<std::vector<std::size_t>> start(count, std::vector<std::size_t>(frames + 1, 0));
    for (std::size_t n = min_length; n <= frames; ++n) previous[n] = cost.weighted(0, n - 1);
    for (std::size_t k = 1; k < count; ++k) {
      std::fill(current.begin(), current.end(), infinity);
      for (std::size_t n = (k + 1) * min_length; n <= frames; ++n)
        for (std::size_t m = k * min_length; m + min_length <= n; ++m) {
          const double c = previous[m] + cost.weighted(m, n - 1);
          if (c < current[n]) {
            current[n] = c;
            start[k][n] = m;
          }
        }
      std::swap(previous, current);
    }
    std::vector<Frame_interval> out;
    for (std::size_t k = count, n = frames; k > 0; --k) {
      const std::size_t m = start[k - 1][n];
      out.push_back({m, n - 1});
      n = m;
    }
    return out;
  }

  static std::vector<Frame_interval> trace_back(const std::vector<std::size_t>& start, std::size_t frames) {
    std::vector<Frame_interval> out;
    for (std::size_t n = frames; n > 0; n = start[n]) out.push_back({start[n], n - 1});
    return out;
  }
};

}  // namespace deformseg::temporal
