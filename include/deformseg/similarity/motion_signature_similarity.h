/// @file similarity/motion_signature_similarity.h
/// @brief `Motion_signature_similarity`: two animations compared frame by frame through how fast,
/// and how far up or down, their surfaces move at several time scales (`motion_signatures`),
/// aligned in time; needs no
/// correspondence between the two meshes, and sees rigid parts on bones as well as skin (beyond the
/// thesis).
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw.h>
#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/motion_signatures.h>
#include <deformseg/similarity/similarity.h>

#include <Eigen/Core>

#include <cmath>
#include <span>
#include <string>
#include <utility>

namespace deformseg {

/// @brief Similarity policy (models `SimilarityPolicy`): each frame of an animation becomes its
/// motion signature (`motion_signatures`: the area-weighted quantiles of its vertices' speeds at
/// lags of 1, 4, 16 and 128 frames, as logarithms, and of their rates up or down), two frames are
/// compared by the root mean square difference r of their signatures, made a dissimilarity
/// `1 - exp(-(r / scale)^2)` in [0, 1), and the two frame sequences are aligned by `alignment`
/// (dynamic time warping by default); `normalization` makes the value, for DTW one minus the mean
/// dissimilarity along the warping path.
///
/// Calibrated values: 1 for an animation and any translated, scaled (or remeshed, up to the area
/// weights' change) copy of it, turned about the up direction (`Motion_signature_options::up`,
/// +Y by default; about any axis with `std::nullopt`). On the shared characters
/// (`deformseg evaluate`) the median value of same-motion pairs of different bodies is about 0.78
/// and that of different-motion pairs about 0.46.
///
/// What it cannot see: which part of the body moves (a signature is a distribution over the
/// surface, not a map), nor any direction but up and down.
/// @tparam Alignment an `alignment::AlignmentPolicy` (default `alignment::Dtw`: the whole of both
/// motions, warped; `alignment::Subsequence_dtw` finds a short motion inside a longer one).
/// @tparam Normalization how the score becomes the value (default `Best_score_normalization`).
/// @par Complexity `describe`: `motion_signatures`' O(T V L log k); `compare`: O(Ta Tb L k) for the
/// frame dissimilarities plus the alignment's O(Ta Tb).
template <alignment::AlignmentPolicy Alignment = alignment::Dtw, class Normalization = Best_score_normalization>
struct Motion_signature_similarity {
  /// @brief The lags, quantiles, floor and up direction of the signatures. Default:
  /// `Motion_signature_options{}`.
  Motion_signature_options signatures{};
  /// @brief The RMS difference of two frames' signatures at which their dissimilarity is 1 - 1/e.
  /// Default 1.77, chosen on the shared characters with each body left out in turn (every fold
  /// chose it but the robot's) as the smallest scale at which same-motion pairs of different bodies
  /// score at least 0.7 and different-motion pairs at most 0.5 at the median.
  double scale = 1.77;
  /// @brief How the two frame sequences are aligned. Default: dynamic time warping, no window.
  Alignment alignment{};
  /// @brief How the score becomes the similarity. Default: `Best_score_normalization`.
  Normalization normalization{};

  /// @brief What is compared of one animation: its `T x (lags x quantiles)` signatures, twice as
  /// wide with an up direction.
  using Description = Eigen::MatrixXd;

  /// @brief The signatures of `animation`'s frames.
  /// @tparam Mesh a `DeformingMesh`.
  /// @throws invalid_input as `motion_signatures` (fewer than two frames, ...).
  template <DeformingMesh Mesh>
  Description describe(const Mesh& animation) const {
    return motion_signatures(animation, signatures);
  }

  /// @brief The signatures of an animation given as raw positions (`T x 3V` coordinates) and
  /// vertex weights (V, summing to 1), for data with no mesh built.
  /// @throws invalid_input as `motion_signatures`.
  template <class Coordinate>
  Description describe_positions(std::span<const Coordinate> positions, std::span<const double> weights) const {
    return motion_signatures(positions, weights, signatures);
  }

  /// @brief The `Ta x Tb` frame dissimilarities in [0, 1): `1 - exp(-(r / scale)^2)`, r the RMS
  /// difference of the two frames' signatures.
  /// @throws invalid_input when the signatures have different widths or the scale is not positive.
  Eigen::MatrixXd frame_dissimilarities(const Description& a, const Description& b) const {
    if (a.cols() != b.cols() || a.cols() == 0)
      throw invalid_input("Motion_signature_similarity: signatures of " + std::to_string(a.cols()) + " and " +
                          std::to_string(b.cols()) + " values per frame");
    if (!(scale > 0)) throw invalid_input("Motion_signature_similarity: the scale must be positive");
    // Differences, not a Gram matrix: equal frames give exactly 0, so a copy gives exactly 1.
    const double unit = 1.0 / (double(a.cols()) * scale * scale);
    Eigen::MatrixXd d(a.rows(), b.rows());
    for (Eigen::Index j = 0; j < b.rows(); ++j)
      for (Eigen::Index i = 0; i < a.rows(); ++i) d(i, j) = 1.0 - std::exp(-(a.row(i) - b.row(j)).squaredNorm() * unit);
    return d;
  }

  /// @brief The similarity of two animations from their signatures: the alignment of their frame
  /// sequences under `frame_dissimilarities`.
  /// @throws invalid_input as `frame_dissimilarities`.
  Similarity compare(const Description& a, const Description& b) const {
    return internal::aligned_similarity(alignment, normalization, frame_dissimilarities(a, b),
                                        "area-weighted distributions of the vertices' speeds and vertical "
                                        "rates at several lags, frames aligned in time");
  }
};

}  // namespace deformseg
