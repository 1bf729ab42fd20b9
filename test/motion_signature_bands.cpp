// The motion signatures' height bands (Motion_signature_options::bands): each band's quantiles are
// those of its vertices alone, found here by brute force (the bands cut by hand, the radix selection
// of every row anew); the streamed description equals the in-memory one; a band without area takes
// its nearest band's vertices; what is refused.
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

// Each vertex's band as the option says: equal heights along up in the first frame, the top one in
// the last band.
std::vector<std::size_t> bands_by_hand(std::span<const double> first, std::size_t count) {
  const std::size_t vertices = first.size() / 3;
  double low = INFINITY, high = -INFINITY;
  for (std::size_t v = 0; v < vertices; ++v) low = std::min(low, first[3 * v + 2]), high = std::max(high, first[3 * v + 2]);
  std::vector<std::size_t> band(vertices);
  for (std::size_t v = 0; v < vertices; ++v)
    band[v] = std::min(std::size_t((first[3 * v + 2] - low) / (high - low) * double(count)), count - 1);
  return band;
}

// The signatures of one band computed anew, row by row: its vertices' rates keyed, their weights
// scaled to sum 1 over the band, the radix selection; the whole body's radius as the unit.
Eigen::MatrixXd band_by_hand(std::span<const double> positions, std::span<const double> weights,
                             const ds::signatures::Motion_signature_options& options, std::size_t band) {
  const std::size_t vertices = weights.size(), frames = positions.size() / (3 * vertices), k = options.quantiles;
  const std::vector<std::size_t> bands = bands_by_hand(positions.first(3 * vertices), options.bands);
  std::vector<std::size_t> chosen;
  double total = 0;
  for (std::size_t v = 0; v < vertices; ++v)
    if (bands[v] == band) chosen.push_back(v), total += weights[v];
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

// Band b's columns of banded signatures: per lag, then per kind, its k quantiles.
Eigen::MatrixXd band_columns(const Eigen::MatrixXd& signatures, std::size_t bands, std::size_t b, std::size_t k) {
  const auto blocks = std::size_t(signatures.cols()) / (bands * k);  // 2 x lags
  Eigen::MatrixXd out(signatures.rows(), Eigen::Index(blocks * k));
  for (std::size_t block = 0; block < blocks; ++block)
    out.middleCols(Eigen::Index(block * k), Eigen::Index(k)) =
        signatures.middleCols(Eigen::Index((block * bands + b) * k), Eigen::Index(k));
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
        const Eigen::MatrixXd expected = band_by_hand(positions, weights, options, b);
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

TEST_CASE("motion_signatures_streamed: height bands streamed give the in-memory bits", "[signatures]") {
  const auto tube = two_joint_tube();
  const auto options = banded(3);
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
  CHECK_NOTHROW(ds::signatures::motion_signatures(tube, {.up = std::nullopt, .bands = 1}));
}
