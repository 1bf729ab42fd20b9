#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>

#include "alignment_test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
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
static_assert(deformseg::alignment::ScoreAndLengthPolicy<Dtw>);
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

namespace {

using deformseg::alignment::Dtw_mean_cost;
using deformseg::alignment::Dtw_mean_cost_options;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// mean_cost without abandoning is align's score, bit for bit, and the length of its pairs.
template <class D>
void check_mean_cost_is_align(const Dtw& dtw, std::size_t n, std::size_t m, const D& d) {
  INFO(n << " x " << m << ", window " << dtw.window.value_or(0) << (dtw.window ? "" : " (none)"));
  const Alignment path = dtw.align(n, m, d);
  const Dtw_mean_cost value = dtw.mean_cost(n, m, d);
  CHECK(bits(value.score) == bits(path.score));
  CHECK(value.length == path.pairs.size());
  CHECK(!value.abandoned);
  CHECK(value.rows_done == n);
}

// A matrix dissimilarity that gives whole rows too, and counts the calls of each kind.
struct Counted_row_dissimilarity {
  const Eigen::MatrixXd* matrix;
  std::size_t* cell_calls;
  std::size_t* row_calls;
  double operator()(std::size_t i, std::size_t j) const {
    ++*cell_calls;
    return (*matrix)(Eigen::Index(i), Eigen::Index(j));
  }
  void row(std::size_t i, std::size_t first, std::size_t count, double* out) const {
    ++*row_calls;
    for (std::size_t k = 0; k < count; ++k) out[k] = (*matrix)(Eigen::Index(i), Eigen::Index(first + k));
  }
};

// Counts the distinct rows a pass reads.
struct Row_reading_dissimilarity {
  const Eigen::MatrixXd* matrix;
  std::vector<bool>* rows_read;
  double operator()(std::size_t i, std::size_t j) const {
    (*rows_read)[i] = true;
    return (*matrix)(Eigen::Index(i), Eigen::Index(j));
  }
};

// r_i = min_j d(i, j) times a factor in [0, 1] (exactly 1 or 0 now and then): valid row bounds.
std::vector<double> random_row_bounds(const Eigen::MatrixXd& d, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> r(std::size_t(d.rows()));
  for (std::size_t i = 0; i < r.size(); ++i) {
    const unsigned kind = random() % 4;
    const double factor = kind == 0 ? 1.0 : kind == 1 ? 0.0 : unit(random);
    r[i] = d.row(Eigen::Index(i)).minCoeff() * factor;
  }
  return r;
}

}  // namespace

static_assert(deformseg::alignment::RowDissimilarity<Counted_row_dissimilarity>);
static_assert(!deformseg::alignment::RowDissimilarity<deformseg::alignment::Matrix_dissimilarity>);

TEST_CASE("Dtw::mean_cost: the hand-worked example, and empty sequences", "[alignment]") {
  const Eigen::MatrixXd d = absolute_differences({1, 3, 4, 9}, {1, 4, 8});
  const Dtw_mean_cost value = Dtw{}.mean_cost(4, 3, deformseg::alignment::matrix_dissimilarity(d));
  CHECK(value.score == 2);
  CHECK(value.length == 4);  // (0, 0) (1, 1) (2, 1) (3, 2)
  CHECK(value.mean() == 0.5);
  const std::vector<int> empty, some{1, 2};
  const Dtw_mean_cost none = Dtw{}.mean_cost(0, 0, deformseg::alignment::label_mismatch(empty, empty));
  CHECK((none.score == 0 && none.length == 0 && !none.abandoned && none.rows_done == 0 && none.mean() == 0));
  CHECK_THROWS_AS(Dtw{}.mean_cost(0, 2, deformseg::alignment::label_mismatch(empty, some)), deformseg::invalid_input);
}

TEST_CASE("Dtw::mean_cost equals align bit for bit on random and tie-heavy grids, with and without window",
          "[alignment]") {
  std::mt19937 random(27);
  for (int trial = 0; trial < 600; ++trial) {
    // Every remainder of the rows taken four at a time, and long thin grids both ways.
    std::size_t n = 1 + std::size_t(trial) % 9, m = 1 + random() % 12;
    if (trial % 10 == 7) std::swap(n, m);
    if (trial % 50 == 3) n = 120 + random() % 5, m = 1 + random() % 4;
    if (trial % 50 == 4) n = 1 + random() % 4, m = 120 + random() % 5;
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    check_mean_cost_is_align(Dtw{}, n, m, dis);
    const Dtw banded{.window = random() % 5};
    try {
      banded.align(n, m, dis);
    } catch (const deformseg::invalid_input&) {  // the band does not connect the corners
      CHECK_THROWS_AS(banded.mean_cost(n, m, dis), deformseg::invalid_input);
      continue;
    }
    check_mean_cost_is_align(banded, n, m, dis);
  }
}

TEST_CASE("Dtw::mean_cost equals align on label sequences, where ties are the rule", "[alignment]") {
  std::mt19937 random(8);
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<int> a(1 + random() % 14), b(1 + random() % 14);
    for (auto& x : a) x = int(random() % 3);
    for (auto& x : b) x = int(random() % 3);
    INFO("trial " << trial);
    check_mean_cost_is_align(Dtw{}, a.size(), b.size(), deformseg::alignment::label_mismatch(a, b));
    check_mean_cost_is_align(Dtw{}, b.size(), a.size(), deformseg::alignment::label_mismatch(b, a));
  }
  // All cells equal: the diagonal is preferred, and its length is counted.
  const std::vector<int> same(7, 1);
  CHECK(Dtw{}.mean_cost(7, 7, deformseg::alignment::label_mismatch(same, same)).length == 7);
}

TEST_CASE("Dtw::mean_cost equals align on larger grids", "[alignment]") {
  std::mt19937 random(3);
  for (const auto& [n, m] : {std::pair<std::size_t, std::size_t>{203, 150}, {150, 203}, {7, 300}, {301, 2}, {1, 64}}) {
    for (int trial : {0, 1}) {
      const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
      const auto dis = deformseg::alignment::matrix_dissimilarity(d);
      check_mean_cost_is_align(Dtw{}, n, m, dis);
      check_mean_cost_is_align(Dtw{.window = 160}, n, m, dis);
    }
  }
}

TEST_CASE("Dtw::mean_cost never abandons when the mean cost is at most the threshold", "[alignment]") {
  std::mt19937 random(12);
  for (int trial = 0; trial < 600; ++trial) {
    const std::size_t n = 1 + random() % 30, m = 1 + random() % 30;
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    const Dtw dtw{.window = trial % 3 == 0 ? std::optional<std::size_t>(std::max(n, m) / 2) : std::nullopt};
    const Dtw_mean_cost exact = dtw.mean_cost(n, m, dis);
    const double mean = exact.score / double(exact.length);
    const std::vector<double> r = random_row_bounds(d, random);
    INFO("trial " << trial << ", " << n << " x " << m << ", mean " << mean);
    const double infinity = std::numeric_limits<double>::infinity();
    for (const double tau : {mean, std::nextafter(mean, infinity), mean * 1.001 + 1e-9, 2.0, infinity}) {
      for (const bool with_bounds : {false, true}) {
        const Dtw_mean_cost value =
            dtw.mean_cost(n, m, dis, {.abandon_above = tau, .row_bounds = with_bounds ? r : std::vector<double>{}});
        CHECK(!value.abandoned);
        CHECK(bits(value.score) == bits(exact.score));
        CHECK(value.length == exact.length);
        CHECK(value.rows_done == n);
      }
    }
    // Below the mean cost, the test after the last row at least proves it.
    if (mean > 0)
      for (const double tau : {std::nextafter(mean, -infinity), mean / 2}) {
        const Dtw_mean_cost value = dtw.mean_cost(n, m, dis, {.abandon_above = tau, .row_bounds = r});
        CHECK(value.abandoned);
        CHECK(value.rows_done >= std::min<std::size_t>(n, 4));
      }
  }
}

TEST_CASE("Dtw::mean_cost abandons early on rows it can prove too costly, without reading the rest", "[alignment]") {
  const std::size_t n = 40, m = 40;
  Eigen::MatrixXd d = Eigen::MatrixXd::Ones(n, m);
  d(0, 0) = 0;
  std::vector<bool> rows_read(n, false);
  const Row_reading_dissimilarity dis{&d, &rows_read};
  // Every row costs at least 1 but the first: after four rows every path is proved to cost
  // at least (3 + 36 + ...) / (4 + ...) on average, far above 0.5.
  std::vector<double> r(n, 1.0);
  r[0] = 0;
  const Dtw_mean_cost with_bounds = Dtw{}.mean_cost(n, m, dis, {.abandon_above = 0.5, .row_bounds = r});
  CHECK(with_bounds.abandoned);
  CHECK(with_bounds.rows_done == 4);
  CHECK(std::count(rows_read.begin(), rows_read.end(), true) == 4);
  // Without row bounds the rest is counted free: the proof needs a lower threshold or more rows.
  std::fill(rows_read.begin(), rows_read.end(), false);
  const Dtw_mean_cost without_bounds = Dtw{}.mean_cost(n, m, dis, {.abandon_above = 0.01});
  CHECK(without_bounds.abandoned);
  CHECK(without_bounds.rows_done < n);
  CHECK(std::size_t(std::count(rows_read.begin(), rows_read.end(), true)) == without_bounds.rows_done);
  const Dtw_mean_cost later = Dtw{}.mean_cost(n, m, dis, {.abandon_above = 0.5});
  CHECK(later.abandoned);
  CHECK(later.rows_done > 4);
  // Windowed, row by row, still every fourth row.
  const Dtw_mean_cost banded = Dtw{.window = 3}.mean_cost(n, m, dis, {.abandon_above = 0.5, .row_bounds = r});
  CHECK(banded.abandoned);
  CHECK(banded.rows_done == 4);
}

TEST_CASE("Dtw::mean_cost refuses unusable options", "[alignment]") {
  const Eigen::MatrixXd d = Eigen::MatrixXd::Ones(3, 2);
  const auto dis = deformseg::alignment::matrix_dissimilarity(d);
  CHECK_THROWS_WITH(Dtw{}.mean_cost(3, 2, dis, {.abandon_above = std::nan("")}), Catch::Contains("NaN"));
  const std::vector<double> two{0, 0}, negative{0, -1, 0}, infinite{0, 0, std::numeric_limits<double>::infinity()};
  CHECK_THROWS_WITH(Dtw{}.mean_cost(3, 2, dis, {.row_bounds = two}), Catch::Contains("2 row bounds for 3 rows"));
  CHECK_THROWS_WITH(Dtw{}.mean_cost(3, 2, dis, {.row_bounds = negative}), Catch::Contains("row bound 1"));
  CHECK_THROWS_WITH(Dtw{}.mean_cost(3, 2, dis, {.row_bounds = infinite}), Catch::Contains("row bound 2"));
  Eigen::MatrixXd bad = d;
  bad(2, 1) = -0.5;
  CHECK_THROWS_WITH(Dtw{}.mean_cost(3, 2, deformseg::alignment::matrix_dissimilarity(bad)), Catch::Contains("d(2, 1)"));
}

TEST_CASE("A dissimilarity that gives whole rows is read by rows, with the same results", "[alignment]") {
  std::mt19937 random(4);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 1 + random() % 20, m = 1 + random() % 20;
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
    const auto cellwise = deformseg::alignment::matrix_dissimilarity(d);
    std::size_t cell_calls = 0, row_calls = 0;
    const Counted_row_dissimilarity rows{&d, &cell_calls, &row_calls};
    const std::optional<std::size_t> window = trial % 2 ? std::optional<std::size_t>(std::max(n, m) - 1) : std::nullopt;
    const Dtw dtw{.window = window};
    const Alignment by_rows = dtw.align(n, m, rows);
    CHECK(row_calls == n);
    CHECK(cell_calls == 0);
    const Alignment by_cells = dtw.align(n, m, cellwise);
    CHECK(bits(by_rows.score) == bits(by_cells.score));
    CHECK(by_rows.pairs == by_cells.pairs);
    row_calls = 0;
    const Dtw_mean_cost value = dtw.mean_cost(n, m, rows);
    CHECK(row_calls == n);
    CHECK(cell_calls == 0);
    CHECK(bits(value.score) == bits(by_cells.score));
    CHECK(value.length == by_cells.pairs.size());
    CHECK(bits(dtw.score(n, m, rows)) == bits(by_cells.score));
    row_calls = 0;
    const Alignment local_by_rows = deformseg::alignment::Smith_waterman{}.align(n, m, rows);
    CHECK(row_calls == n);
    const Alignment local_by_cells = deformseg::alignment::Smith_waterman{}.align(n, m, cellwise);
    CHECK(bits(local_by_rows.score) == bits(local_by_cells.score));
    CHECK(local_by_rows.pairs == local_by_cells.pairs);
  }
  // Its values are checked as the cellwise ones are.
  Eigen::MatrixXd bad = Eigen::MatrixXd::Ones(2, 5);
  bad(1, 3) = std::numeric_limits<double>::quiet_NaN();
  std::size_t cell_calls = 0, row_calls = 0;
  CHECK_THROWS_WITH(Dtw{}.mean_cost(2, 5, Counted_row_dissimilarity{&bad, &cell_calls, &row_calls}),
                    Catch::Contains("d(1, 3)"));
}

TEST_CASE("Dtw::score_and_length is align's score and number of pairs, through a byte per cell or in linear "
          "space, ties included",
          "[alignment]") {
  std::mt19937 random(45);
  for (int trial = 0; trial < 400; ++trial) {
    const auto [n, m] = deformseg::alignment_test::small_shape(trial, random);
    const Eigen::MatrixXd d = deformseg::alignment_test::random_dissimilarities(n, m, trial, random);
    const auto dis = deformseg::alignment::matrix_dissimilarity(d);
    for (const std::optional<std::size_t> window : {std::optional<std::size_t>{}, std::optional<std::size_t>(4)}) {
      for (const std::size_t budget : {std::size_t(1) << 25, std::size_t(0)}) {  // 0: always in linear space
        const Dtw dtw{.window = window, .max_trace_bytes = budget};
        INFO("trial " << trial << ", " << n << " x " << m << ", budget " << budget);
        Alignment path;
        try {
          path = dtw.align(n, m, dis);
        } catch (const deformseg::invalid_input&) {  // the band does not connect the corners
          CHECK_THROWS_AS(dtw.score_and_length(n, m, dis), deformseg::invalid_input);
          continue;
        }
        deformseg::alignment_test::check_score_and_length(dtw.score_and_length(n, m, dis), path);
      }
    }
  }
  const std::vector<int> empty;
  const auto none = Dtw{}.score_and_length(0, 0, deformseg::alignment::label_mismatch(empty, empty));
  CHECK((none.score == 0 && none.length == 0));
}
