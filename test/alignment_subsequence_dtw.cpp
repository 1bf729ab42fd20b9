#include <deformseg/alignment/subsequence_dtw.h>

#include "alignment_test_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace {

using deformseg::alignment::Alignment;
using deformseg::alignment::Subsequence_dtw;
using deformseg::alignment::Subsequence_query;
using deformseg::alignment_test::absolute_differences;
using deformseg::alignment_test::Pairs;

// The least cost of warping all rows of d onto columns first..last, over every such part.
double brute_force_subsequence(const Eigen::MatrixXd& d) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t first = 0; first < std::size_t(d.cols()); ++first)
    for (std::size_t last = first; last < std::size_t(d.cols()); ++last)
      best = std::min(best, deformseg::alignment_test::brute_force_warping(d, first, last,
                                                                 [](std::size_t, std::size_t) { return true; }));
  return best;
}

}  // namespace

static_assert(deformseg::alignment::AlignmentPolicy<Subsequence_dtw>);
static_assert(!Subsequence_dtw::higher_is_better);
static_assert(deformseg::alignment::ScoreAndLengthPolicy<Subsequence_dtw>);

TEST_CASE("Subsequence_dtw: a query found inside a longer sequence costs nothing", "[alignment]") {
  const std::vector<int> query{1, 2, 2}, other{5, 1, 2, 3, 1, 2};
  const Alignment result = deformseg::alignment::align(query, other, Subsequence_dtw{});
  CHECK(result.score == 0);
  CHECK(result.pairs == Pairs{{0, 1}, {1, 2}, {2, 2}});  // the first of the two places it fits
}

TEST_CASE("Subsequence_dtw: worked by hand on numbers", "[alignment]") {
  // Query 2 6 against 9 1 5 7 2, cost |x - y|: row 0 is 7 1 3 5 0 (free starts); row 1:
  // 3 + 7 = 10, 5 + min(7, 1, 10) = 6, 1 + min(1, 3, 6) = 2, 1 + min(3, 5, 2) = 3, 4 + min(5, 0, 3) = 4.
  // The least of the last row is 2: 2 at 1 then 6 at 5.
  const Eigen::MatrixXd d = absolute_differences({2, 6}, {9, 1, 5, 7, 2});
  const Alignment result = Subsequence_dtw{}.align(2, 5, deformseg::alignment::matrix_dissimilarity(d));
  CHECK(result.score == 2);
  CHECK(result.pairs == Pairs{{0, 1}, {1, 2}});
}

TEST_CASE("Subsequence_dtw: a longer first sequence is matched whole, or the shorter is on request", "[alignment]") {
  const Eigen::MatrixXd d = absolute_differences({1, 2, 3}, {2});
  const auto dis = deformseg::alignment::matrix_dissimilarity(d);
  const Alignment whole_first = Subsequence_dtw{}.align(3, 1, dis);
  CHECK(whole_first.score == 2);  // 1 + 0 + 1
  CHECK(whole_first.pairs == Pairs{{0, 0}, {1, 0}, {2, 0}});
  const Subsequence_dtw shorter{.query = Subsequence_query::shorter};
  const Alignment whole_shorter = shorter.align(3, 1, dis);
  CHECK(whole_shorter.score == 0);  // 2 found in A
  CHECK(whole_shorter.pairs == Pairs{{1, 0}});
  CHECK(shorter.score(3, 1, dis) == 0);
  CHECK(Subsequence_dtw{}.score(3, 1, dis) == 2);
}

TEST_CASE("Subsequence_dtw: empty sequences", "[alignment]") {
  const std::vector<int> empty, some{1, 2};
  CHECK(deformseg::alignment::align(empty, empty, Subsequence_dtw{}).pairs.empty());
  CHECK(Subsequence_dtw{}.score(0, 0, deformseg::alignment::label_mismatch(empty, empty)) == 0);
  CHECK_THROWS_AS(deformseg::alignment::align(some, empty, Subsequence_dtw{}), deformseg::invalid_input);
  CHECK_THROWS_AS(Subsequence_dtw{}.score(0, 2, deformseg::alignment::label_mismatch(empty, some)),
                  deformseg::invalid_input);
}

TEST_CASE("Subsequence_dtw: equals the brute force over all parts and paths", "[alignment]") {
  std::mt19937 random(13);
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 1 + random() % 5, m = 1 + random() % 7;
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    INFO("trial " << trial << ", " << n << " x " << m);
    for (const Subsequence_query query : {Subsequence_query::first, Subsequence_query::shorter}) {
      const bool swapped = query == Subsequence_query::shorter && n > m;
      const Eigen::MatrixXd q = swapped ? Eigen::MatrixXd(d.transpose()) : d;  // the query along the rows
      const Subsequence_dtw policy{.query = query};
      const Alignment result = policy.align(n, m, dis);
      CHECK(result.score == Approx(brute_force_subsequence(q)).margin(1e-12));
      Pairs along_query = result.pairs;
      if (swapped)
        for (auto& [i, j] : along_query) std::swap(i, j);
      REQUIRE(!along_query.empty());
      const double sum = deformseg::alignment_test::check_warping_path(along_query, q, along_query.front().second,
                                                                       along_query.back().second);
      CHECK(sum == Approx(result.score).margin(1e-12));
      CHECK(policy.score(n, m, dis) == result.score);
    }
  }
}

TEST_CASE("Subsequence_dtw: score alone equals align on long sequences", "[alignment]") {
  std::mt19937 random(17);
  for (const auto& [n, m] : {std::pair<std::size_t, std::size_t>{40, 333}, {333, 40}, {101, 101}, {1, 9}, {9, 1}}) {
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, 1, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    for (const Subsequence_query query : {Subsequence_query::first, Subsequence_query::shorter}) {
      const Subsequence_dtw policy{.query = query};
      CHECK(policy.score(n, m, dis) == policy.align(n, m, dis).score);
    }
  }
}

TEST_CASE("Subsequence_dtw::score_and_length is align's score and number of pairs, either query, ties included",
          "[alignment]") {
  std::mt19937 random(46);
  for (int trial = 0; trial < 400; ++trial) {
    const auto [n, m] = deformseg::alignment_test::small_shape(trial, random);
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    for (const Subsequence_query query : {Subsequence_query::first, Subsequence_query::shorter}) {
      for (const std::size_t budget : {std::size_t(1) << 25, std::size_t(0)}) {  // 0: always in linear space
        const Subsequence_dtw policy{.query = query, .max_trace_bytes = budget};
        INFO("trial " << trial << ", " << n << " x " << m << ", budget " << budget);
        deformseg::alignment_test::check_score_and_length(policy.score_and_length(n, m, dis),
                                                          policy.align(n, m, dis));
      }
    }
  }
  const std::vector<int> empty, some{1, 2};
  CHECK(Subsequence_dtw{}.score_and_length(0, 0, deformseg::alignment::label_mismatch(empty, empty)).length == 0);
  CHECK_THROWS_AS(Subsequence_dtw{}.score_and_length(0, 2, deformseg::alignment::label_mismatch(empty, some)),
                  deformseg::invalid_input);
}
