// label_mismatch: the dissimilarity of two label sequences (0 for equal labels, 1 for different
// ones) that an alignment policy reads; here the key-frame labels of two performances of one
// motion, the second holding its middle pose longer, aligned by DTW and by Smith-Waterman.
#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>

#include <cstdio>
#include <vector>

int main() {
  namespace al = deformseg::alignment;
  const std::vector<int> a{0, 1, 2, 1, 0};
  const std::vector<int> b{0, 1, 2, 2, 2, 1, 0};
  const auto d = al::label_mismatch(a, b);  // refers to a and b
  std::printf("d(2, 3) = %.0f (the same pose), d(1, 2) = %.0f\n", d(2, 3), d(1, 2));
  const al::Alignment warped = al::Dtw{}.align(a.size(), b.size(), d);
  const al::Alignment local = al::Smith_waterman{}.align(a.size(), b.size(), d);
  std::printf("DTW cost %.0f over %zu pairs; Smith-Waterman score %.1f\n", warped.score, warped.pairs.size(),
              local.score);
  return warped.score == 0 && warped.pairs.size() == b.size() ? 0 : 1;
}
