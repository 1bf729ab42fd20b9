#include <deformseg/ged/assignment.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

namespace {

// Minimum over every injective map from the smaller side to the larger: all permutations of the
// larger side, of which the first min(n, m) entries are used.
double brute_force_assignment(const Eigen::MatrixXd& cost) {
  const Eigen::MatrixXd wide = cost.rows() <= cost.cols() ? cost : Eigen::MatrixXd(cost.transpose());
  std::vector<int> columns(static_cast<std::size_t>(wide.cols()));
  std::iota(columns.begin(), columns.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {
    double sum = 0;
    for (Eigen::Index r = 0; r < wide.rows(); ++r) sum += wide(r, columns[static_cast<std::size_t>(r)]);
    best = std::min(best, sum);
  } while (std::next_permutation(columns.begin(), columns.end()));
  return wide.rows() == 0 ? 0.0 : best;
}

void check_is_valid(const Eigen::MatrixXd& cost, const deformseg::ged::Assignment& a) {
  REQUIRE(a.row_to_column.size() == static_cast<std::size_t>(cost.rows()));
  std::set<int> used;
  double sum = 0;
  for (std::size_t r = 0; r < a.row_to_column.size(); ++r) {
    const int c = a.row_to_column[r];
    if (c < 0) continue;
    REQUIRE(c < cost.cols());
    REQUIRE(used.insert(c).second);
    sum += cost(static_cast<Eigen::Index>(r), c);
  }
  CHECK(used.size() == static_cast<std::size_t>(std::min(cost.rows(), cost.cols())));
  CHECK(a.cost == Approx(sum).margin(1e-9));
}

}  // namespace

TEST_CASE("solve_assignment equals brute force on random matrices up to 8 x 8", "[ged][assignment]") {
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> size(0, 8);
  std::uniform_real_distribution<double> real(-5.0, 10.0);
  std::uniform_int_distribution<int> small_int(0, 2);  // many equal costs: ties everywhere
  for (int trial = 0; trial < 400; ++trial) {
    const int n = size(rng), m = size(rng);
    Eigen::MatrixXd cost(n, m);
    const bool ties = trial % 2 == 0;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < m; ++c) cost(r, c) = ties ? small_int(rng) : real(rng);
    INFO("trial " << trial << ", " << n << " x " << m);
    const auto a = deformseg::ged::solve_assignment(cost);
    check_is_valid(cost, a);
    CHECK(a.cost == Approx(brute_force_assignment(cost)).margin(1e-9));
  }
}

TEST_CASE("solve_assignment: exact answers on small cases", "[ged][assignment]") {
  Eigen::MatrixXd cost(3, 3);
  cost << 4, 1, 3, 2, 0, 5, 3, 2, 2;
  const auto a = deformseg::ged::solve_assignment(cost);
  CHECK(a.cost == 5.0);
  CHECK(a.row_to_column == std::vector<int>{1, 0, 2});

  Eigen::MatrixXd tall(3, 1);
  tall << 7, 2, 9;
  const auto t = deformseg::ged::solve_assignment(tall);
  CHECK(t.row_to_column == std::vector<int>{-1, 0, -1});
  CHECK(t.cost == 2.0);

  CHECK(deformseg::ged::solve_assignment(Eigen::MatrixXd(0, 4)).row_to_column.empty());
}

TEST_CASE("solve_assignment is deterministic and rejects non-finite costs", "[ged][assignment]") {
  const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(5, 5);
  CHECK(deformseg::ged::solve_assignment(ones).row_to_column ==
        deformseg::ged::solve_assignment(ones).row_to_column);
  Eigen::MatrixXd bad = ones;
  bad(2, 3) = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(deformseg::ged::solve_assignment(bad), deformseg::invalid_input);
}
