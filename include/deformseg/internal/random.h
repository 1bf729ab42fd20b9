// deformseg's one source of random draws wherever a result must not depend on the standard
// library: the engines std::mt19937 and std::mt19937_64, whose sequences the C++ standard fixes,
// with the draws made here. std::shuffle and the std::uniform_*_distribution classes are not
// used, as each standard library implements them its own way (the same seed gives another
// shuffle with libc++ than with libstdc++).
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace deformseg::internal {

/// The engine of deformseg's own random draws (k-means++ seeding, the order of k-medoids' build).
using Random_engine = std::mt19937_64;

/// A generator whose draws are 32 or 64 uniform bits, as std::mt19937 and std::mt19937_64.
template <class G>
concept Bits_generator = std::uniform_random_bit_generator<G> && G::min() == 0 &&
                         (G::max() == std::numeric_limits<std::uint32_t>::max() ||
                          G::max() == std::numeric_limits<std::uint64_t>::max());

// 64 uniform bits: one draw of a 64-bit engine, two of a 32-bit one (the first the high half).
template <Bits_generator G>
std::uint64_t random_bits(G& random) {
  if constexpr (G::max() == std::numeric_limits<std::uint64_t>::max()) {
    return std::uint64_t(random());
  } else {
    const std::uint64_t high = std::uint64_t(random());
    return high << 32 | std::uint64_t(random());
  }
}

// Uniform in [0, 1) from the top 53 bits of a 64-bit draw.
template <Bits_generator G>
double uniform01(G& random) {
  return double(random_bits(random) >> 11) * 0x1.0p-53;
}

// Uniform in [0, n) for n > 0, by rejecting the draws above the largest multiple of n.
template <Bits_generator G>
std::uint64_t uniform_below(G& random, std::uint64_t n) {
  constexpr std::uint64_t top = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t limit = top - top % n;
  std::uint64_t draw = random_bits(random);
  while (draw >= limit) draw = random_bits(random);
  return draw % n;
}

// Shuffles [first, last) by Fisher-Yates from the back, each swap partner by uniform_below.
template <std::random_access_iterator It, Bits_generator G>
void shuffle(It first, It last, G& random) {
  using std::swap;
  for (auto i = std::uint64_t(last - first); i > 1; --i)
    swap(first[std::ptrdiff_t(i - 1)], first[std::ptrdiff_t(uniform_below(random, i))]);
}

// 0 .. n-1 shuffled by a Random_engine seeded with `seed`.
inline std::vector<std::size_t> shuffled_indices(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  Random_engine random(seed);
  shuffle(order.begin(), order.end(), random);
  return order;
}

}  // namespace deformseg::internal
