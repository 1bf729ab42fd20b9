/// @file signatures/motion_signatures.h
/// @brief `motion_signatures`: each frame of an animation as how fast its surface moves, at several
/// time scales and which way up or down: the area-weighted distributions of its vertices'
/// displacement rates, which need no correspondence between two meshes to compare (beyond the
/// thesis).
///
/// Strain sees only deformation: a robot whose limbs are rigid parts on bones has almost none,
/// whatever it does. Displacements see every motion, articulated or deforming, and their
/// distribution over the surface says how much of the body moves how fast (the legs of a walk, one
/// arm and its weapon in a strike) without saying which vertex is where, so that two animations of
/// different meshes can be compared frame by frame. The distribution of their vertical rates adds
/// the one direction that every body shares: rising or falling.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/signatures/internal/weighted_quantiles.h>
#include <deformseg/signatures/procrustes_distances.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::signatures {

/// @brief The options of `motion_signatures`, an aggregate for designated initializers.
struct Motion_signature_options {
  /// @brief The time scales, in seconds: at lag k, a vertex's rate at the time t of a frame is its
  /// displacement from time t - k to time t + k over 2k, its positions between two frames
  /// interpolated linearly, so that the same motion sampled at any frame rate has the same rates.
  /// Near either end the span is cut at the animation's first or last instant, still over 2k, as if
  /// the body stood still before the first frame and after the last (game and captured clips mostly
  /// start and end at rest). Short lags see speed, long ones the amplitude of a motion; the
  /// longest, 128/30 s (128 frames at 30 fps), spans most clips whole, from their first frame to
  /// their last, and so says how far the body ends from where it started (sat down, fallen, back
  /// where it began). Chapter 7 of the manual gives how these choices measured on the shared
  /// characters.
  /// Default {1, 4, 16, 128} thirtieths of a second (1, 4, 16 and 128 frames at 30 fps); each
  /// positive and finite.
  std::vector<double> lags = {1.0 / 30, 4.0 / 30, 16.0 / 30, 128.0 / 30};
  /// @brief Quantiles of the rates per lag, at (q + 1/2) / quantiles of the surface's area. Default 8.
  std::size_t quantiles = 8;
  /// @brief The smallest rate told apart from standing still, in RMS radii per second: smaller rates
  /// count as this one, so that the logarithm stays finite. Default 3e-3 (1e-4 per frame at 30 fps).
  double floor = 3e-3;
  /// @brief The animation's up direction (any length but 0), or `std::nullopt`. When set, each lag
  /// also gives the quantiles of the vertices' signed vertical rates, positive rising: a speed says
  /// how fast, not which way, so that without them sitting down and standing up, a jump's take-off
  /// and its landing, look alike. The signatures are then invariant to rotations about this axis
  /// only; `std::nullopt` keeps the speeds alone, invariant to every rotation. Default +Y, the up of
  /// glTF, three.js and the usual OBJ export.
  std::optional<Eigen::Vector3d> up = Eigen::Vector3d::UnitY();
  /// @brief The vertical rate, in RMS radii per second, up to which a vertical quantile counts
  /// linearly and beyond which logarithmically: q is kept as `asinh(q / vertical_unit)`, since it
  /// has a sign and no logarithm. Default 9e-3 (3e-4 per frame at 30 fps).
  double vertical_unit = 9e-3;
  /// @brief The weight of the vertical quantiles against the speeds' in the squared distance of two
  /// signatures: they are multiplied by its square root. Default 0.2. The three vertical defaults
  /// were chosen leaving each body of the shared characters out in turn (chapter 7).
  double vertical_weight = 0.2;
  /// @brief The surface cut into this many bands of equal height along `up` in the first frame (the
  /// pose the animation starts in), each band's area-weighted quantiles side by side: per lag (and
  /// for the speeds, then the vertical rates), the lowest band's `quantiles` values, then the next
  /// band's, so that a part covering much of the surface (a big head) no longer outweighs the legs.
  /// A band without area takes the vertices of the nearest band that has some (the lower first).
  /// Above 1 it needs `up`. Default 1: the whole surface, one distribution (chapter 7 of the manual
  /// gives what 3 or 4 bands change on the shared characters and the motion library); 1 to
  /// `max_bands`.
  std::size_t bands = 1;
  /// @brief The direction across the body (any length but 0), or `std::nullopt` (default). When
  /// set, each height band is cut in two at the first frame's area-weighted centroid along it, the
  /// half on the negative side first, so that a motion and its mirror image across the body (a left
  /// and a right kick) differ; without it they are alike, since a distribution over the surface is
  /// the same for a mirror image. For glTF characters, which face +Z with +Y up, +X. A half without
  /// area takes the vertices of the nearest band's half on its side that has some, else the other
  /// half's.
  std::optional<Eigen::Vector3d> sides = std::nullopt;
  /// @brief The threads of the rows, computed in parallel: 0 (default) for all the hardware's
  /// threads (`thread_count`), else 1 to `max_threads`. The signatures do not depend on it, nor
  /// does a `Motion_signature_similarity` holding these options.
  int threads = 0;
};

/// @brief The most height bands `Motion_signature_options::bands` takes.
inline constexpr std::size_t max_bands = 64;

namespace internal {

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

/// `options.up` made of unit length; refuses a zero or non-finite direction.
inline std::optional<Eigen::Vector3d> unit_up(const Motion_signature_options& options) {
  if (!options.up) return std::nullopt;
  const double length = options.up->norm();
  if (!(length > 0) || !std::isfinite(length))
    throw invalid_input("motion_signatures: the up direction must be finite and not zero");
  return *options.up / length;
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

/// Throws unless the options and the frame rate make signatures (the checks of `motion_signatures`).
inline void check_signature_options(const Motion_signature_options& options, double frames_per_second) {
  if (options.quantiles == 0) throw invalid_input("motion_signatures: 0 quantiles");
  if (options.lags.empty()) throw invalid_input("motion_signatures: no lag");
  for (const double lag : options.lags)
    if (!(lag > 0) || !std::isfinite(lag))
      throw invalid_input("motion_signatures: a lag of " + std::to_string(lag) + " s; lags must be positive");
  mesh::check_frames_per_second(frames_per_second, "motion_signatures");
  if (!(options.floor > 0)) throw invalid_input("motion_signatures: the floor must be positive");
  if (options.up && !(options.vertical_unit > 0))
    throw invalid_input("motion_signatures: the vertical unit must be positive");
  if (options.up && !(options.vertical_weight >= 0 && std::isfinite(options.vertical_weight)))
    throw invalid_input("motion_signatures: the vertical weight must be finite and not negative");
  if (options.bands == 0 || options.bands > max_bands)
    throw invalid_input("motion_signatures: " + std::to_string(options.bands) + " bands; 1 to " +
                        std::to_string(max_bands));
  if (options.bands > 1 && !options.up)
    throw invalid_input("motion_signatures: " + std::to_string(options.bands) +
                        " height bands need an up direction");
  if (options.sides && !(options.sides->norm() > 0 && std::isfinite(options.sides->norm())))
    throw invalid_input("motion_signatures: the direction across the body (sides) must be finite and not zero");
  thread_count(options.threads, "motion_signatures");
}

/// Throws unless an animation of `frames` frames is long enough to move.
inline void check_frame_count(std::size_t frames) {
  if (frames < 2) throw invalid_input("motion_signatures: an animation of " + std::to_string(frames) +
                                      " frame(s); a motion needs at least 2");
}

/// Throws unless the RMS radius is a unit: positive and finite.
inline void check_radius(double radius) {
  if (!(radius > 0) || !std::isfinite(radius))
    throw invalid_input("motion_signatures: the animation has no extent (RMS radius " + std::to_string(radius) + ")");
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

}  // namespace internal


/// @brief `motion_signatures` at the given instants (seconds from the first frame) instead of at
/// the frames': row r is the signature at `instants[r]`, positions interpolated between frames.
/// @pre as `motion_signatures` on raw positions; instants in [0, (T - 1) / `frames_per_second`]
/// (an instant outside reads the nearest end frame).
/// @throws invalid_input as `motion_signatures`.
/// @par Complexity O(I V L log k) expected for I instants, in parallel over instants on
/// `options.threads` threads; deterministic whatever their number.
/// @par Example
/// @include motion_signatures_at.cpp
template <class Coordinate>
Eigen::MatrixXd motion_signatures_at(std::span<const Coordinate> positions, std::span<const double> weights,
                              const Motion_signature_options& options, double frames_per_second,
                              std::span<const double> instants) {
  const std::size_t vertices = weights.size();
  if (vertices == 0 || positions.size() % (3 * vertices) != 0)
    throw invalid_input("motion_signatures: positions are not T x 3V for the weights' V = " + std::to_string(vertices));
  const std::size_t frames = positions.size() / (3 * vertices);
  internal::check_frame_count(frames);
  internal::check_signature_options(options, frames_per_second);
  const double radius = internal::rms_radius(positions, weights, frames);
  internal::check_radius(radius);
  internal::Signature_rows rows = internal::signature_rows(options, frames_per_second, frames, radius);
  if (internal::region_count(options) > 1)
    rows.regions = internal::surface_regions(positions.data(), weights, options, rows.up);

  using Row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Row_major out = Row_major(static_cast<Eigen::Index>(instants.size()), static_cast<Eigen::Index>(rows.columns));
  const auto frame_of = [&](std::size_t t) { return positions.data() + 3 * vertices * t; };
  deformseg::internal::parallel_for_with_locals(
      instants.size(), options.threads, 1, [&] { return internal::Row_scratch(vertices); },
      [&](internal::Row_scratch& scratch, std::size_t r) {
        internal::signature_row(rows, frame_of, weights, instants[r], out.data() + r * rows.columns, scratch);
      });
  return out;
}

/// @brief The instants of an animation's T frames sampled at `fps`: t / fps, in seconds.
/// @pre `fps` is positive. @par Complexity O(T).
/// @par Example
/// @include frame_instants.cpp
inline std::vector<double> frame_instants(std::size_t frames, double fps) {
  std::vector<double> instants(frames);
  for (std::size_t t = 0; t < frames; ++t) instants[t] = double(t) / fps;
  return instants;
}

/// @brief Calls `f(positions, weights)` with `animation`'s contiguous positions (a `std::span` of its
/// coordinates, `T x 3V`) and its vertices' shares of the first frame's area (`vertex_area_weights`),
/// copying the animation first when it is not a `Deforming_mesh`; returns what `f` returns.
/// @throws invalid_input for an animation without frames.
/// @par Complexity O(V + F), plus a copy of the positions for a mesh that is not a `Deforming_mesh`.
/// @par Example
/// @include with_positions_and_weights.cpp
template <mesh::DeformingMesh Mesh, class F>
decltype(auto) with_positions_and_weights(const Mesh& animation, F&& f) {
  if constexpr (requires { animation.all_positions(); animation.triangles(); }) {
    if (animation.num_frames() == 0) throw invalid_input("motion_signatures: an animation without frames");
    const auto positions = animation.all_positions();
    using Coordinate = std::remove_cvref_t<decltype(positions[0])>;
    std::vector<double> first(positions.begin(), positions.begin() + std::ptrdiff_t(3 * animation.num_vertices()));
    const auto weights = vertex_area_weights(std::span<const double>(first), animation.triangles(),
                                             animation.num_vertices());
    return f(std::span<const Coordinate>(positions), std::span<const double>(weights));
  } else {
    return with_positions_and_weights(mesh::make_deforming_mesh<double>(animation), std::forward<F>(f));
  }
}

/// @brief The motion signature of every frame of an animation given as raw positions, for data
/// with no mesh built (a triangle soup, a sampled glTF clip).
///
/// Row t holds, for each lag k of `options.lags` in turn (and within it for each region: each
/// height band of `options.bands`, the lowest first, and within it each side of `options.sides`,
/// the negative first), the `options.quantiles` area-weighted quantiles of the vertices' (the
/// region's) speeds at lag k (`Motion_signature_options::lags`) at frame t's
/// instant t / `frames_per_second`, in units of the animation's RMS radius (`rms_radius`) per
/// second, as natural logarithms of at least `log(options.floor)`. With `options.up` set, the same
/// number of columns follow, for each lag in turn: the quantiles of the vertices' signed rates
/// along up, as `sqrt(vertical_weight) * asinh(q / vertical_unit)`.
///
/// Invariant to translating and scaling the whole animation, to rotating it about `options.up`
/// (about any axis without it), and (up to the weights' sampling of the surface) to remeshing it.
/// The rates are per second and the lags in seconds, positions between frames interpolated
/// linearly: a motion sampled at any frame rate has (up to that interpolation) the same signatures
/// at the same instants, while a motion played faster (the same frames at a higher rate) moves
/// faster and has other signatures.
/// @param positions `T x 3V` coordinates, frame after frame, x y z per vertex.
/// @param weights V non-negative vertex weights summing to 1 (e.g. each vertex's share of the
/// area, `vertex_area_weights`).
/// @param options the lags, quantiles, floor and up direction (default `Motion_signature_options{}`).
/// @param frames_per_second the frame rate the positions are sampled at. Default 30.
/// @return the `T x (lags x regions x quantiles)` signatures (regions: `bands`, twice that with
/// `sides`), `T x (2 x lags x regions x quantiles)` with an up direction.
/// @throws invalid_input when the sizes disagree, when there are fewer than two frames (a single
/// pose has no motion), when a lag or the frame rate is not positive and finite, when `quantiles`
/// is 0, when `floor` is not positive, when the up direction is zero or not finite, when `bands`
/// is 0, above `max_bands`, or above 1 without an up direction, when `sides` is zero or not
/// finite, when
/// `vertical_unit` is not positive or `vertical_weight` negative, or when the animation does not
/// move its vertices apart from each other (zero radius).
/// @par Complexity O(T V L log k) expected for T frames, V vertices, L lags and k quantiles (a
/// selection or two per frame and lag), in parallel over frames; O(T L k) memory for the result.
/// Deterministic whatever the thread count.
template <class Coordinate>
Eigen::MatrixXd motion_signatures(std::span<const Coordinate> positions, std::span<const double> weights,
                                  const Motion_signature_options& options = {},
                                  double frames_per_second = mesh::default_frames_per_second) {
  const std::size_t frames = weights.empty() ? 0 : positions.size() / (3 * weights.size());
  const double rate = frames_per_second > 0 && std::isfinite(frames_per_second) ? frames_per_second : 1.0;
  return motion_signatures_at(positions, weights, options, frames_per_second,
                                 std::span<const double>(frame_instants(frames, rate)));
}

/// @brief The motion signature of every frame of `animation`, each vertex weighted by its share of
/// the first frame's area, at the animation's frame rate (`frames_per_second`: its own, else 30);
/// see the overload on raw positions for what a signature is.
/// @tparam Mesh a `DeformingMesh`.
/// @return the `T x (lags x regions x quantiles)` signatures (twice the columns with an up direction).
/// @throws invalid_input as the overload on raw positions.
/// @par Complexity O(T V L log k) expected, plus a copy of the positions for a mesh that is not a
/// `Deforming_mesh`.
template <mesh::DeformingMesh Mesh>
Eigen::MatrixXd motion_signatures(const Mesh& animation, const Motion_signature_options& options = {}) {
  return with_positions_and_weights(animation, [&](auto positions, std::span<const double> weights) {
    return motion_signatures(positions, weights, options, mesh::frames_per_second(animation));
  });
}

}  // namespace deformseg::signatures

#if DEFORMSEG_COMPILED
// deformseg::compiled holds these instantiations (src/compiled/similarity.cpp): a program that
// links it compiles against their declarations. Any other type instantiates where it is used.
#include <deformseg/mesh/default_mesh.h>

namespace deformseg::signatures {
extern template Eigen::MatrixXd motion_signatures_at<double>(std::span<const double>, std::span<const double>,
                                                             const Motion_signature_options&, double,
                                                             std::span<const double>);
extern template Eigen::MatrixXd motion_signatures<double>(std::span<const double>, std::span<const double>,
                                                          const Motion_signature_options&, double);
extern template Eigen::MatrixXd motion_signatures<mesh::Surface_mesh_animation>(const mesh::Surface_mesh_animation&,
                                                                               const Motion_signature_options&);
}  // namespace deformseg::signatures
#endif
