/// @file similarity/self_similarity_matching.h
/// @brief `Self_similarity_matching`: two animations compared through their own frame x frame
/// self-dissimilarity matrices, so location-aware inside each animation yet needing no
/// correspondence between the two meshes (beyond the thesis; after Junejo et al. 2011 and
/// Tralie 2017).
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/signatures/procrustes_distances.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/similarity/similarity.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::similarity {

/// @brief What `Self_similarity_matching` compares of one animation.
struct Self_similarity_description {
  /// @brief The `T x T` self-dissimilarity matrix: the area-weighted Procrustes distance between
  /// every two frames, in units of the animation's RMS radius.
  Eigen::MatrixXd distances;
  /// @brief `T x k`: per frame, the k quantiles of its row of `distances` inside the window
  /// (`Self_similarity_options::window`), ascending.
  Eigen::MatrixXd profiles;
};

/// @brief The options of `Self_similarity_matching` (how the defaults were chosen:
/// @ref section_self_similarity_defaults).
struct Self_similarity_options {
  /// @brief Frames on either side of a frame whose distances make its profile: 0 for the whole
  /// row. A finite window lets a motion found inside a longer one keep its profiles. Default 30
  /// (one second at 30 fps).
  std::size_t window = 30;
  /// @brief Quantiles k per profile. Default 16.
  std::size_t quantiles = 16;
  /// @brief The mean absolute difference between two profiles at which two frames stop being
  /// alike: the frame dissimilarity is `min(1, difference / (2 tolerance))`, so a pair of frames
  /// scores above 0 under Smith–Waterman's default +1 / -1 below the tolerance and below 0 above
  /// it. Default 0.3 (30 % of the body's RMS radius, averaged over the profile).
  double tolerance = 0.3;
};

namespace internal {

/// The normalisation `Self_similarity_matching` starts with: for `Best_score_normalization`, by
/// the longer animation (a short piece of motion found inside a long clip of another motion is
/// common, and the shorter's self-score would make it 1); any other normalisation as it defaults.
template <class Normalization>
Normalization self_similarity_normalization() {
  if constexpr (std::is_same_v<Normalization, Best_score_normalization>) return {Normalize_by::longer};
  else return {};
}

/// The `k` quantiles (at (q + 1/2) / k, linearly interpolated) of `values`, which it sorts.
inline Eigen::RowVectorXd sorted_quantiles(std::vector<double>& values, Eigen::Index k) {
  std::sort(values.begin(), values.end());
  Eigen::RowVectorXd out(k);
  const double last = double(values.size() - 1);
  for (Eigen::Index q = 0; q < k; ++q) {
    const double at = std::clamp((double(q) + 0.5) / double(k) * double(values.size()) - 0.5, 0.0, last);
    const std::size_t below = std::size_t(std::floor(at));
    const std::size_t above = std::min(below + 1, values.size() - 1);
    const double f = at - double(below);
    out(q) = (1 - f) * values[below] + f * values[above];
  }
  return out;
}

/// Per row i of `distances`, the distances D(i, i + d) to the frames at offsets d spread evenly
/// over [-window, window] (k of them; a frame past either end counts as that end's frame).
inline Eigen::MatrixXd temporal_profiles(const Eigen::MatrixXd& distances, std::size_t window, std::size_t samples) {
  const Eigen::Index frames = distances.rows();
  Eigen::MatrixXd profiles(frames, Eigen::Index(samples));
  for (Eigen::Index i = 0; i < frames; ++i)
    for (Eigen::Index q = 0; q < Eigen::Index(samples); ++q) {
      const double offset = samples == 1 ? 0.0 : (2.0 * double(q) / double(samples - 1) - 1.0) * double(window);
      const Eigen::Index j = std::clamp(i + Eigen::Index(std::lround(offset)), Eigen::Index(0), frames - 1);
      profiles(i, q) = distances(i, j);
    }
  return profiles;
}

/// Per row of `distances`, the quantiles of its entries within `window` frames of the diagonal.
inline Eigen::MatrixXd row_profiles(const Eigen::MatrixXd& distances, std::size_t window, std::size_t quantiles) {
  const std::size_t frames = std::size_t(distances.rows());
  Eigen::MatrixXd profiles(distances.rows(), Eigen::Index(quantiles));
  std::vector<double> values;
  for (std::size_t i = 0; i < frames; ++i) {
    const std::size_t first = window == 0 || i < window ? 0 : i - window;
    const std::size_t last = window == 0 ? frames - 1 : std::min(frames - 1, i + window);
    values.clear();
    for (std::size_t j = first; j <= last; ++j) values.push_back(distances(Eigen::Index(i), Eigen::Index(j)));
    profiles.row(Eigen::Index(i)) = sorted_quantiles(values, Eigen::Index(quantiles));
  }
  return profiles;
}

}  // namespace internal

/// @brief Similarity policy (models `SimilarityPolicy`): each animation's frames are compared with
/// each other (the weighted Procrustes distance of their vertex positions: centred, scaled to the
/// body's size, rotated onto each other), and two animations are compared through these
/// self-dissimilarity matrices, row against row.
///
/// Inside one animation the vertices correspond, so its matrix knows where on the body things
/// change; articulated rigid parts (a robot's limbs on bones) count as much as skin, as positions
/// are compared, not strain. The matrix does not depend on the mesh, its position, orientation or
/// scale. Each frame is described by the profile of its row: the quantiles of its distances to the
/// frames within `window` of it, which do not depend on the phase, nor (within the window) on the
/// cycle length or on what the animation does before or after. Frames are compared by the mean
/// absolute difference of their profiles, made a dissimilarity in [0, 1] by the tolerance, and the
/// frame sequences are aligned by `alignment` (Smith–Waterman by default: a motion inside a longer
/// one is found, and aligned); `normalization` makes the value, 1 for an animation and any moved, rotated,
/// scaled copy of it (or a remeshed one, up to the Procrustes distances' change).
///
/// Calibration: a pair of frames whose profiles differ by more than the tolerance scores below 0,
/// so unrelated motions gather little score and their value falls towards 0.
///
/// What it cannot see: which of two body parts moves (the profiles are per frame, not per part),
/// nor the direction of time within a window (a motion and its reverse have alike profiles;
/// the alignment still orders them).
/// @tparam Alignment an `alignment::AlignmentPolicy` (default `alignment::Smith_waterman`).
/// @tparam Normalization how the score becomes the value (default `Best_score_normalization`,
/// here over the longer animation's self-score).
/// @par Complexity `describe`: O(T^2 V) (one matrix product) plus O(T^2) 3 x 3 SVDs and
/// O(T w log w) for the profiles; `compare`: O(Ta Tb k) for the frame dissimilarities plus the
/// alignment's O(Ta Tb).
template <alignment::AlignmentPolicy Alignment = alignment::Smith_waterman,
          class Normalization = Best_score_normalization>
struct Self_similarity_matching {
  /// @brief The window, quantiles and tolerance. Default: `Self_similarity_options{}`.
  Self_similarity_options options{};
  /// @brief How the two frame sequences are aligned. Default: Smith–Waterman, +1 / -1 / -1.
  Alignment alignment{};
  /// @brief How the score becomes the similarity. Default: `Best_score_normalization` by the
  /// longer animation (`Normalize_by::longer`): a motion inside a longer one scores the share of
  /// the longer it fills; set `Normalize_by::shorter` for 1.
  Normalization normalization = internal::self_similarity_normalization<Normalization>();

  /// @brief What is compared of one animation.
  using Description = Self_similarity_description;

  /// @brief The description of `animation`, weighting each vertex by its share of the first
  /// frame's area.
  /// @tparam Mesh a `DeformingMesh`.
  /// @throws invalid_input when the animation has no frame or no vertex.
  template <mesh::DeformingMesh Mesh>
  Description describe(const Mesh& animation) const {
    if constexpr (requires { animation.all_positions(); animation.triangles(); }) {
      if (animation.num_frames() == 0) throw invalid_input("Self_similarity_matching: an animation without frames");
      const std::vector<double> positions(animation.all_positions().begin(), animation.all_positions().end());
      const std::span<const double> first(positions.data(), 3 * animation.num_vertices());
      return describe_positions(positions, signatures::vertex_area_weights(first, animation.triangles(),
                                                                         animation.num_vertices()));
    } else {
      return describe(mesh::make_deforming_mesh<double>(animation));
    }
  }

  /// @brief The description of an animation given as raw positions, for data with no mesh built
  /// (a triangle soup, a sampled glTF clip): `positions` holds `T x 3V` coordinates (frame after
  /// frame, x y z per vertex), `weights` V non-negative vertex weights (e.g.
  /// `signatures::vertex_area_weights`), not all 0.
  /// @throws invalid_input when the sizes disagree.
  Description describe_positions(std::span<const double> positions, std::span<const double> weights) const {
    if (options.quantiles == 0) throw invalid_input("Self_similarity_matching: 0 quantiles");
    Description d;
    d.distances = signatures::procrustes_distances(positions, weights);
    if (d.distances.rows() == 0) throw invalid_input("Self_similarity_matching: an animation without frames");
    d.profiles = internal::row_profiles(d.distances, options.window, options.quantiles);
    return d;
  }

  /// @brief The `Ta x Tb` frame dissimilarities in [0, 1]: the profiles' mean absolute
  /// difference over twice the tolerance, at most 1.
  Eigen::MatrixXd frame_dissimilarities(const Description& a, const Description& b) const {
    if (a.profiles.cols() != b.profiles.cols())
      throw invalid_input("Self_similarity_matching: descriptions with different quantile counts");
    Eigen::MatrixXd d(a.profiles.rows(), b.profiles.rows());
    const double scale = 1.0 / (2 * options.tolerance * double(a.profiles.cols()));
    for (Eigen::Index j = 0; j < d.cols(); ++j)
      for (Eigen::Index i = 0; i < d.rows(); ++i)
        d(i, j) = std::min(1.0, (a.profiles.row(i) - b.profiles.row(j)).cwiseAbs().sum() * scale);
    return d;
  }

  /// @brief The similarity of two animations from their descriptions: the alignment of their
  /// frame sequences under `frame_dissimilarities`.
  /// @throws invalid_input when the descriptions have different quantile counts.
  Similarity compare(const Description& a, const Description& b) const {
    return internal::aligned_similarity(
        alignment, normalization, frame_dissimilarities(a, b),
        "profiles of each frame's Procrustes distances to its neighbouring frames, aligned in time");
  }
};

/// @brief The description with its frames in the order `order` gives (row t of the profiles is
/// row `order[t]`; the self-dissimilarity matrix is kept, as `compare` reads only the profiles):
/// what `similarity_significance` shuffles.
inline Self_similarity_description reordered_frames(const Self_similarity_description& d,
                                                    std::span<const std::size_t> order) {
  return {d.distances, reordered_frames(d.profiles, order)};
}

/// @brief The number of frames of a description: its profiles' rows.
inline std::size_t frame_count(const Self_similarity_description& d) { return std::size_t(d.profiles.rows()); }

/// @brief `similarity_significance` for `Self_similarity_matching`: the z-score of
/// `policy.compare(a, b).value` against `copies` copies of `b` with frames shuffled by `random`.
/// @tparam Policy a `Self_similarity_matching`.
/// @tparam Random a generator of 32 or 64 uniform bits: `std::mt19937` or `std::mt19937_64`.
/// @param policy, a, b, copies, random as `similarity_significance`.
/// @param threads the threads that compare the copies: 0 (default) for all (`thread_count`), else
/// 1 to `max_threads`. The result does not depend on it.
/// @return the z-score; 0 when the copies all score the same as each other (no spread).
/// @throws invalid_input when `copies < 2` or `threads` is out of range, or as `compare`.
/// @par Complexity `copies + 1` compares.
template <class Policy, class Random>
double self_similarity_significance(const Policy& policy, const Self_similarity_description& a,
                                    const Self_similarity_description& b, std::size_t copies, Random& random,
                                    int threads = 0) {
  return similarity_significance(policy, a, b, copies, random, threads);
}

}  // namespace deformseg::similarity
