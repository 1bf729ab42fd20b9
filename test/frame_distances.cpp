// Tests of frame_distances.h and segment_cost.h: against direct computations, symmetry, the
// cancellation of near-identical frames, thread counts, and bad input.
#include "test_support.h"

#include <deformseg/strain/frame_distances.h>
#include <deformseg/temporal/segment_cost.h>

#include <cmath>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

// A field of random strains, with frames 3 and 4 equal but for one triangle and frame 5 zero.
strain::Strain_field<float> random_field(std::size_t faces, std::size_t frames, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> strain(0.0f, 1.0f);
  strain::Strain_field<float>::Storage values(faces * frames);
  for (auto& v : values) v = strain(random);
  for (std::size_t j = 0; j < faces; ++j) values[4 * faces + j] = values[3 * faces + j];
  values[4 * faces + 7] += 1e-3f;
  for (std::size_t j = 0; j < faces; ++j) values[5 * faces + j] = 0;
  return strain::Strain_field<float>(faces, frames, std::move(values), {}, std::nullopt, 0);
}

double direct(const strain::Strain_field<float>& field, std::size_t a, std::size_t b, strain::Frame_metric metric) {
  double sum = 0, xx = 0, yy = 0, xy = 0;
  for (std::size_t j = 0; j < field.num_faces(); ++j) {
    const double x = field(j, a), y = field(j, b);
    sum += metric == strain::Frame_metric::l1 ? std::abs(x - y) : (x - y) * (x - y);
    xx += x * x, yy += y * y, xy += x * y;
  }
  if (metric == strain::Frame_metric::cosine) return xx * yy > 0 ? 1 - xy / std::sqrt(xx * yy) : (xx + yy > 0 ? 1 : 0);
  return metric == strain::Frame_metric::l1 ? sum : std::sqrt(sum);
}

}  // namespace

TEST_CASE("frame_distances: equal to the direct formulas, symmetric, 0 on the diagonal", "[temporal]") {
  // 300 frames: three tiles of 128, so tiles off the diagonal and a partial one are exercised.
  const auto field = random_field(500, 300, 1);
  for (const auto metric : {strain::Frame_metric::euclidean, strain::Frame_metric::l1, strain::Frame_metric::cosine}) {
    const Eigen::MatrixXd d = frame_distances<double>(field, {.metric = metric});
    REQUIRE(d.rows() == 300);
    CHECK(d.diagonal().isZero(0.0));
    CHECK(d == d.transpose());
    CHECK(d.minCoeff() >= 0);
    double worst = 0;
    for (std::size_t a = 0; a < 300; a += 7)
      for (std::size_t b = 0; b < 300; b += 3)
        if (a != b)
          worst = std::max(worst, std::abs(d(Eigen::Index(a), Eigen::Index(b)) - direct(field, a, b, metric)));
    INFO("metric " << int(metric) << ", worst difference " << worst);
    CHECK(worst < 1e-4);
  }
}

TEST_CASE("frame_distances: near-identical frames keep their small distance, no cancellation", "[temporal]") {
  const auto field = random_field(2000, 10, 2);
  const Eigen::MatrixXf d = frame_distances(field);
  // Frames 3 and 4 differ by 1e-3 in one triangle: the Gram formula in float would give noise
  // of about 1e-2 (|x|^2 ~ 700, float epsilon 6e-8).
  CHECK(d(3, 4) == Approx(1e-3).epsilon(1e-3));
  CHECK(d(5, 5) == 0);
  const Eigen::MatrixXf cosine = frame_distances(field, {.metric = strain::Frame_metric::cosine});
  CHECK(cosine(5, 0) == 1);  // a frame without strain against one with
}

TEST_CASE("frame_distances: one thread and all threads give bit-identical matrices", "[temporal]") {
  const auto field = random_field(3000, 400, 3);
  for (const auto metric : {strain::Frame_metric::euclidean, strain::Frame_metric::l1, strain::Frame_metric::cosine}) {
    const Eigen::MatrixXf one = frame_distances(field, {.metric = metric, .threads = 1});
    const Eigen::MatrixXf all = frame_distances(field, {.metric = metric, .threads = 0});
    const Eigen::MatrixXf three = frame_distances(field, {.metric = metric, .threads = 3});
    CHECK(one == all);
    CHECK(one == three);
  }
}

TEST_CASE("frame_distances: an empty field is rejected", "[temporal]") {
  CHECK_THROWS_WITH(frame_distances(strain::Strain_field<float>()), Catch::Contains("empty"));
}

TEST_CASE("Segment_cost: Ds equals the average over all pairs, by brute force", "[temporal]") {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> value(0, 2);
  Eigen::MatrixXd d(13, 13);
  for (Eigen::Index i = 0; i < 13; ++i)
    for (Eigen::Index j = 0; j <= i; ++j) d(i, j) = d(j, i) = i == j ? 0 : value(random);
  const temporal::Segment_cost cost(d);
  CHECK(cost.num_frames() == 13);
  for (std::size_t m = 0; m < 13; ++m)
    for (std::size_t n = m; n < 13; ++n) {
      double sum = 0;
      for (std::size_t i = m; i <= n; ++i)
        for (std::size_t j = m; j <= n; ++j) sum += d(Eigen::Index(i), Eigen::Index(j));
      const double length = double(n - m + 1);
      CHECK(cost(m, n) == Approx(sum / (length * length)).margin(1e-12));
      CHECK(cost.weighted(m, n) == Approx(sum / length).margin(1e-12));
      CHECK(cost.distance(m, n) == Approx(d(Eigen::Index(m), Eigen::Index(n))).margin(1e-12));
    }
  CHECK(cost(5, 5) == 0);
  CHECK(cost.mean_distance() == Approx(d.sum() / (13.0 * 12.0)));
}

TEST_CASE("Segment_cost: bad matrices name the problem", "[temporal]") {
  CHECK_THROWS_WITH(temporal::Segment_cost(Eigen::MatrixXd(2, 3)), Catch::Contains("square"));
  CHECK_THROWS_WITH(temporal::Segment_cost(Eigen::MatrixXd(0, 0)), Catch::Contains("square"));
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(3, 3);
  d(1, 2) = -1;
  CHECK_THROWS_WITH(temporal::Segment_cost(d), Catch::Contains("(1, 2)"));
  d(1, 2) = std::nan("");
  CHECK_THROWS_WITH(temporal::Segment_cost(d), Catch::Contains("(1, 2)"));
}
