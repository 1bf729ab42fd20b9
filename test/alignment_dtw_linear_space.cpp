// Dtw::align's linear-space traceback (Dtw::max_trace_bytes, internal/dtw_linear_space.h): the same
// pairs and the same score, bit for bit, as the traceback through a byte per cell, on random and
// tie-heavy grids of many shapes, with every start and end rule of the DTW passes, with and without
// a window, through Dtw and Subsequence_dtw, and on the signatures of two shared clips.
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include "alignment_test_support.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace al = deformseg::alignment;
using End = al::internal::Dtw_ends::End;

constexpr std::size_t no_limit = std::numeric_limits<std::size_t>::max();

void check_same(const al::Alignment& linear, const al::Alignment& whole) {
  CHECK(std::bit_cast<std::uint64_t>(linear.score) == std::bit_cast<std::uint64_t>(whole.score));
  CHECK(linear.pairs == whole.pairs);
}

// An n x m grid: on even trials values from {0, 0.25, 0.5} (ties everywhere), on odd ones those of
// alignment_test_support (integer differences, or uniform in [0, 1)).
Eigen::MatrixXd grid(std::size_t n, std::size_t m, int trial, std::mt19937& random) {
  if (trial % 2 == 1) return deformseg::alignment_test::random_dissimilarities(n, m, trial / 2, random);
  Eigen::MatrixXd d(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  for (Eigen::Index k = 0; k < d.size(); ++k) d(k) = 0.25 * double(random() % 3);
  return d;
}

// Shapes: 1 x 1, single rows and columns, thin both ways, square, and larger.
std::pair<std::size_t, std::size_t> shape(int trial, std::mt19937& random) {
  switch (trial % 8) {
    case 0: return {1, 1 + random() % 40};
    case 1: return {1 + random() % 40, 1};
    case 2: return {2 + random() % 3, 20 + random() % 40};
    case 3: return {20 + random() % 40, 2 + random() % 3};
    case 4: {
      const std::size_t n = 1 + random() % 30;
      return {n, n};
    }
    case 5: return {30 + random() % 40, 30 + random() % 40};
    default: return {1 + random() % 25, 1 + random() % 25};
  }
}

}  // namespace

TEST_CASE("Dtw linear space: every start and end rule, on random and tie-heavy grids of many shapes", "[alignment]") {
  std::mt19937 random(2027);
  const std::vector<std::size_t> budgets{0, 1, 3, 17, 200};
  for (int trial = 0; trial < 800; ++trial) {
    const auto [n, m] = shape(trial, random);
    const Eigen::MatrixXd d = grid(n, m, trial, random);
    const auto dis = al::matrix_dissimilarity(d);
    const al::internal::Band band(n, m, {});
    for (int rule = 0; rule < 12; ++rule) {
      const al::internal::Dtw_ends ends{bool(rule & 1), bool(rule & 2), End(rule / 4)};
      const al::Alignment whole = al::internal::dtw_align(n, m, dis, band, ends, no_limit, "test");
      for (const std::size_t budget : budgets) {
        INFO("trial " << trial << ", " << n << " x " << m << ", rule " << rule << ", budget " << budget);
        check_same(al::internal::dtw_align(n, m, dis, band, ends, budget, "test"), whole);
      }
    }
  }
}

TEST_CASE("Dtw linear space: align with and without a window, the same path as the byte per cell", "[alignment]") {
  std::mt19937 random(27);
  for (int trial = 0; trial < 600; ++trial) {
    const auto [n, m] = shape(trial, random);
    const Eigen::MatrixXd d = grid(n, m, trial, random);
    const auto dis = al::matrix_dissimilarity(d);
    const std::optional<std::size_t> windows[] = {std::nullopt, std::size_t(random() % 6)};
    for (const std::optional<std::size_t> window : windows) {
      const al::Dtw whole{.window = window, .max_trace_bytes = no_limit};
      al::Alignment expected;
      try {
        expected = whole.align(n, m, dis);
      } catch (const deformseg::invalid_input&) {  // the band does not connect the corners
        const al::Dtw linear{.window = window, .max_trace_bytes = 0};
        CHECK_THROWS_AS(linear.align(n, m, dis), deformseg::invalid_input);
        continue;
      }
      for (const std::size_t budget : {std::size_t(0), std::size_t(5), n * m - 1}) {
        INFO("trial " << trial << ", " << n << " x " << m << ", window " << window.value_or(99) << ", budget "
                      << budget);
        check_same(al::Dtw{.window = window, .max_trace_bytes = budget}.align(n, m, dis), expected);
      }
    }
  }
}

TEST_CASE("Dtw linear space: Subsequence_dtw, either sequence the query", "[alignment]") {
  std::mt19937 random(4);
  for (int trial = 0; trial < 400; ++trial) {
    const auto [n, m] = shape(trial, random);
    const Eigen::MatrixXd d = grid(n, m, trial, random);
    const auto dis = al::matrix_dissimilarity(d);
    for (const auto query : {al::Subsequence_query::first, al::Subsequence_query::shorter}) {
      const al::Subsequence_dtw whole{.query = query, .max_trace_bytes = no_limit};
      const al::Alignment expected = whole.align(n, m, dis);
      INFO("trial " << trial << ", " << n << " x " << m);
      check_same(al::Subsequence_dtw{.query = query, .max_trace_bytes = 0}.align(n, m, dis), expected);
      check_same(al::Subsequence_dtw{.query = query, .max_trace_bytes = 7}.align(n, m, dis), expected);
    }
  }
}

TEST_CASE("Dtw linear space: the default budget switches on a grid of 6,000 x 5,800, with the same path",
          "[alignment]") {
  // Two slow waves, their differences rounded to 1/64 so that many cells tie.
  const std::size_t n = 6000, m = 5800;
  REQUIRE(n * m > al::Dtw{}.max_trace_bytes);
  const auto dis = [](std::size_t i, std::size_t j) {
    return std::round(64 * std::abs(std::sin(0.003 * double(i)) - std::sin(0.0031 * double(j) + 0.2))) / 64;
  };
  check_same(al::Dtw{}.align(n, m, dis), al::Dtw{.max_trace_bytes = no_limit}.align(n, m, dis));
}

TEST_CASE("Dtw linear space: an invalid value is the same error, naming the same cell", "[alignment]") {
  Eigen::MatrixXd d = Eigen::MatrixXd::Constant(30, 20, 0.5);
  d(17, 3) = -1;
  d(22, 0) = std::nan("");
  const auto dis = al::matrix_dissimilarity(d);
  std::string whole, linear;
  try {
    al::Dtw{.max_trace_bytes = no_limit}.align(30, 20, dis);
  } catch (const deformseg::invalid_input& e) {
    whole = e.what();
  }
  try {
    al::Dtw{.max_trace_bytes = 0}.align(30, 20, dis);
  } catch (const deformseg::invalid_input& e) {
    linear = e.what();
  }
  CHECK(whole.find("d(17, 3)") != std::string::npos);
  CHECK(linear == whole);
}

TEST_CASE("Dtw linear space: two shared clips compared, the same path and value", "[alignment][data]") {
  namespace sim = deformseg::similarity;
  const auto dir = deformseg::test::data_dir() / "characters";
  std::ifstream labels(dir / "motions.csv");
  REQUIRE(labels);
  std::string line;
  std::getline(labels, line);
  const sim::Motion_signature_similarity<> policy;
  std::vector<sim::Motion_signature_description> described;
  // The first and the 40th clip of the labels: different motions of different lengths.
  for (int index = 0; described.size() < 2 && std::getline(labels, line); ++index) {
    if (index != 0 && index != 39) continue;
    std::stringstream fields(line);
    std::string file, clip;
    std::getline(fields, file, ',');
    std::getline(fields, clip, ',');
    described.push_back(policy.describe(deformseg::io::read_animation((dir / file).string(), {.clip = clip})));
  }
  REQUIRE(described.size() == 2);
  const auto &a = described[0], &b = described[1];
  const std::size_t n = sim::frame_count(a), m = sim::frame_count(b);
  REQUIRE(n * m > 100);
  const auto dis = policy.dissimilarity(a, b);
  const al::Alignment whole = al::Dtw{}.align(n, m, dis);
  for (const std::size_t budget : {std::size_t(0), std::size_t(64), n * m / 3}) {
    INFO(n << " x " << m << ", budget " << budget);
    check_same(al::Dtw{.max_trace_bytes = budget}.align(n, m, dis), whole);
    auto forced = policy;
    forced.alignment.max_trace_bytes = budget;
    const sim::Similarity expected = policy.compare(a, b), got = forced.compare(a, b);
    CHECK(std::bit_cast<std::uint64_t>(got.value) == std::bit_cast<std::uint64_t>(expected.value));
    CHECK(got.alignment == expected.alignment);
  }
}
