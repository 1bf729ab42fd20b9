// Lower bounds of the default policy's dissimilarity D = 1 - value, from summaries
// (deformseg/search/motion_bounds.h): two made-up signature blocks of 3 values per row, a slow
// rise and a faster, higher one, summarised once; each bound beside the D that Dtw gives, and the
// pruning rule of a search that already holds a k-th best value.
#include <deformseg/alignment/dtw.h>
#include <deformseg/search/motion_bounds.h>

#include <Eigen/Core>

#include <iostream>
#include <vector>

int main() {
  namespace search = deformseg::search;
  namespace signatures = deformseg::signatures;
  // Rows are instants, columns the signature's values; Eigen stores them dimension-major.
  Eigen::MatrixXf slow(8, 3), fast(5, 3);
  for (int i = 0; i < 8; ++i) slow.row(i) << 0.1f * float(i), -1.0f, 0.5f;
  for (int i = 0; i < 5; ++i) fast.row(i) << 0.5f + 0.4f * float(i), -0.2f, 0.5f;
  const signatures::Motion_signature_view a{slow.data(), 8, 3}, b{fast.data(), 5, 3};

  // [bounds]
  const search::Motion_summary sa = search::summarize(a), sb = search::summarize(b);  // 4 chunk boxes each
  const double unit = signatures::frame_dissimilarity_unit(3, 1.77);                  // the default scale
  const double box = search::lb_box(sa.view(), sb.view(), unit);
  const double mean = search::lb_mean(sa.view(), sb.view(), unit);
  const double rows = search::lb_rows_columns(sa.view(), sb.view(), unit);
  // [bounds]

  // D itself: the frame dissimilarities, Dtw's path, its mean.
  const auto d = [&](std::size_t i, std::size_t j) {
    const Eigen::RowVector3d difference = (slow.row(Eigen::Index(i)) - fast.row(Eigen::Index(j))).cast<double>();
    return signatures::frame_dissimilarity(difference.squaredNorm(), unit);
  };
  const auto path = deformseg::alignment::Dtw{}.align(8, 5, d);
  const double dissimilarity = path.score / double(path.pairs.size());
  std::cout << "summary of " << sa.view().rows() << " rows: " << sa.floats.size() << " floats\n"
            << "lb_box " << box << ", lb_mean " << mean << ", lb_rows_columns " << rows << " <= D " << dissimilarity
            << " (value " << 1 - dissimilarity << ")\n";

  // [prune]
  for (const double kth_value : {0.85, 0.95})
    std::cout << "k-th best value " << kth_value << ": "
              << (search::may_beat(rows, kth_value) ? "compute the value" : "skip, it cannot reach the k best") << '\n';
  // [prune]
  std::vector<double> row_bound(8);
  search::row_bounds(a, sb.view(), unit, row_bound);
  std::cout << "per row of the slow rise, at most every cell of its row:";
  for (const double r : row_bound) std::cout << ' ' << r;
  std::cout << '\n';
  return box <= dissimilarity && mean <= dissimilarity && rows <= dissimilarity ? 0 : 1;
}
