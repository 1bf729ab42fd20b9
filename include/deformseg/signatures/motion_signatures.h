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

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/signatures/internal/signature_rows.h>
#include <deformseg/signatures/motion_signature_options.h>
#include <deformseg/signatures/procrustes_distances.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::signatures {

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
