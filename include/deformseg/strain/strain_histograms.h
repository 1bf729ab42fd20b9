/// @file strain/strain_histograms.h
/// @brief Each frame of a strain field as the area-weighted histogram of its triangles' strain, on
/// log-spaced bins: `strain_histograms`, its options and `histogram_edges`.
///
/// A histogram forgets where the strain lies and keeps how much of the surface strains how much,
/// so that frames of two animations of different meshes, with no correspondence between their
/// triangles, can be compared (see `strain/histogram_distance.h`).
#pragma once

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/strain/strain.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace deformseg::strain {

/// @brief Per-frame strain histograms: a `T x (B + 2)` row-major matrix of doubles, row `t` the
/// histogram of frame `t` (contiguous), each row non-negative and summing to 1 (up to rounding).
///
/// Column 0 is the underflow bin ("rigid": strain below `Histogram_options::min_strain`), columns
/// 1 to B the log-spaced bins, column B + 1 the overflow bin; see `histogram_edges`.
using Strain_histograms = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// @brief The bins of `strain_histograms`, an aggregate for designated initializers.
///
/// The histogram of a frame has `bins + 2` columns: an underflow bin for strains `s < min_strain`
/// (the triangles that hardly deform, rounding included: "rigid"), `bins` log-spaced bins from
/// `min_strain` to `max_strain`, and an overflow bin for `s >= max_strain` (slivers, strains of
/// hundreds); see `histogram_edges`. The defaults were chosen for the default strain of
/// `Strain_histogram_options` (the raw `Max_principal_strain` of each frame against the one
/// before, a relative stretch): below 5 % of stretch from one frame to the next counts as rigid,
/// at or above 100 % as overflow (@ref section_histogram_defaults).
struct Histogram_options {
  /// @brief The number B of log-spaced bins between `min_strain` and `max_strain`, at least 1.
  /// Default: 16 (fewer or more bins rank pairs of animations alike: @ref section_histogram_defaults).
  std::size_t bins = 16;
  /// @brief The lower edge of the first log-spaced bin, finite and > 0. Default: 0.05, which
  /// tells motions apart with the largest margin (@ref section_histogram_defaults).
  double min_strain = 0.05;
  /// @brief The upper edge of the last log-spaced bin, finite and > `min_strain`. Default: 1.
  double max_strain = 1.0;
  /// @brief Threads (0: all the hardware's threads, `thread_count`), at most `max_threads`. The
  /// result is bit-identical
  /// for any number.
  int threads = 0;
};

namespace internal {

inline void check_histogram_options(const Histogram_options& options) {
  if (options.bins == 0) throw invalid_input("strain_histograms: bins must be at least 1");
  if (!(std::isfinite(options.min_strain) && options.min_strain > 0 && std::isfinite(options.max_strain) &&
        options.max_strain > options.min_strain))
    throw invalid_input("strain_histograms: need 0 < min_strain < max_strain, both finite, not " +
                        std::to_string(options.min_strain) + " and " + std::to_string(options.max_strain));
  thread_count(options.threads, "strain_histograms");
}

}  // namespace internal

/// @brief The `B + 1` edges of the log-spaced bins: `e_k = min_strain (max_strain /
/// min_strain)^(k / B)` for k = 0..B, with `e_0 = min_strain` and `e_B = max_strain` exactly.
///
/// Column 0 of a histogram holds `s < e_0`, column k (1 <= k <= B) holds `e_(k-1) <= s < e_k`,
/// column B + 1 holds `s >= e_B`: a strain on an edge falls in the bin above it.
/// @param options the bins.
/// @return the edges, increasing.
/// @throws invalid_input when `options` is invalid (see `Histogram_options`).
/// @par Complexity O(B).
inline std::vector<double> histogram_edges(const Histogram_options& options) {
  internal::check_histogram_options(options);
  std::vector<double> edges(options.bins + 1);
  const double ratio = options.max_strain / options.min_strain;
  for (std::size_t k = 0; k <= options.bins; ++k)
    edges[k] = options.min_strain * std::pow(ratio, double(k) / double(options.bins));
  edges.front() = options.min_strain;
  edges.back() = options.max_strain;
  return edges;
}

namespace internal {

// The column of strain magnitude `s` (not NaN): a logarithm gives a guess, the stored edges the
// exact answer, so that a value on an edge always falls in the bin above it.
class Strain_binning {
public:
  explicit Strain_binning(const Histogram_options& options)
      : edges_(histogram_edges(options)),
        scale_(double(options.bins) / std::log(options.max_strain / options.min_strain)) {}

  std::size_t column(double s) const {
    const std::size_t bins = edges_.size() - 1;
    if (s < edges_.front()) return 0;
    if (s >= edges_.back()) return bins + 1;
    std::size_t k = std::min(bins, std::size_t(std::log(s / edges_.front()) * scale_) + 1);
    while (k > 1 && s < edges_[k - 1]) --k;
    while (k < bins && s >= edges_[k]) ++k;
    return k;
  }

private:
  std::vector<double> edges_;
  double scale_;
};

inline double checked_total_weight(std::span<const double> weights, std::size_t faces) {
  if (weights.size() != faces)
    throw invalid_input("strain_histograms: " + std::to_string(weights.size()) + " weights for " +
                        std::to_string(faces) + " triangles");
  double total = 0;
  for (std::size_t j = 0; j < weights.size(); ++j) {
    if (!(std::isfinite(weights[j]) && weights[j] >= 0))
      throw invalid_input("strain_histograms: the weight of triangle " + std::to_string(j) +
                          " is not finite and >= 0: " + std::to_string(weights[j]));
    total += weights[j];
  }
  if (!(total > 0 && std::isfinite(total)))
    throw invalid_input("strain_histograms: the weights must have a finite sum > 0 (every triangle "
                        "degenerate?), not " + std::to_string(total));
  return total;
}

// The histogram of one frame into `row`; returns 1 + the first triangle whose strain is NaN, or 0.
template <class Value>
std::size_t frame_histogram(std::span<const Value> strains, std::span<const double> weights, double total,
                            const Strain_binning& binning, double* row, std::size_t columns) {
  std::fill(row, row + columns, 0.0);
  for (std::size_t j = 0; j < strains.size(); ++j) {
    const double s = std::abs(double(strains[j]));
    if (std::isnan(s)) return j + 1;
    row[binning.column(s)] += weights[j];
  }
  for (std::size_t k = 0; k < columns; ++k) row[k] /= total;
  return 0;
}


}  // namespace internal

/// @brief The area-weighted histogram of the strain of every frame of a strain field.
///
/// Row t, column k is the share of the total weight carried by the triangles whose strain
/// magnitude `|s|` at frame t falls in column k (see `histogram_edges`): `sum of weights[j] over
/// those j / sum of all weights`. Triangles of weight 0 (degenerate ones, when the weights are
/// areas) count for nothing; the strain 0 that `compute_strain` gives degenerate reference
/// triangles falls in the underflow bin, and an infinite strain in the overflow bin. A `float`
/// strain is compared with the (double) edges after its exact conversion to double.
///
/// Frames are computed in parallel, each by one thread in triangle order, so the result is the
/// same for any number of threads.
/// @tparam Value the field's value type.
/// @param field the `F x T` strain field.
/// @param weights F weights, one per triangle (typically the areas of the rest pose).
/// @param options the bins and threads; see `Histogram_options` for the defaults.
/// @return the `T x (B + 2)` histograms, each row summing to 1.
/// @pre `weights.size() == F`, every weight finite and >= 0, their sum finite and > 0; no strain
/// is NaN; `options` valid (`bins >= 1`, `0 < min_strain < max_strain` finite, `threads` from 0 to `max_threads`).
/// @throws invalid_input naming the first broken precondition (the triangle, or the frame and
/// triangle of the first NaN).
/// @par Complexity O(T (F + B)) with a logarithm per triangle-frame; O(T B) memory (chapter 10 of
/// the manual gives throughputs).
/// @sa histogram_distances, Strain_histogram_options
template <std::floating_point Value>
Strain_histograms strain_histograms(const Strain_field<Value>& field, std::span<const double> weights,
                                    const Histogram_options& options = {}) {
  const internal::Strain_binning binning(options);
  const double total = internal::checked_total_weight(weights, field.num_faces());
  const std::size_t frames = field.num_frames(), columns = options.bins + 2;
  Strain_histograms histograms(static_cast<Eigen::Index>(frames), static_cast<Eigen::Index>(columns));
  std::vector<std::size_t> nan_at(frames, 0);
  deformseg::internal::parallel_for(frames, options.threads, [&](std::size_t t) {
    nan_at[t] = internal::frame_histogram(field.frame(t), weights, total, binning,
                                          histograms.row(Eigen::Index(t)).data(), columns);
  });
  for (std::size_t t = 0; t < frames; ++t)
    if (nan_at[t] != 0)
      throw invalid_input("strain_histograms: the strain of triangle " + std::to_string(nan_at[t] - 1) + " is NaN",
                          {.frame = t});
  return histograms;
}

/// @brief The options of the animation overload of `strain_histograms`: which strain to compute
/// and how to bin it, an aggregate for designated initializers.
///
/// Defaults: the raw `Max_principal_strain` against the previous pose, binned by the default
/// `Histogram_options` (16 log bins from 0.05 to 1), to be compared with
/// `Histogram_metric::earth_movers`: of the settings tried, the one that ranks the same motion on
/// another mesh nearest with the widest margin (@ref section_histogram_defaults). The previous
/// pose because a histogram against the rest pose does not depend on the order of the other poses,
/// so it cannot tell a motion from its poses reordered. Its price: frame 0's histogram is all
/// rigid, and the strain between frames, so the histograms, depend on the speed of the motion and
/// the frame rate (lower `min_strain` for animations sampled much more densely).
///
/// A strain of one's own measure or normalisation is binned by the overload of `strain_histograms`
/// that takes a field (`compute_strain` with the policy objects, weights from `face_areas`).
struct Strain_histogram_options {
  /// @brief The strain that is binned. Default: the raw strain (no normalisation) against the
  /// previous pose, `Strain_options{.reference = Strain_reference::previous_pose, .normalization =
  /// No_normalization{}}`. Options given here replace all of these: name `No_normalization{}`
  /// among them to keep the strain raw.
  Strain_options strain{.reference = Strain_reference::previous_pose, .normalization = No_normalization{}};
  /// @brief The bins (and threads). Default: `Histogram_options{}`.
  Histogram_options histogram{};
};

/// @brief The strain histograms of an animation: its strain field (`compute_strain` with
/// `options.strain`), each frame binned with the triangles weighted by their areas at frame
/// `options.strain.rest_frame` (default 0), the rest pose, whatever the reference.
///
/// Fixed weights make a histogram the share of the rest surface that strains so much. They make
/// it invariant to rigid motion and to a uniform scale of the whole animation (areas scale
/// alike, shares do not change; the strain is invariant to both), and nearly independent of the
/// mesh's resolution: another mesh of the same animal in the same motion gives alike histograms,
/// where counting triangles would weigh densely meshed parts more.
/// @tparam Mesh a `DeformingMesh`; a `Deforming_mesh` is read in place, any other model is first
/// copied with `make_deforming_mesh`, once for the strain (which would copy it too) and the rest
/// pose's areas: O(T V) time and 3 T V doubles.
/// @param animation the animation.
/// @param options the strain and the bins.
/// @return the `T x (B + 2)` histograms.
/// @pre as for `compute_strain` and the field overload; `options.strain.rest_frame` is a frame of
/// the animation; the rest pose has a triangle of non-zero area.
/// @throws invalid_input naming the broken precondition.
/// @par Complexity that of `compute_strain`, plus O(T (F + B)).
template <mesh::DeformingMesh Mesh>
Strain_histograms strain_histograms(const Mesh& animation, const Strain_histogram_options& options = {}) {
  if constexpr (mesh::is_deforming_mesh_v<Mesh>) {
    if (options.strain.rest_frame >= animation.num_frames())
      throw invalid_input("strain_histograms: rest frame " + std::to_string(options.strain.rest_frame) +
                          " out of range for an animation of " + std::to_string(animation.num_frames()) + " frames");
    const Strain_field<float> field = compute_strain(animation, options.strain);
    const std::vector<double> areas = mesh::face_areas(animation, options.strain.rest_frame);
    return strain_histograms(field, areas, options.histogram);
  } else {
    return strain_histograms(mesh::make_deforming_mesh(animation), options);
  }
}

}  // namespace deformseg::strain
