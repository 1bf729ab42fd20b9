// The path of a DTW alignment in linear space, by deformseg::alignment::Dtw::max_trace_bytes:
// above that many cells, align finds the same path without a byte per cell of the grid.
#include <deformseg/alignment/dtw.h>

#include <cmath>
#include <cstddef>
#include <iostream>
#include <vector>

int main() {
  namespace al = deformseg::alignment;
  // Two sine waves of 3,000 and 2,000 samples, one of them sped up: 6 million cells, whose trace
  // bytes (6 MB) are under the default budget of 32 MiB.
  std::vector<double> x(3000), y(2000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.010 * double(i));
  for (std::size_t j = 0; j < y.size(); ++j) y[j] = std::sin(0.017 * double(j));
  const auto cost = [&](std::size_t i, std::size_t j) { return std::abs(x[i] - y[j]); };

  const al::Alignment whole = al::Dtw{}.align(x.size(), y.size(), cost);
  // A budget of 1 MiB: the same path, found in blocks of at most 2^20 cells.
  const al::Alignment linear = al::Dtw{.max_trace_bytes = 1 << 20}.align(x.size(), y.size(), cost);

  std::cout << "byte per cell: cost " << whole.score << " over " << whole.pairs.size() << " pairs\n"
            << "linear space:  cost " << linear.score << " over " << linear.pairs.size() << " pairs\n"
            << (linear.score == whole.score && linear.pairs == whole.pairs ? "the same path\n" : "different!\n");
  return linear.score == whole.score && linear.pairs == whole.pairs ? 0 : 1;
}
