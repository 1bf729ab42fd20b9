/// @file alignment/alignment.h
/// @brief What an alignment policy returns (`Alignment`, and `Score_and_length` without the
/// pairs), the `AlignmentPolicy` and `ScoreAndLengthPolicy` concepts, the dissimilarity
/// adaptors `label_mismatch` and `matrix_dissimilarity`, and `align` for two label sequences.
#pragma once

#include <Eigen/Core>

#include <concepts>
#include <cstddef>
#include <ranges>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::alignment {

/// @brief The result of aligning a sequence A of n elements with a sequence B of m elements.
struct Alignment {
  /// @brief The policy's score: for a policy whose `higher_is_better` is true (Smith_waterman) a
  /// score to maximise, otherwise (Dtw, Subsequence_dtw) a cost to minimise.
  double score = 0;
  /// @brief The aligned index pairs (i of A, j of B), in increasing order of both; elements left
  /// against a gap are omitted. A local alignment gives only its local part (possibly none).
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
};

/// @brief An alignment's score and its number of pairs, without the pairs: all that
/// `similarity::Best_score_normalization` reads of an alignment, which a policy can compute in
/// memory linear in the lengths (`ScoreAndLengthPolicy`) where the pairs need a traceback.
struct Score_and_length {
  /// @brief `Alignment::score`, bit for bit.
  double score = 0;
  /// @brief The number of aligned pairs, `Alignment::pairs.size()`.
  std::size_t length = 0;
};

/// @brief The score and the number of pairs of `alignment`.
/// @par Complexity O(1).
inline Score_and_length score_and_length(const Alignment& alignment) {
  return {alignment.score, alignment.pairs.size()};
}

/// @brief A pairwise dissimilarity: `d(i, j)` is a `double >= 0`, finite, between element i of
/// the first sequence and element j of the second; typically in [0, 1] (0 for equal elements).
/// A dissimilarity whose values are known to be finite and `>= 0` may say so with a member
/// `static constexpr bool values_are_valid = true`: the policies then skip their checks.
template <class D>
concept Dissimilarity = std::copy_constructible<D> && requires(const D& d, std::size_t i, std::size_t j) {
  { d(i, j) } -> std::convertible_to<double>;
};

/// @brief A `Dissimilarity` that also gives a run of one row at once, which the policies then
/// read instead of calling `d(i, j)` once per cell (a vectorised kernel computes several cells
/// together): `d.row(i, first, count, out)` sets `out[k] = d(i, first + k)` for `k < count`.
///
/// The values must be those of `d(i, j)` bit for bit: a policy may read a cell either way
/// (`Dtw::score` reads cells one by one when it walks the transposed grid), and its results must
/// not depend on which. They are checked (finite, `>= 0`) as the cellwise ones are, unless
/// `values_are_valid`. `row` is called with `first + count` at most the second sequence's length
/// and `count >= 1`; it must not keep `out`.
template <class D>
concept RowDissimilarity =
    Dissimilarity<D> && requires(const D& d, std::size_t i, std::size_t first, std::size_t count, double* out) {
      d.row(i, first, count, out);
    };

namespace internal {
// The dissimilarity the AlignmentPolicy concept checks policies with; never defined or called.
struct Dissimilarity_archetype {
  double operator()(std::size_t, std::size_t) const;
};
}  // namespace internal

/// @brief An alignment policy (see @ref AlignmentPolicyConcept): for `const P& p`, lengths
/// `std::size_t n, m` and a `Dissimilarity d`, `p.align(n, m, d)` returns the `Alignment` with
/// its pairs, `p.score(n, m, d)` the same score alone (in memory linear in `min(n, m)` for the
/// library's policies), and the constant `P::higher_is_better` says whether the score is to be
/// maximised (true) or is a cost (false).
template <class P>
concept AlignmentPolicy = std::copy_constructible<P> &&
                          requires(const P& p, std::size_t n, const internal::Dissimilarity_archetype& d) {
                            { p.align(n, n, d) } -> std::same_as<Alignment>;
                            { p.score(n, n, d) } -> std::same_as<double>;
                            { P::higher_is_better } -> std::convertible_to<bool>;
                            typename std::bool_constant<P::higher_is_better>;
                          };

/// @brief An `AlignmentPolicy` that also gives `align`'s score and number of pairs without the
/// pairs: for `const P& p`, `p.score_and_length(n, m, d)` returns
/// `score_and_length(p.align(n, m, d))` exactly (the same score bit for bit, the length of the
/// path that `align`'s ties choose), in memory linear in one length. The library's three policies
/// model it; `Motion_signature_similarity` scores the significance's shuffled copies so.
template <class P>
concept ScoreAndLengthPolicy =
    AlignmentPolicy<P> && requires(const P& p, std::size_t n, const internal::Dissimilarity_archetype& d) {
      { p.score_and_length(n, n, d) } -> std::same_as<Score_and_length>;
    };

/// @brief The dissimilarity of two label sequences: 0 where the labels are equal, 1 elsewhere.
/// Refers to the sequences, which must outlive it; made by `label_mismatch`.
/// @tparam LabelA, LabelB the element types, comparable with `==`.
template <class LabelA, class LabelB>
class Label_mismatch {
public:
  /// @brief The dissimilarity of `a` and `b`, which it refers to.
  Label_mismatch(std::span<const LabelA> a, std::span<const LabelB> b) : a_(a), b_(b) {}
  /// @brief 0 when `a[i] == b[j]`, else 1.
  /// @pre `i < a.size()`, `j < b.size()` (not checked: this is the inner loop).
  double operator()(std::size_t i, std::size_t j) const { return a_[i] == b_[j] ? 0.0 : 1.0; }
  /// @brief Its values are 0 or 1, so the policies need not check them. (A dissimilarity of one's
  /// own may declare the same to skip the checks.)
  static constexpr bool values_are_valid = true;

private:
  std::span<const LabelA> a_;
  std::span<const LabelB> b_;
};

/// @brief The dissimilarity of two label sequences, 0 for equal labels and 1 for different ones.
/// @param a, b contiguous sequences of labels comparable with `==` (`std::vector<int>`, ...),
/// referred to, not copied: they must outlive the result.
/// @return a `Label_mismatch`, a `Dissimilarity` for `align(a.size(), b.size(), d)`.
/// @par Complexity O(1); each call O(1).
/// @par Example
/// @include label_mismatch.cpp
template <std::ranges::contiguous_range A, std::ranges::contiguous_range B>
  requires std::equality_comparable_with<std::ranges::range_value_t<A>, std::ranges::range_value_t<B>>
auto label_mismatch(const A& a, const B& b) {
  using La = std::ranges::range_value_t<A>;
  using Lb = std::ranges::range_value_t<B>;
  return Label_mismatch<La, Lb>(std::span<const La>(std::ranges::data(a), std::ranges::size(a)),
                                std::span<const Lb>(std::ranges::data(b), std::ranges::size(b)));
}

/// @brief The dissimilarity given by a precomputed n x m matrix: `d(i, j) = matrix(i, j)`.
/// Refers to the matrix, which must outlive it; made by `matrix_dissimilarity`.
class Matrix_dissimilarity {
public:
  /// @brief The dissimilarity of the entries of `matrix`, which it refers to.
  explicit Matrix_dissimilarity(const Eigen::MatrixXd& matrix)
      : data_(matrix.data()), stride_(std::size_t(matrix.outerStride())) {}
  /// @brief `matrix(i, j)`.
  /// @pre `i < rows`, `j < cols` (not checked: this is the inner loop).
  double operator()(std::size_t i, std::size_t j) const { return data_[i + j * stride_]; }

private:
  const double* data_;
  std::size_t stride_;
};

/// @brief The dissimilarity of a precomputed `n x m` matrix (frame distances, distances between
/// cluster medoids, ...), to pass with `n = matrix.rows()` and `m = matrix.cols()`.
/// @param matrix the entries, each finite and `>= 0` (the policies check them as they read them);
/// referred to, not copied: it must outlive the result (a temporary is rejected at compile time).
/// @par Complexity O(1); each call O(1).
/// @par Example
/// @include matrix_dissimilarity.cpp
inline Matrix_dissimilarity matrix_dissimilarity(const Eigen::MatrixXd& matrix) {
  return Matrix_dissimilarity(matrix);
}

/// @brief Deleted: the result would refer to a temporary matrix.
Matrix_dissimilarity matrix_dissimilarity(Eigen::MatrixXd&&) = delete;

/// @brief Aligns two label sequences with `policy`, under `label_mismatch(a, b)`.
/// @tparam Policy an `AlignmentPolicy` (Smith_waterman, Dtw, Subsequence_dtw or one's own).
/// @param a, b contiguous sequences of labels comparable with `==`.
/// @param policy the policy and its parameters.
/// @return `policy.align(a.size(), b.size(), label_mismatch(a, b))`.
/// @throws invalid_input as the policy does (invalid parameters, sequences it cannot align).
/// @par Complexity that of the policy.
template <std::ranges::contiguous_range A, std::ranges::contiguous_range B, AlignmentPolicy Policy>
  requires std::equality_comparable_with<std::ranges::range_value_t<A>, std::ranges::range_value_t<B>>
Alignment align(const A& a, const B& b, const Policy& policy) {
  return policy.align(std::ranges::size(a), std::ranges::size(b), label_mismatch(a, b));
}

}  // namespace deformseg::alignment
