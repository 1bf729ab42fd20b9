// deformseg's portable random draws (internal/random.h): pinned sequences, so that a change of
// standard library (or of the draws) cannot change a result unnoticed.
#include <deformseg/internal/random.h>
#include <deformseg/similarity/significance.h>

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <span>
#include <vector>

// shuffle stays qualified: std::shuffle, found by argument-dependent lookup, would be ambiguous with it.
using deformseg::internal::Random_engine;
using deformseg::internal::shuffled_indices;
using deformseg::internal::uniform01;
using deformseg::internal::uniform_below;

namespace {


// The values below were computed by an implementation of MT19937 written from its published
// definition in Python (checked against the standard's 10000th draw, 4123659995), with the same
// Fisher-Yates and rejection draws: they depend on no C++ library.
TEST_CASE("random: the shuffle and the draws of a std::mt19937 are pinned", "[random]") {
  std::vector<int> items(10);
  std::iota(items.begin(), items.end(), 0);
  std::mt19937 random(7);
  deformseg::internal::shuffle(items.begin(), items.end(), random);
  CHECK(items == std::vector<int>{5, 9, 0, 1, 6, 7, 4, 8, 3, 2});
  std::mt19937 again(7);
  std::vector<std::uint64_t> draws;
  for (int i = 0; i < 8; ++i) draws.push_back(uniform_below(again, 6));
  CHECK(draws == std::vector<std::uint64_t>{4, 0, 1, 1, 3, 5, 5, 0});
  std::mt19937 one(1);
  CHECK(uniform01(one) == 0.4170219986692967);
}

// The order of k-medoids' build, from a std::mt19937_64: the same as clustering drew before the
// draws moved to internal/random.h (checked against that code), so no clustering changed.
TEST_CASE("random: shuffled_indices of a seed are pinned", "[random]") {
  CHECK(shuffled_indices(10, 42) == std::vector<std::size_t>{1, 7, 9, 0, 3, 8, 4, 2, 5, 6});
  CHECK(shuffled_indices(0, 42).empty());
  CHECK(shuffled_indices(1, 42) == std::vector<std::size_t>{0});
}

TEST_CASE("random: draws stay in their range and cover it", "[random]") {
  Random_engine random(3);
  std::vector<int> seen(7, 0);
  for (int i = 0; i < 700; ++i) {
    const std::uint64_t k = uniform_below(random, 7);
    REQUIRE(k < 7);
    ++seen[k];
    const double u = uniform01(random);
    REQUIRE((u >= 0 && u < 1));
  }
  for (const int count : seen) CHECK(count > 50);
  CHECK(uniform_below(random, 1) == 0);
}

// A policy whose value is the first frame's single entry: the z-score then depends only on which
// frame each shuffle puts first.
struct First_frame {
  struct Value {
    double value;
  };
  Value compare(const Eigen::MatrixXd&, const Eigen::MatrixXd& b) const { return {b(0, 0)}; }
};

TEST_CASE("random: similarity_significance shuffles with the portable shuffle", "[random][similarity]") {
  Eigen::MatrixXd frames(6, 1);
  frames << 10, 1, 2, 3, 4, 5;
  std::mt19937 random(7);
  const double z = deformseg::similarity::similarity_significance(First_frame{}, frames, frames, 5, random);
  // The same five shuffles made here: their first frames' values.
  std::mt19937 again(7);
  std::vector<std::size_t> order(6);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::vector<double> values;
  for (int c = 0; c < 5; ++c) {
    deformseg::internal::shuffle(order.begin(), order.end(), again);
    values.push_back(frames(Eigen::Index(order[0]), 0));
  }
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / 5;
  double square = 0;
  for (const double v : values) square += (v - mean) * (v - mean);
  CHECK(z == (10 - mean) / std::sqrt(square / 4));
  CHECK(values == std::vector<double>{10, 3, 4, 5, 2});
}

}  // namespace
