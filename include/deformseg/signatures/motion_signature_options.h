/// @file signatures/motion_signature_options.h
/// @brief `Motion_signature_options`: the time scales, quantiles, up direction, height bands and
/// sides of `motion_signatures`, and their checks.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
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
  /// where it began). How they were chosen: @ref section_signature_calibration.
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
  /// signatures: they are multiplied by its square root. Default 0.2. How the three vertical
  /// defaults were chosen: @ref section_signature_calibration.
  double vertical_weight = 0.2;
  /// @brief The surface cut into this many bands of equal height along `up` in the first frame (the
  /// pose the animation starts in), each band's area-weighted quantiles side by side: per lag (and
  /// for the speeds, then the vertical rates), the lowest band's `quantiles` values, then the next
  /// band's, so that a part covering much of the surface (a big head) no longer outweighs the legs.
  /// A band without area takes the vertices of the nearest band that has some (the lower first).
  /// Above 1 it needs `up`. Default 1: the whole surface, one distribution (what more bands
  /// change: @ref section_descriptions); 1 to `max_bands`.
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

/// `options.up` made of unit length; refuses a zero or non-finite direction.
inline std::optional<Eigen::Vector3d> unit_up(const Motion_signature_options& options) {
  if (!options.up) return std::nullopt;
  const double length = options.up->norm();
  if (!(length > 0) || !std::isfinite(length))
    throw invalid_input("motion_signatures: the up direction must be finite and not zero");
  return *options.up / length;
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

}  // namespace internal

}  // namespace deformseg::signatures
