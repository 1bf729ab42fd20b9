/// @file signatures/motion_signature_kernel.h
/// @brief `Motion_signature_dissimilarity`: the frame dissimilarities of two described animations
/// computed on demand, a cell or a row at a time, by one vectorised float kernel; what
/// `Motion_signature_similarity` aligns, and what a search over many descriptions calls.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/signatures/motion_signature_view.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace deformseg::signatures {

namespace internal {

// The columns of the second sequence that the kernel computes together. Each lane's sum is one
// chain of dependent additions (no reassociation); 16 lanes are 4 SSE2 or 2 AVX vectors of
// chains, enough to hide the latency of an addition behind the other chains.
inline constexpr std::size_t signature_lanes = 16;

// The floats of the widest vector the build targets (AVX-512, AVX or SSE2), and such a vector of
// floats or int32s in GCC's and Clang's vector extension, whose every operation is lane by lane.
#if defined(__AVX512F__)
inline constexpr std::size_t vector_floats = 16;
#elif defined(__AVX__)
inline constexpr std::size_t vector_floats = 8;
#else
inline constexpr std::size_t vector_floats = 4;
#endif
using Float_vector = float __attribute__((vector_size(4 * vector_floats)));
using Int_vector = std::int32_t __attribute__((vector_size(4 * vector_floats)));
inline constexpr std::size_t signature_vectors = signature_lanes / vector_floats;

// out[l] = 1 - exp(-s_l unit) for the lanes l < signature_lanes, s_l the squared distance of row
// `a` (its dimension k at a[k * a_stride]) and column l of `b` (its dimension k at
// b[k * b_stride + l]), summed over the dimensions in order, in float. Not inlined, so that every
// cell of every comparison runs these very instructions, whoever asks, and every lane the same
// ones: a lane's value depends on its row and column alone, never on the lane nor on the caller
// (no contraction or vectorisation decided differently in another context).
//
// 1 - exp(-x), x = s unit >= 0, is computed as -expm1(-x): accurate relatively near 0 (where
// 1 - exp would lose every digit), within a few float roundings everywhere. With k the nearest
// integer of x / ln 2 and r = k ln 2 - x (ln 2 split in two so that k ln 2 loses nothing),
// |r| <= ln 2 / 2 and exp(-x) = 2^-k (1 + p), p = expm1(r) by its Taylor series to degree 7 (the
// next term is below 2^-26 of r); then 1 - exp(-x) = (1 - 2^-k) - 2^-k p, where 1 - 2^-k and
// 2^-k p are exact. x is clamped at 87 (2^-k stays a normal float; the result rounds to 1), and so
// is a NaN.
[[gnu::noinline]] inline void signature_dissimilarity_lanes(const float* a, std::size_t a_stride, const float* b,
                                                            std::size_t b_stride, std::size_t width, float unit,
                                                            float* out) {
  constexpr std::size_t vectors = signature_vectors;
  Float_vector sum[vectors] = {};
  for (std::size_t k = 0; k < width; ++k) {
    const float x = a[k * a_stride];
    for (std::size_t v = 0; v < vectors; ++v) {
      Float_vector column;
      std::memcpy(&column, b + k * b_stride + v * vector_floats, sizeof column);
      const Float_vector difference = column - x;
      sum[v] += difference * difference;
    }
  }
  constexpr float log2_e = 1.44269504088896341f;
  constexpr float ln2_high = 0.693359375f;             // 355 / 512: k ln2_high is exact for k < 2^15
  constexpr float ln2_low = -2.12194440054690583e-4f;  // ln 2 - ln2_high
  const Float_vector largest = Float_vector{} + 87.0f;
  for (std::size_t v = 0; v < vectors; ++v) {
    Float_vector x = sum[v] * unit;
    const Int_vector below = x < largest;  // all bits set where x < 87 (not for a NaN)
    x = (Float_vector)(((Int_vector)x & below) | ((Int_vector)largest & ~below));
    const Int_vector k = __builtin_convertvector(x * log2_e + 0.5f, Int_vector);  // x >= 0: truncation rounds
    const Float_vector kf = __builtin_convertvector(k, Float_vector);
    const Float_vector r = (kf * ln2_high - x) + kf * ln2_low;
    Float_vector q = r * (1.0f / 5040) + 1.0f / 720;
    q = q * r + 1.0f / 120;
    q = q * r + 1.0f / 24;
    q = q * r + 1.0f / 6;
    q = q * r + 0.5f;
    const Float_vector p = r + r * (r * q);
    const Float_vector scale = (Float_vector)((127 - k) << 23);  // 2^-k
    const Float_vector d = (1.0f - scale) - scale * p;
    std::memcpy(out + v * vector_floats, &d, sizeof d);
  }
}

}  // namespace internal

/// @brief The frame dissimilarities of two described animations, `d(i, j) = 1 - exp(-s unit)` with
/// s the squared distance of row i of `a` and row j of `b` (their signatures), computed when asked
/// in float: an `alignment::Dissimilarity` that an alignment policy reads a cell (`operator()`) or
/// a row (`row`) at a time, with no `rows() x cols()` matrix.
///
/// One vectorised kernel computes every value, 16 columns of `b` at once: s summed over the
/// dimensions in their order in float (no reassociation, so no `-ffast-math` is needed), then
/// `1 - exp(-s unit)` by a float exponential of its own, accurate relatively near 0. A value
/// depends on its two rows alone, never on whether it was asked as a cell or within a row nor on
/// where the row started: `operator()(i, j)` equals `row(i, first, count, out)[j - first]` bit for
/// bit. Equal rows give exactly 0 (so an animation against itself scores exactly 1), and `d(i, j)`
/// of (a, b) is `d(j, i)` of (b, a) bit for bit. Values are in [0, 1]: within `2^-12 f + 2^-22`
/// of the double reference `f = frame_dissimilarity(s_exact, unit)`, s_exact the squared distance
/// of the two float rows in exact arithmetic (the tests measure at most 6e-7 f, from
/// the float sum of s). Within one build the values are deterministic; builds for other
/// instruction sets (`-march`, whether the compiler fuses multiply-adds) may differ in the last
/// bits.
/// @par Complexity `operator()`: O(16 width) (the 16 columns around j); `row`: O(width) per value,
/// in chunks of 16 columns (a row shorter than 16 costs 16). Copies are cheap (views, plus a padded
/// copy of `b` when it has fewer than 16 rows).
/// @par Example
/// @include motion_signature_dissimilarity.cpp
class Motion_signature_dissimilarity {
public:
  /// @brief The values are always finite and in [0, 1]: an alignment need not check them.
  static constexpr bool values_are_valid = true;

  /// @brief The dissimilarities of the rows of `a` and those of `b`, which it refers to (they must
  /// outlive it); `unit` is `frame_dissimilarity_unit(width, scale)`, rounded to float once.
  /// @pre the signatures are finite (else a NaN or infinite distance gives 1).
  /// @throws invalid_input when `a` and `b` have different widths or none, or when `unit` is not
  /// positive and finite.
  Motion_signature_dissimilarity(Motion_signature_view a, Motion_signature_view b, double unit)
      : a_(a), b_(b), unit_(float(unit)) {
    if (a.width != b.width || a.width == 0)
      throw invalid_input("Motion_signature_dissimilarity: signatures of " + std::to_string(a.width) + " and " +
                          std::to_string(b.width) + " values per frame");
    if (!(unit > 0) || !std::isfinite(unit) || !(unit_ > 0) || !std::isfinite(unit_))
      throw invalid_input("Motion_signature_dissimilarity: the unit " + std::to_string(unit) +
                          " is not a positive float");
    if (b.rows < lanes) pad_short_b();
  }

  /// @brief The sequences' lengths: the rows of `a` and of `b`.
  std::size_t rows() const { return a_.rows; }
  /// @copydoc rows
  std::size_t cols() const { return b_.rows; }

  /// @brief `d(i, j)`, the dissimilarity of row i of `a` and row j of `b`.
  /// @pre `i < rows()`, `j < cols()` (not checked: this is an alignment's inner loop).
  double operator()(std::size_t i, std::size_t j) const {
    float lanes_out[lanes];
    const std::size_t start = chunk_start(j);
    compute(i, start, lanes_out);
    // j - start < lanes when j < cols(); the min tells the compiler, which cannot know it.
    return double(lanes_out[std::min(j - start, lanes - 1)]);
  }

  /// @brief `out[k] = d(i, first + k)` for `k < count`, each value the very one `operator()` gives.
  /// @pre `i < rows()`, `first + count <= cols()`, `out` has room for `count` values (not checked).
  void row(std::size_t i, std::size_t first, std::size_t count, double* out) const {
    float lanes_out[lanes];
    for (std::size_t done = 0; done < count; done += lanes) {
      const std::size_t j = first + done, take = std::min(lanes, count - done);
      const std::size_t start = chunk_start(j);
      compute(i, start, lanes_out);
      const std::size_t lane = std::min(j - start, lanes - take);  // j - start, as in operator()
      for (std::size_t k = 0; k < take; ++k) out[done + k] = double(lanes_out[lane + k]);
    }
  }

private:
  static constexpr std::size_t lanes = internal::signature_lanes;

  // The first column of the chunk of `lanes` columns holding column j: j itself, moved back so
  // that the chunk ends inside b (the lanes are independent, so where j falls does not matter);
  // 0 when b is padded.
  std::size_t chunk_start(std::size_t j) const { return b_.rows < lanes ? 0 : std::min(j, b_.rows - lanes); }

  void compute(std::size_t i, std::size_t start, float* out) const {
    if (b_.rows < lanes)
      internal::signature_dissimilarity_lanes(a_.values + i, a_.rows, padded_b_.data(), lanes, a_.width, unit_, out);
    else
      internal::signature_dissimilarity_lanes(a_.values + i, a_.rows, b_.values + start, b_.rows, a_.width, unit_,
                                              out);
  }

  // b with `lanes` columns per dimension, the missing ones 0: the kernel reads whole chunks.
  void pad_short_b() {
    padded_b_.assign(lanes * b_.width, 0.0f);
    for (std::size_t k = 0; k < b_.width; ++k)
      for (std::size_t r = 0; r < b_.rows; ++r) padded_b_[k * lanes + r] = b_(r, k);
  }

  Motion_signature_view a_, b_;
  float unit_;
  std::vector<float> padded_b_;
};

}  // namespace deformseg::signatures
