// Tests of strain_histograms and histogram_edges: exact histograms of hand-made fields, edges and
// their sides, brute force on random fields, invariance to placement, independence of the mesh,
// and the shared real animations ([data]).
#include "test_support.h"
#include "mesh_types.h"

#include <deformseg/strain/histogram_distance.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/strain/strain_histograms.h>
#include <deformseg/mesh/synthetic.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

template <class Value>
strain::Strain_field<Value> field_of(std::size_t faces, const std::vector<Value>& values) {
  return strain::Strain_field<Value>(faces, values.size() / faces,
                             typename strain::Strain_field<Value>::Storage(values.begin(), values.end()), {}, {}, 0);
}

// The column of s by the definition: the number of edges at or below it.
std::size_t column_by_search(const std::vector<double>& edges, double s) {
  return std::size_t(std::upper_bound(edges.begin(), edges.end(), s) - edges.begin());
}

// A tube bending at two joints, one after the other, and back.
mesh::Bending_tube two_joint_tube(const mesh::Tube_shape& shape) {
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube spec;
  spec.shape = shape;
  spec.joints = {{.position = 0.3}, {.position = 0.7}};
  spec.schedule = {{4, {}}, {8, {right, 0.0}}, {8, {right, right}}, {8, {0.0, 0.0}}, {4, {}}};
  return spec;
}

}  // namespace

TEST_CASE("strain_histograms: the edges are log-spaced from min to max", "[strain_histograms]") {
  const auto edges = strain::histogram_edges({.bins = 3, .min_strain = 1e-3, .max_strain = 1});
  REQUIRE(edges.size() == 4);
  CHECK(edges[0] == 1e-3);
  CHECK(edges[1] == Approx(1e-2).epsilon(1e-14));
  CHECK(edges[2] == Approx(1e-1).epsilon(1e-14));
  CHECK(edges[3] == 1.0);
  const auto defaults = strain::histogram_edges({});
  CHECK(defaults.size() == 17);
  CHECK(defaults.front() == 0.05);
  CHECK(defaults.back() == 1.0);
  CHECK(std::is_sorted(defaults.begin(), defaults.end()));
}

TEST_CASE("strain_histograms: a hand-made field, values on edges in the bin above", "[strain_histograms]") {
  const strain::Histogram_options options{.bins = 2, .min_strain = 0.01, .max_strain = 1};
  const auto e = strain::histogram_edges(options);  // 0.01, 0.1, 1: columns < 0.01 | [0.01, 0.1) | [0.1, 1) | >= 1
  const std::vector<double> weights{1, 2, 3, 4};
  const double inf = std::numeric_limits<double>::infinity();
  const auto field = field_of<double>(4, {0.0, e[0], e[1], e[2],                       // frame 0: on the edges
                                          std::nextafter(e[0], 0.0), std::nextafter(e[1], 0.0),
                                          std::nextafter(e[2], 0.0), inf,               // frame 1: just below
                                          0.05, -0.5, 0.5, 7.0});                       // frame 2: |s|
  const strain::Strain_histograms h = strain::strain_histograms(field, weights, options);
  REQUIRE(h.rows() == 3);
  REQUIRE(h.cols() == 4);
  const Eigen::RowVector4d frame0(0.1, 0.2, 0.3, 0.4), frame1(0.1, 0.2, 0.3, 0.4), frame2(0, 0.1, 0.5, 0.4);
  CHECK(h.row(0).isApprox(frame0, 1e-15));
  CHECK(h.row(1).isApprox(frame1, 1e-15));
  CHECK(h.row(2).isApprox(frame2, 1e-15));
  // Just below an edge is in the bin below it: frame 1 puts triangle 1 (weight 2) in column 0.
  const auto shifted = field_of<double>(4, {std::nextafter(e[0], 0.0), std::nextafter(e[0], 0.0), 0.0, 0.0});
  CHECK(strain::strain_histograms(shifted, weights, options)(0, 0) == 1.0);
}

TEST_CASE("strain_histograms: zero weights count for nothing, degenerate strain is rigid", "[strain_histograms]") {
  const strain::Histogram_options options{.bins = 1, .min_strain = 0.1, .max_strain = 1};
  // Triangle 1 has no area (a degenerate one: its strain is 0 by compute_strain's convention).
  const auto h =
      strain::strain_histograms(field_of<float>(3, {0.5f, 0.0f, 2.0f}), std::vector<double>{1, 0, 3}, options);
  CHECK(h(0, 0) == 0.0);
  CHECK(h(0, 1) == 0.25);
  CHECK(h(0, 2) == 0.75);
  CHECK(std::isfinite(h.sum()));
}

TEST_CASE("strain_histograms: bad input is rejected, naming the problem", "[strain_histograms]") {
  const auto field = field_of<float>(2, {0.1f, 0.2f, 0.3f, std::numeric_limits<float>::quiet_NaN()});
  const std::vector<double> weights{1, 1};
  CHECK_THROWS_WITH(strain::strain_histograms(field, weights),
                    Catch::Contains("frame 1") && Catch::Contains("triangle 1"));
  const auto good = field_of<float>(2, {0.1f, 0.2f});
  CHECK_THROWS_WITH(strain::strain_histograms(good, std::vector<double>{1}), Catch::Contains("1 weights for 2"));
  CHECK_THROWS_WITH(strain::strain_histograms(good, std::vector<double>{1, -1}), Catch::Contains("triangle 1"));
  CHECK_THROWS_WITH(strain::strain_histograms(good, std::vector<double>{0, 0}), Catch::Contains("sum > 0"));
  CHECK_THROWS_AS(strain::strain_histograms(good, weights, {.bins = 0}), invalid_input);
  CHECK_THROWS_AS(strain::strain_histograms(good, weights, {.min_strain = 1, .max_strain = 1}), invalid_input);
  CHECK_THROWS_AS(strain::strain_histograms(good, weights, {.min_strain = 0}), invalid_input);
  CHECK_THROWS_AS(strain::strain_histograms(good, weights, {.max_strain = std::numeric_limits<double>::infinity()}),
                  invalid_input);
  CHECK_THROWS_AS(strain::strain_histograms(good, weights, {.threads = -1}), invalid_input);
}

TEST_CASE("strain_histograms: random fields agree with binning by search, rows sum to 1", "[strain_histograms]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-5, 1.5), weight(0, 2);
  const strain::Histogram_options options{.bins = 13, .min_strain = 2e-4, .max_strain = 5};
  const auto edges = strain::histogram_edges(options);
  const std::size_t faces = 300, frames = 20;
  std::vector<double> values(faces * frames), weights(faces);
  for (auto& v : values) v = std::pow(10.0, exponent(rng));
  for (std::size_t i = 0; i < values.size(); i += 7) values[i] = edges[i % edges.size()];  // on the edges
  for (auto& w : weights) w = weight(rng);
  const auto field = field_of<double>(faces, values);
  const strain::Strain_histograms h = strain::strain_histograms(field, weights, options);
  double total = 0;
  for (double w : weights) total += w;
  strain::Strain_histograms expected =
      strain::Strain_histograms::Zero(Eigen::Index(frames), Eigen::Index(options.bins + 2));
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t j = 0; j < faces; ++j)
      expected(Eigen::Index(t), Eigen::Index(column_by_search(edges, values[t * faces + j]))) += weights[j] / total;
  CHECK(h.isApprox(expected, 1e-12));
  for (Eigen::Index t = 0; t < h.rows(); ++t) CHECK(h.row(t).sum() == Approx(1.0).epsilon(1e-14));
  CHECK((h.array() >= 0).all());
  // The same for any number of threads, bit for bit.
  CHECK(strain::strain_histograms(field, weights, {.bins = 13, .min_strain = 2e-4, .max_strain = 5, .threads = 1}) ==
        h);
  CHECK(strain::strain_histograms(field, weights, {.bins = 13, .min_strain = 2e-4, .max_strain = 5, .threads = 2}) ==
        h);
}

TEST_CASE("strain_histograms: a rigidly moved, uniformly scaled copy has the same histograms", "[strain_histograms]") {
  mesh::Bending_tube spec = two_joint_tube({});
  const strain::Strain_histograms original = strain::strain_histograms(mesh::make_bending_tube(spec).animation);
  spec.placement = {.scale = 3.5,
                    .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, -2, 0.5).normalized())),
                    .translation = Eigen::Vector3d(40, -25, 60)};
  const strain::Strain_histograms moved = strain::strain_histograms(mesh::make_bending_tube(spec).animation);
  REQUIRE(moved.rows() == original.rows());
  CHECK((moved - original).cwiseAbs().maxCoeff() < 1e-6);
  // The histograms do say something: some frames deform, frame 0 (no previous pose) does not.
  CHECK(original(0, 0) == Approx(1.0));
  CHECK(original.col(0).minCoeff() < 0.9);
  // Against the rest pose, too.
  const strain::Strain_histogram_options rest{
      .strain = {.reference = strain::Strain_reference::rest_pose, .normalization = strain::No_normalization{}}};
  const auto a = strain::strain_histograms(mesh::make_bending_tube(two_joint_tube({})).animation, rest);
  const auto b = strain::strain_histograms(mesh::make_bending_tube(spec).animation, rest);
  CHECK((a - b).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("strain_histograms: another mesh of the same tube gives alike histograms", "[strain_histograms]") {
  const auto coarse =
      strain::strain_histograms(mesh::make_bending_tube(two_joint_tube({.sectors = 16, .rings = 48})).animation);
  const auto fine =
      strain::strain_histograms(mesh::make_bending_tube(two_joint_tube({.sectors = 24, .rings = 80})).animation);
  // The same frames compared with other frames of the same motion: the mesh matters less.
  const Eigen::MatrixXd d = strain::histogram_distances(coarse, fine);
  REQUIRE(d.rows() == d.cols());
  double same_frame = 0, other_frames = 0;
  for (Eigen::Index t = 0; t < d.rows(); ++t) {
    same_frame = std::max(same_frame, d(t, t));
    other_frames += (d.row(t).sum() - d(t, t)) / double(d.cols() - 1);
  }
  other_frames /= double(d.rows());
  INFO("largest same-frame distance " << same_frame << ", mean distance to other frames " << other_frames);
  CHECK(same_frame < 0.25 * other_frames);
}

TEST_CASE("strain_histograms: which of two alike joints bends first is invisible (a known limitation)",
          "[strain_histograms]") {
  // Histograms forget where the strain lies: two joints of equal blend zones, bent in either order
  // on a symmetric tube, give the same histograms frame by frame.
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube first = two_joint_tube({});
  first.schedule = {{4, {}}, {8, {right, 0.0}}, {8, {0.0, right}}, {8, {0.0, 0.0}}};
  mesh::Bending_tube second = first;
  second.schedule = {{4, {}}, {8, {0.0, right}}, {8, {right, 0.0}}, {8, {0.0, 0.0}}};
  const auto a = strain::strain_histograms(mesh::make_bending_tube(first).animation);
  const auto b = strain::strain_histograms(mesh::make_bending_tube(second).animation);
  CHECK(strain::histogram_distances(a, b).diagonal().maxCoeff() < 1e-3);
  CHECK(strain::histogram_distances(a, a).maxCoeff() > 0.01);  // while the frames themselves differ
}

TEST_CASE("strain_histograms: the options choose the strain", "[strain_histograms]") {
  const auto animation = mesh::make_bending_tube(two_joint_tube({})).animation;
  const auto field =
      strain::compute_strain(animation, strain::Strain_options{.reference = strain::Strain_reference::previous_pose,
                                                               .normalization = strain::No_normalization{}});
  std::vector<double> areas(animation.num_faces());
  const auto rest = animation.frame_matrix(0);
  for (std::size_t j = 0; j < areas.size(); ++j) {
    const auto& t = animation.triangles()[j];
    areas[j] = 0.5 * (rest.col(t[1]) - rest.col(t[0])).cross(rest.col(t[2]) - rest.col(t[0])).norm();
  }
  CHECK(strain::strain_histograms(animation) == strain::strain_histograms(field, areas));
  const auto normalised = strain::strain_histograms(
      animation, strain::Strain_histogram_options{
                     .strain = strain::Strain_options{.normalization = strain::Gaussian_normalization{}},
                     .histogram = {.bins = 8, .min_strain = 1e-3}});
  CHECK(normalised.cols() == 10);
  CHECK(normalised(0, 0) == 1.0);  // the rest frame
  CHECK_THROWS_WITH(strain::strain_histograms(animation, {.strain = {.rest_frame = 99}}),
                    Catch::Contains("rest frame 99"));
}

TEMPLATE_LIST_TEST_CASE("strain_histograms: every mesh type gives the default model's histograms, to the last bit",
                        "[strain_histograms][mesh_types]", test::Mesh_types) {
  const auto tube = mesh::make_bending_tube(two_joint_tube({.sectors = 8, .rings = 20})).animation;
  const TestType on(tube);
  for (std::size_t rest_frame : {0, 5}) {
    const strain::Strain_histogram_options options{.strain = {.rest_frame = rest_frame}};
    CHECK(strain::strain_histograms(on.model(), options) == strain::strain_histograms(tube, options));
  }
}

TEST_CASE("strain_histograms data: the horse gallop's second cycle repeats the first", "[strain_histograms][data]") {
  const auto horse = io::read_animation((test::unpacked("horse-gallop/horse-gallop.tar.xz") / "horse-gallop").string());
  REQUIRE(horse.num_frames() == 48);
  const strain::Strain_histograms h = strain::strain_histograms(horse);
  const Eigen::MatrixXd d = strain::histogram_distances(h, h);
  // Frames 25-48 repeat 1-24 (0-based: t + 24 repeats t), so the motion from t - 1 to t does too.
  double repeat = 0, neighbour = 0;
  for (Eigen::Index t = 1; t < 24; ++t) {
    repeat = std::max(repeat, d(t, t + 24));
    neighbour += d(t, t + 1 == 24 ? 1 : t + 1) / 23;
  }
  INFO("largest distance to the repeat " << repeat << ", mean distance to the next frame " << neighbour);
  CHECK(repeat < 0.1 * neighbour);
  CHECK(h(0, 0) == 1.0);                       // frame 0 has no previous pose
  CHECK(h.col(0).tail(47).maxCoeff() < 1.0);  // the gallop deforms the horse at every other frame
}

TEST_CASE("strain_histograms data: the cat and lion poses match pose by pose", "[strain_histograms][data]") {
  const auto cat = io::read_animation((test::unpacked("cat-lion-poses/cat-poses.tgz") / "cat-poses").string());
  const auto lion = io::read_animation((test::unpacked("cat-lion-poses/lion-poses.tgz") / "lion-poses").string());
  REQUIRE(cat.num_frames() == 10);
  REQUIRE(lion.num_frames() == 10);
  // Against the rest pose (the reference, frame 9), so that each frame is one pose, not a move.
  const strain::Strain_histogram_options poses{.strain = {.reference = strain::Strain_reference::rest_pose,
                                                          .rest_frame = 9,
                                                          .normalization = strain::No_normalization{}}};
  const Eigen::MatrixXd d =
      strain::histogram_distances(strain::strain_histograms(cat, poses), strain::strain_histograms(lion, poses));
  std::size_t nearest_is_same = 0;
  double same = 0, other = 0;
  for (Eigen::Index t = 0; t < 9; ++t) {
    Eigen::Index nearest = 0;
    d.row(t).head(9).minCoeff(&nearest);
    nearest_is_same += nearest == t ? 1 : 0;
    same += d(t, t) / 9;
    other += (d.row(t).head(9).sum() - d(t, t)) / 72;
  }
  INFO("same pose " << same << ", other poses " << other << "; nearest is the same pose for " << nearest_is_same
                    << " of 9");
  CHECK(same < 0.5 * other);
  CHECK(nearest_is_same >= 6);  // 6 of 9 when measured
}
