// The best local alignment of two label sequences by deformseg::alignment::Smith_waterman, with the
// thesis' scores (match +1, mismatch -1, gap -1) and with affine gaps; then with a continuous
// dissimilarity, here the distance between two sequences of numbers, with and without the path.
#include <deformseg/alignment/smith_waterman.h>

#include <cmath>
#include <iostream>
#include <string>

int main() {
  namespace al = deformseg::alignment;
  // Two label sequences, say the cluster labels of the key frames of two animations.
  const std::string a = "aabbbccaa", b = "xxbbbcyccaz";
  // [labels]
  const al::Alignment linear = al::align(a, b, al::Smith_waterman{});
  std::cout << "linear gaps: score " << linear.score << ", pairs";
  for (const auto& [i, j] : linear.pairs) std::cout << " (" << i << ", " << j << ")";
  std::cout << '\n';

  const al::Smith_waterman affine{.gap_open = 2, .gap_extend = 0.5};
  std::cout << "affine gaps: score " << al::align(a, b, affine).score << '\n';
  // [labels]

  // A continuous dissimilarity: 0 for equal values, 1 and above for values 1 apart or more.
  const double x[] = {0.0, 1.0, 2.0, 3.0}, y[] = {5.0, 1.1, 2.2, 2.9, 7.0};
  const auto distance = [&](std::size_t i, std::size_t j) { return std::min(1.0, std::abs(x[i] - y[j])); };
  const al::Alignment close = al::Smith_waterman{}.align(4, 5, distance);
  std::cout << "numbers: score " << close.score << " over " << close.pairs.size() << " pairs\n";
  // score() gives the same score in memory linear in the shorter sequence; score_and_length() the
  // score and the path's length (what a similarity's normalisation reads), without the path.
  const al::Score_and_length without_path = al::Smith_waterman{}.score_and_length(4, 5, distance);
  std::cout << "without the path: score " << without_path.score << " over " << without_path.length << " pairs\n";
  return linear.score == 4 && close.pairs.size() == 3 && al::Smith_waterman{}.score(4, 5, distance) == close.score &&
                 without_path.score == close.score && without_path.length == close.pairs.size()
             ? 0
             : 1;
}
