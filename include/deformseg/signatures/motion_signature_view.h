/// @file signatures/motion_signature_view.h
/// @brief `Motion_signature_view`: the signatures of one described animation as a read-only block
/// of floats that it does not own, and the frame dissimilarity of two signatures; what a
/// description, a motion store, the comparison kernel and the lower bounds of a search share.
#pragma once

#include <cmath>
#include <cstddef>

namespace deformseg::signatures {

/// @brief The `rows x width` signatures of one described animation (one row per described instant,
/// `width` values per signature), stored dimension-major: the `rows` values of dimension 0, then
/// those of dimension 1, and so on, which is Eigen's default (column-major) layout of a
/// `Eigen::MatrixXf` and the layout of a motion store's blocks. It does not own the floats: the
/// description or store it views must outlive it.
struct Motion_signature_view {
  /// @brief `width` blocks of `rows` floats: the value of row r in dimension k is `values[k * rows + r]`.
  const float* values = nullptr;
  /// @brief The number of signatures (described instants).
  std::size_t rows = 0;
  /// @brief The values per signature (64 with the default options).
  std::size_t width = 0;

  /// @brief The value of row `r` in dimension `k`.
  /// @pre `r < rows`, `k < width` (not checked).
  float operator()(std::size_t r, std::size_t k) const { return values[k * rows + r]; }
};

/// @brief The factor that makes a squared distance of two signatures of `width` values the
/// exponent of their frame dissimilarity: `1 / (width scale^2)`, so that an RMS difference of
/// `scale` per value gives `1 - 1/e`.
/// @pre `width > 0`, `scale > 0` (not checked).
inline double frame_dissimilarity_unit(std::size_t width, double scale) {
  return 1.0 / (double(width) * scale * scale);
}

/// @brief The dissimilarity in [0, 1) of two signatures at squared distance `squared_distance`:
/// `1 - exp(-squared_distance unit)`, in double precision. Increasing and concave in the
/// distance, 0 for equal signatures. The reference that the vectorised comparison kernel
/// approximates and that the search's lower bounds are proven against.
/// @param squared_distance the squared Euclidean distance of the two signatures, `>= 0`.
/// @param unit `frame_dissimilarity_unit(width, scale)`.
inline double frame_dissimilarity(double squared_distance, double unit) {
  return -std::expm1(-squared_distance * unit);
}

}  // namespace deformseg::signatures
