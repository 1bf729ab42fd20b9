// The value of a DTW alignment without its path, by deformseg::alignment::Dtw::mean_cost (and
// score_and_length, what a similarity's normalisation reads): the same cost and path length as
// align, in memory linear in one length; then early abandoning,
// when only whether the mean cost is below a threshold matters (a nearest-neighbour search).
#include <deformseg/alignment/dtw.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

int main() {
  namespace al = deformseg::alignment;
  const std::vector<double> x{0, 1, 2, 3, 2, 1, 0}, y{0, 0, 1, 3, 3, 1, 0, 0};
  const auto cost = [&](std::size_t i, std::size_t j) { return std::min(1.0, std::abs(x[i] - y[j])); };

  const al::Alignment path = al::Dtw{}.align(x.size(), y.size(), cost);
  const al::Dtw_mean_cost value = al::Dtw{}.mean_cost(x.size(), y.size(), cost);
  const al::Score_and_length score = al::Dtw{}.score_and_length(x.size(), y.size(), cost);
  std::cout << "align: cost " << path.score << " over " << path.pairs.size() << " pairs\n"
            << "mean_cost: cost " << value.score << " over " << value.length << " cells, mean " << value.mean()
            << '\n';

  // [abandon]
  // Against a sequence far from x, with row bounds (min_j d(i, j) here, any lower bound will do),
  // stop as soon as the mean cost is proved to exceed 0.5.
  const std::vector<double> far(40, 9.0);
  const auto far_cost = [&](std::size_t i, std::size_t j) { return std::min(1.0, std::abs(x[i] - far[j])); };
  std::vector<double> row_bounds(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) row_bounds[i] = far_cost(i, 0);  // far is constant
  const al::Dtw_mean_cost stopped =
      al::Dtw{}.mean_cost(x.size(), far.size(), far_cost, {.abandon_above = 0.5, .row_bounds = row_bounds});
  std::cout << "against a far sequence: " << (stopped.abandoned ? "abandoned" : "computed") << " after "
            << stopped.rows_done << " of " << x.size() << " rows\n";
  // [abandon]

  const bool same = value.score == path.score && value.length == path.pairs.size() && score.score == path.score &&
                    score.length == path.pairs.size();
  return same && stopped.abandoned && stopped.rows_done == 4 ? 0 : 1;
}
