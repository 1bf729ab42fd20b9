/// @file strain/strain_measures.h
/// @brief The strain measures of `compute_strain`: how the principal stretches of a triangle
/// become one scalar, and the `StrainMeasure` concept a user's own measure models.
///
/// Every measure here is 0 for a triangle that moved rigidly (or was scaled by the same factor as
/// its reference, see `compute_strain`), grows with the deformation, and is invariant to rotation
/// and translation of the deformed triangle.
#pragma once

#include <deformseg/strain/internal/strain_math.h>

#include <algorithm>
#include <concepts>

namespace deformseg::strain {

/// @brief What a triangle's deformation gradient tells of its stretch: the input of a strain
/// measure.
///
/// With `F` the 3x2 in-plane deformation gradient of the triangle (from its reference to its
/// deformed position, see `compute_strain`) and `C = F^T F` the right Cauchy–Green tensor, the
/// principal stretches `l1 >= l2 >= 0` are the singular values of `F`, and `l1^2`, `l2^2` the
/// eigenvalues of `C`. All fields are finite. The differences from 1 are computed without
/// cancellation, so that a strain of 1e-4 is as accurate, relatively, as one of 1: a measure
/// should use them rather than subtract 1 itself.
///
/// A measure should also read these fields rather than call `std::sqrt` or `std::exp`: under
/// GCC's default `-fmath-errno` such a call keeps the kernel's loop from vectorising (the result is
/// still right, only slower).
/// @tparam T `float` or `double`, the arithmetic of the kernel.
template <std::floating_point T>
struct Principal_stretches {
  T stretch1;     ///< the larger principal stretch `l1`
  T stretch2;     ///< the smaller principal stretch `l2`
  T strain1;      ///< `l1 - 1`
  T strain2;      ///< `l2 - 1`
  T lambda1;      ///< the larger eigenvalue of C, `l1^2`
  T lambda2;      ///< the smaller eigenvalue of C, `l2^2`
  T green1;       ///< the larger Green–Lagrange principal strain `(l1^2 - 1) / 2`
  T green2;       ///< the smaller Green–Lagrange principal strain `(l2^2 - 1) / 2`
  T area_ratio;   ///< deformed area over reference area, `J = l1 l2 = sqrt(det C)`
  T area_change;  ///< `J - 1`
};

/// @brief A strain measure: a default-constructible, copyable function object that maps the
/// principal stretches of a triangle to one scalar, for both `float` and `double` arithmetic.
///
/// It is called inside the kernel's innermost loop, so it should be small, branch-free and
/// inline: write it as a template `T operator()(const Principal_stretches<T>&) const`. It should
/// give 0 for `l1 = l2 = 1` (a rigid motion). Has models: `Max_principal_strain` (the default),
/// `Green_lagrange_strain`, `Frobenius_strain`, `Area_ratio_strain`.
///
/// @code
/// // The larger principal stretch minus 1, signed: > 0 where the triangle is stretched.
/// struct Largest_stretch {
///   template <std::floating_point T>
///   T operator()(const deformseg::strain::Principal_stretches<T>& p) const { return p.strain1; }
/// };
/// auto field = deformseg::strain::compute_strain(animation, {}, Largest_stretch{},
///                                                deformseg::strain::Gaussian_normalization{});
/// @endcode
template <class M>
concept StrainMeasure = std::default_initializable<M> && std::copy_constructible<M> &&
    requires(const M& measure, const Principal_stretches<float>& f, const Principal_stretches<double>& d) {
      { measure(f) } -> std::same_as<float>;
      { measure(d) } -> std::same_as<double>;
    };

/// @brief The maximal absolute principal strain `s = max(|l1 - 1|, |l2 - 1|)`, the default
/// measure (@ref method_strain).
///
/// It is the largest relative change of length of any segment in the triangle: `s = 0.1` means
/// some direction in the triangle is stretched or compressed by 10 %. Since `l1 >= l2`, it equals
/// `max(l1 - 1, 1 - l2)`.
struct Max_principal_strain {
  /// @brief `max(l1 - 1, 1 - l2)`.
  template <std::floating_point T>
  T operator()(const Principal_stretches<T>& p) const {
    return std::max(p.strain1, -p.strain2);
  }
};

/// @brief The Green–Lagrange strain of largest magnitude, `max(|l1^2 - 1|, |l2^2 - 1|) / 2`:
/// the largest eigenvalue in magnitude of `E = (C - I) / 2`.
///
/// It needs no square root, and weighs stretching more than compression (`l = 2` gives 1.5,
/// `l = 0` gives 0.5).
struct Green_lagrange_strain {
  /// @brief `max(l1^2 - 1, 1 - l2^2) / 2`.
  template <std::floating_point T>
  T operator()(const Principal_stretches<T>& p) const {
    return std::max(p.green1, -p.green2);
  }
};

/// @brief The Frobenius norm of `U - I`, `sqrt((l1 - 1)^2 + (l2 - 1)^2)`, with `U = sqrt(C)` the
/// right stretch tensor: both principal strains at once, in a root-mean-square sense.
struct Frobenius_strain {
  /// @brief `sqrt((l1 - 1)^2 + (l2 - 1)^2)`.
  template <std::floating_point T>
  T operator()(const Principal_stretches<T>& p) const {
    return internal::sqrt_nonnegative(p.strain1 * p.strain1 + p.strain2 * p.strain2);
  }
};

/// @brief The change of area, `|J - 1|` with `J = l1 l2` the ratio of deformed to reference area:
/// 0 for any area-preserving deformation (a pure shear too), so it sees inflation, not shape.
struct Area_ratio_strain {
  /// @brief `|l1 l2 - 1|`.
  template <std::floating_point T>
  T operator()(const Principal_stretches<T>& p) const {
    return std::max(p.area_change, -p.area_change);
  }
};

}  // namespace deformseg::strain
