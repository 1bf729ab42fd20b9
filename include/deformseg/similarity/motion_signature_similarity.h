/// @file similarity/motion_signature_similarity.h
/// @brief `Motion_signature_similarity`: two animations compared frame by frame through how fast,
/// and how far up or down, their surfaces move at several time scales (`motion_signatures`),
/// aligned in time; needs no
/// correspondence between the two meshes, and sees rigid parts on bones as well as skin (beyond the
/// thesis).
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw.h>
#include <deformseg/exceptions.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/signatures/motion_signature_kernel.h>
#include <deformseg/signatures/motion_signature_stream.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/similarity/motion_signature_explanation.h>
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

/// @brief What `Motion_signature_similarity` compares of one animation: its motion signatures
/// (`motion_signatures`) at instants at most 1 / `signature_rate` seconds apart, each row with the
/// frame nearest its instant.
struct Motion_signature_description {
  /// @brief One signature per row, at increasing instants: `R x (lags x regions x quantiles)`
  /// (regions: the options' bands, twice that with sides), twice as wide with an up direction. In
  /// float, rounded once from the double values `motion_signatures_at` computes, and column-major
  /// (each dimension's R values contiguous): the layout of `Motion_signature_view` (see `view`),
  /// which the comparison kernel reads.
  Eigen::MatrixXf signatures;
  /// @brief Per row, the animation's frame nearest its instant: non-decreasing, from 0 to the last
  /// frame, every frame at least once.
  std::vector<std::size_t> frames;
};

/// @brief The rows of `d` in the order `order` gives (see `similarity_significance`); the frame of
/// each row is kept in place, so that alignments still name frames in order.
/// @pre every entry of `order` is below `d.signatures.rows()` (not checked).
inline Motion_signature_description reordered_frames(const Motion_signature_description& d,
                                                     std::span<const std::size_t> order) {
  return {reordered_frames(d.signatures, order), d.frames};
}

/// @brief The number of rows of `d` (see `similarity_significance`).
inline std::size_t frame_count(const Motion_signature_description& d) { return std::size_t(d.signatures.rows()); }

/// @brief The signatures of `d` as a view: its rows, width and floats, which `d` keeps (it must
/// outlive the view and not be resized meanwhile).
/// @par Complexity O(1).
inline signatures::Motion_signature_view view(const Motion_signature_description& d) {
  return {d.signatures.data(), std::size_t(d.signatures.rows()), std::size_t(d.signatures.cols())};
}

namespace internal {

/// The instants `Motion_signature_similarity` describes an animation of `frames` frames at `fps`:
/// its frames' when it is sampled at least `rate` times a second; else every 1 / rate seconds,
/// and its last frame's.
inline std::vector<double> signature_instants(std::size_t frames, double fps, double rate) {
  if (fps >= rate || frames < 2) return signatures::frame_instants(frames, fps);
  const double end = double(frames - 1) / fps;
  std::vector<double> instants;
  for (std::size_t k = 0; double(k) / rate < end - 1e-9 / rate; ++k) instants.push_back(double(k) / rate);
  instants.push_back(end);
  return instants;
}

/// Per instant, the nearest of frames sampled at `fps`.
inline std::vector<std::size_t> nearest_frames(std::span<const double> instants, double fps, std::size_t frames) {
  std::vector<std::size_t> nearest(instants.size());
  for (std::size_t r = 0; r < instants.size(); ++r)
    nearest[r] = std::min(frames - 1, std::size_t(std::llround(instants[r] * fps)));
  return nearest;
}

/// Alignment pairs of rows made pairs of frames (`frames_a`, `frames_b` per row), repeats dropped.
inline std::vector<std::pair<std::size_t, std::size_t>> pairs_of_frames(
    std::span<const std::pair<std::size_t, std::size_t>> rows, std::span<const std::size_t> frames_a,
    std::span<const std::size_t> frames_b) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const auto& [i, j] : rows) {
    const std::pair<std::size_t, std::size_t> pair{frames_a[i], frames_b[j]};
    if (out.empty() || out.back() != pair) out.push_back(pair);
  }
  return out;
}

// Dissimilarities kept row by row, each row contiguous: the alignments read them so.
using Row_major_floats = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The columns of an n x m matrix of valid dissimilarities in the order `order` gives: d(i, t) =
// matrix(i, order[t]). Refers to both. A row is gathered from the matrix's row i, contiguous, so
// that the shuffled reads stay within one row's cache lines.
struct Reordered_columns {
  const Row_major_floats& matrix;
  std::span<const std::size_t> order;
  static constexpr bool values_are_valid = true;
  double operator()(std::size_t i, std::size_t t) const { return matrix(Eigen::Index(i), Eigen::Index(order[t])); }
  void row(std::size_t i, std::size_t first, std::size_t count, double* out) const {
    const float* row = matrix.data() + i * std::size_t(matrix.cols());
    for (std::size_t k = 0; k < count; ++k) out[k] = row[order[first + k]];
  }
};

// Every value of `d` as a matrix of Scalar: double, or float, which holds the kernel's values (float
// computations) exactly in half the memory; column-major, or row-major with Options.
template <class Scalar, int Options = Eigen::ColMajor>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Options> dissimilarity_matrix(
    const signatures::Motion_signature_dissimilarity& d) {
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Options> out(Eigen::Index(d.rows()), Eigen::Index(d.cols()));
  std::vector<double> row(d.cols());
  for (std::size_t i = 0; i < d.rows(); ++i) {
    d.row(i, 0, d.cols(), row.data());
    for (std::size_t j = 0; j < d.cols(); ++j) out(Eigen::Index(i), Eigen::Index(j)) = Scalar(row[j]);
  }
  return out;
}

// What Motion_signature_similarity::reordering_comparison returns: the frame dissimilarities of
// a and b computed once, and the alignment and normalization to score b's reorderings with.
// Normalises the alignment's score and length alone when the policy gives them and the
// normalization takes them (Dtw, Subsequence_dtw, Smith_waterman with Best_score_normalization):
// no path, linear memory, the same value bit for bit; otherwise the whole alignment.
template <class Alignment, class Normalization>
class Reordering_comparison {
public:
  Reordering_comparison(Row_major_floats d, const Alignment& alignment, const Normalization& normalization)
      : d_(std::move(d)), alignment_(alignment), normalization_(normalization) {}

  // The value of a against b with its rows in the order `order`. Safe to call from several threads.
  double operator()(std::span<const std::size_t> order) const {
    const std::size_t n = std::size_t(d_.rows()), m = std::size_t(d_.cols());
    const Reordered_columns d{d_, order};
    if constexpr (without_path)
      return normalization_(alignment_, alignment_.score_and_length(n, m, d), n, m);
    else
      return normalization_(alignment_, alignment_.align(n, m, d), n, m);
  }

private:
  static constexpr bool without_path =
      alignment::ScoreAndLengthPolicy<Alignment> &&
      std::is_invocable_r_v<double, const Normalization&, const Alignment&, const alignment::Score_and_length&,
                            std::size_t, std::size_t>;

  Row_major_floats d_;
  Alignment alignment_;
  Normalization normalization_;
};

}  // namespace internal

/// @brief Similarity policy (models `SimilarityPolicy`): each frame of an animation becomes its
/// motion signature (`motion_signatures`: the area-weighted quantiles of its vertices' speeds at
/// lags of 1, 4, 16 and 128 thirtieths of a second, as logarithms, and of their rates up or down,
/// measured in seconds at the animation's frame rate), two frames are
/// compared by the root mean square difference r of their signatures, made a dissimilarity
/// `1 - exp(-(r / scale)^2)` in [0, 1], and the two frame sequences are aligned by `alignment`
/// (dynamic time warping by default); `normalization` makes the value, for DTW one minus the mean
/// dissimilarity along the warping path.
///
/// The value is 1 for an animation and any translated, scaled (or remeshed, up to the area
/// weights' change) copy of it, turned about the up direction (`Motion_signature_options::up`,
/// +Y by default; about any axis with `std::nullopt`), and (up to the linear interpolation between
/// frames) for the same motion sampled at another frame rate, each animation's own
/// (`frames_per_second`). A motion played faster, such as the same frames shown at twice the rate,
/// is a faster motion and scores lower, as a run against a walk. The calibration, and what values
/// to expect on real characters: @ref section_signature_calibration.
///
/// What it cannot see: which part of the body moves (a signature is a distribution over the
/// surface, not a map), nor any direction but up and down.
/// @tparam Alignment an `alignment::AlignmentPolicy` (default `alignment::Dtw`: the whole of both
/// motions, warped; `alignment::Subsequence_dtw` finds a short motion inside a longer one).
/// @tparam Normalization how the score becomes the value (default `Best_score_normalization`).
/// @par Complexity `describe`: `motion_signatures`' O(R V L log k) for R rows (the T frames, or
/// duration x `signature_rate` + 1 rows for an animation sampled more slowly); `compare`:
/// O(Ra Rb L k) for the row dissimilarities plus the alignment's O(Ra Rb).
/// @par Precision The signatures are computed in double and kept in float; the frame
/// dissimilarities are computed in float by one vectorised kernel (`Motion_signature_dissimilarity`),
/// the alignment and the value in double. Values are within the kernel's bound of an all-double
/// computation (`Motion_signature_dissimilarity`, @ref section_signature_precision), identical
/// however a comparison is reached (`compare`, `similarity_matrix`, `frame_dissimilarities`, the
/// significance's shuffled copies), and may differ in the last bits between builds for other
/// instruction sets.
template <alignment::AlignmentPolicy Alignment = alignment::Dtw, class Normalization = Best_score_normalization>
struct Motion_signature_similarity {
  /// @brief The lags, quantiles, floor and up direction of the signatures. Default:
  /// `Motion_signature_options{}`.
  signatures::Motion_signature_options signatures{};
  /// @brief The RMS difference of two frames' signatures at which their dissimilarity is 1 - 1/e.
  /// It sets where values fall between 0 and 1: the same motion on different bodies high, different
  /// motions low. Default 1.77 (how it was chosen: @ref section_signature_calibration).
  double scale = 1.77;
  /// @brief How the two frame sequences are aligned. Default: dynamic time warping, no window.
  Alignment alignment{};
  /// @brief How the score becomes the similarity. Default: `Best_score_normalization`.
  Normalization normalization{};
  /// @brief The fewest signatures per second: an animation sampled more slowly is described every
  /// 1 / `signature_rate` seconds (and at its last frame), its positions interpolated between
  /// frames, so that its signatures meet those of the same motion sampled faster at the same
  /// instants; one sampled at least this fast, at its frames. Default 30, the lags' unit (what it
  /// changes: @ref section_signature_frame_rate).
  double signature_rate = 30;

  /// @brief What is compared of one animation: its signatures and the frame of each.
  using Description = Motion_signature_description;

  /// @brief The signatures of `animation` at its frames, or every 1 / `signature_rate` seconds
  /// when its frame rate (`frames_per_second`) is lower.
  /// @tparam Mesh a `DeformingMesh`.
  /// @throws invalid_input as `motion_signatures` (fewer than two frames, ...), or when
  /// `signature_rate` is not positive and finite.
  template <mesh::DeformingMesh Mesh>
  Description describe(const Mesh& animation) const {
    return signatures::with_positions_and_weights(animation, [&](auto positions, std::span<const double> weights) {
      return describe_positions(positions, weights, mesh::frames_per_second(animation));
    });
  }

  /// @brief The signatures of an animation given as raw positions (`T x 3V` coordinates) and
  /// vertex weights (V, summing to 1), for data with no mesh built, sampled at `frames_per_second`
  /// (default 30); as `describe`.
  /// @throws invalid_input as `describe`.
  template <class Coordinate>
  Description describe_positions(std::span<const Coordinate> positions, std::span<const double> weights,
                                 double frames_per_second = mesh::default_frames_per_second) const {
    if (!(signature_rate > 0) || !std::isfinite(signature_rate))
      throw invalid_input("Motion_signature_similarity: the signature rate must be positive and finite");
    mesh::check_frames_per_second(frames_per_second, "motion_signatures");
    const std::size_t frames = weights.empty() ? 0 : positions.size() / (3 * weights.size());
    const std::vector<double> instants = internal::signature_instants(frames, frames_per_second, signature_rate);
    Description d;
    d.signatures = signatures::motion_signatures_at(positions, weights, signatures, frames_per_second,
                                                    std::span<const double>(instants))
                       .template cast<float>();
    d.frames = internal::nearest_frames(instants, frames_per_second, frames);
    return d;
  }

  /// @brief The signatures of an animation read frame by frame from `source` (a point cache, a
  /// frame sequence or a glTF clip: `io/frame_stream.h`), equal bit for bit to `describe` of the
  /// same frames, in memory that grows with the longest lag (`signatures::streamed_ring_frames`
  /// frames), not with the animation's length.
  /// @tparam Source a `signatures::FrameSource`, read twice from its start.
  /// @throws invalid_input as `describe`, or as the source does (a frame that cannot be read).
  /// @par Complexity as `describe`; memory O(V ring + R W).
  template <signatures::FrameSource Source>
  Description describe_stream(Source& source) const {
    if (!(signature_rate > 0) || !std::isfinite(signature_rate))
      throw invalid_input("Motion_signature_similarity: the signature rate must be positive and finite");
    const double fps = source.frames_per_second();
    mesh::check_frames_per_second(fps, "motion_signatures");
    const std::size_t frames = source.num_frames();
    const std::vector<double> instants = internal::signature_instants(frames, fps, signature_rate);
    Description d;
    d.signatures = signatures::motion_signatures_streamed(source, signatures, std::span<const double>(instants))
                       .template cast<float>();
    d.frames = internal::nearest_frames(instants, fps, frames);
    return d;
  }

  /// @brief The dissimilarities of the rows of `described_a` and those of `described_b` (their
  /// frames, unless an animation is sampled below `signature_rate`), computed when asked:
  /// `1 - exp(-(r / scale)^2)` in [0, 1], r the RMS difference of two rows' signatures, by the
  /// float kernel of `Motion_signature_dissimilarity` (which refers to the descriptions: they must
  /// outlive it).
  /// @throws invalid_input when the signatures have different widths or none, or the scale is not
  /// positive.
  /// @par Complexity O(1), plus a copy of `described_b`'s signatures when it has fewer than 16 rows.
  signatures::Motion_signature_dissimilarity dissimilarity(const Description& described_a,
                                                           const Description& described_b) const {
    return dissimilarity(view(described_a), view(described_b));
  }

  /// @brief `dissimilarity` of two views of signatures (a description's, a stored clip's: a
  /// `search::MotionCollection`'s `view(i)`), which it refers to: they must outlive it.
  /// @throws invalid_input as `dissimilarity` of descriptions.
  /// @par Complexity O(1), plus a copy of `b`'s signatures when it has fewer than 16 rows.
  signatures::Motion_signature_dissimilarity dissimilarity(signatures::Motion_signature_view a,
                                                           signatures::Motion_signature_view b) const {
    if (a.width != b.width || a.width == 0)
      throw invalid_input("Motion_signature_similarity: signatures of " + std::to_string(a.width) + " and " +
                          std::to_string(b.width) + " values per frame");
    if (!(scale > 0)) throw invalid_input("Motion_signature_similarity: the scale must be positive");
    return signatures::Motion_signature_dissimilarity(a, b, signatures::frame_dissimilarity_unit(a.width, scale));
  }

  /// @brief The `Ra x Rb` dissimilarities in [0, 1] of the descriptions' rows as a matrix: entry
  /// (i, j) is `dissimilarity(described_a, described_b)(i, j)`, the very value `compare` aligns.
  /// @throws invalid_input as `dissimilarity`.
  /// @par Complexity O(Ra Rb width) time, O(Ra Rb) memory.
  Eigen::MatrixXd frame_dissimilarities(const Description& described_a, const Description& described_b) const {
    return frame_dissimilarities(view(described_a), view(described_b));
  }

  /// @brief `frame_dissimilarities` of two views of signatures (a description's, a stored clip's).
  /// @throws invalid_input as `dissimilarity`.
  /// @par Complexity O(Ra Rb width) time, O(Ra Rb) memory.
  Eigen::MatrixXd frame_dissimilarities(signatures::Motion_signature_view a,
                                        signatures::Motion_signature_view b) const {
    return internal::dissimilarity_matrix<double>(dissimilarity(a, b));
  }

  /// @brief The similarity of two animations from their signatures: the alignment of their rows
  /// under `dissimilarity` (read a cell or a row at a time, no matrix kept), its pairs given as the
  /// animations' frames (`Description::frames`, repeats dropped).
  /// @throws invalid_input as `dissimilarity`.
  /// @par Complexity O(Ra Rb width) for the dissimilarities plus the alignment's O(Ra Rb).
  Similarity compare(const Description& a, const Description& b) const {
    Similarity result = aligned_rows(a, b);
    result.alignment = internal::pairs_of_frames(result.alignment, a.frames, b.frames);
    return result;
  }

  /// @brief Where the signatures of `a` and `b` differ along the alignment `compare` finds
  /// (`explain_signatures` of its pairs of rows): each channel's share of the differences and its
  /// mean difference, so that a user can see which time scale, height band and half of the
  /// surface made two motions alike or different.
  /// @throws invalid_input as `dissimilarity`, or when the descriptions were not made with this
  /// policy's `signatures` options (another width).
  /// @par Complexity `compare`'s, plus O(P width) for the P aligned pairs.
  /// @par Example
  /// @include explain_similarity.cpp
  Motion_signature_explanation explain(const Description& a, const Description& b) const {
    return explain_signatures(a.signatures, b.signatures, aligned_rows(a, b).alignment, signatures);
  }

  /// @brief What `similarity_significance` scores the shuffled copies of `b` with (see
  /// `ReorderingComparison`): a function object `c` such that `c(order)` is
  /// `compare(a, reordered_frames(b, order)).value` bit for bit, which computes the `Ra x Rb`
  /// frame dissimilarities once, here, and for each order only the alignment of their columns
  /// reordered (a reordered row of b has the very dissimilarities it had in place, the kernel's
  /// values depending on the two rows alone). The value needs no path: when `Alignment` models
  /// `alignment::ScoreAndLengthPolicy` and `normalization` takes an
  /// `alignment::Score_and_length` (the library's policies with `Best_score_normalization`),
  /// `c(order)` normalises `alignment.score_and_length`'s score and number of pairs, those of the
  /// path; otherwise it aligns in full. `c` may be called from several threads at once.
  /// @throws invalid_input as `dissimilarity`.
  /// @par Complexity here O(Ra Rb width), O(Ra Rb) floats of memory (kept by `c`); each
  /// `c(order)` the alignment's O(Ra Rb) time, in O(Ra + Rb) memory without the path (with it,
  /// O(Ra Rb) bytes for the traceback, up to the policy's `max_trace_bytes`).
  internal::Reordering_comparison<Alignment, Normalization> reordering_comparison(const Description& a,
                                                                                  const Description& b) const {
    return {internal::dissimilarity_matrix<float, Eigen::RowMajor>(dissimilarity(a, b)), alignment, normalization};
  }

private:
  // The similarity of the rows of a and b, its alignment pairs of rows.
  Similarity aligned_rows(const Description& a, const Description& b) const {
    return internal::aligned_similarity(alignment, normalization, frame_count(a), frame_count(b), dissimilarity(a, b),
                                        "area-weighted distributions of the vertices' speeds and vertical rates at "
                                        "several lags, frames aligned in time");
  }
};

}  // namespace deformseg::similarity
