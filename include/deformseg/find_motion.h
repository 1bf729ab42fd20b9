/// @file find_motion.h
/// @brief `find_motion`: the k best non-overlapping windows of a long animation that match a short
/// one (a query), with their frames, values and frame-to-frame alignments (beyond the thesis).
#pragma once

#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/motion_similarity.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace deformseg {

/// @brief A window of a long animation that matches a query, found by `find_motion`.
struct Motion_match {
  std::size_t first = 0;  ///< the window's first frame in the long animation
  std::size_t last = 0;   ///< its last frame (inclusive)
  /// @brief 1 minus the mean frame dissimilarity along the warping path, in [0, 1]: 1 where every
  /// query frame has an identical frame in the window.
  double value = 0;
  /// @brief The warping path: pairs (frame of the query, frame of the long animation), increasing.
  std::vector<std::pair<std::size_t, std::size_t>> alignment{};
};

/// @brief A similarity policy that gives its frame dissimilarities, as `find_motion` needs:
/// `p.frame_dissimilarities(a, b)` is the `Ta x Tb` matrix of values in [0, 1] between the frames of
/// two descriptions (`Motion_signature_similarity`, `Self_similarity_matching`).
template <class P>
concept FrameDissimilarityPolicy = requires(const P& p, const typename P::Description& d) {
  { p.frame_dissimilarities(d, d) } -> std::convertible_to<Eigen::MatrixXd>;
};

/// @brief The options of `find_motion`, an aggregate for designated initializers.
struct Find_motion_options {
  /// @brief How many windows at most. Default 1.
  std::size_t count = 1;
  /// @brief The shortest stretch of the long animation a window may be found in, as a fraction of
  /// the query's length: 0.5 (the default) lets a window play the query up to twice as fast.
  double shortest = 0.5;
};

/// @brief The best non-overlapping windows of `long_animation`'s description that match `query`'s:
/// the query is warped whole onto a contiguous window by subsequence DTW (`alignment::Subsequence_dtw`)
/// under the policy's frame dissimilarities, the best window is kept, and the search goes on in the
/// stretches of frames left on either side of the windows found, each stretch at least
/// `options.shortest` times the query's length.
/// @return at most `options.count` matches, best value first (ties: the earlier window first).
/// @throws invalid_input when a description has no frame or `options.shortest` is not in (0, 1].
/// @par Complexity O(k Tq Tl) for k windows, Tq and Tl frames, besides the frame dissimilarities'
/// own cost; O(Tq Tl) memory.
template <FrameDissimilarityPolicy Policy>
std::vector<Motion_match> find_motion_in(const Policy& policy, const typename Policy::Description& query,
                                         const typename Policy::Description& long_animation,
                                         const Find_motion_options& options = {}) {
  if (!(options.shortest > 0 && options.shortest <= 1))
    throw invalid_input("find_motion: shortest must be in (0, 1], not " + std::to_string(options.shortest));
  const Eigen::MatrixXd d = policy.frame_dissimilarities(query, long_animation);
  const std::size_t n = std::size_t(d.rows()), m = std::size_t(d.cols());
  if (n == 0 || m == 0) throw invalid_input("find_motion: an animation without frames");
  const std::size_t shortest = std::max<std::size_t>(1, std::size_t(std::ceil(options.shortest * double(n))));

  // The best match inside the stretch of frames [first, last].
  const auto best_in = [&](std::size_t first, std::size_t last) {
    const auto inside = [&](std::size_t i, std::size_t j) { return d(Eigen::Index(i), Eigen::Index(first + j)); };
    const alignment::Subsequence_dtw subsequence;
    alignment::Alignment a = subsequence.align(n, last - first + 1, inside);
    Motion_match match;
    match.value = Best_score_normalization{}(subsequence, a, n, last - first + 1);  // as motion_similarity's
    for (auto& [i, j] : a.pairs) j += first;
    match.first = a.pairs.front().second;
    match.last = a.pairs.back().second;
    match.alignment = std::move(a.pairs);
    return match;
  };

  std::vector<Motion_match> found;
  std::vector<std::pair<std::size_t, std::size_t>> stretches{{0, m - 1}};  // free frames, inclusive
  while (found.size() < options.count) {
    std::vector<Motion_match> candidates;
    for (auto [first, last] : stretches)
      if (last - first + 1 >= shortest) candidates.push_back(best_in(first, last));
    if (candidates.empty()) break;
    const auto best = std::min_element(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
      return x.value != y.value ? x.value > y.value : x.first < y.first;
    });
    // The stretch the window came from splits in two around it.
    std::vector<std::pair<std::size_t, std::size_t>> rest;
    for (auto [first, last] : stretches) {
      if (best->first < first || best->first > last) {
        rest.push_back({first, last});
        continue;
      }
      if (best->first > first) rest.push_back({first, best->first - 1});
      if (best->last < last) rest.push_back({best->last + 1, last});
    }
    stretches = std::move(rest);
    found.push_back(std::move(*best));
  }
  return found;
}

/// @brief The best non-overlapping windows of `long_animation` that match `query`, by `policy`
/// (default `Default_similarity`, the motion signatures): `find_motion_in` on their descriptions.
/// @tparam Mesh a `DeformingMesh` (both animations of one type; they need not share a mesh).
/// @tparam Policy a `SimilarityPolicy` that is a `FrameDissimilarityPolicy`.
/// @return at most `options.count` matches, best value first, with their frames and alignments.
/// @throws invalid_input as the policy's `describe` and `find_motion_in`.
/// @par Complexity two descriptions, then O(k Tq Tl).
template <DeformingMesh Mesh, class Policy = Default_similarity>
  requires SimilarityPolicy<Policy, Mesh> && FrameDissimilarityPolicy<Policy>
std::vector<Motion_match> find_motion(const Mesh& query, const Mesh& long_animation,
                                      const Find_motion_options& options = {}, const Policy& policy = {}) {
  return find_motion_in(policy, policy.describe(query), policy.describe(long_animation), options);
}

}  // namespace deformseg
