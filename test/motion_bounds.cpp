// Tests of search/motion_bounds.h: the summary's layout and errors; every lower bound at most
// the mean along Dtw's path and the least mean over all paths on random small pairs (overlapping,
// apart, identical, constant, one row) and on real pairs of the shared characters; the row bounds
// at most every cell of their row; the safe bound strictly below a kernel's value perturbed by the
// worst case of its contract, so that the pruning rule never drops a candidate that ties or beats.
#include "motion_bounds_reference.h"
#include "test_support.h"

#include <deformseg/io/read_animation.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace deformseg;
using signatures::Motion_signature_view;

namespace {

Motion_signature_view view_of(const Eigen::MatrixXf& m) {
  return {m.data(), std::size_t(m.rows()), std::size_t(m.cols())};
}

// The slack the bounds' double rounding may take beyond the exact bound (see safe_lower_bound).
bool at_most(double bound, double value) { return bound <= value * (1 + 0x1p-40) + 0x1p-50; }

// The kernel's contract at its worst: every cell 2^-12 f + 2^-22 below the reference (not below 0).
Eigen::MatrixXd kernel_worst_case(const Eigen::MatrixXd& d) {
  return (d.array() * (1 - 0x1p-12) - 0x1p-22).max(0.0).matrix();
}

struct Bounds {
  double box, mean, rows_columns;
};

Bounds bounds_of(const search::Motion_summary& a, const search::Motion_summary& b, double unit) {
  return {search::lb_box(a.view(), b.view(), unit), search::lb_mean(a.view(), b.view(), unit),
          search::lb_rows_columns(a.view(), b.view(), unit)};
}

// Checks every bound of (a, b) against the brute-force D, and the least mean over all paths when
// `least_mean` is set; gives the bounds.
Bounds check_bounds(const Eigen::MatrixXf& a, const Eigen::MatrixXf& b, std::size_t chunks_a, std::size_t chunks_b,
                    double unit, bool least_mean) {
  const auto sa = search::summarize(view_of(a), chunks_a), sb = search::summarize(view_of(b), chunks_b);
  const Bounds lb = bounds_of(sa, sb, unit);
  const Eigen::MatrixXd d = test::reference_dissimilarities(view_of(a), view_of(b), unit);
  const double dtw = test::dtw_mean(d);
  const double least = least_mean ? test::least_mean_over_paths(d) : dtw;
  INFO("n " << a.rows() << " m " << b.rows() << " W " << a.cols() << " chunks " << chunks_a << "/" << chunks_b
            << " D " << dtw << " least " << least << " box " << lb.box << " mean " << lb.mean << " rows "
            << lb.rows_columns);
  CHECK(least <= dtw);
  for (const double bound : {lb.box, lb.mean, lb.rows_columns}) {
    CHECK(bound >= 0);
    CHECK(at_most(bound, least));
  }
  // The box is the weakest of the three (every chunk box and corner lies in it).
  CHECK(at_most(lb.box, lb.mean));
  CHECK(at_most(lb.box, lb.rows_columns));
  // Row bounds: at most every cell of their row, exactly (the same sums, each term no larger).
  std::vector<double> rows(std::size_t(a.rows()));
  search::row_bounds(view_of(a), sb.view(), unit, rows);
  for (Eigen::Index i = 0; i < a.rows(); ++i) CHECK(rows[std::size_t(i)] <= d.row(i).minCoeff());
  // Row i's bound is f of its least gap2 to a chunk box, each summed over the dimensions in order.
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < sb.view().chunks(); ++c) {
      double sum = 0;
      for (Eigen::Index k = 0; k < a.cols(); ++k) {
        const double x = a(i, k), g = std::max({0.0, x - double(sb.view().chunk_hi(c)[std::size_t(k)]),
                                                double(sb.view().chunk_lo(c)[std::size_t(k)]) - x});
        sum += g * g;
      }
      least = std::min(least, sum);
    }
    CHECK(rows[std::size_t(i)] == signatures::frame_dissimilarity(least, unit));
  }
  // With the caller's scratch, dirty and longer than needed: the same bounds, bit for bit.
  std::vector<double> scratch(rows.size() + 3, 7.5), again(rows.size(), -1.0);
  search::row_bounds(view_of(a), sb.view(), unit, again, scratch);
  CHECK(again == rows);
  std::vector<double> gaps(chunks_a + chunks_b + 2, -1.0);
  CHECK(search::lb_rows_columns(sa.view(), sb.view(), unit, gaps) == lb.rows_columns);
  // A kernel at the worst of its contract: the safe bounds stay strictly below its value, and a
  // candidate whose value ties the k-th is never pruned.
  const double kernel = test::dtw_mean(kernel_worst_case(d));
  for (const double bound : {lb.box, lb.mean, lb.rows_columns, least}) {
    CHECK(search::safe_lower_bound(bound) < kernel);
    CHECK(search::may_beat(bound, 1 - kernel));
  }
  return lb;
}

}  // namespace

TEST_CASE("summarize: bounds, mean, first and last rows and chunk boxes, dimension-major, in a flat block",
          "[motion_bounds]") {
  Eigen::MatrixXf m(5, 2);  // rows 0..4, dimension 0 then dimension 1
  m << 1, -1, 4, 0, 2, 7, -3, 2, 5, 1;
  const auto s = search::summarize(view_of(m), 2);
  REQUIRE(s.floats.size() == search::summary_width(2, 2));
  CHECK(search::summary_width(64, 4) == 833);
  const auto v = s.view();
  CHECK(v.rows() == 5);
  CHECK(v.width() == 2);
  CHECK(v.chunks() == 2);
  const auto equal = [](std::span<const float> got, std::vector<float> expected) {
    return std::vector<float>(got.begin(), got.end()) == expected;
  };
  CHECK(equal(v.lo(), {-3, -1}));
  CHECK(equal(v.hi(), {5, 7}));
  CHECK(equal(v.mean(), {9.0f / 5, 9.0f / 5}));
  CHECK(equal(v.first_row(), {1, -1}));
  CHECK(equal(v.last_row(), {5, 1}));
  // Chunks of 5 rows in 2: rows 0-1 and 2-4.
  CHECK(equal(v.chunk_lo(0), {1, -1}));
  CHECK(equal(v.chunk_hi(0), {4, 0}));
  CHECK(equal(v.chunk_lo(1), {-3, 1}));
  CHECK(equal(v.chunk_hi(1), {5, 7}));
  // The flat layout: rows, lo, hi, mean, first, last, then each chunk's lows and highs.
  CHECK(s.floats[0] == 5);
  CHECK(s.floats[1] == -3);
  CHECK(s.floats[1 + 2] == 5);
  // Round trip through a caller's block.
  std::vector<float> block(s.floats.size());
  search::write_summary(s, block);
  CHECK(search::read_summary(block, 2, 2).floats == s.floats);
  search::summarize_into(view_of(m), 2, block);
  CHECK(block == s.floats);
}

TEST_CASE("summarize: fewer rows than chunks repeat the last row's box", "[motion_bounds]") {
  Eigen::MatrixXf m(2, 1);
  m << 3, 8;
  const auto s = search::summarize(view_of(m));
  const auto v = s.view();
  REQUIRE(v.chunks() == 4);
  const float expected[] = {3, 8, 8, 8};
  for (std::size_t c = 0; c < 4; ++c) {
    CHECK(v.chunk_lo(c)[0] == expected[c]);
    CHECK(v.chunk_hi(c)[0] == expected[c]);
  }
}

TEST_CASE("summarize and the bounds: errors name what is wrong", "[motion_bounds]") {
  Eigen::MatrixXf m = Eigen::MatrixXf::Ones(3, 2), wide = Eigen::MatrixXf::Ones(3, 4), empty(0, 2);
  CHECK_THROWS_WITH(search::summarize(view_of(empty)), Catch::Contains("no row"));
  CHECK_THROWS_WITH(search::summarize(view_of(m), 0), Catch::Contains("chunks must be positive"));
  const auto s = search::summarize(view_of(m));
  std::vector<float> block(s.floats.size() + 1);
  CHECK_THROWS_WITH(search::write_summary(s, block), Catch::Contains("holds 28 floats"));
  CHECK_THROWS_WITH(search::read_summary(std::span(block).first(27), 2, 3),
                    Catch::Contains("has 23 floats, not 27"));
  CHECK_THROWS_WITH(search::summarize_into(view_of(m), 4, block), Catch::Contains("holds 28 floats"));
  auto broken = s.floats;
  broken[0] = 2.5f;
  CHECK_THROWS_WITH(search::read_summary(broken, 2, 4), Catch::Contains("not a summary"));
  broken[0] = 0;
  CHECK_THROWS_WITH(search::read_summary(broken, 2, 4), Catch::Contains("not a summary"));
  const auto w = search::summarize(view_of(wide));
  CHECK_THROWS_WITH(search::lb_box(s.view(), w.view(), 1), Catch::Contains("different widths (2 and 4)"));
  CHECK_THROWS_WITH(search::lb_mean(s.view(), w.view(), 1), Catch::Contains("lb_mean"));
  CHECK_THROWS_WITH(search::lb_rows_columns(w.view(), s.view(), 1), Catch::Contains("lb_rows_columns"));
  std::vector<double> out(3);
  CHECK_THROWS_WITH(search::row_bounds(view_of(wide), s.view(), 1, out), Catch::Contains("4 wide"));
  CHECK_THROWS_WITH(search::row_bounds(view_of(m), s.view(), 1, std::span(out).first(2)),
                    Catch::Contains("3 rows"));
  std::vector<double> short_scratch(2);
  CHECK_THROWS_WITH(search::row_bounds(view_of(m), s.view(), 1, out, short_scratch),
                    Catch::Contains("the scratch 2, the query has 3 rows"));
  CHECK_THROWS_WITH(search::lb_rows_columns(s.view(), s.view(), 1, short_scratch),
                    Catch::Contains("the scratch holds 2 values"));
  // A view made unchecked reads the same block as a checked one.
  const auto unchecked = search::Motion_summary_view::unchecked(s.floats, s.width, s.chunks);
  CHECK(unchecked.rows() == s.view().rows());
  CHECK(search::lb_mean(unchecked, s.view(), 1) == search::lb_mean(s.view(), s.view(), 1));
}

TEST_CASE("may_beat: prunes only when 1 - the safe bound is strictly below the k-th value", "[motion_bounds]") {
  CHECK(search::safe_lower_bound(1) == 1 - 0x1p-10 - 0x1p-20);
  CHECK(search::may_beat(0.5, -std::numeric_limits<double>::infinity()));
  CHECK(search::may_beat(0.5, 0.5));
  CHECK(search::may_beat(0.5, 0.5 + 0x1p-11));  // within the slack
  CHECK(!search::may_beat(0.5, 0.5 + 0x1p-10));
  CHECK(!search::may_beat(0.9, 0.2));
  CHECK(search::may_beat(std::numeric_limits<double>::quiet_NaN(), 0.9));
  CHECK(search::may_beat(0, 1));  // a bound of 0 prunes nothing
}

TEST_CASE("lb_box, lb_mean, lb_rows_columns, row_bounds: at most D and the least mean over all paths on random "
          "pairs",
          "[motion_bounds]") {
  std::mt19937 random(27);
  const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  std::normal_distribution<float> normal(0, 1);
  const auto noise = [&](Eigen::Index rows, Eigen::Index cols, float spread) {
    Eigen::MatrixXf m(rows, cols);
    for (float& x : m.reshaped()) x = spread * normal(random);
    return m;
  };
  int apart = 0, tight = 0;
  for (int trial = 0; trial < 12000; ++trial) {
    const Eigen::Index n = pick(1, 12), m = pick(1, 12), width = pick(1, 8);
    const float spread = std::array{0.05f, 0.5f, 2.0f}[std::size_t(pick(0, 2))];
    Eigen::MatrixXf a = noise(n, width, spread), b;
    switch (trial % 6) {
    case 0:  // independent, boxes mostly overlapping
      b = noise(m, width, spread);
      break;
    case 1:  // shifted apart in some dimensions
      b = noise(m, width, spread);
      for (Eigen::Index k = 0; k < width; ++k)
        if (pick(0, 1)) b.col(k).array() += float(pick(-4, 4)) * spread;
      break;
    case 2:  // the same clip
      b = a;
      break;
    case 3:  // constant clips
      a = a.row(0).replicate(n, 1);
      b = (noise(1, width, spread).array() + float(pick(0, 2)) * spread).matrix().replicate(m, 1);
      break;
    case 4:  // a time-warped copy of a, perturbed
      b.resize(m, width);
      for (Eigen::Index j = 0; j < m; ++j) b.row(j) = a.row(j * n / m);
      b += noise(m, width, spread / 10);
      break;
    default:  // a drifting motion against a still one
      for (Eigen::Index i = 0; i < n; ++i) a.row(i).array() += float(i) * spread;
      b = noise(1, width, spread).replicate(m, 1);
      break;
    }
    const double unit = signatures::frame_dissimilarity_unit(std::size_t(width), std::array{0.3, 1.77, 5.0}[trial % 3]);
    const std::size_t chunks_a = trial % 4 == 0 ? std::size_t(pick(1, 6)) : 4;
    const std::size_t chunks_b = trial % 4 == 0 ? std::size_t(pick(1, 6)) : 4;
    const Bounds lb = check_bounds(a, b, chunks_a, chunks_b, unit, true);
    apart += lb.box > 0;
    tight += lb.rows_columns > lb.box;
  }
  // The cases are not all trivial: the boxes are often apart, the chunks often beat the box.
  CHECK(apart > 2000);
  CHECK(tight > 4000);
}

TEST_CASE("lb_rows_columns: exact for one cell, and for one row against one row", "[motion_bounds]") {
  Eigen::MatrixXf a(1, 3), b(1, 3);
  a << 0.5f, -1, 2;
  b << 0, 1, 1.5f;
  const double unit = signatures::frame_dissimilarity_unit(3, 1.77);
  const auto sa = search::summarize(view_of(a)), sb = search::summarize(view_of(b));
  const Eigen::MatrixXd d = test::reference_dissimilarities(view_of(a), view_of(b), unit);
  CHECK(search::lb_rows_columns(sa.view(), sb.view(), unit) == d(0, 0));
  CHECK(search::lb_rows_columns(sb.view(), sa.view(), unit) == d(0, 0));
}

TEST_CASE("lb_box, lb_mean, lb_rows_columns, row_bounds: at most D on pairs of the shared characters",
          "[motion_bounds][data]") {
  const auto dir = test::data_dir() / "characters";
  std::ifstream labels(dir / "motions.csv");
  REQUIRE(labels);
  std::string line;
  std::getline(labels, line);
  const similarity::Motion_signature_similarity<> policy;
  std::vector<Eigen::MatrixXf> clips;
  // Every 20th clip of the labels: eighteen clips of several bodies and motions.
  for (int index = 0; std::getline(labels, line); ++index) {
    if (index % 20 != 0) continue;
    std::stringstream fields(line);
    std::string file, clip;
    std::getline(fields, file, ',');
    std::getline(fields, clip, ',');
    const auto animation = io::read_animation((dir / file).string(), {.clip = clip});
    clips.push_back(policy.describe(animation).signatures.cast<float>());
  }
  REQUIRE(clips.size() >= 18);
  const double unit = signatures::frame_dissimilarity_unit(std::size_t(clips[0].cols()), policy.scale);
  const std::size_t count = clips.size(), k = 3;
  std::vector<Bounds> bounds(count * count);
  std::vector<double> values(count * count);
  for (std::size_t q = 0; q < count; ++q)
    for (std::size_t c = 0; c < count; ++c) {
      const auto &a = clips[q], &b = clips[c];
      bounds[q * count + c] = check_bounds(a, b, 4, 4, unit, a.rows() * b.rows() <= 40 * 40);
      values[q * count + c] = 1 - test::dtw_mean(test::reference_dissimilarities(view_of(a), view_of(b), unit));
    }
  // A top-3 search of each clip among the others: no candidate that reaches the 3rd best value is
  // pruned, and the bounds do prune some of the others (the figures: test/bench/motion_bounds_pruning).
  std::size_t pruned = 0;
  for (std::size_t q = 0; q < count; ++q) {
    std::vector<double> others;
    for (std::size_t c = 0; c < count; ++c)
      if (c != q) others.push_back(values[q * count + c]);
    std::sort(others.begin(), others.end(), std::greater<>());
    const double kth = others[k - 1];
    for (std::size_t c = 0; c < count; ++c) {
      if (c == q) continue;
      const Bounds& lb = bounds[q * count + c];
      const bool prunable = !search::may_beat(std::max({lb.box, lb.mean, lb.rows_columns}), kth);
      if (values[q * count + c] >= kth) CHECK(!prunable);
      pruned += prunable;
    }
  }
  CHECK(pruned > count);
}
