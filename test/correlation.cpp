#include <deformseg/evaluation/correlation.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using deformseg::evaluation::pearson_correlation;
using deformseg::evaluation::spearman_correlation;

TEST_CASE("pearson_correlation: a value worked by hand", "[correlation]") {
  // Deviations -2 -1 0 1 2 and -2 0 1 0 1: r = 6 / sqrt(10 * 6).
  const std::vector<double> x{1, 2, 3, 4, 5}, y{2, 4, 5, 4, 5};
  CHECK(evaluation::pearson_correlation(x, y) == Approx(6 / std::sqrt(60.0)).epsilon(1e-14));
  CHECK(evaluation::pearson_correlation(y, x) == evaluation::pearson_correlation(x, y));
  CHECK(evaluation::pearson_correlation(x, x) == 1.0);
}

TEST_CASE("pearson_correlation: unchanged by positive affine maps, negated by negative ones", "[correlation]") {
  std::mt19937 random(21);
  std::normal_distribution<double> normal;
  std::vector<double> x(50), y(50), scaled(50), flipped(50);
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = normal(random);
    y[k] = 0.5 * x[k] + normal(random);
    scaled[k] = 3 * y[k] + 7;
    flipped[k] = -2 * y[k] + 1;
  }
  const double r = evaluation::pearson_correlation(x, y);
  CHECK(r > 0.2);
  CHECK(r < 1.0);
  CHECK(evaluation::pearson_correlation(x, scaled) == Approx(r).epsilon(1e-12));
  CHECK(evaluation::pearson_correlation(x, flipped) == Approx(-r).epsilon(1e-12));
}

TEST_CASE("spearman_correlation: values worked by hand, with and without ties", "[correlation]") {
  // No ties: rank differences -2 1 -1 -1 3, so 1 - 6 * 16 / (5 * 24) = 0.2.
  const std::vector<double> x{10, 20, 30, 40, 50}, y{3, 1, 4, 5, 2};
  CHECK(evaluation::spearman_correlation(x, y) == Approx(0.2).epsilon(1e-14));
  // Ties: the ranks of 2 4 5 4 5 are 1 2.5 4.5 2.5 4.5, deviations -2 -0.5 1.5 -0.5 1.5 against
  // -2 -1 0 1 2: 7 / sqrt(10 * 9).
  const std::vector<double> u{1, 2, 3, 4, 5}, v{2, 4, 5, 4, 5};
  CHECK(evaluation::spearman_correlation(u, v) == Approx(7 / std::sqrt(90.0)).epsilon(1e-14));
}

TEST_CASE("spearman_correlation: unchanged by increasing transforms, 1 for any monotone relation", "[correlation]") {
  std::mt19937 random(22);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> x(40), y(40), grown(40), cubed(40);
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = unit(random);
    y[k] = x[k] + 0.3 * unit(random);
    grown[k] = std::exp(5 * y[k]);
    cubed[k] = x[k] * x[k] * x[k];
  }
  const double rho = evaluation::spearman_correlation(x, y);
  CHECK(evaluation::spearman_correlation(x, grown) == Approx(rho).epsilon(1e-14));
  CHECK(evaluation::spearman_correlation(x, cubed) == Approx(1.0).epsilon(1e-14));
  CHECK(evaluation::pearson_correlation(x, cubed) < 0.99);  // Pearson sees the curve
}

TEST_CASE("correlation: invalid input throws", "[correlation]") {
  using deformseg::invalid_input;
  const std::vector<double> three{1, 2, 3}, two{1, 2}, one{1}, constant{4, 4, 4};
  for (const auto correlation : {&pearson_correlation, &evaluation::spearman_correlation}) {
    CHECK_THROWS_AS(correlation(three, two), invalid_input);
    CHECK_THROWS_AS(correlation(one, one), invalid_input);
    CHECK_THROWS_WITH(correlation(three, constant), Catch::Contains("constant"));
    CHECK_THROWS_AS(correlation(constant, three), invalid_input);
    const std::vector<double> with_nan{1, std::numeric_limits<double>::quiet_NaN(), 3};
    CHECK_THROWS_AS(correlation(three, with_nan), invalid_input);
    CHECK(correlation(two, two) == 1.0);
  }
}
