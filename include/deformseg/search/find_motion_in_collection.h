/// @file search/find_motion_in_collection.h
/// @brief `find_motion_in_collection`: where a motion occurs in a library, the best non-overlapping
/// windows over all the clips of a `MotionCollection` that match a query, from the descriptions as
/// given (`find_motion_in` on each clip, merged).
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/search/motion_collection.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace deformseg::search {

/// @brief A window of one clip of a collection that matches a query, found by
/// `find_motion_in_collection`.
struct Clip_match {
  std::size_t clip = 0;  ///< the clip's index in the collection
  /// @brief The window in the clip's frames (its rows' frames, as the collection keeps them), its
  /// value and alignment, as `find_motion_in` gives them for the query and this clip.
  similarity::Motion_match match;
};

/// @brief The options of `find_motion_in_collection`, an aggregate for designated initializers.
struct Find_in_collection_options {
  /// @brief How many windows at most, over all the clips. Default 3.
  std::size_t count = 3;
  /// @brief The shortest window as a fraction of the query's rows, as `Find_motion_options::shortest`
  /// (default 0.5: from half to twice the query's rows). In (0, 1].
  double shortest = 0.5;
  /// @brief The threads (0: all the hardware's threads (`thread_count`)); the result does not depend on it.
  int threads = 0;
};

namespace internal {

/// The frame of clip i's row r: the collection's frames where it keeps them (`frames(i)`, a store's
/// `store().frames(i)`, an in-memory description's `frames`), else r.
template <MotionCollection C>
std::size_t clip_frame(const C& collection, std::size_t i, std::size_t row) {
  if constexpr (requires { collection.frames(i)[row]; })
    return std::size_t(collection.frames(i)[row]);
  else if constexpr (requires { collection.store().frames(i)[row]; })
    return std::size_t(collection.store().frames(i)[row]);
  else if constexpr (requires { collection.description(i).frames[row]; })
    return std::size_t(collection.description(i).frames[row]);
  else
    return row;
}

}  // namespace internal

/// @brief Where `query` occurs in `collection`: the best `options.count` non-overlapping windows
/// over all its clips, each found as `find_motion_in(policy, query, clip)` finds it, from the
/// descriptions as given.
///
/// Each clip is searched alone, exactly as `find_motion_in` searches a long animation: its best
/// `options.count` windows (at most), not overlapping one another, each window's value 1 minus the
/// mean dissimilarity along the warping path of the descriptions as given (the query's rows against
/// the clip's stored rows; a window is not re-described alone, as `find_motion` does, so a copy of
/// the query inside a longer clip may score below 1: see `find_motion_in`). Then the windows of all
/// the clips, taken clip by clip in index order and each clip's in `find_motion_in`'s order, are
/// stably sorted by value descending and cut at `options.count`: windows of different clips never
/// overlap. The same result as running `find_motion_in` on each clip and merging so, whatever the
/// number of threads (the clips are searched in parallel, each on one thread); no bound prunes a clip.
/// @param query the query's description, `policy.describe(animation)`, described as the clips were.
/// @param collection a `MotionCollection` described with `policy`'s options; a clip's frames are
/// those the collection keeps (a store's, a `Motion_collection`'s descriptions'), else its rows.
/// @param options count (default 3), shortest (default 0.5), threads (default 0).
/// @param policy the scale of the frame dissimilarities (default: the default policy's).
/// @return at most `options.count` windows, best value first (ties: the lower clip index, then the
/// clip's own order), each with its clip's index and its frames in that clip.
/// @throws invalid_input when the query has no row or another width than the collection's, when
/// `options.shortest` is not in (0, 1], when `options.threads` is out of range, or when the scale
/// is not positive.
/// @throws cancelled as `similarity_matrix`.
/// @par Complexity per clip of m rows, `find_motion_in`'s O(k n m s^2) for k = `options.count`, n
/// query rows and the steepest slope s = ceil(1 / shortest), plus O(n m W) for the dissimilarities;
/// O(n m) memory per thread, and O(N k) windows kept for N clips.
/// @par Example
/// @include find_motion_in_collection.cpp
template <MotionCollection C>
std::vector<Clip_match> find_motion_in_collection(const similarity::Motion_signature_description& query,
                                                  const C& collection, const Find_in_collection_options& options = {},
                                                  const similarity::Motion_signature_similarity<>& policy = {}) {
  const similarity::Find_motion_options per_clip{.count = options.count, .shortest = options.shortest};
  similarity::check_find_motion_options(per_clip);  // before any clip, so that an empty collection checks too
  const signatures::Motion_signature_view q = similarity::view(query);
  internal::check_query(collection, q, "find_motion_in_collection");
  if (!(policy.scale > 0)) throw invalid_input("find_motion_in_collection: the scale must be positive");
  std::vector<std::vector<similarity::Motion_match>> per(collection.size());
  deformseg::internal::parallel_for(collection.size(), options.threads, [&](std::size_t i) {
    per[i] = similarity::find_motion_windows(
        policy.frame_dissimilarities(q, collection.view(i)), query,
        [&](std::size_t row) { return internal::clip_frame(collection, i, row); }, per_clip);
  });
  std::vector<Clip_match> found;
  for (std::size_t i = 0; i < per.size(); ++i)
    for (similarity::Motion_match& m : per[i]) found.push_back({i, std::move(m)});
  std::stable_sort(found.begin(), found.end(),
                   [](const Clip_match& x, const Clip_match& y) { return x.match.value > y.match.value; });
  if (found.size() > options.count) found.resize(options.count);
  return found;
}

}  // namespace deformseg::search
