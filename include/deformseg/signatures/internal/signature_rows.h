// The rows of `motion_signatures` (signatures/motion_signatures.h): where an instant falls among
// the frames, the animation's unit (its RMS radius), the surface's regions (height bands and sides),
// and one row's quantiles of the vertices' rates at every lag, which the whole animation in memory
// and the stream of `motion_signatures_streamed` share.
#pragma once

#include <deformseg/signatures/internal/weighted_quantiles.h>
#include <deformseg/signatures/motion_signature_options.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::signatures::internal {

/// Where the instant `time` (seconds from the first frame) falls among frames sampled at `fps`:
/// the frame at or before it and the fraction of the way to the next, the instant first cut to the
/// animation's first and last frames. An instant within 1e-9 frame of a frame is that frame, so
/// that lags that are whole frames read the frames themselves.
inline std::pair<std::size_t, double> frame_at(double time, double fps, std::size_t frames) {
  double u = std::clamp(time * fps, 0.0, double(frames - 1));
  if (std::abs(u - std::round(u)) < 1e-9) u = std::round(u);
  const std::size_t before = std::min(std::size_t(u), frames - 1);
  return {before, u - double(before)};
}

/// Vertex v of a frame's x y z coordinates, in double precision.
template <class Coordinate>
Eigen::Vector3d point(const Coordinate* frame, std::size_t v) {
  return Eigen::Vector3d(static_cast<double>(frame[3 * v]), static_cast<double>(frame[3 * v + 1]),
                         static_cast<double>(frame[3 * v + 2]));
}

/// Where an instant falls among frames: the frame at or before it, the frame after it (the same
/// frame when the fraction is 0, so that a frame past the last is never asked for) and the
/// fraction of the way between them. Both paths of `motion_signatures_at`, the whole animation in
/// memory and the stream of `motion_signatures_streamed`, read positions through it.
template <class Coordinate>
struct Frames_around {
  const Coordinate* before;
  const Coordinate* after;
  double fraction;
};

/// The frames around the instant `at` (a frame and a fraction, as `frame_at` gives it), found by
/// `frame_of(t)`, which returns frame t's `3V` coordinates.
template <class FrameOf>
auto frames_around(const FrameOf& frame_of, std::pair<std::size_t, double> at) {
  const auto* before = frame_of(at.first);
  return Frames_around<std::remove_cvref_t<decltype(*before)>>{
      before, at.second == 0 ? before : frame_of(at.first + 1), at.second};
}

/// Vertex v's position at an instant between two frames, interpolated linearly.
template <class Coordinate>
Eigen::Vector3d point_at(const Frames_around<Coordinate>& at, std::size_t v) {
  const Eigen::Vector3d p = point(at.before, v);
  if (at.fraction == 0) return p;
  return p + at.fraction * (point(at.after, v) - p);
}

/// Adds frame's weighted sum of squared distances of the vertices from their weighted centroid
/// to `sum`: one frame's share of `rms_radius`, in the order `rms_radius` adds them.
template <class Coordinate>
void add_frame_spread(const Coordinate* frame, std::span<const double> weights, double& sum) {
  const std::size_t vertices = weights.size();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (std::size_t v = 0; v < vertices; ++v) centroid += weights[v] * point(frame, v);
  for (std::size_t v = 0; v < vertices; ++v) sum += weights[v] * (point(frame, v) - centroid).squaredNorm();
}

/// The animation's weighted RMS distance of the vertices from their frame's centroid, averaged
/// over the frames: the unit of the rates.
template <class Coordinate>
double rms_radius(std::span<const Coordinate> positions, std::span<const double> weights, std::size_t frames) {
  double sum = 0;
  for (std::size_t t = 0; t < frames; ++t) add_frame_spread(positions.data() + 3 * weights.size() * t, weights, sum);
  return std::sqrt(sum / double(frames));
}

/// One region of the surface: a height band (`Motion_signature_options::bands`), or one side of it
/// (`Motion_signature_options::sides`); its vertices, and their weights scaled to sum to 1 over it.
struct Surface_region {
  std::vector<std::size_t> vertices;
  std::vector<double> weights;
};

/// The regions of the surface the options cut: per band, its halves when `sides` is set.
inline std::size_t region_count(const Motion_signature_options& options) {
  return options.bands * (options.sides ? 2 : 1);
}

/// The vertices of `frame` (`3V` coordinates, the first) cut into `options.bands` bands of equal
/// height along the unit `up` (not read for one band), each in two at the weighted centroid along
/// `options.sides` when it is set: region b * halves + s, s 0 on the negative side. A region without
/// weight takes the vertices of the nearest band's region on its side that has some (the lower
/// first), else the other side's; at least one has, weights summing to 1.
template <class Coordinate>
std::vector<Surface_region> surface_regions(const Coordinate* frame, std::span<const double> weights,
                                            const Motion_signature_options& options,
                                            const std::optional<Eigen::Vector3d>& up) {
  const std::size_t vertices = weights.size(), bands = options.bands, halves = options.sides ? 2 : 1;
  std::vector<double> height(vertices, 0.0), across(vertices, 0.0);
  double middle = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    if (up) height[v] = point(frame, v).dot(*up);
    if (options.sides) across[v] = point(frame, v).dot(*options.sides), middle += weights[v] * across[v];
  }
  const auto [low, high] = std::ranges::minmax(height);
  const double span = high - low;
  std::vector<Surface_region> regions(bands * halves);
  std::vector<double> totals(regions.size());
  for (std::size_t v = 0; v < vertices; ++v) {
    const double u = span > 0 ? (height[v] - low) / span : 0.0;
    const std::size_t band = std::min(std::size_t(u * double(bands)), bands - 1);
    const std::size_t r = band * halves + (halves == 2 && across[v] >= middle ? 1 : 0);
    regions[r].vertices.push_back(v);
    regions[r].weights.push_back(weights[v]);
    totals[r] += weights[v];
  }
  // The nearest band's region with weight on side s, from band b; none when the side has none.
  const auto nearest = [&](std::size_t b, std::size_t s) -> std::optional<std::size_t> {
    for (std::size_t d = 0; d < bands; ++d) {
      if (b >= d && totals[(b - d) * halves + s] > 0) return (b - d) * halves + s;
      if (b + d < bands && totals[(b + d) * halves + s] > 0) return (b + d) * halves + s;
    }
    return std::nullopt;
  };
  std::vector<Surface_region> out(regions.size());
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const std::size_t b = r / halves, s = r % halves;
    const std::size_t from = nearest(b, s).value_or(nearest(b, halves - 1 - s).value_or(r));
    out[r] = regions[from];
    for (double& w : out[r].weights) w /= totals[from];
  }
  return out;
}

/// What every row of an animation's signatures shares: the options, the unit up direction, the
/// RMS radius, the frame rate and count, and the row's width.
struct Signature_rows {
  const Motion_signature_options& options;
  std::optional<Eigen::Vector3d> up;
  double radius;
  double frames_per_second;
  std::size_t frames;
  std::size_t columns;
  std::vector<Surface_region> regions;  ///< empty for one region: the whole surface, every vertex's weight
};

/// The rows' shared values, once the options, the frame count and the radius are checked.
inline Signature_rows signature_rows(const Motion_signature_options& options, double frames_per_second,
                                     std::size_t frames, double radius) {
  std::optional<Eigen::Vector3d> up = unit_up(options);
  const std::size_t columns = (up ? 2 : 1) * options.lags.size() * region_count(options) * options.quantiles;
  return {options, up, radius, frames_per_second, frames, columns, {}};
}

/// The first and last frames (inclusive) that the row at `instant` reads.
inline std::pair<std::size_t, std::size_t> frames_of_row(const Signature_rows& rows, double instant) {
  std::size_t first = rows.frames, last = 0;
  for (const double lag : rows.options.lags) {
    const auto before = frame_at(instant - lag, rows.frames_per_second, rows.frames);
    const auto after = frame_at(instant + lag, rows.frames_per_second, rows.frames);
    first = std::min(first, before.first);
    last = std::max(last, after.first + (after.second == 0 ? 0 : 1));
  }
  return {first, last};
}

/// A lag's share of the last row that one `Row_scratch` computed: where its two instants fell
/// among the frames, and its signature values (the speeds', then the vertical rates'). A row whose
/// instants fall at the same places has the same values: near both ends of a clip, where spans are
/// cut at its first and last frames (every row of a clip shorter than the longest lag).
struct Lag_values {
  std::pair<std::size_t, double> before{~std::size_t(0), 0.0}, after{~std::size_t(0), 0.0};
  std::vector<double> values;
};

/// The scratch of `signature_row`, kept from row to row by one thread: V keys each for the speeds
/// and the vertical rates of a lag, one region's keys, the selection's, the span of the buckets of
/// each lag's (and region's) speeds and vertical rates, and each lag's last values.
struct Row_scratch {
  explicit Row_scratch(std::size_t vertices)
      : speeds(vertices), rises(vertices), keyed(vertices), spare(vertices) {}
  std::vector<std::uint64_t> speeds, rises;
  std::vector<std::uint64_t> region_keys;  // one region's keys, gathered (several regions alone)
  std::vector<Keyed_rate> keyed, spare;
  Bucket_quantiles selection;
  std::vector<Bucket_quantiles::Bucket_span> spans;  // per lag and region: the speeds', the vertical rates'
  std::vector<Lag_values> last;                      // per lag
};

/// The smallest and largest of some keys.
struct Key_range {
  std::uint64_t low = ~std::uint64_t(0), high = 0;
  void add(std::uint64_t key) { low = std::min(low, key), high = std::max(high, key); }
};

/// The `order_key`s of the vertices' speeds and, with `up`, vertical rates between two instants,
/// in units of `unit` per coordinate unit of displacement, and their ranges.
template <class Coordinate>
std::pair<Key_range, Key_range> displacement_rates(const Frames_around<Coordinate>& before,
                                                   const Frames_around<Coordinate>& after, std::size_t vertices,
                                                   double unit, const std::optional<Eigen::Vector3d>& up,
                                                   std::uint64_t* speeds, std::uint64_t* rises) {
  Key_range speed, rise;
  // Positions read as they are where both instants fall on frames (whole lags), as `point_at` does.
  const bool on_frames = before.fraction == 0 && after.fraction == 0;
  const auto rates = [&](const auto& displacement) {
    for (std::size_t v = 0; v < vertices; ++v) {
      const Eigen::Vector3d d = displacement(v);
      speed.add(speeds[v] = order_key(d.norm() * unit));
      if (up) rise.add(rises[v] = order_key(d.dot(*up) * unit));
    }
  };
  if (on_frames)
    rates([&](std::size_t v) -> Eigen::Vector3d { return point(after.before, v) - point(before.before, v); });
  else
    rates([&](std::size_t v) -> Eigen::Vector3d { return point_at(after, v) - point_at(before, v); });
  return {speed, rise};
}

/// The keys of `keys` at a region's vertices, gathered into `out`, and their range.
inline Key_range gathered_keys(const std::vector<std::uint64_t>& keys, const Surface_region& region,
                               std::vector<std::uint64_t>& out) {
  Key_range range;
  out.resize(region.vertices.size());
  for (std::size_t i = 0; i < region.vertices.size(); ++i) range.add(out[i] = keys[region.vertices[i]]);
  return range;
}

/// The signature at `instant` into `row` (`rows.columns` values), the frames read through
/// `frame_of(t)` (frame t's `3V` coordinates).
template <class FrameOf>
void signature_row(const Signature_rows& rows, const FrameOf& frame_of, std::span<const double> weights,
                   double instant, double* row, Row_scratch& scratch) {
  const Motion_signature_options& options = rows.options;
  const std::size_t vertices = weights.size(), k = options.quantiles, lags = options.lags.size();
  const std::size_t regions = std::max<std::size_t>(rows.regions.size(), 1), width = regions * k;
  const double vertical_factor = std::sqrt(options.vertical_weight);
  scratch.spans.resize(2 * lags * regions);
  scratch.last.resize(lags);
  // Quantiles of stream `stream` (a lag, region and kind of rate) of the keys of region r, or of
  // every vertex when the surface is one region.
  const auto quantiles = [&](std::size_t stream, std::size_t r, const std::vector<std::uint64_t>& keys,
                             Key_range range, std::vector<std::uint64_t>& gathered, double* out) {
    std::span<const std::uint64_t> chosen(keys);
    std::span<const double> chosen_weights = weights;
    if (!rows.regions.empty()) {
      range = gathered_keys(keys, rows.regions[r], gathered);
      chosen = gathered, chosen_weights = rows.regions[r].weights;
    }
    scratch.selection.quantiles(chosen, range.low, range.high, chosen_weights, k, out, scratch.spans[stream],
                                scratch.keyed, scratch.spare);
  };
  for (std::size_t l = 0; l < lags; ++l) {
    const double lag = options.lags[l];
    const auto at_before = frame_at(instant - lag, rows.frames_per_second, rows.frames);
    const auto at_after = frame_at(instant + lag, rows.frames_per_second, rows.frames);
    double* speed_quantiles = row + l * width;
    double* vertical = speed_quantiles + lags * width;
    Lag_values& last = scratch.last[l];
    if (last.before == at_before && last.after == at_after) {
      std::copy_n(last.values.begin(), width, speed_quantiles);
      if (rows.up) std::copy_n(last.values.begin() + std::ptrdiff_t(width), width, vertical);
      continue;
    }
    const auto before = frames_around(frame_of, at_before);
    const auto after = frames_around(frame_of, at_after);
    const double unit = 1.0 / (2.0 * lag * rows.radius);
    const auto [speed, rise] =
        displacement_rates(before, after, vertices, unit, rows.up, scratch.speeds.data(), scratch.rises.data());
    for (std::size_t r = 0; r < regions; ++r)
      quantiles(2 * (l * regions + r), r, scratch.speeds, speed, scratch.region_keys, speed_quantiles + r * k);
    for (std::size_t q = 0; q < width; ++q) speed_quantiles[q] = std::log(std::max(speed_quantiles[q], options.floor));
    last.values.assign(speed_quantiles, speed_quantiles + width);
    last.before = at_before, last.after = at_after;
    if (!rows.up) continue;
    for (std::size_t r = 0; r < regions; ++r)
      quantiles(2 * (l * regions + r) + 1, r, scratch.rises, rise, scratch.region_keys, vertical + r * k);
    for (std::size_t q = 0; q < width; ++q)
      vertical[q] = vertical_factor * std::asinh(vertical[q] / options.vertical_unit);
    last.values.insert(last.values.end(), vertical, vertical + width);
  }
}

}  // namespace deformseg::signatures::internal
