/// @file temporal/temporal_segmentation.h
/// @brief Temporal segmentation of a deforming mesh into intervals of similar poses
/// (@ref method_temporal): `segment_frames` over a frame distance matrix, `temporal_segmentation` from an
/// animation or a strain field, and the result `Temporal_segmentation`.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/strain/frame_distances.h>
#include <deformseg/temporal/segment_cost.h>
#include <deformseg/strain/strain.h>
#include <deformseg/temporal/barbic_pca.h>
#include <deformseg/temporal/binary_split.h>
#include <deformseg/temporal/optimal_partition.h>
#include <deformseg/temporal/segments.h>
#include <deformseg/temporal/thesis_greedy.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace deformseg::temporal {

/// @brief One temporal segment and its cost.
struct Temporal_segment {
  std::size_t first = 0;  ///< its first frame
  std::size_t last = 0;   ///< its last frame
  /// @brief Its within-segment dissimilarity `Ds(first, last)`, the mean distance between its
  /// frames (0 for one frame).
  double cost = 0;
};

/// @brief A temporal segmentation: segments that cover the frames 0 to T - 1 in order, without
/// gap or overlap.
struct Temporal_segmentation {
  /// @brief The number of frames T.
  std::size_t frames = 0;
  /// @brief The segments, in frame order: `segments[0].first == 0`, each next one starts after
  /// the last frame of the one before, the last one ends at `frames - 1`.
  std::vector<Temporal_segment> segments;

  /// @brief The segment of frame `t`.
  /// @throws invalid_input when `t >= frames`.
  /// @par Complexity O(log K).
  std::size_t segment_of(std::size_t t) const {
    if (t >= frames)
      throw invalid_input("frame " + std::to_string(t) + " asked of a segmentation of " + std::to_string(frames) +
                          " frames");
    const auto it = std::upper_bound(segments.begin(), segments.end(), t,
                                     [](std::size_t frame, const Temporal_segment& s) { return frame < s.first; });
    return std::size_t(it - segments.begin()) - 1;
  }
};

/// @brief Segments the frames whose dissimilarities `cost` holds with `policy`.
/// @tparam Policy a `TemporalSegmentationPolicy`; default `Optimal_partition`.
/// @param cost the within-segment dissimilarities of a frame distance matrix.
/// @param policy the policy and its parameters.
/// @return the segments in frame order, each with its `Ds`.
/// @throws invalid_input when the policy's parameters are invalid, or its intervals do not cover
/// the frames exactly once (a policy of one's own that is wrong).
/// @par Complexity that of the policy, plus O(K log K) for K segments.
template <TemporalSegmentationPolicy Policy = Optimal_partition>
Temporal_segmentation segment_frames(const Segment_cost& cost, const Policy& policy = {}) {
  std::vector<Frame_interval> intervals = policy(cost);
  std::sort(intervals.begin(), intervals.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  Temporal_segmentation result{cost.num_frames(), {}};
  std::size_t next = 0;
  for (const auto& [first, last] : intervals) {
    if (first != next || last < first || last >= cost.num_frames())
      throw invalid_input("segment_frames: the policy gave the interval [" + std::to_string(first) + ", " +
                          std::to_string(last) + "] where frame " + std::to_string(next) + " was to start one, of " +
                          std::to_string(cost.num_frames()) + " frames");
    result.segments.push_back({first, last, cost(first, last)});
    next = last + 1;
  }
  if (next != cost.num_frames())
    throw invalid_input("segment_frames: the policy's intervals end at frame " + std::to_string(next) + " of " +
                        std::to_string(cost.num_frames()));
  return result;
}

/// @brief Segments the frames of a strain field: its frame distances (`frame_distances`), their
/// `Segment_cost`, then `policy`.
/// @param field the strain field; the method's frame descriptor is the normalised rest-pose strain
/// (`compute_strain`'s default).
/// @param policy the policy; default `Optimal_partition`.
/// @param distances the metric and threads of the frame distances.
/// @throws invalid_input as `frame_distances` and `segment_frames`.
/// @par Complexity O(T^2 F) for the distances, then the policy's.
template <std::floating_point Value, TemporalSegmentationPolicy Policy = Optimal_partition>
Temporal_segmentation temporal_segmentation(const strain::Strain_field<Value>& field, const Policy& policy = {},
                                            const strain::Frame_distance_options& distances = {}) {
  return segment_frames(Segment_cost(frame_distances(field, distances)), policy);
}

/// @brief Segments the frames of an animation: its normalised rest-pose strain (`compute_strain`
/// with its defaults, frame 0 the rest pose), then as the overload for a strain field.
/// @tparam Mesh a `DeformingMesh`.
/// @param animation the animation.
/// @param policy the policy; default `Optimal_partition`.
/// @param distances the metric and threads of the frame distances.
/// @throws invalid_input as `compute_strain`, `frame_distances` and `segment_frames`.
/// @par Complexity O(T F) for the strain, O(T^2 F) for the distances, then the policy's.
template <mesh::DeformingMesh Mesh, TemporalSegmentationPolicy Policy = Optimal_partition>
Temporal_segmentation temporal_segmentation(const Mesh& animation, const Policy& policy = {},
                                            const strain::Frame_distance_options& distances = {}) {
  return temporal_segmentation(strain::compute_strain(animation, {.threads = distances.threads}), policy, distances);
}

}  // namespace deformseg::temporal

#if DEFORMSEG_COMPILED
// deformseg::compiled holds these instantiations (src/compiled/temporal.cpp): a program that links
// it compiles against their declarations. Any other type or policy instantiates where it is used.
#include <deformseg/mesh/default_mesh.h>

namespace deformseg::temporal {
extern template Temporal_segmentation segment_frames<Optimal_partition>(const Segment_cost&, const Optimal_partition&);
extern template Temporal_segmentation temporal_segmentation<float, Optimal_partition>(
    const strain::Strain_field<float>&, const Optimal_partition&, const strain::Frame_distance_options&);
extern template Temporal_segmentation temporal_segmentation<mesh::Surface_mesh_animation, Optimal_partition>(
    const mesh::Surface_mesh_animation&, const Optimal_partition&, const strain::Frame_distance_options&);
}  // namespace deformseg::temporal
#endif
