/// @file similarity/find_motion.h
/// @brief `find_motion`: the k best non-overlapping windows of a long animation that match a short
/// one (a query), with their frames, values and frame-to-frame alignments (beyond the thesis).
#pragma once

#include <deformseg/alignment/dtw.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/similarity/motion_similarity.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::similarity {

/// @brief A window of a long animation that matches a query, found by `find_motion`.
struct Motion_match {
  std::size_t first = 0;  ///< the window's first frame in the long animation
  std::size_t last = 0;   ///< its last frame (inclusive)
  /// @brief The similarity in [0, 1] of the query to the window: for `find_motion`, the policy's
  /// value of the query against the window's frames cut out as an animation of their own (1 for an
  /// exact, moved or scaled copy); for `find_motion_in`, 1 minus the mean dissimilarity along the
  /// warping path of the descriptions as given.
  double value = 0;
  /// @brief The warping path: pairs (frame of the query, frame of the long animation), increasing,
  /// from (0, `first`) to (the query's last frame, `last`).
  std::vector<std::pair<std::size_t, std::size_t>> alignment{};
};

/// @brief A similarity policy that gives its frame dissimilarities, as `find_motion` needs:
/// `p.frame_dissimilarities(a, b)` is the `Ta x Tb` matrix of values in [0, 1] between the frames (or
/// rows) of two descriptions (`Motion_signature_similarity`, `Self_similarity_matching`).
template <class P>
concept FrameDissimilarityPolicy = requires(const P& p, const typename P::Description& d) {
  { p.frame_dissimilarities(d, d) } -> std::convertible_to<Eigen::MatrixXd>;
};

/// @brief The options of `find_motion`, an aggregate for designated initializers.
struct Find_motion_options {
  /// @brief How many windows at most. Default 3 (as `Find_in_collection_options`).
  std::size_t count = 3;
  /// @brief The shortest window as a fraction of the query's duration, whose inverse bounds the
  /// longest: with 0.5 (the default) a window lasts from half to twice the query's duration (a
  /// motion played up to twice as fast or as slow); with 1, exactly as long. In (0, 1].
  double shortest = 0.5;
  /// @brief The threads that describe a step's windows: 0 (default) for all the hardware's threads
  /// (`thread_count`), else 1 to `max_threads`. The result does not depend on it.
  int threads = 0;
};

/// @brief Throws unless `options` are those of a search: `shortest` in (0, 1], `threads` 0 or 1 to
/// `max_threads`. What `find_motion`, `find_motion_in` and `search::find_motion_in_collection` check
/// first.
/// @throws invalid_input naming `find_motion` and the option.
/// @par Complexity O(1).
inline void check_find_motion_options(const Find_motion_options& options) {
  if (!(options.shortest > 0 && options.shortest <= 1))
    throw invalid_input("find_motion: shortest must be in (0, 1], not " + std::to_string(options.shortest));
  thread_count(options.threads, "find_motion");
}

namespace internal {

/// The frame of each row of a description: its `frames` where it has them (descriptions sampled
/// at instants other than the frames', as `Motion_signature_description`), else row r is frame r.
template <class Description>
std::size_t frame_of_row(const Description& d, std::size_t row) {
  if constexpr (requires { d.frames[row]; })
    return d.frames[row];
  else
    return row;
}

/// The window [first, last] brought to a length in [shortest, longest] inside [lowest, highest],
/// grown or shrunk about its middle, unchanged when its length is already in bounds (shortest <=
/// longest, shortest <= highest - lowest + 1, lowest <= first <= last <= highest).
inline std::pair<std::size_t, std::size_t> clamped_window(std::size_t first, std::size_t last, std::size_t shortest,
                                                          std::size_t longest, std::size_t lowest,
                                                          std::size_t highest) {
  const std::size_t old_length = last - first + 1;
  const std::size_t length = std::clamp(old_length, shortest, std::min(longest, highest - lowest + 1));
  std::size_t start = first + (old_length - std::min(length, old_length)) / 2;  // shrunk: half off each end
  if (length > old_length) {                                                    // grown: half on each end
    const std::size_t grow = (length - old_length) / 2;
    start = first > lowest + grow ? first - grow : lowest;
  }
  start = std::min(start, highest + 1 - length);
  return {start, start + length - 1};
}

/// Windows of columns [first, last] of `d` (query rows x long rows) onto which the whole query
/// warps best, best first, at most `count`, none overlapping another: per end column, the
/// least-cost path of steps (1, 1), (1, k) and (k, 1) for k up to `steepest` (so that a window
/// spans between 1 / steepest and steepest times the query's rows), each step's cells weighted so
/// that a path's weights sum to the query's rows plus the window's; a window's cost is its path's
/// weighted mean.
/// Complexity O(n w steepest^2) time and O(n w) memory for n query rows and w columns.
inline std::vector<std::pair<std::size_t, std::size_t>> warped_windows(const Eigen::MatrixXd& d, std::size_t first,
                                                                       std::size_t last, std::size_t steepest,
                                                                       std::size_t count) {
  const std::size_t n = std::size_t(d.rows()), w = last - first + 1;
  constexpr double none = std::numeric_limits<double>::infinity();
  // Row i, column j of the grid is query row i - 1 and column first + j - 1; row 0 is where paths start.
  std::vector<double> cost((n + 1) * (w + 1), none);
  std::vector<std::size_t> start((n + 1) * (w + 1), 0);
  const auto at = [w](std::size_t i, std::size_t j) { return i * (w + 1) + j; };
  const auto cell = [&](std::size_t i, std::size_t j) { return d(Eigen::Index(i - 1), Eigen::Index(first + j - 1)); };
  for (std::size_t j = 0; j <= w; ++j) cost[at(0, j)] = 0, start[at(0, j)] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= w; ++j) {
      double best = none;
      std::size_t from = 0;
      const auto step = [&](std::size_t rows, std::size_t columns, double cells) {
        if (rows > i || columns > j) return;
        const double c = cost[at(i - rows, j - columns)] + double(rows + columns) / double(rows * columns) * cells;
        if (c < best) best = c, from = start[at(i - rows, j - columns)];
      };
      step(1, 1, cell(i, j));
      double across = cell(i, j), down = cell(i, j);
      for (std::size_t k = 2; k <= steepest; ++k) {
        if (j >= k) across += cell(i, j - k + 1), step(1, k, across);
        if (i >= k) down += cell(i - k + 1, j), step(k, 1, down);
      }
      cost[at(i, j)] = best, start[at(i, j)] = from;
    }
  std::vector<std::pair<double, std::size_t>> ends;  // (mean cost, end column)
  for (std::size_t j = 1; j <= w; ++j)
    if (cost[at(n, j)] < none) ends.push_back({cost[at(n, j)] / double(n + j - start[at(n, j)]), j});
  std::sort(ends.begin(), ends.end());
  std::vector<std::pair<std::size_t, std::size_t>> windows;
  for (const auto& [mean, j] : ends) {
    const std::pair<std::size_t, std::size_t> window{first + start[at(n, j)], first + j - 1};
    const bool overlaps = std::any_of(windows.begin(), windows.end(), [&](const auto& other) {
      return !(window.second < other.first || other.second < window.first);
    });
    if (!overlaps) windows.push_back(window);
    if (windows.size() == count) break;
  }
  return windows;
}

/// The stretches left of `stretches` (inclusive intervals) once the window [first, last] is taken.
inline std::vector<std::pair<std::size_t, std::size_t>> without_window(
    const std::vector<std::pair<std::size_t, std::size_t>>& stretches, std::size_t first, std::size_t last) {
  std::vector<std::pair<std::size_t, std::size_t>> rest;
  for (auto [begin, end] : stretches) {
    if (last < begin || first > end) {
      rest.push_back({begin, end});
      continue;
    }
    if (first > begin) rest.push_back({begin, first - 1});
    if (last < end) rest.push_back({last + 1, end});
  }
  return rest;
}

/// The number of steps of the longest slope `warped_windows` needs for windows of `shortest` to
/// `longest` rows of a query of n rows.
inline std::size_t steepest_slope(std::size_t n, std::size_t shortest, std::size_t longest) {
  const double steepest = std::max(double(longest) / double(n), double(n) / double(shortest));
  return std::max<std::size_t>(1, std::size_t(std::ceil(steepest - 1e-9)));
}

/// The window lengths, in rows or frames, that `options.shortest` allows for a query of `length`
/// (already counted in the long animation's rows or frames): [ceil(shortest x length),
/// floor(length / shortest)], at least 1.
inline std::pair<std::size_t, std::size_t> window_lengths(double length, const Find_motion_options& options) {
  const auto shortest = std::size_t(std::ceil(options.shortest * length - 1e-9));
  const auto longest = std::size_t(std::floor(length / options.shortest + 1e-9));
  return {std::max<std::size_t>(1, shortest), std::max<std::size_t>(1, std::max(shortest, longest))};
}

/// How many candidate windows `find_motion_in` and `find_motion` take from each stretch of frames
/// for each window they report.
inline constexpr std::size_t find_motion_candidates = 6;
/// How many of them `find_motion` moves a frame at a time while their value rises (the best first).
inline constexpr std::size_t find_motion_refined = 2;

/// The windows of `find_motion_in` from the query's rows' dissimilarities to the long rows, `d`
/// (query rows x long rows), with each row's frame (`query_frame(row)`, `long_frame(row)`).
template <class QueryFrame, class LongFrame>
std::vector<Motion_match> find_windows_in(const Eigen::MatrixXd& d, const QueryFrame& query_frame,
                                          const LongFrame& long_frame, const Find_motion_options& options) {
  const std::size_t n = std::size_t(d.rows()), m = std::size_t(d.cols());
  if (n == 0 || m == 0) throw invalid_input("find_motion: an animation without frames");
  const auto [shortest, longest] = window_lengths(double(n), options);
  const std::size_t steepest = steepest_slope(n, shortest, longest);

  // The match of the whole query warped onto the rows [first, last].
  const auto match_of = [&](std::size_t first, std::size_t last) {
    const auto inside = [&](std::size_t i, std::size_t j) { return d(Eigen::Index(i), Eigen::Index(first + j)); };
    const alignment::Dtw dtw;
    const alignment::Alignment a = dtw.align(n, last - first + 1, inside);
    Motion_match match;
    match.value = Best_score_normalization{}(dtw, a, n, last - first + 1);
    for (const auto& [i, j] : a.pairs) {
      const std::pair<std::size_t, std::size_t> pair{query_frame(i), long_frame(first + j)};
      if (match.alignment.empty() || match.alignment.back() != pair) match.alignment.push_back(pair);
    }
    match.first = match.alignment.front().second, match.last = match.alignment.back().second;
    return std::pair{match, std::pair{first, last}};
  };

  std::vector<Motion_match> found;
  std::vector<std::pair<std::size_t, std::size_t>> stretches{{0, m - 1}};  // free rows, inclusive
  while (found.size() < options.count) {
    std::vector<std::pair<Motion_match, std::pair<std::size_t, std::size_t>>> candidates;
    for (auto [first, last] : stretches) {
      if (last - first + 1 < shortest) continue;
      for (auto [s, e] : warped_windows(d, first, last, steepest, find_motion_candidates)) {
        const auto [a, b] = clamped_window(s, e, shortest, longest, first, last);
        candidates.push_back(match_of(a, b));
      }
    }
    if (candidates.empty()) break;
    const auto best = std::min_element(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
      return x.first.value != y.first.value ? x.first.value > y.first.value : x.second.first < y.second.first;
    });
    stretches = without_window(stretches, best->second.first, best->second.second);
    found.push_back(std::move(best->first));
  }
  return found;
}

}  // namespace internal

/// @brief The windows `find_motion_in` finds, from the dissimilarities of the query's rows to the
/// long rows, wherever these come from (two descriptions, or a description and a stored clip, as
/// `search::find_motion_in_collection` searches each clip).
/// @param dissimilarities the `Tq x Tl` dissimilarities in [0, 1] of the query's rows to the long
/// rows (a policy's `frame_dissimilarities`).
/// @param query the query's description, whose rows' frames (`frames`, else the rows) the
/// alignments name.
/// @param long_frame `long_frame(row)`: the frame of a long row, increasing with the row.
/// @param options count (default 3), shortest (default 0.5); `threads` is only checked.
/// @return and @throws as `find_motion_in`.
/// @par Complexity as `find_motion_in`, without the dissimilarities' cost.
template <class Description, std::invocable<std::size_t> LongFrame>
std::vector<Motion_match> find_motion_windows(const Eigen::MatrixXd& dissimilarities, const Description& query,
                                              const LongFrame& long_frame, const Find_motion_options& options = {}) {
  check_find_motion_options(options);
  return internal::find_windows_in(
      dissimilarities, [&](std::size_t row) { return internal::frame_of_row(query, row); }, long_frame, options);
}

/// @brief The best non-overlapping windows of `long_animation`'s description that match `query`'s,
/// from the descriptions as given (what `find_motion` starts from; it then re-describes the windows).
///
/// The whole query is warped onto windows of the long description by a dynamic time warping with
/// open ends whose steps, (1, 1), (1, k) and (k, 1) for k up to the steepest slope the lengths
/// allow, keep a window between `options.shortest` and 1 / `options.shortest` times the query's
/// rows; the few best windows (at most 6, not overlapping) are brought to a length in those bounds
/// and warped on whole by DTW (`alignment::Dtw`), the best of them is kept (value 1 minus the mean
/// dissimilarity along its path), and the search goes on in the stretches left on either side of
/// the windows found.
///
/// What it guarantees: windows within the bounds, not overlapping, best value first, each value
/// that of its path under the policy's `frame_dissimilarities`. What it does not: a frame's
/// description may depend on its neighbours (motion signatures look up to 128/30 s away), so a copy
/// of the query inside the long animation is described there otherwise than the query alone, and
/// its value may be below 1 and another window's above it. `find_motion` re-describes each window
/// alone, and so finds copies exactly.
///
/// Rows are frames, except for descriptions that give each row's frame (`frames`, as
/// `Motion_signature_description` of an animation sampled below the signature rate): the windows
/// are then bounded in rows, and reported, with their alignments, in frames.
/// @return at most `options.count` matches, best value first (ties: the earlier window first).
/// @throws invalid_input when a description has no frame or `options.shortest` is not in (0, 1].
/// @par Complexity O(k Tq Tl s^2) for k windows, Tq and Tl rows and the steepest slope s =
/// ceil(1 / shortest), besides the frame dissimilarities' own cost; O(Tq Tl) memory.
/// @par Example
/// @include find_motion_in.cpp
template <FrameDissimilarityPolicy Policy>
std::vector<Motion_match> find_motion_in(const Policy& policy, const typename Policy::Description& query,
                                         const typename Policy::Description& long_animation,
                                         const Find_motion_options& options = {}) {
  return find_motion_windows(
      policy.frame_dissimilarities(query, long_animation), query,
      [&](std::size_t row) { return internal::frame_of_row(long_animation, row); }, options);
}

namespace internal {

/// The type of the frames of an animation cut out as one of their own (`find_motion`'s windows):
/// a `Deforming_mesh`'s own type, else a `Deforming_mesh` of its connectivity.
template <class Mesh>
struct Frames_type {
  using type = mesh::Deforming_mesh<typename Mesh::Face_graph>;
};
template <class Mesh>
  requires requires(const Mesh& m) { { m.frames(std::size_t(0), std::size_t(0)) } -> std::same_as<Mesh>; }
struct Frames_type<Mesh> {
  using type = Mesh;
};

/// The window search of `find_motion` on an animation whose frames can be cut out (`frames`).
template <class Policy, class Animation>
std::vector<Motion_match> find_cut_windows(const Policy& policy, const typename Policy::Description& query,
                                           std::size_t query_frames, double query_fps, const Animation& long_animation,
                                           const Find_motion_options& options) {
  const typename Policy::Description described = policy.describe(long_animation);
  const Eigen::MatrixXd d = policy.frame_dissimilarities(query, described);
  const std::size_t n = std::size_t(d.rows()), m = std::size_t(d.cols()), frames = long_animation.num_frames();
  if (n == 0 || m == 0) throw invalid_input("find_motion: an animation without frames");
  // Lengths in the long animation's frames: the query's duration at its frame rate.
  const double in_frames = double(query_frames - 1) * mesh::frames_per_second(long_animation) / query_fps + 1;
  // At least two frames: a single pose has no motion to describe.
  const auto lengths = window_lengths(in_frames, options);
  const std::size_t shortest = std::max<std::size_t>(lengths.first, std::min<std::size_t>(2, frames));
  const std::size_t longest = std::max(lengths.second, shortest);
  const double in_rows = frames > 1 ? (in_frames - 1) * double(m - 1) / double(frames - 1) + 1 : 1;
  const auto [shortest_rows, longest_rows] = window_lengths(in_rows, options);
  const std::size_t steepest = steepest_slope(n, shortest_rows, longest_rows);

  using Window = std::pair<std::size_t, std::size_t>;
  std::map<Window, Similarity> scored;
  // Scores the windows not scored yet, several at once (each then described on one thread: a loop
  // inside a loop runs on one), so that the threads share the windows rather than one window's rows.
  const auto score = [&](const std::vector<Window>& windows) {
    std::vector<Window> missing;
    for (const Window& w : windows)
      if (!scored.count(w) && std::find(missing.begin(), missing.end(), w) == missing.end()) missing.push_back(w);
    if (missing.empty()) return;
    std::vector<std::optional<Similarity>> values(missing.size());
    deformseg::internal::parallel_for(missing.size(), options.threads, [&](std::size_t i) {
      values[i] = policy.compare(query, policy.describe(long_animation.frames(missing[i].first, missing[i].second)));
    });
    for (std::size_t i = 0; i < missing.size(); ++i) scored.emplace(missing[i], std::move(*values[i]));
  };
  // Looked up in the sorts and climbs below: scored first when it is not yet.
  const auto value_of = [&](Window w) {
    auto found = scored.find(w);
    if (found == scored.end()) score({w}), found = scored.find(w);
    return found->second.value;
  };
  // From a window, the neighbour (an end or both moved by one frame, inside [lowest, highest] and
  // the lengths) of highest value, while one is higher.
  const auto refined = [&](std::pair<std::size_t, std::size_t> w, std::size_t lowest, std::size_t highest) {
    for (std::size_t moves = 0; moves < 2 * query_frames; ++moves) {
      std::vector<Window> neighbours{w};
      for (const auto& [df, dl] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, 1}}) {
        const std::ptrdiff_t f = std::ptrdiff_t(w.first) + df, l = std::ptrdiff_t(w.second) + dl;
        if (f < std::ptrdiff_t(lowest) || l > std::ptrdiff_t(highest) || f > l) continue;
        const Window next{std::size_t(f), std::size_t(l)};
        const std::size_t length = next.second - next.first + 1;
        if (length >= shortest && length <= longest) neighbours.push_back(next);
      }
      score(neighbours);
      Window best = w;
      for (const Window& next : neighbours)
        if (value_of(next) > value_of(best)) best = next;
      if (best == w) break;
      w = best;
    }
    return w;
  };

  std::vector<Motion_match> found;
  std::vector<std::pair<std::size_t, std::size_t>> stretches{{0, frames - 1}};  // free frames, inclusive
  while (found.size() < options.count) {
    // Candidates: each with the stretch it lies in.
    std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, std::size_t>>> candidates;
    for (auto [lowest, highest] : stretches) {
      if (highest - lowest + 1 < shortest) continue;
      // The stretch's rows: those whose frame lies in it.
      std::size_t first = 0;
      while (first < m && frame_of_row(described, first) < lowest) ++first;
      std::size_t last = first;
      while (last + 1 < m && frame_of_row(described, last + 1) <= highest) ++last;
      if (first >= m || frame_of_row(described, first) > highest) continue;
      for (auto [s, e] : warped_windows(d, first, last, steepest, find_motion_candidates)) {
        const auto w = clamped_window(frame_of_row(described, s), frame_of_row(described, e), shortest, longest,
                                      lowest, highest);
        candidates.push_back({w, {lowest, highest}});
      }
    }
    if (candidates.empty()) break;
    std::vector<Window> windows;
    for (const auto& candidate : candidates) windows.push_back(candidate.first);
    score(windows);
    const auto better = [&](const auto& x, const auto& y) {
      return value_of(x) != value_of(y) ? value_of(x) > value_of(y) : x.first < y.first;
    };
    // The most promising few, alone, are moved while their value rises.
    std::stable_sort(candidates.begin(), candidates.end(),
                     [&](const auto& x, const auto& y) { return better(x.first, y.first); });
    // Each from itself and from windows of the query's duration that start or end where it does.
    const std::size_t same = std::clamp<std::size_t>(std::size_t(std::lround(in_frames)), shortest, longest);
    for (std::size_t c = 0; c < std::min(candidates.size(), find_motion_refined); ++c) {
      const auto [w, stretch] = candidates[c];
      std::pair<std::size_t, std::size_t> best_seed = refined(w, stretch.first, stretch.second);
      for (const std::size_t end : {w.first + same - 1, w.second}) {
        if (end + 1 < same + stretch.first || end > stretch.second) continue;
        const auto seed = refined({end + 1 - same, end}, stretch.first, stretch.second);
        if (better(seed, best_seed)) best_seed = seed;
      }
      candidates[c].first = best_seed;
    }
    const auto best_candidate = std::min_element(
        candidates.begin(), candidates.end(), [&](const auto& x, const auto& y) { return better(x.first, y.first); });
    const auto* best = &best_candidate->first;
    const Similarity& s = scored.at(*best);
    Motion_match match{.first = best->first, .last = best->second, .value = s.value, .alignment = s.alignment};
    for (auto& pair : match.alignment) pair.second += best->first;
    stretches = without_window(stretches, best->first, best->second);
    found.push_back(std::move(match));
  }
  return found;
}

}  // namespace internal

/// @brief The best non-overlapping windows of `long_animation` that match `query`, by `policy`
/// (default `Default_similarity`, the motion signatures).
///
/// The value of a window is the policy's similarity of the query to the window's frames cut out
/// as an animation of their own (`policy.compare(describe(query), describe(frames))`), so that a
/// copy of the query, moved or scaled, inside the long animation scores exactly as the query
/// against itself (1), and a window is judged by its own frames only, not by what comes before or
/// after it. Windows last from `options.shortest` to 1 / `options.shortest` times the query's
/// duration (counted in the long animation's frames at the two frame rates, `frames_per_second`),
/// and at least two frames.
///
/// The search: the long animation is described whole once, and `find_motion_in`'s warping with
/// bounded slopes proposes the 6 best windows of each free stretch; each is re-described alone; the
/// two of highest value, and windows of the query's duration that start or end where they do, are
/// moved an end or both by one frame at a time while their value rises; the best window is kept,
/// and the search goes on in the stretches left on either side of the windows found. The
/// re-descriptions are kept, so that a later window reuses them; the windows of a step (the
/// candidates, a window's neighbours) are described at once, one per thread (`options.threads`);
/// the result does not depend on their number. A search, not an exhaustive scan:
/// where every window is alike (a steady wave), the window found may be another than the copy,
/// with a value nearly as high (@ref section_find_motion).
/// @tparam Mesh a `DeformingMesh` (both animations of one type; they need not share a mesh).
/// @tparam Policy a `SimilarityPolicy` that is a `FrameDissimilarityPolicy`.
/// @return at most `options.count` matches, best value first (ties: the earlier window first),
/// with their frames and alignments (the policy's, from the query's frames to the long
/// animation's).
/// @throws invalid_input as the policy's `describe` and `find_motion_in`.
/// @par Complexity the descriptions of both animations, `find_motion_in`'s O(k Tq Tl s^2) for k
/// windows, then per window 6 s' + 6 (r + 1) descriptions and compares of windows of at most Tq /
/// shortest frames, s' the free stretches and r the moves of the six hill climbs (a few each, at
/// most 2 Tq); O(Tq Tl) memory, plus a copy of the long animation when `Mesh` is not a
/// `Deforming_mesh`. What a search costs on the shared data: @ref section_find_motion.
template <mesh::DeformingMesh Mesh, class Policy = Default_similarity>
  requires SimilarityPolicy<Policy, Mesh> && FrameDissimilarityPolicy<Policy> &&
           SimilarityPolicy<Policy, typename internal::Frames_type<Mesh>::type>
std::vector<Motion_match> find_motion(const Mesh& query, const Mesh& long_animation,
                                      const Find_motion_options& options = {}, const Policy& policy = {}) {
  check_find_motion_options(options);
  if (query.num_frames() == 0 || long_animation.num_frames() == 0)
    throw invalid_input("find_motion: an animation without frames");
  const typename Policy::Description described = policy.describe(query);
  const double query_fps = mesh::frames_per_second(query);
  if constexpr (std::same_as<typename internal::Frames_type<Mesh>::type, Mesh>)
    return internal::find_cut_windows(policy, described, query.num_frames(), query_fps, long_animation, options);
  else
    return internal::find_cut_windows(policy, described, query.num_frames(), query_fps,
                                      mesh::make_deforming_mesh<double>(long_animation), options);
}

}  // namespace deformseg::similarity
