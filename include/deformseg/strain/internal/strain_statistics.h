// Statistics of large arrays of strains (F x T values, tens of millions), the same for any number
// of threads: sums are taken over fixed blocks and the block sums added in order; order statistics
// are found exactly by radix selection on the values' bits, with integer histograms.
#pragma once

#include <deformseg/internal/parallel_for.h>
#include <deformseg/strain/internal/strain_math.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace deformseg::strain::internal {

// Up to two contiguous runs of values, seen as one sequence.
template <std::floating_point Value>
using Sample_runs = std::array<std::span<const Value>, 2>;

template <std::floating_point Value>
std::size_t sample_count(const Sample_runs<Value>& runs) {
  return runs[0].size() + runs[1].size();
}

// Values per block of the statistics' parallel loops, a fixed size so that sums do not depend on
// the number of threads.
inline constexpr std::size_t statistics_block = std::size_t(1) << 16;

// Calls visit(block_values) for the fixed-size blocks of both runs, in parallel, and gives the
// per-block results in block order.
template <std::floating_point Value, class Result, class Visit>
std::vector<Result> per_block(const Sample_runs<Value>& runs, int threads, const Visit& visit) {
  const std::size_t blocks0 = (runs[0].size() + statistics_block - 1) / statistics_block;
  const std::size_t blocks1 = (runs[1].size() + statistics_block - 1) / statistics_block;
  std::vector<Result> results(blocks0 + blocks1);
  deformseg::internal::parallel_for(results.size(), threads, [&](std::size_t i) {
    const auto& run = i < blocks0 ? runs[0] : runs[1];
    const std::size_t first = (i < blocks0 ? i : i - blocks0) * statistics_block;
    results[i] = visit(run.subspan(first, std::min(statistics_block, run.size() - first)));
  });
  return results;
}

// The sum of f(value) over all values, in double.
template <std::floating_point Value, class F>
double sum_of(const Sample_runs<Value>& runs, int threads, const F& f) {
  const auto sums = per_block<Value, double>(runs, threads, [&](std::span<const Value> values) {
    double s = 0;
    for (Value v : values) s += f(double(v));
    return s;
  });
  double total = 0;
  for (double s : sums) total += s;
  return total;
}

// Bits of a float or double, mapped so that unsigned order is numeric order (-0 before +0).
template <std::floating_point Value>
Float_bits<Value> order_key(Value v) {
  using Bits = Float_bits<Value>;
  constexpr Bits sign = Bits(1) << (8 * sizeof(Value) - 1);
  const Bits bits = std::bit_cast<Bits>(v);
  return (bits & sign) ? Bits(~bits) : Bits(bits | sign);
}

template <std::floating_point Value>
Value from_order_key(Float_bits<Value> key) {
  using Bits = Float_bits<Value>;
  constexpr Bits sign = Bits(1) << (8 * sizeof(Value) - 1);
  return std::bit_cast<Value>((key & sign) ? Bits(key & ~sign) : Bits(~key));
}

// Radix selection digits: 16 bits, so 2 passes for float, 4 for double.
inline constexpr int selection_digit_bits = 16;
inline constexpr std::size_t selection_bins = std::size_t(1) << selection_digit_bits;

// The histogram of the digit below `known_bits` of the order keys of key(v), over the values whose
// key starts with `prefix` (its top `known_bits` bits; every value when known_bits is 0). Each
// thread counts into a histogram of its own; integer sums make the result the same for any
// number of threads.
template <std::floating_point Value, class Key>
std::vector<std::size_t> digit_histogram(const Sample_runs<Value>& runs, int threads, const Key& key,
                                         Float_bits<Value> prefix, int known_bits) {
  using Bits = Float_bits<Value>;
  constexpr int total_bits = 8 * sizeof(Value);
  const int shift = total_bits - known_bits - selection_digit_bits;
  const std::size_t blocks0 = (runs[0].size() + statistics_block - 1) / statistics_block;
  const std::size_t blocks = blocks0 + (runs[1].size() + statistics_block - 1) / statistics_block;
  struct Counts {
    std::vector<std::size_t> mine, odd;
  };
  const auto make_counts = [&] {
    return Counts{std::vector<std::size_t>(selection_bins, 0),
                  std::vector<std::size_t>(known_bits == 0 ? selection_bins : 0, 0)};
  };
  const auto count_block = [&](Counts& counts, std::size_t i) {
    std::vector<std::size_t>& mine = counts.mine;
    std::vector<std::size_t>& odd = counts.odd;
    const auto& run = i < blocks0 ? runs[0] : runs[1];
    const std::size_t first = (i < blocks0 ? i : i - blocks0) * statistics_block;
    const std::size_t last = std::min(run.size(), first + statistics_block);
    if (known_bits == 0) {
      // Runs of equal keys (neighbouring triangles strain alike) would chain each increment to
      // the one before through memory; two histograms, even and odd values, halve the chains.
      std::size_t j = first;
      for (; j + 1 < last; j += 2) {
        ++mine[std::size_t(order_key(key(run[j])) >> shift)];
        ++odd[std::size_t(order_key(key(run[j + 1])) >> shift)];
      }
      if (j < last) ++mine[std::size_t(order_key(key(run[j])) >> shift)];
      return;
    }
    // Later passes: few values match the prefix, so count matches 64 at a time (a loop that
    // vectorises) and only walk the groups that have some.
    const int prefix_shift = shift + selection_digit_bits;
    for (std::size_t group = first; group < last; group += 64) {
      const std::size_t end = std::min(last, group + 64);
      Bits matches = 0;
      for (std::size_t j = group; j < end; ++j)
        matches += Bits(order_key(key(run[j])) >> prefix_shift) == prefix ? 1 : 0;
      if (matches == 0) continue;
      for (std::size_t j = group; j < end; ++j) {
        const Bits k = order_key(key(run[j]));
        if (Bits(k >> prefix_shift) == prefix) ++mine[std::size_t(k >> shift) & (selection_bins - 1)];
      }
    }
  };
  std::vector<std::size_t> histogram(selection_bins, 0);
  for (const Counts& counts :
       deformseg::internal::parallel_for_with_locals(blocks, threads, 1, make_counts, count_block))
    for (std::size_t i = 0; i < selection_bins; ++i)
      histogram[i] += counts.mine[i] + (counts.odd.empty() ? 0 : counts.odd[i]);
  return histogram;
}

// The nearest-rank `share`-quantile (0 < share <= 1) of key(v) over the values v with
// key(v) >= 0, the others (key -1) left out: the smallest kept key that at least `share` of the
// kept keys do not exceed. None when no value is kept. Exact, by radix selection.
template <std::floating_point Value, class Key>
std::optional<Value> kept_quantile(const Sample_runs<Value>& runs, double share, int threads, const Key& key) {
  using Bits = Float_bits<Value>;
  constexpr int total_bits = 8 * sizeof(Value);
  std::size_t rank = 0;
  Bits prefix = 0;
  for (int known_bits = 0; known_bits < total_bits; known_bits += selection_digit_bits) {
    const auto histogram = digit_histogram(runs, threads, key, prefix, known_bits);
    if (known_bits == 0) {
      // Left-out values (key -1) share one bin below every kept one (keys >= 0 have the top bit).
      const std::size_t left_out = histogram[std::size_t(order_key(Value(-1)) >> (total_bits - selection_digit_bits))];
      const std::size_t kept = sample_count(runs) - left_out;
      if (kept == 0) return std::nullopt;
      const double wanted = std::ceil(share * double(kept)) - 1;
      rank = left_out + std::size_t(std::clamp(wanted, 0.0, double(kept - 1)));
    }
    std::size_t bin = 0;
    while (rank >= histogram[bin]) rank -= histogram[bin++];
    prefix = Bits((prefix << selection_digit_bits) | Bits(bin));
  }
  return from_order_key<Value>(prefix);
}

}  // namespace deformseg::strain::internal
