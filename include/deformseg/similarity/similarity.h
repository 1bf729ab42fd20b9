/// @file similarity/similarity.h
/// @brief What a motion similarity gives (`Similarity`), the `SimilarityPolicy` concept, and the
/// default normalisation of alignment scores into [0, 1] (`Best_score_normalization`).
#pragma once

#include <deformseg/alignment/alignment.h>

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::similarity {

/// @brief The similarity of two animations A and B.
struct Similarity {
  /// @brief The similarity in [0, 1]: 1 for an animation and itself (or a rotated, translated,
  /// scaled copy of it), lower the less alike the two motions are; as the policy's normalisation
  /// makes it from `score`.
  double value = 0;
  /// @brief The raw score of the alignment (its sense is the alignment policy's:
  /// `higher_is_better`).
  double score = 0;
  /// @brief The frame-to-frame alignment: pairs (frame of A, frame of B), increasing in both.
  std::vector<std::pair<std::size_t, std::size_t>> alignment;
  /// @brief Per frame of A, the label the policy aligned (for `Evolving_graph_similarity`, the
  /// cluster of the frame's key-frame graph); empty for a policy that aligns no labels.
  std::vector<std::size_t> labels_a;
  /// @brief Per frame of B, as `labels_a`.
  std::vector<std::size_t> labels_b;
  /// @brief What the policy compared, in words, for reports.
  std::string compared;
};

/// @brief A motion similarity policy for animations of type `Mesh`: `p.describe(mesh)` computes
/// what the policy compares of one animation (`P::Description`: its evolving graph, its strain
/// histograms, ...), once per animation, and `p.compare(a, b)` compares two descriptions into a
/// `Similarity`. `motion_similarity` and `similarity_matrix` run them. See @ref SimilarityPolicyConcept.
template <class P, class Mesh>
concept SimilarityPolicy = std::copy_constructible<P> && requires(const P& p, const Mesh& mesh,
                                                                  const typename P::Description& d) {
  { p.describe(mesh) } -> std::same_as<typename P::Description>;
  { p.compare(d, d) } -> std::same_as<Similarity>;
};

/// @brief Which length `Best_score_normalization` measures a maximising alignment against.
enum class Normalize_by {
  shorter,  ///< the shorter sequence's self-score (@ref method_similarity): a motion found whole inside a longer one scores 1
  longer  ///< the longer one's: a motion scores 1 only against one of its own length
};

/// @brief The default normalisation of an alignment into a similarity in [0, 1].
///
/// For a policy that maximises a score (`higher_is_better`, such as `alignment::Smith_waterman`):
/// the score over the best score two sequences of `length`'s length can reach (every pair at
/// dissimilarity 0: that sequence's self-score); by default the shorter one, as the method says
/// (@ref method_similarity), so that a local alignment which finds the whole shorter motion inside the longer one
/// gives 1 (a tube standing still for 6 frames against one that stands still for 6 frames and then
/// bends); `Normalize_by::longer` counts what the longer motion does besides. For a policy that
/// minimises a cost (`alignment::Dtw`, `alignment::Subsequence_dtw`): 1 minus the mean
/// dissimilarity along the aligned pairs, which needs dissimilarities in [0, 1]. Either way the
/// value is clamped to [0, 1], an empty sequence gives 0, and two identical sequences give 1.
///
/// Not invariant under time reversal: a motion played backwards is another motion, and it scores
/// as much as its alignment with the original finds alike.
struct Best_score_normalization {
  /// @brief The sequence whose self-score is the best possible score. Default: the shorter.
  Normalize_by length = Normalize_by::shorter;

  /// @brief The similarity of `result`, the alignment by `policy` of sequences of `n` and `m`
  /// elements: the value of its score and number of pairs (below).
  /// @par Complexity for a maximising policy, its score of two perfect sequences of the chosen
  /// length k: O(k^2) for Smith–Waterman (by default k = min(n, m), so no more than the alignment
  /// itself); else O(1).
  template <alignment::AlignmentPolicy Policy>
  double operator()(const Policy& policy, const alignment::Alignment& result, std::size_t n, std::size_t m) const {
    return (*this)(policy, alignment::score_and_length(result), n, m);
  }

  /// @brief The same similarity from the alignment's score and number of pairs alone (what a
  /// `ScoreAndLengthPolicy`'s `score_and_length` gives, without the pairs): bit for bit the value
  /// of the alignment they come from.
  /// @par Complexity as above.
  template <alignment::AlignmentPolicy Policy>
  double operator()(const Policy& policy, const alignment::Score_and_length& result, std::size_t n,
                    std::size_t m) const {
    if (n == 0 || m == 0) return 0.0;
    double value = 0;
    if constexpr (Policy::higher_is_better) {
      const std::size_t k = length == Normalize_by::shorter ? std::min(n, m) : std::max(n, m);
      const double best = policy.score(k, k, [](std::size_t, std::size_t) { return 0.0; });
      value = best > 0 ? result.score / best : 0.0;
    } else {
      value = result.length == 0 ? 0.0 : 1.0 - result.score / double(result.length);
    }
    return std::clamp(value, 0.0, 1.0);
  }
};

namespace internal {

/// The similarity of two frame sequences of `n` and `m` frames under the frame dissimilarity `d`
/// (an `alignment::Dissimilarity`): aligned by `alignment`, the score made a value by
/// `normalization`; what the per-frame policies' `compare` shares.
template <alignment::AlignmentPolicy Alignment, class Normalization, alignment::Dissimilarity D>
Similarity aligned_similarity(const Alignment& alignment, const Normalization& normalization, std::size_t n,
                              std::size_t m, const D& d, std::string compared) {
  alignment::Alignment aligned = alignment.align(n, m, d);
  Similarity result;
  result.value = normalization(alignment, aligned, n, m);
  result.score = aligned.score;
  result.alignment = std::move(aligned.pairs);
  result.compared = std::move(compared);
  return result;
}

/// As above, under the `n x m` frame dissimilarities `d`.
template <alignment::AlignmentPolicy Alignment, class Normalization>
Similarity aligned_similarity(const Alignment& alignment, const Normalization& normalization, const Eigen::MatrixXd& d,
                              std::string compared) {
  return aligned_similarity(alignment, normalization, std::size_t(d.rows()), std::size_t(d.cols()),
                            alignment::matrix_dissimilarity(d), std::move(compared));
}

}  // namespace internal

}  // namespace deformseg::similarity
