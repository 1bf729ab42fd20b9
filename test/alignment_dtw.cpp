#include <deformseg/alignment/dtw.h>

#include "alignment_test_support.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

using deformseg::alignment::Alignment;
using deformseg::alignment::Dtw;
using deformseg::alignment_test::absolute_differences;
using deformseg::alignment_test::Pairs;

// The Sakoe–Chiba band as documented: |i (m - 1) - j (n - 1)| <= w min(n - 1, m - 1):
// within w cells, counted along the longer sequence, of the line from corner to corner.
bool in_band(std::size_t i, std::size_t j, std::size_t n, std::size_t m, std::size_t w) {
  const long long along = (long long)(i * (m - 1)) - (long long)(j * (n - 1));
  return std::llabs(along) <= (long long)(w * std::min(n - 1, m - 1));
}

}  // namespace

static_assert(deformseg::alignment::AlignmentPolicy<Dtw>);
static_assert(!Dtw::higher_is_better);

TEST_CASE("Dtw: a small numeric example worked by hand", "[alignment]") {
  // x = 1 3 4 9, y = 1 4 8, cost |x - y|. Cumulative costs, row by row:
  //   0  3 10 /  2  1  6 /  5  1  5 / 13  6  2
  // and back from the corner: (3, 2) <- (2, 1) <- (1, 1) <- (0, 0), costs 1 + 0 + 1 + 0.
  const Eigen::MatrixXd d = absolute_differences({1, 3, 4, 9}, {1, 4, 8});
  const auto dis = deformseg::alignment::matrix_dissimilarity(d);
  const Alignment result = Dtw{}.align(4, 3, dis);
  CHECK(result.score == 2);
  CHECK(result.pairs == Pairs{{0, 0}, {1, 1}, {2, 1}, {3, 2}});
  CHECK(Dtw{}.score(4, 3, dis) == 2);
}

TEST_CASE("Dtw: label sequences that differ only in timing cost 0", "[alignment]") {
  const std::vector<int> a{1, 1, 2, 3, 3, 3}, b{1, 2, 2, 2, 3};
  const Alignment result = deformseg::alignment::align(a, b, Dtw{});
  CHECK(result.score == 0);
  CHECK(result.pairs == Pairs{{0, 0}, {1, 0}, {2, 1}, {2, 2}, {2, 3}, {3, 4}, {4, 4}, {5, 4}});
  const std::vector<int> c{1, 2, 4};
  CHECK(deformseg::alignment::align(a, c, Dtw{}).score == 3);  // the three 3s against the 4
}

TEST_CASE("Dtw: a zero window on equal lengths is the diagonal", "[alignment]") {
  const Eigen::MatrixXd d = absolute_differences({0, 5, 0, 5}, {5, 0, 5, 0});
  const Alignment result = Dtw{.window = 0}.align(4, 4, deformseg::alignment::matrix_dissimilarity(d));
  CHECK(result.score == 20);
  CHECK(result.pairs == Pairs{{0, 0}, {1, 1}, {2, 2}, {3, 3}});
  // Unconstrained, a shift by one does better: 5 + 0 + 0 + 0 + 5.
  CHECK(Dtw{}.score(4, 4, deformseg::alignment::matrix_dissimilarity(d)) == 10);
}

TEST_CASE("Dtw: a window too narrow to connect the corners is an error naming the narrowest", "[alignment]") {
  const std::vector<int> a(3, 0), b(20, 0);
  std::size_t narrowest = 0;
  while (true) {
    try {
      deformseg::alignment::align(a, b, Dtw{.window = narrowest});
      break;
    } catch (const deformseg::invalid_input&) {
      ++narrowest;
    }
  }
  // By hand: with w = 4 row 0 keeps the columns with |2 j| <= 8, 0 to 4, and row 1 those with
  // |19 - 2 j| <= 8, 6 to 13, which do not touch; with w = 5, 0 to 5 and 5 to 14 do.
  CHECK(narrowest == 5);
  CHECK_THROWS_WITH(deformseg::alignment::align(a, b, Dtw{.window = narrowest - 1}),
                    Catch::Contains("narrowest that does is " + std::to_string(narrowest)));
  CHECK_THROWS_AS(Dtw{.window = narrowest - 1}.score(a.size(), b.size(), deformseg::alignment::label_mismatch(a, b)),
                  deformseg::invalid_input);
  CHECK(Dtw{.window = narrowest}.score(a.size(), b.size(), deformseg::alignment::label_mismatch(a, b)) == 0);
}

TEST_CASE("Dtw: empty sequences", "[alignment]") {
  const std::vector<int> empty, some{1, 2};
  const Alignment both = deformseg::alignment::align(empty, empty, Dtw{});
  CHECK(both.score == 0);
  CHECK(both.pairs.empty());
  CHECK_THROWS_AS(deformseg::alignment::align(empty, some, Dtw{}), deformseg::invalid_input);
  CHECK_THROWS_AS(Dtw{}.score(2, 0, deformseg::alignment::label_mismatch(some, empty)), deformseg::invalid_input);
}

TEST_CASE("Dtw: equals the brute force over all warping paths, with and without window", "[alignment]") {
  std::mt19937 random(11);
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 1 + random() % 6, m = 1 + random() % 6;
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    const std::optional<std::size_t> window =
        trial % 3 == 0 ? std::nullopt : std::optional<std::size_t>(random() % 4);
    const std::size_t w = window.value_or(1000);
    const double expected = deformseg::alignment_test::brute_force_warping(
        d, 0, m - 1, [&](std::size_t i, std::size_t j) { return in_band(i, j, n, m, w); });
    INFO("trial " << trial << ", " << n << " x " << m << ", window " << w);
    const Dtw dtw{.window = window};
    if (std::isinf(expected)) {  // the band does not connect the corners
      CHECK_THROWS_AS(dtw.align(n, m, dis), deformseg::invalid_input);
      CHECK_THROWS_AS(dtw.score(n, m, dis), deformseg::invalid_input);
      continue;
    }
    const Alignment result = dtw.align(n, m, dis);
    CHECK(result.score == Approx(expected).margin(1e-12));
    CHECK(deformseg::alignment_test::check_warping_path(result.pairs, d, 0, m - 1) ==
          Approx(result.score).margin(1e-12));
    for (const auto& [i, j] : result.pairs) CHECK(in_band(i, j, n, m, w));
    CHECK(dtw.score(n, m, dis) == result.score);
  }
}

TEST_CASE("Dtw: score alone equals align on long sequences, four rows at a time or banded", "[alignment]") {
  std::mt19937 random(5);
  for (const auto& [n, m] : {std::pair<std::size_t, std::size_t>{203, 150}, {150, 203}, {7, 300}, {301, 2}}) {
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, 1, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    for (const std::optional<std::size_t> window : {std::optional<std::size_t>{}, std::optional<std::size_t>{160}}) {
      const Dtw dtw{.window = window};
      const Alignment result = dtw.align(n, m, dis);
      CHECK(deformseg::alignment_test::check_warping_path(result.pairs, d, 0, m - 1) == Approx(result.score));
      CHECK(dtw.score(n, m, dis) == result.score);
      const Eigen::MatrixXd transposed = d.transpose();
      CHECK(dtw.score(m, n, deformseg::alignment::matrix_dissimilarity(transposed)) == result.score);
    }
  }
}

TEST_CASE("Dtw: a negative dissimilarity is an error naming the cell", "[alignment]") {
  Eigen::MatrixXd d = Eigen::MatrixXd::Ones(3, 3);
  d(2, 0) = -1;
  CHECK_THROWS_WITH(Dtw{}.align(3, 3, deformseg::alignment::matrix_dissimilarity(d)), Catch::Contains("d(2, 0)"));
  CHECK_THROWS_AS(Dtw{.window = 2}.score(3, 3, deformseg::alignment::matrix_dissimilarity(d)),
                  deformseg::invalid_input);
  // Outside the window, d is not read.
  CHECK(Dtw{.window = 1}.score(3, 3, deformseg::alignment::matrix_dissimilarity(d)) == 3);
}
