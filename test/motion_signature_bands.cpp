// The motion signatures' regions: height bands (Motion_signature_options::bands) and the two sides
// across the body (sides). Each region's quantiles are those of its vertices alone, found here by
// brute force (the regions cut by hand, the radix selection of every row anew); the streamed
// description equals the in-memory one; a band without area takes its nearest band's vertices; a
// motion and its mirror image are alike without sides and apart with them; what is refused.
#include "test_support.h"

#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signature_stream.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <vector>

namespace {

namespace ds = deformseg;
namespace si = ds::signatures::internal;
using Catch::Matchers::Contains;

// A tube along +z bending one way and back with a second joint, so that its bands move unlike.
ds::mesh::Surface_mesh_animation two_joint_tube() {
  ds::mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 8, .rings = 24, .caps = true};
  spec.joints = {{.position = 0.3}, {.position = 0.7, .direction = 1.0}};
  spec.schedule = {{12, {ds::test::right_angle, 0.0}}, {8, {0.0, ds::test::right_angle}}, {10, {0.0, 0.0}}};
  return ds::mesh::make_bending_tube(spec).animation;
}

ds::signatures::Motion_signature_options banded(std::size_t bands) {
  return {.up = Eigen::Vector3d::UnitZ(), .bands = bands};
}

// Each vertex's region as the options say (up +z, sides +x): its band of equal heights in the first
// frame, the top one in the last band, then its side of the weighted centroid's x (1 from it on).
std::vector<std::size_t> regions_by_hand(std::span<const double> first, std::span<const double> weights,
                                         std::size_t bands, bool sides) {
  const std::size_t vertices = first.size() / 3;
  double low = INFINITY, high = -INFINITY, middle = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    low = std::min(low, first[3 * v + 2]), high = std::max(high, first[3 * v + 2]);
    middle += weights[v] * first[3 * v];
  }
  std::vector<std::size_t> region(vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    const std::size_t band = std::min(std::size_t((first[3 * v + 2] - low) / (high - low) * double(bands)), bands - 1);
    region[v] = sides ? 2 * band + (first[3 * v] >= middle ? 1 : 0) : band;
  }
  return region;
}

// The signatures of one region computed anew, row by row: its vertices' rates keyed, their weights
// scaled to sum 1 over the region, the radix selection; the whole body's radius as the unit.
Eigen::MatrixXd region_by_hand(std::span<const double> positions, std::span<const double> weights,
                               const ds::signatures::Motion_signature_options& options, std::size_t region) {
  const std::size_t vertices = weights.size(), frames = positions.size() / (3 * vertices), k = options.quantiles;
  const std::vector<std::size_t> regions =
      regions_by_hand(positions.first(3 * vertices), weights, options.bands, options.sides.has_value());
  std::vector<std::size_t> chosen;
  double total = 0;
  for (std::size_t v = 0; v < vertices; ++v)
    if (regions[v] == region) chosen.push_back(v), total += weights[v];
  const double radius = si::rms_radius(positions, weights, frames);
  const std::size_t lags = options.lags.size();
  Eigen::MatrixXd out(Eigen::Index(frames), Eigen::Index(2 * lags * k));
  std::vector<si::Keyed_rate> speeds(chosen.size()), rises(chosen.size()), spare(chosen.size());
  std::vector<double> values(k);
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t l = 0; l < lags; ++l) {
      const auto lag_frames = std::size_t(std::llround(options.lags[l] * 30));
      const double* before = positions.data() + 3 * vertices * (t >= lag_frames ? t - lag_frames : 0);
      const double* after = positions.data() + 3 * vertices * std::min(t + lag_frames, frames - 1);
      const double unit = 1.0 / (2.0 * options.lags[l] * radius);
      for (std::size_t i = 0; i < chosen.size(); ++i) {
        const std::size_t v = chosen[i];
        const Eigen::Vector3d d = si::point(after, v) - si::point(before, v);
        speeds[i] = {si::order_key(d.norm() * unit), weights[v] / total};
        rises[i] = {si::order_key(d.z() * unit), weights[v] / total};
      }
      si::weighted_quantiles(speeds, spare, k, values.data());
      for (std::size_t q = 0; q < k; ++q)
        out(Eigen::Index(t), Eigen::Index(l * k + q)) = std::log(std::max(values[q], options.floor));
      si::weighted_quantiles(rises, spare, k, values.data());
      for (std::size_t q = 0; q < k; ++q)
        out(Eigen::Index(t), Eigen::Index((lags + l) * k + q)) =
            std::sqrt(options.vertical_weight) * std::asinh(values[q] / options.vertical_unit);
    }
  return out;
}

// Region r's columns of signatures of `regions` regions: per lag, then per kind, its k quantiles.
Eigen::MatrixXd band_columns(const Eigen::MatrixXd& signatures, std::size_t regions, std::size_t r, std::size_t k) {
  const auto blocks = std::size_t(signatures.cols()) / (regions * k);  // 2 x lags
  Eigen::MatrixXd out(signatures.rows(), Eigen::Index(blocks * k));
  for (std::size_t block = 0; block < blocks; ++block)
    out.middleCols(Eigen::Index(block * k), Eigen::Index(k)) =
        signatures.middleCols(Eigen::Index((block * regions + r) * k), Eigen::Index(k));
  return out;
}

// `animation`'s positions mirrored across x = 0 (its left and right swapped).
std::vector<double> mirrored(const ds::mesh::Surface_mesh_animation& animation) {
  std::vector<double> out(animation.all_positions().begin(), animation.all_positions().end());
  for (std::size_t i = 0; i < out.size(); i += 3) out[i] = -out[i];
  return out;
}

}  // namespace

TEST_CASE("motion_signatures: each height band's quantiles are those of its vertices alone", "[signatures]") {
  const auto tube = two_joint_tube();
  for (const std::size_t bands : {2, 3, 5}) {
    INFO(bands << " bands");
    const auto options = banded(bands);
    ds::signatures::with_positions_and_weights(tube, [&](auto positions, std::span<const double> weights) {
      const Eigen::MatrixXd signatures = ds::signatures::motion_signatures(positions, weights, options);
      REQUIRE(signatures.cols() == Eigen::Index(2 * options.lags.size() * bands * options.quantiles));
      for (std::size_t b = 0; b < bands; ++b) {
        const Eigen::MatrixXd expected = region_by_hand(positions, weights, options, b);
        const Eigen::MatrixXd got = band_columns(signatures, bands, b, options.quantiles);
        CHECK(std::memcmp(got.data(), expected.data(), sizeof(double) * std::size_t(got.size())) == 0);
      }
      // The bands see what the whole surface blurs: the lowest (below the first joint) moves least.
      const Eigen::MatrixXd lowest = band_columns(signatures, bands, 0, options.quantiles);
      const Eigen::MatrixXd highest = band_columns(signatures, bands, bands - 1, options.quantiles);
      CHECK(lowest.leftCols(8).mean() < highest.leftCols(8).mean() - 1);
    });
  }
}

TEST_CASE("motion_signatures: each side of each band is its vertices alone", "[signatures]") {
  const auto tube = two_joint_tube();
  for (const std::size_t bands : {1, 3}) {
    INFO(bands << " bands");
    auto options = banded(bands);
    options.sides = Eigen::Vector3d(2, 0, 0);  // +x, of any length
    ds::signatures::with_positions_and_weights(tube, [&](auto positions, std::span<const double> weights) {
      const Eigen::MatrixXd signatures = ds::signatures::motion_signatures(positions, weights, options);
      REQUIRE(signatures.cols() == Eigen::Index(2 * options.lags.size() * 2 * bands * options.quantiles));
      for (std::size_t r = 0; r < 2 * bands; ++r) {
        const Eigen::MatrixXd expected = region_by_hand(positions, weights, options, r);
        const Eigen::MatrixXd got = band_columns(signatures, 2 * bands, r, options.quantiles);
        CHECK(std::memcmp(got.data(), expected.data(), sizeof(double) * std::size_t(got.size())) == 0);
      }
    });
  }
}

TEST_CASE("Motion_signature_similarity: a motion and its mirror image alike, apart with sides", "[signatures]") {
  // The tube bends towards +x; its mirror image towards -x. The distributions over the whole surface
  // are the same; those of each side are swapped.
  const auto tube = two_joint_tube();
  const std::vector<double> mirror = mirrored(tube);
  ds::similarity::Motion_signature_similarity<> policy;
  policy.signatures.up = Eigen::Vector3d::UnitZ();
  const auto value = [&] {
    return ds::signatures::with_positions_and_weights(tube, [&](auto positions, std::span<const double> weights) {
      return policy.compare(policy.describe_positions(positions, weights),
                            policy.describe_positions(std::span<const double>(mirror), weights))
          .value;
    });
  };
  CHECK(value() == 1.0);
  policy.signatures.bands = 3;
  CHECK(value() == 1.0);
  policy.signatures.sides = Eigen::Vector3d::UnitX();
  CHECK(value() < 0.9);
}

TEST_CASE("motion_signatures_streamed: height bands streamed give the in-memory bits", "[signatures]") {
  const auto tube = two_joint_tube();
  auto options = banded(3);
  options.sides = Eigen::Vector3d::UnitX();
  ds::signatures::Positions_frame_source<double> source(tube.all_positions(), tube.num_vertices(), tube.triangles(),
                                                         30);
  const std::vector<double> instants = ds::signatures::frame_instants(tube.num_frames(), 30);
  const Eigen::MatrixXd streamed =
      ds::signatures::motion_signatures_streamed(source, options, std::span<const double>(instants));
  const Eigen::MatrixXd whole = ds::signatures::motion_signatures(tube, options);
  REQUIRE(streamed.rows() == whole.rows());
  REQUIRE(streamed.cols() == whole.cols());
  CHECK(std::memcmp(streamed.data(), whole.data(), sizeof(double) * std::size_t(whole.size())) == 0);
}

TEST_CASE("motion_signatures: a height band without area takes its nearest band's vertices", "[signatures]") {
  // Two triangles, one at height 0 moving sideways, one at height 1 rising: of 3 bands, the middle
  // one holds no vertex and takes the lower band's (the nearest, the lower first at equal distance).
  std::vector<double> positions;
  const std::size_t frames = 6;
  for (std::size_t t = 0; t < frames; ++t) {
    const double s = 0.05 * double(t * t);
    for (const double z : {0.0, 1.0})
      for (const auto& [x, y] : {std::pair{0.0, 0.0}, std::pair{1.0, 0.0}, std::pair{0.0, 1.0}})
        positions.insert(positions.end(), {x + (z == 0 ? s : 0.0), y, z + (z == 1 ? s : 0.0)});
  }
  const std::vector<double> weights(6, 1.0 / 6);
  const auto options = banded(3);
  const Eigen::MatrixXd signatures =
      ds::signatures::motion_signatures(std::span<const double>(positions), std::span<const double>(weights), options);
  const std::size_t k = options.quantiles;
  CHECK(band_columns(signatures, 3, 1, k) == band_columns(signatures, 3, 0, k));
  CHECK(band_columns(signatures, 3, 2, k) != band_columns(signatures, 3, 0, k));
  // The lower triangle moves sideways, the upper one rises: only the upper band's vertical rates are positive.
  const Eigen::Index verticals = Eigen::Index(options.lags.size() * 3 * k);
  CHECK(signatures.block(1, verticals + Eigen::Index(2 * k), 4, Eigen::Index(k)).minCoeff() > 0);
  CHECK(signatures.block(1, verticals, 4, Eigen::Index(k)).cwiseAbs().maxCoeff() == 0);
}

TEST_CASE("motion_signatures: height bands keep the invariances of the whole surface", "[signatures]") {
  const auto tube = two_joint_tube();
  const auto options = banded(4);
  const Eigen::MatrixXd here = ds::signatures::motion_signatures(tube, options);
  std::vector<double> moved(tube.all_positions().begin(), tube.all_positions().end());
  const Eigen::AngleAxisd turn(0.7, Eigen::Vector3d::UnitZ());  // about up
  for (std::size_t v = 0; v < moved.size() / 3; ++v) {
    Eigen::Map<Eigen::Vector3d> p(moved.data() + 3 * v);
    p = 2.5 * (turn * p) + Eigen::Vector3d(3, -1, 7);
  }
  const std::vector<double> weights = ds::signatures::with_positions_and_weights(
      tube, [](auto, std::span<const double> w) { return std::vector<double>(w.begin(), w.end()); });
  const Eigen::MatrixXd there =
      ds::signatures::motion_signatures(std::span<const double>(moved), std::span<const double>(weights), options);
  CHECK((here - there).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("motion_signatures: the bands refused", "[signatures]") {
  const auto tube = two_joint_tube();
  const auto refused = [&](ds::signatures::Motion_signature_options options, const char* words) {
    CHECK_THROWS_WITH(ds::signatures::motion_signatures(tube, options), Contains(words));
  };
  refused(banded(0), "0 bands; 1 to 64");
  refused(banded(ds::signatures::max_bands + 1), "65 bands; 1 to 64");
  refused({.up = std::nullopt, .bands = 2}, "2 height bands need an up direction");
  refused({.sides = Eigen::Vector3d::Zero()}, "the direction across the body (sides) must be finite and not zero");
  CHECK_NOTHROW(ds::signatures::motion_signatures(tube, {.up = std::nullopt, .bands = 1}));
}
