/// @file signatures/motion_signature_stream.h
/// @brief `motion_signatures_streamed`: the motion signatures of an animation read frame by frame
/// from a `FrameSource`, in memory that grows with the signature's longest lag, not with the
/// animation's length, and equal to the last bit to `motion_signatures_at` on the whole animation.
///
/// A signature at an instant reads the frames within the longest lag (128/30 s by default) before
/// and after it. The stream is read twice: first for the first frame's area weights and the RMS
/// radius over every frame (the unit of the rates, added in the order `motion_signatures_at` adds
/// it); then through a ring of the frames that the next rows read, each row computed, in parallel
/// with its neighbours, as soon as its last frame is in. A clip no longer than the ring (most game
/// clips: 273 frames at 30 fps with the default lags) is read once, into the ring.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/signatures/procrustes_distances.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::signatures {

/// @brief An animation read one frame at a time, from its first frame, any number of times: what
/// `motion_signatures_streamed` reads.
///
/// A model has a `Coordinate` type (the precision frames are read in: `float` for point caches);
/// `num_vertices()` (V, at least 1), `num_frames()` (T) and `frames_per_second()`, known before
/// any frame is read; `triangles()`, the connectivity as vertex index triples in `[0, V)`;
/// `read_frame(out)`, which reads the next frame's `3V` coordinates (x y z per vertex) into `out`
/// and throws `invalid_input` naming the file and the frame when it cannot; and `rewind()`, after
/// which the next frame read is frame 0 again, and the counts are those of the data as it is now
/// (a file rewritten since is read anew).
template <class Source>
concept FrameSource = requires(Source& source, const Source& read_only, std::span<typename Source::Coordinate> out) {
  requires std::floating_point<typename Source::Coordinate>;
  { read_only.num_vertices() } -> std::convertible_to<std::size_t>;
  { read_only.num_frames() } -> std::convertible_to<std::size_t>;
  { read_only.frames_per_second() } -> std::convertible_to<double>;
  { read_only.triangles() } -> std::convertible_to<std::span<const std::array<std::uint32_t, 3>>>;
  source.read_frame(out);
  source.rewind();
};

/// @brief A `FrameSource` over positions already in memory (`T x 3V` coordinates, not copied): for
/// tests, and for data held elsewhere one frame after another.
/// @tparam T the coordinate type.
template <std::floating_point T>
class Positions_frame_source {
public:
  /// @brief The coordinate type frames are read in.
  using Coordinate = T;

  /// @brief A source over `positions`, which must outlive it, with `triangles` (copied) over its
  /// `vertices` vertices, sampled at `frames_per_second`.
  /// @throws invalid_input when `vertices` is 0 or `positions` is not a multiple of `3 vertices`.
  /// @par Complexity O(F) for F triangles.
  Positions_frame_source(std::span<const T> positions, std::size_t vertices,
                         std::span<const std::array<std::uint32_t, 3>> triangles, double frames_per_second)
      : positions_(positions), vertices_(vertices), triangles_(triangles.begin(), triangles.end()),
        frames_per_second_(frames_per_second) {
    if (vertices == 0 || positions.size() % (3 * vertices) != 0)
      throw invalid_input("Positions_frame_source: positions are not T x 3V for V = " + std::to_string(vertices));
  }

  /// @brief V.
  std::size_t num_vertices() const noexcept { return vertices_; }
  /// @brief T.
  std::size_t num_frames() const noexcept { return positions_.size() / (3 * vertices_); }
  /// @brief The frame rate given.
  double frames_per_second() const noexcept { return frames_per_second_; }
  /// @brief The triangles given.
  std::span<const std::array<std::uint32_t, 3>> triangles() const noexcept { return triangles_; }
  /// @brief Copies the next frame into `out` (`3V` values).
  /// @throws invalid_input past the last frame, or when `out` is not `3V` values.
  void read_frame(std::span<T> out) {
    if (next_ >= num_frames() || out.size() != 3 * vertices_)
      throw invalid_input("Positions_frame_source: no frame " + std::to_string(next_) + " of " +
                          std::to_string(out.size()) + " coordinates", {.frame = next_});
    std::copy_n(positions_.begin() + std::ptrdiff_t(3 * vertices_ * next_), 3 * vertices_, out.begin());
    ++next_;
  }
  /// @brief The next frame read is frame 0.
  void rewind() noexcept { next_ = 0; }

private:
  std::span<const T> positions_;
  std::size_t vertices_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  double frames_per_second_;
  std::size_t next_ = 0;
};

/// @brief The frames `motion_signatures_streamed` reads ahead of the rows it can compute, beyond
/// those one row needs: rows whose frames are all in are computed together, in parallel.
inline constexpr std::size_t streamed_batch_frames = 16;

namespace internal {

/// Per row, the first and last frames it reads; throws unless the instants are finite and in
/// increasing order (equal neighbours allowed).
inline std::vector<std::pair<std::size_t, std::size_t>> frames_of_rows(const Signature_rows& rows,
                                                                       std::span<const double> instants) {
  std::vector<std::pair<std::size_t, std::size_t>> spans(instants.size());
  for (std::size_t r = 0; r < instants.size(); ++r) {
    if (!std::isfinite(instants[r]) || (r > 0 && instants[r] < instants[r - 1]))
      throw invalid_input("motion_signatures_streamed: instant " + std::to_string(r) + " (" +
                          std::to_string(instants[r]) + " s) is not finite or comes before the one before it");
    spans[r] = frames_of_row(rows, instants[r]);
  }
  return spans;
}

/// The frames the ring holds: the most that one row reads, plus a batch, at most the animation.
inline std::size_t ring_frames(std::span<const std::pair<std::size_t, std::size_t>> spans, std::size_t frames) {
  std::size_t widest = 1;
  for (const auto& [first, last] : spans) widest = std::max(widest, last - first + 1);
  return std::min(frames, widest + streamed_batch_frames);
}

/// What the first pass reads: the first frame, its area weights, and the RMS radius over every frame.
struct First_pass {
  std::vector<double> first, weights;
  double radius;
};

/// The first pass, each frame read into `frame_of(t)` (`3V` coordinates: the same place for every
/// frame, or a place each).
template <FrameSource Source, class FrameOf>
First_pass weights_and_radius(Source& source, std::size_t frames, const FrameOf& frame_of) {
  const std::size_t vertices = source.num_vertices();
  const auto read = [&](std::size_t t) {
    source.read_frame(std::span<typename Source::Coordinate>(frame_of(t), 3 * vertices));
    return frame_of(t);
  };
  const auto* frame = read(0);
  std::vector<double> first(frame, frame + 3 * vertices);
  std::vector<double> weights = vertex_area_weights(std::span<const double>(first), source.triangles(), vertices);
  double sum = 0;
  for (std::size_t t = 0;; ++t) {
    add_frame_spread(frame, std::span<const double>(weights), sum);
    if (t + 1 == frames) break;
    frame = read(t + 1);
  }
  return {std::move(first), std::move(weights), std::sqrt(sum / double(frames))};
}

/// Throws unless the source still has `frames` frames of `vertices` vertices after its rewind.
template <FrameSource Source>
void check_unchanged(const Source& source, std::size_t frames, std::size_t vertices) {
  if (source.num_frames() != frames || source.num_vertices() != vertices)
    throw invalid_input("motion_signatures_streamed: the animation changed between its two readings: " +
                        std::to_string(frames) + " frames of " + std::to_string(vertices) + " vertices, then " +
                        std::to_string(source.num_frames()) + " of " + std::to_string(source.num_vertices()));
}

}  // namespace internal

/// @brief The number of frames `motion_signatures_streamed` holds at once for an animation of
/// `frames` frames at `frames_per_second` described at `instants`: the most frames one row reads
/// (2 x the longest lag x the frame rate, plus 1 or 2), plus `streamed_batch_frames`, at most
/// `frames`. Times `3V` coordinates, this is the ring's memory: 273 frames at 30 fps with the
/// default lags, 115 MB for 35,000 vertices read as `float` (230 MB as `double`).
/// @pre the instants are finite and non-decreasing; the options and frame rate are valid (as for
/// `motion_signatures`); `frames` at least 2.
/// @throws invalid_input when a precondition fails.
/// @par Complexity O(I L) for I instants and L lags.
inline std::size_t streamed_ring_frames(const Motion_signature_options& options, double frames_per_second,
                                        std::size_t frames, std::span<const double> instants) {
  internal::check_frame_count(frames);
  internal::check_signature_options(options, frames_per_second);
  const internal::Signature_rows rows = internal::signature_rows(options, frames_per_second, frames, 1.0);
  return internal::ring_frames(internal::frames_of_rows(rows, instants), frames);
}

/// @brief `motion_signatures_at` of an animation read frame by frame from `source`, at
/// `instants` (seconds from the first frame), holding only the frames the next rows read.
///
/// Weights are each vertex's share of the first frame's area (`vertex_area_weights` of
/// `source.triangles()`), as `with_positions_and_weights` gives them to the in-memory path. The
/// result equals, bit for bit, `motion_signatures_at` of the same frames (in either precision of
/// which `Source::Coordinate` is exact) with those weights, at the same frame rate and instants,
/// whatever the number of threads: each row is computed by the same code from the same values.
/// The source is read twice from its start (`rewind` before each pass): first for the weights and
/// the RMS radius over every frame, then through a ring of `streamed_ring_frames` frames; once
/// (one `rewind`, before it) when that ring holds every frame, which the first pass then fills.
/// @tparam Source a `FrameSource`.
/// @param source the animation; its frame rate is `source.frames_per_second()`.
/// @param options the lags, quantiles, floor and up direction (as `motion_signatures`).
/// @param instants the instants of the rows, finite and non-decreasing, e.g. `frame_instants`
/// (one per frame) or those `Motion_signature_similarity` describes at; an instant outside
/// [0, (T - 1) / fps] reads the nearest end frame.
/// @return the `I x (lags x regions x quantiles)` signatures, twice as wide with an up direction.
/// @throws invalid_input as `motion_signatures` (fewer than two frames, bad options or frame rate,
/// an animation without extent); for instants out of order or not finite; when the source has no
/// vertex, or a different frame or vertex count after its second rewind (a file rewritten between
/// the passes); and as `source.read_frame` (naming the file and the frame).
/// @par Complexity O(I V L log k) expected, as `motion_signatures_at`, plus reading the source
/// twice (once when the ring holds every frame); memory O(V (2 max_lag fps +
/// `streamed_batch_frames`)) coordinates for the ring, O(I) for the rows' frame spans, plus the
/// result. Rows are computed in parallel, a batch at a time, on `options.threads` threads.
/// @par Example
/// @include motion_signature_stream.cpp
template <FrameSource Source>
Eigen::MatrixXd motion_signatures_streamed(Source& source, const Motion_signature_options& options,
                                           std::span<const double> instants) {
  using Coordinate = typename Source::Coordinate;
  const std::size_t vertices = source.num_vertices(), frames = source.num_frames();
  const double fps = source.frames_per_second();
  if (vertices == 0) throw invalid_input("motion_signatures_streamed: an animation without vertices");
  internal::check_frame_count(frames);
  internal::check_signature_options(options, fps);

  // The rows' frames do not depend on the radius: the ring's size is known before the first pass.
  const auto spans = internal::frames_of_rows(internal::signature_rows(options, fps, frames, 1.0), instants);
  const std::size_t capacity = internal::ring_frames(spans, frames), block = 3 * vertices;
  std::vector<Coordinate> ring(capacity * block);
  const auto frame_of = [&](std::size_t t) { return ring.data() + block * (t % capacity); };
  // A ring that holds every frame is filled by the first pass, and the source read once.
  const bool once = capacity == frames;
  source.rewind();
  const internal::First_pass first_pass =
      internal::weights_and_radius(source, frames, [&](std::size_t t) { return frame_of(once ? t : 0); });
  const std::span<const double> weights(first_pass.weights);
  internal::check_radius(first_pass.radius);
  internal::Signature_rows rows = internal::signature_rows(options, fps, frames, first_pass.radius);
  if (internal::region_count(options) > 1)
    rows.regions = internal::surface_regions(first_pass.first.data(), weights, options, rows.up);
  if (!once) {
    source.rewind();
    internal::check_unchanged(source, frames, vertices);
  }

  using Row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Row_major out(static_cast<Eigen::Index>(instants.size()), static_cast<Eigen::Index>(rows.columns));
  std::size_t loaded = once ? frames : 0;  // frames read into the ring so far
  for (std::size_t next_row = 0; next_row < instants.size();) {
    // Frame `loaded` replaces frame `loaded - capacity`, which no row from `next_row` on reads.
    while (loaded < frames && loaded < spans[next_row].first + capacity)
      source.read_frame(std::span<Coordinate>(frame_of(loaded++), block));
    std::size_t end = next_row;
    while (end < instants.size() && spans[end].second < loaded) ++end;
    if (end == next_row)  // the ring holds every row's frames (ring_frames): this would loop for ever
      throw std::logic_error("motion_signatures_streamed: row " + std::to_string(next_row) + " reads frames " +
                             std::to_string(spans[next_row].first) + " to " + std::to_string(spans[next_row].second) +
                             ", more than the ring's " + std::to_string(capacity));
    deformseg::internal::parallel_for_with_locals(
        end - next_row, options.threads, 1, [&] { return internal::Row_scratch(vertices); },
        [&](internal::Row_scratch& scratch, std::size_t k) {
          const std::size_t r = next_row + k;
          internal::signature_row(rows, frame_of, weights, instants[r], out.data() + r * rows.columns, scratch);
        });
    next_row = end;
  }
  return out;
}

}  // namespace deformseg::signatures
