#include <deformseg/alignment/smith_waterman.h>

#include "alignment_test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using deformseg::alignment::Alignment;
using deformseg::alignment::Smith_waterman;
using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

double gap_cost(const Smith_waterman& p, std::size_t length) {
  return length == 0 ? 0.0 : p.gap_open + double(length - 1) * p.gap_extend;
}

double substitution(const Smith_waterman& p, double d) { return p.match - (p.match - p.mismatch) * d; }

// The score of a local alignment given by its pairs: their substitution scores, less one gap in
// each sequence for the elements skipped between two consecutive pairs.
double score_of_pairs(const Smith_waterman& p, const Eigen::MatrixXd& d, const Pairs& pairs) {
  double score = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [i, j] = pairs[k];
    score += substitution(p, d(Eigen::Index(i), Eigen::Index(j)));
    if (k > 0) score -= gap_cost(p, i - pairs[k - 1].first - 1) + gap_cost(p, j - pairs[k - 1].second - 1);
  }
  return score;
}

// The best local alignment by another route than Gotoh's: over all chains of pairs increasing in
// both indices, best[i][j] the best chain ending with (i, j), trying every previous pair, with the
// gaps between two pairs priced as above. O(n^2 m^2), obviously correct.
double naive_local_score(const Smith_waterman& p, const Eigen::MatrixXd& d) {
  const Eigen::Index n = d.rows(), m = d.cols();
  Eigen::MatrixXd best(n, m);
  double overall = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < m; ++j) {
      double before = 0;  // or start here
      for (Eigen::Index pi = 0; pi < i; ++pi)
        for (Eigen::Index pj = 0; pj < j; ++pj)
          before = std::max(before, best(pi, pj) - gap_cost(p, std::size_t(i - pi - 1)) -
                                        gap_cost(p, std::size_t(j - pj - 1)));
      best(i, j) = before + substitution(p, d(i, j));
      overall = std::max(overall, best(i, j));
    }
  return overall;
}

void check_valid_local(const Pairs& pairs, std::size_t n, std::size_t m) {
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    REQUIRE(pairs[k].first < n);
    REQUIRE(pairs[k].second < m);
    if (k > 0) {
      REQUIRE(pairs[k].first > pairs[k - 1].first);
      REQUIRE(pairs[k].second > pairs[k - 1].second);
    }
  }
}

Eigen::MatrixXd mismatch_matrix(const std::string& a, const std::string& b) {
  Eigen::MatrixXd d(Eigen::Index(a.size()), Eigen::Index(b.size()));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) d(Eigen::Index(i), Eigen::Index(j)) = a[i] == b[j] ? 0 : 1;
  return d;
}

}  // namespace

static_assert(deformseg::alignment::AlignmentPolicy<Smith_waterman>);
static_assert(Smith_waterman::higher_is_better);
static_assert(deformseg::alignment::ScoreAndLengthPolicy<Smith_waterman>);

TEST_CASE("Smith_waterman: the textbook example, linear gaps", "[alignment]") {
  // Wikipedia's example: match 3, mismatch -3, gap 2. Best: GTT-AC over GTTGAC, 5 * 3 - 2 = 13.
  const std::string a = "TGTTACGG", b = "GGTTGACTA";
  const Smith_waterman sw{.match = 3, .mismatch = -3, .gap_open = 2, .gap_extend = 2};
  const Alignment result = deformseg::alignment::align(a, b, sw);
  CHECK(result.score == 13);
  CHECK(result.pairs == Pairs{{1, 1}, {2, 2}, {3, 3}, {4, 5}, {5, 6}});
  CHECK(sw.score(a.size(), b.size(), deformseg::alignment::label_mismatch(a, b)) == 13);
}

TEST_CASE("Smith_waterman: affine gaps bridge an insertion that linear ones do not", "[alignment]") {
  // B has "xyz" inserted after ABC. Bridging it keeps 8 matches less one gap of 3.
  const std::string a = "ABCDEFGH", b = "ABCxyzDEFGH";
  const Smith_waterman affine{.gap_open = 1.5, .gap_extend = 0.5};  // 8 - (1.5 + 2 * 0.5) = 5.5
  const Alignment bridged = deformseg::alignment::align(a, b, affine);
  CHECK(bridged.score == 5.5);
  CHECK(bridged.pairs == Pairs{{0, 0}, {1, 1}, {2, 2}, {3, 6}, {4, 7}, {5, 8}, {6, 9}, {7, 10}});
  const Smith_waterman linear{.gap_open = 1.5, .gap_extend = 1.5};  // 8 - 4.5 = 3.5 < DEFGH's 5
  const Alignment local = deformseg::alignment::align(a, b, linear);
  CHECK(local.score == 5);
  CHECK(local.pairs == Pairs{{3, 6}, {4, 7}, {5, 8}, {6, 9}, {7, 10}});
}

TEST_CASE("Smith_waterman: ties end at the first best cell, shortest", "[alignment]") {
  const std::vector<int> a{1, 2}, b{1, 2, 1, 2};
  const Alignment result = deformseg::alignment::align(a, b, Smith_waterman{});
  CHECK(result.score == 2);
  CHECK(result.pairs == Pairs{{0, 0}, {1, 1}});
  // Zero-cost gaps: AxB against AB can skip x for free; the alignment stops where it scores 0.
  const std::string c = "AxB", e = "AB";
  const Alignment free_gap = deformseg::alignment::align(c, e, Smith_waterman{.gap_open = 0, .gap_extend = 0});
  CHECK(free_gap.score == 2);
  CHECK(free_gap.pairs == Pairs{{0, 0}, {2, 1}});
}

TEST_CASE("Smith_waterman: empty and hopeless inputs score 0 without pairs", "[alignment]") {
  const std::vector<int> empty, some{1, 2, 3}, other{4, 5};
  for (const auto& [a, b] : {std::pair{empty, some}, std::pair{some, empty}, std::pair{empty, empty},
                             std::pair{some, other}}) {
    const Alignment result = deformseg::alignment::align(a, b, Smith_waterman{});
    CHECK(result.score == 0);
    CHECK(result.pairs.empty());
    CHECK(Smith_waterman{}.score(a.size(), b.size(), deformseg::alignment::label_mismatch(a, b)) == 0);
  }
}

TEST_CASE("Smith_waterman: a continuous dissimilarity scales the substitution score", "[alignment]") {
  Eigen::MatrixXd d(2, 2);
  d << 0.25, 1.0,
       1.0, 0.5;
  const auto dis = deformseg::alignment::matrix_dissimilarity(d);
  // Substitution 1 - 2 d: 0.5 and 0 on the diagonal.
  const Alignment result = Smith_waterman{}.align(2, 2, dis);
  CHECK(result.score == 0.5);
  CHECK(result.pairs == Pairs{{0, 0}});
  const Smith_waterman scaled{.match = 2, .mismatch = 0};  // 2 - 2 d: 1.5 + 1
  CHECK(scaled.align(2, 2, dis).score == 2.5);
}

TEST_CASE("Smith_waterman: equals the naive chain recursion on random sequences", "[alignment]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = random() % 9, m = random() % 9;
    Eigen::MatrixXd d(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
    if (trial % 2 == 0) {  // labels of a small alphabet
      std::vector<int> a(n), b(m);
      for (auto& x : a) x = int(random() % 3);
      for (auto& x : b) x = int(random() % 3);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j) d(Eigen::Index(i), Eigen::Index(j)) = a[i] == b[j] ? 0 : 1;
    } else {
      for (Eigen::Index k = 0; k < d.size(); ++k) d(k) = unit(random);
    }
    Smith_waterman p;
    p.match = trial % 3 == 0 ? 1.0 : 0.5 + 2 * unit(random);
    p.mismatch = p.match - 3 * unit(random);
    p.gap_open = trial % 5 == 0 ? 0.0 : 2 * unit(random);
    p.gap_extend = trial % 4 == 0 ? p.gap_open : p.gap_open * unit(random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    const Alignment result = p.align(n, m, dis);
    INFO("trial " << trial << ", " << n << " x " << m);
    CHECK(result.score == Approx(naive_local_score(p, d)).margin(1e-9));
    check_valid_local(result.pairs, n, m);
    CHECK(score_of_pairs(p, d, result.pairs) == Approx(result.score).margin(1e-9));
    CHECK(p.score(n, m, dis) == result.score);
  }
}

TEST_CASE("Smith_waterman: score alone equals align on long sequences either way round", "[alignment]") {
  std::mt19937 random(3);
  std::vector<int> a(300), b(517);
  for (auto& x : a) x = int(random() % 4);
  for (auto& x : b) x = int(random() % 4);
  const Smith_waterman affine{.mismatch = -0.5, .gap_open = 2, .gap_extend = 0.25};
  for (const Smith_waterman& p : {Smith_waterman{}, affine}) {
    const Alignment ab = deformseg::alignment::align(a, b, p), ba = deformseg::alignment::align(b, a, p);
    CHECK(ab.score == ba.score);
    CHECK(p.score(a.size(), b.size(), deformseg::alignment::label_mismatch(a, b)) == ab.score);
    CHECK(p.score(b.size(), a.size(), deformseg::alignment::label_mismatch(b, a)) == ab.score);
    CHECK(score_of_pairs(p, mismatch_matrix(std::string(a.begin(), a.end()), std::string(b.begin(), b.end())),
                         ab.pairs) == Approx(ab.score));
  }
}

TEST_CASE("Smith_waterman: invalid scores and dissimilarities throw", "[alignment]") {
  using deformseg::invalid_input;
  const std::vector<int> a{1, 2}, b{1, 3};
  const auto d = deformseg::alignment::label_mismatch(a, b);
  const Smith_waterman inverted{.match = -1, .mismatch = 1}, growing{.gap_open = 1, .gap_extend = 2},
      negative{.gap_open = -1, .gap_extend = -1}, not_finite{.match = std::nan("")};
  CHECK_THROWS_AS(inverted.align(2, 2, d), invalid_input);
  CHECK_THROWS_AS(growing.align(2, 2, d), invalid_input);
  CHECK_THROWS_AS(negative.score(2, 2, d), invalid_input);
  CHECK_THROWS_AS(not_finite.score(2, 2, d), invalid_input);
  Eigen::MatrixXd bad = Eigen::MatrixXd::Zero(2, 3);
  bad(1, 2) = -0.5;
  CHECK_THROWS_WITH(Smith_waterman{}.align(2, 3, deformseg::alignment::matrix_dissimilarity(bad)),
                    Catch::Contains("d(1, 2)"));
  bad(1, 2) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(Smith_waterman{}.score(2, 3, deformseg::alignment::matrix_dissimilarity(bad)), invalid_input);
  bad(1, 2) = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(Smith_waterman{}.score(2, 3, deformseg::alignment::matrix_dissimilarity(bad)), invalid_input);
}

namespace {
struct Not_an_alignment_policy {  // no higher_is_better
  template <class D>
  Alignment align(std::size_t, std::size_t, const D&) const {
    return {};
  }
  template <class D>
  double score(std::size_t, std::size_t, const D&) const {
    return 0;
  }
};
}  // namespace

static_assert(!deformseg::alignment::AlignmentPolicy<Not_an_alignment_policy>);

TEST_CASE("Smith_waterman::score_and_length is align's score and number of pairs, linear and affine gaps, ties "
          "included",
          "[alignment]") {
  std::mt19937 random(47);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 600; ++trial) {
    const std::size_t n = random() % 14, m = random() % 14;
    Eigen::MatrixXd d(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
    for (Eigen::Index k = 0; k < d.size(); ++k)  // quantised on most trials: ties everywhere
      d(k) = trial % 3 == 2 ? unit(random) : 0.5 * double(random() % 3);
    // Scores on a grid of halves (exact sums, so equal paths tie), or drawn.
    Smith_waterman p;
    if (trial % 2 == 0) {
      p.match = 1;
      p.mismatch = -0.5 * double(random() % 4);
      p.gap_open = 0.5 * double(random() % 4);
      p.gap_extend = trial % 4 == 0 ? p.gap_open : 0.5 * double(random() % (1 + unsigned(2 * p.gap_open)));
    } else {
      p.match = 0.5 + unit(random);
      p.mismatch = p.match - 3 * unit(random);
      p.gap_open = 2 * unit(random);
      p.gap_extend = trial % 3 == 0 ? p.gap_open : p.gap_open * unit(random);
    }
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    INFO("trial " << trial << ", " << n << " x " << m << ", gaps " << p.gap_open << " / " << p.gap_extend);
    deformseg::alignment_test::check_score_and_length(p.score_and_length(n, m, dis), p.align(n, m, dis));
  }
}
