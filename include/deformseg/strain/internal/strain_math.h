// Elementary functions the strain kernels call inside loops that must vectorise.
//
// With GCC's default -fmath-errno, std::sqrt and std::exp may set errno, which keeps every loop
// that calls them scalar; and a clamp against a constant followed by more arithmetic invites jump
// threading, which leaves control flow the vectoriser refuses under -ftrapping-math. These
// functions use only arithmetic, integer bit operations and integer min, so that a loop calling
// them vectorises under the project's plain -O2/-O3, whatever the user's math flags.
#pragma once

#include <bit>
#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace deformseg::strain::internal {

// The unsigned integer with the bits of T.
template <std::floating_point T>
using Float_bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;

static_assert(std::numeric_limits<float>::is_iec559 && std::numeric_limits<double>::is_iec559,
              "deformseg's strain kernels need IEEE 754 float and double");

// min(x, limit) for x >= 0 and limit >= 0 (no NaN): non-negative IEEE numbers order as their bits,
// so an integer min does it without a floating-point branch.
template <std::floating_point T>
inline T min_nonnegative(T x, T limit) {
  using Bits = Float_bits<T>;
  const Bits a = std::bit_cast<Bits>(x);
  const Bits b = std::bit_cast<Bits>(limit);
  return std::bit_cast<T>(a < b ? a : b);
}

// max(x, +0), mapping -0 and negative numbers to +0 (no NaN), by the sign bit.
template <std::floating_point T>
inline T max_zero(T x) {
  using Bits = Float_bits<T>;
  using Signed = std::make_signed_t<Bits>;
  const Signed bits = std::bit_cast<Signed>(x);
  return std::bit_cast<T>(bits < 0 ? Signed(0) : bits);
}

// 1 / sqrt(x) for a normal x > 0: the classic bit-level first guess (relative error below 3.5e-2),
// then `steps` Newton steps y <- y (3/2 - x/2 y^2), each squaring the error: 3 give float
// precision, 4 double precision. For x = +0 it gives a finite number, so that x * rsqrt(x) = 0.
template <std::floating_point T, int steps = sizeof(T) == 4 ? 3 : 4>
inline T rsqrt_nonnegative(T x) {
  using Bits = Float_bits<T>;
  constexpr Bits magic = sizeof(T) == 4 ? Bits(0x5f3759dfu) : Bits(0x5fe6eb50c7b537a9ull);
  const T half_x = T(0.5) * x;
  T y = std::bit_cast<T>(Bits(magic - (std::bit_cast<Bits>(x) >> 1)));
  for (int i = 0; i < steps; ++i) y = y * (T(1.5) - half_x * y * y);
  return y;
}

// sqrt(x) for x >= 0, vectorisable: s = x rsqrt(x) with one Newton step fewer than full precision,
// then one Heron correction s + (x - s^2) / (2 s), written with the reciprocal square root, which
// squares the error again. Within 1 ulp of std::sqrt for normal x (the tests check it); +0 gives
// +0, subnormal x a result below sqrt(min normal). No NaN for x >= 0.
template <std::floating_point T>
inline T sqrt_nonnegative(T x) {
  const T r = rsqrt_nonnegative<T, sizeof(T) == 4 ? 2 : 3>(x);
  const T s = x * r;
  return s + T(0.5) * r * (x - s * s);
}

// The Taylor coefficient 1 / n!, a constant expression.
template <std::floating_point T>
constexpr T inverse_factorial(int n) {
  T f = 1;
  for (int i = 2; i <= n; ++i) f *= T(i);
  return T(1) / f;
}

// 1/n! + r/(n+1)! + ... + r^(degree-n)/degree!, by Horner's rule unrolled at compile time.
template <std::floating_point T, int n, int degree>
inline T taylor_tail(T r) {
  constexpr T coefficient = inverse_factorial<T>(n);
  if constexpr (n == degree)
    return coefficient;
  else
    return coefficient + r * taylor_tail<T, n + 1, degree>(r);
}

// expm1(r) for |r| <= ln(2)/2 by its Taylor polynomial, of degree 7 for float (truncation below
// 2e-8 relative) and 13 for double (below 2e-17 relative).
template <std::floating_point T>
inline T expm1_reduced(T r) {
  constexpr int degree = sizeof(T) == 4 ? 7 : 13;
  return r * taylor_tail<T, 1, degree>(r);
}

// 1 - exp(-y) for y >= 0 (no NaN), vectorisable, to a few ulp of the result, including for tiny y
// where 1 - std::exp(-y) would cancel. exp(-y) = 2^k exp(r) with k = round(-y / ln 2) and
// |r| <= ln(2) / 2; then 1 - 2^k (1 + expm1(r)) = (1 - 2^k) - 2^k expm1(r), where 1 - 2^k is exact.
// y is first limited to where exp(-y) is still a normal number; beyond it the result rounds to 1.
template <std::floating_point T>
inline T one_minus_exp_neg(T y) {
  using Bits = Float_bits<T>;
  constexpr int mantissa_bits = std::numeric_limits<T>::digits - 1;
  constexpr int bias = std::numeric_limits<T>::max_exponent - 1;
  constexpr T y_max = sizeof(T) == 4 ? T(87) : T(708);  // exp(-y_max) is normal, 2^k too
  constexpr T log2e = T(1.442695040888963407359924681001892137);
  // ln 2 in two parts, the first with few enough bits that k * ln2_high is exact.
  constexpr T ln2_high = sizeof(T) == 4 ? T(0.693145751953125) : T(0.6931471803691238164901733398437500);
  constexpr T ln2_low = sizeof(T) == 4 ? T(1.4286068203094172321e-06) : T(1.9082149292705878161e-10);

  y = min_nonnegative(y, y_max);
  // k = round(-y log2 e), by truncating -y log2 e - 1/2 (a negative number) towards zero. Taken
  // from an integer so that the result stays right under -ffast-math too.
  const auto k = static_cast<std::int32_t>(-y * log2e - T(0.5));
  const T k_real = T(k);
  const T r = (-y - k_real * ln2_high) - k_real * ln2_low;
  // 2^k: k + bias lands in the low bits of the significand of 2^mantissa_bits + k + bias (exactly,
  // as the sum is an integer below 2^(mantissa_bits+1)); shifting moves them to the exponent. This
  // avoids integer widening, which SSE2 cannot vectorise for double.
  constexpr T shift = T(Bits(1) << mantissa_bits) + T(bias);
  const T two_k = std::bit_cast<T>(std::bit_cast<Bits>(k_real + shift) << mantissa_bits);
  return (T(1) - two_k) - two_k * expm1_reduced(r);
}

}  // namespace deformseg::strain::internal
