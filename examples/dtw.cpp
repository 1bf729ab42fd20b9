// Dynamic time warping by deformseg::alignment::Dtw: two sequences of numbers of different
// lengths, cost |x - y|, without and with a Sakoe–Chiba window; then two label sequences.
#include <deformseg/alignment/dtw.h>

#include <cmath>
#include <iostream>
#include <vector>

int main() {
  namespace al = deformseg::alignment;
  const std::vector<double> x{0, 1, 2, 3, 2, 1, 0}, y{0, 0, 1, 3, 3, 1, 0, 0};
  const auto cost = [&](std::size_t i, std::size_t j) { return std::abs(x[i] - y[j]); };

  const al::Alignment free = al::Dtw{}.align(x.size(), y.size(), cost);
  std::cout << "total cost " << free.score << " (lower is better), path";
  for (const auto& [i, j] : free.pairs) std::cout << " (" << i << ", " << j << ")";
  std::cout << '\n';

  // [window]
  const al::Dtw banded{.window = 1};  // within one cell of the scaled diagonal
  std::cout << "with window 1: " << banded.score(x.size(), y.size(), cost) << '\n';
  // [window]

  const std::vector<int> a{1, 1, 2, 2, 2, 3}, b{1, 2, 3, 3};
  std::cout << "labels: " << al::align(a, b, al::Dtw{}).score << '\n';  // the same motion, slower
  return free.score == 2 && al::align(a, b, al::Dtw{}).score == 0 ? 0 : 1;
}
