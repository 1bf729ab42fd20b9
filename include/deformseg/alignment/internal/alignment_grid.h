// What the alignment policies share: reading one row of dissimilarities into a contiguous buffer
// (checked, so the dynamic programmes run over plain arrays), the transposed dissimilarity for
// score-only passes over the shorter sequence, and the byte matrix of a traceback.
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/exceptions.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::alignment::internal {

// d with its arguments swapped: the grid seen with the second sequence along the rows.
template <class D>
struct Transposed {
  const D& d;
  double operator()(std::size_t i, std::size_t j) const { return d(j, i); }
  static constexpr bool values_are_valid = requires { requires D::values_are_valid; };
};

// Whether D promises values that are finite and >= 0, so that they need no check.
template <class D>
inline constexpr bool values_are_valid = requires { requires D::values_are_valid; };

// row[k] = d(i, first + k) for k < count, by d.row when D has it (RowDissimilarity); throws when
// a value is negative, NaN or infinite. The check is a branch-free reduction, so this loop costs
// about as much as calling d.
template <class D>
void read_row(const D& d, std::size_t i, std::size_t first, std::size_t count, double* row, const char* who) {
  if constexpr (RowDissimilarity<D>) {
    if (count != 0) d.row(i, first, count, row);
    if constexpr (values_are_valid<D>) return;
  } else if constexpr (values_are_valid<D>) {
    for (std::size_t k = 0; k < count; ++k) row[k] = static_cast<double>(d(i, first + k));
    return;
  }
  bool all_valid = true;
  for (std::size_t k = 0; k < count; ++k) {
    double v;
    if constexpr (RowDissimilarity<D>)
      v = row[k];
    else
      v = row[k] = static_cast<double>(d(i, first + k));
    all_valid &= (v >= 0.0) & (v <= std::numeric_limits<double>::max());
  }
  if (all_valid) return;
  for (std::size_t k = 0; k < count; ++k)
    if (!(row[k] >= 0.0 && row[k] <= std::numeric_limits<double>::max()))
      throw invalid_input(std::string(who) + ": the dissimilarity d(" + std::to_string(i) + ", " +
                          std::to_string(first + k) + ") = " + std::to_string(row[k]) +
                          " is not a finite value >= 0");
}

// f(std::integral_constant<std::size_t, k>{}) for k = 0, ..., K - 1, in order: constant indices.
template <std::size_t K, class F>
[[gnu::always_inline]] inline void for_each_index(const F& f) {
  [&]<std::size_t... k>(std::index_sequence<k...>) { (f(std::integral_constant<std::size_t, k>{}), ...); }(
      std::make_index_sequence<K>{});
}

// How many rows the passes walk together: enough chains to hide the latency of one (a few
// dependent additions and maxima per cell); 8 gained nothing here.
inline constexpr std::size_t rows_at_once = 4;

// Walks K consecutive rows of a grid together as a skewed band: at step j, row k is at column
// j - k (columns 1-based, 1..cols), so row k reads what row k - 1 wrote at the step before and the
// K dependency chains along the rows overlap in the processor. visit(row, k, column) does one
// cell; every index into `rows` is a constant and the walk is inlined into its caller, so that
// the compiler can keep the rows in registers.
template <std::size_t K, class Row, class Visit>
[[gnu::always_inline]] inline void walk_skewed(std::array<Row, K>& rows, std::size_t cols, const Visit& visit) {
  for (std::size_t j = 1; j < cols + K; ++j) {
    if (j >= K && j <= cols)
      for_each_index<K>([&](auto k) { visit(rows[k], k, j - k); });
    else
      for_each_index<K>([&](auto k) {
        if (j > k && j - k <= cols) visit(rows[k], k, j - k);
      });
  }
}

// A traceback byte. Its own type rather than unsigned char, which may alias anything: a store of
// one would make the compiler reload every double of the inner loop.
enum class Trace_byte : std::uint8_t {};

// One byte per cell of an n x m grid, row-major, for a traceback; left uninitialised (zeroing
// it would cost a fifth of a DTW): the passes write every cell that a traceback can read.
inline std::unique_ptr<Trace_byte[]> trace_matrix(std::size_t n, std::size_t m, const char* who) {
  if (m != 0 && n > std::numeric_limits<std::size_t>::max() / m)
    throw invalid_input(std::string(who) + ": a " + std::to_string(n) + " x " + std::to_string(m) +
                        " grid is too large to trace back");
  return std::make_unique_for_overwrite<Trace_byte[]>(n * m);
}

// Throws unless rows of `length` doubles (times a few) can be allocated; also tells the compiler
// that `length + 1` does not wrap.
inline void require_row_length(std::size_t length, const char* who) {
  if (length > std::numeric_limits<std::size_t>::max() / 64)
    throw invalid_input(std::string(who) + ": a sequence of " + std::to_string(length) + " elements is too long");
}

inline void require_finite(double value, const char* who, const char* name) {
  if (!std::isfinite(value))
    throw invalid_input(std::string(who) + ": " + name + " = " + std::to_string(value) + " is not finite");
}

}  // namespace deformseg::alignment::internal
