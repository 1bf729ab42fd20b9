// Subsequence DTW by deformseg::alignment::Subsequence_dtw: where a short motion (a query of
// labels) appears inside a longer one, at what cost; the whole query is matched, the other
// sequence only over the part that fits best; then its cost and length without the path.
#include <deformseg/alignment/subsequence_dtw.h>

#include <iostream>
#include <vector>

int main() {
  namespace al = deformseg::alignment;
  const std::vector<int> query{2, 3, 3, 4};
  const std::vector<int> longer{1, 1, 2, 2, 3, 4, 4, 1, 1};
  // [find]
  const al::Alignment found = al::align(query, longer, al::Subsequence_dtw{});  // 2 3 4 at 3 to 5
  std::cout << "cost " << found.score << ", found at frames " << found.pairs.front().second << " to "
            << found.pairs.back().second << " of the longer sequence\n";
  // [find]

  // The policy can also match whichever sequence is the shorter, given in any order.
  const al::Subsequence_dtw shorter{.query = al::Subsequence_query::shorter};
  std::cout << "the other way round: cost " << al::align(longer, query, shorter).score << '\n';

  // The cost and the path's length without the path (what a similarity's normalisation reads).
  const auto d = [&](std::size_t i, std::size_t j) { return query[i] == longer[j] ? 0.0 : 1.0; };
  const al::Score_and_length without_path = al::Subsequence_dtw{}.score_and_length(query.size(), longer.size(), d);
  std::cout << "without the path: cost " << without_path.score << " over " << without_path.length << " pairs\n";
  return found.score == 0 && found.pairs.front().second == 3 && found.pairs.back().second == 5 &&
                 without_path.score == found.score && without_path.length == found.pairs.size()
             ? 0
             : 1;
}
