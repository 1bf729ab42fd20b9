// Tests of temporal_segmentation.h and its policies: a tube that holds three poses, the same
// motion on another tube, the optimum against brute force, thresholds, the horse gallop.
#include "test_support.h"
#include "mesh_types.h"
#include "same_as_default_model.h"

#include <deformseg/io/frame_sequence.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

using deformseg::test::right_angle;

// Two joints; poses (0, 0), (90, 0), (0, 90) degrees, each held 20 frames, with 4-frame
// transitions: 66 frames.
mesh::Synthetic_animation<> three_poses(const mesh::Tube_shape& shape = {}, const mesh::Placement& placement = {}) {
  mesh::Bending_tube spec;
  spec.shape = shape;
  spec.joints = {{.position = 0.3, .blend_width = 0.15}, {.position = 0.7, .blend_width = 0.15}};
  spec.schedule = {{19, {}}, {4, {right_angle, 0.0}}, {19, {}}, {4, {0.0, right_angle}}, {19, {}}};
  spec.placement = placement;
  return mesh::make_bending_tube(spec);
}

// The frames where a segment may start: frame 0 and the frames of the transitions.
bool in_a_transition(std::size_t frame, const mesh::Synthetic_animation<>& tube) {
  return frame == 0 || (frame >= tube.phase_frames[1][0] && frame <= tube.phase_frames[1][1]) ||
         (frame >= tube.phase_frames[3][0] && frame <= tube.phase_frames[3][1]);
}

template <class Policy>
void check_boundaries(const Policy& policy, const mesh::Synthetic_animation<>& tube,
                      const strain::Strain_field<float>& field) {
  const auto result = temporal::temporal_segmentation(field, policy);
  std::vector<std::size_t> starts;
  for (const auto& s : result.segments) starts.push_back(s.first);
  INFO("segment starts: " << Catch::Detail::stringify(starts));
  for (std::size_t b : starts) CHECK(in_a_transition(b, tube));
  // Each transition holds a boundary: the three poses are apart.
  for (int phase : {1, 3}) {
    const auto [first, last] = tube.phase_frames[std::size_t(phase)];
    CHECK(std::any_of(starts.begin(), starts.end(), [&](std::size_t b) { return b >= first && b <= last; }));
  }
}

std::vector<std::size_t> starts_of(const temporal::Temporal_segmentation& s) {
  std::vector<std::size_t> starts;
  for (const auto& segment : s.segments) starts.push_back(segment.first);
  return starts;
}

// The least sum of weighted costs (plus `penalty` per segment) over every partition with
// segments of at least `min_length` frames and, if `count` is not 0, exactly `count` segments.
double brute_force_optimum(const temporal::Segment_cost& cost, double penalty, std::size_t count,
                           std::size_t min_length) {
  const std::size_t frames = cost.num_frames();
  double best = std::numeric_limits<double>::infinity();
  for (std::uint32_t cuts = 0; cuts < (1u << (frames - 1)); ++cuts) {
    double total = 0;
    std::size_t segments = 0, first = 0;
    bool valid = true;
    for (std::size_t t = 0; t < frames; ++t)
      if (t == frames - 1 || (cuts >> t & 1u)) {
        valid = valid && t + 1 - first >= min_length;
        total += cost.weighted(first, t) + penalty;
        ++segments;
        first = t + 1;
      }
    if (valid && (count == 0 || segments == count)) best = std::min(best, total);
  }
  return best;
}

double partition_cost(const temporal::Segment_cost& cost, const std::vector<temporal::Frame_interval>& intervals,
                      double penalty) {
  double total = 0;
  for (const auto& [first, last] : intervals) total += cost.weighted(first, last) + penalty;
  return total;
}

}  // namespace

TEST_CASE("temporal segmentation: three held poses are cut in the transitions, by every policy", "[temporal]") {
  const auto tube = three_poses();
  const auto field = strain::compute_strain(tube.animation);
  check_boundaries(temporal::Optimal_partition{}, tube, field);
  check_boundaries(temporal::Optimal_partition{.segments = 3}, tube, field);
  check_boundaries(temporal::Optimal_partition{.min_length = 5}, tube, field);
  check_boundaries(temporal::Binary_split{}, tube, field);
  check_boundaries(temporal::Thesis_greedy{}, tube, field);
  check_boundaries(temporal::Barbic_pca{}, tube, field);
  // Three poses and two transitions: 3 segments, or up to 5 when a transition is one of its own.
  CHECK(temporal::temporal_segmentation(field, temporal::Optimal_partition{}).segments.size() <= 5);
  CHECK(temporal::temporal_segmentation(field, temporal::Binary_split{}).segments.size() == 3);
}

TEST_CASE("temporal segmentation: the same motion on another tube segments the same way", "[temporal]") {
  const auto tube = three_poses();
  const auto other =
      three_poses({.radius = 0.25, .length = 2.0, .sectors = 11, .rings = 37, .caps = false},
                  {.scale = 3.0,
                   .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized())),
                   .translation = Eigen::Vector3d(10, -4, 2)});
  REQUIRE(other.animation.num_faces() != tube.animation.num_faces());
  CHECK(starts_of(temporal::temporal_segmentation(tube.animation)) ==
        starts_of(temporal::temporal_segmentation(other.animation)));
  CHECK(starts_of(temporal::temporal_segmentation(tube.animation, temporal::Binary_split{})) ==
        starts_of(temporal::temporal_segmentation(other.animation, temporal::Binary_split{})));
  CHECK(starts_of(temporal::temporal_segmentation(tube.animation, temporal::Thesis_greedy{})) ==
        starts_of(temporal::temporal_segmentation(other.animation, temporal::Thesis_greedy{})));
  CHECK(starts_of(temporal::temporal_segmentation(tube.animation, temporal::Barbic_pca{})) ==
        starts_of(temporal::temporal_segmentation(other.animation, temporal::Barbic_pca{})));
}

TEMPLATE_LIST_TEST_CASE("temporal segmentation: every mesh type gives the default model's segments, to the last bit",
                        "[temporal][mesh_types]", test::Mesh_types) {
  const auto tube = three_poses({.sectors = 8, .rings = 24});
  const TestType on(tube.animation);
  test::check_every_method_same(on.model(), tube.animation);
}

TEST_CASE("Optimal_partition equals brute force over all partitions, T <= 12", "[temporal]") {
  std::mt19937 random(5);
  for (int trial = 0; trial < 60; ++trial) {
    const auto frames = Eigen::Index(2 + trial % 11);
    // Distances between random points on a line with a few clusters: structure to find.
    std::vector<double> x;
    for (Eigen::Index i = 0; i < frames; ++i) x.push_back(double(random() % 4) + 0.1 * double(random() % 10));
    Eigen::MatrixXd d(frames, frames);
    for (Eigen::Index i = 0; i < frames; ++i)
      for (Eigen::Index j = 0; j < frames; ++j) d(i, j) = std::abs(x[std::size_t(i)] - x[std::size_t(j)]);
    const temporal::Segment_cost cost(d);
    const std::size_t min_length = 1 + std::size_t(trial % 3);
    if (std::size_t(frames) < min_length) continue;
    const double penalty = 0.2 * double(trial % 5);
    const auto free =
        temporal::Optimal_partition{.penalty = {.value = penalty, .relative = false}, .min_length = min_length}(cost);
    CHECK(partition_cost(cost, free, penalty) == Approx(brute_force_optimum(cost, penalty, 0, min_length)));
    for (std::size_t count = 1; count * min_length <= std::size_t(frames); ++count) {
      const auto fixed = temporal::Optimal_partition{.segments = count, .min_length = min_length}(cost);
      CHECK(fixed.size() == count);
      CHECK(partition_cost(cost, fixed, 0) == Approx(brute_force_optimum(cost, 0, count, min_length)));
    }
  }
}

TEST_CASE("temporal segmentation: a lower threshold never gives fewer segments (binary split, optimum)",
          "[temporal]") {
  const auto field = strain::compute_strain(three_poses().animation);
  const temporal::Segment_cost cost(frame_distances(field));
  std::size_t split_before = 0, optimum_before = 0;
  for (double threshold = 2.0; threshold > 0.001; threshold *= 0.7) {
    const auto split = temporal::segment_frames(cost, temporal::Binary_split{.threshold = {threshold}}).segments.size();
    const auto optimum =
        temporal::segment_frames(cost, temporal::Optimal_partition{.penalty = {threshold * 0.1}}).segments.size();
    CHECK(split >= split_before);
    CHECK(optimum >= optimum_before);
    split_before = split, optimum_before = optimum;
  }
  CHECK(split_before >= 9);  // down to small thresholds, the transitions are cut frame by frame
}

TEST_CASE("temporal segmentation: results cover the frames / segment_of / bad parameters", "[temporal]") {
  const auto field = strain::compute_strain(three_poses().animation);
  const auto result = temporal::temporal_segmentation(field, temporal::Thesis_greedy{.threshold = {0.1}});
  CHECK(result.frames == 66);
  CHECK(result.segments.front().first == 0);
  CHECK(result.segments.back().last == 65);
  for (std::size_t k = 1; k < result.segments.size(); ++k)
    CHECK(result.segments[k].first == result.segments[k - 1].last + 1);
  for (std::size_t t = 0; t < 66; ++t) {
    const auto& s = result.segments[result.segment_of(t)];
    CHECK((s.first <= t && t <= s.last));
  }
  CHECK_THROWS_WITH(result.segment_of(66), Catch::Contains("frame 66"));
  const temporal::Segment_cost cost(frame_distances(field));
  CHECK_THROWS_WITH(temporal::segment_frames(cost, temporal::Optimal_partition{.segments = 67}),
                    Catch::Contains("cannot make 67"));
  CHECK_THROWS_WITH(temporal::segment_frames(cost, temporal::Optimal_partition{.min_length = 0}),
                    Catch::Contains("min_length"));
  CHECK_THROWS_WITH(temporal::segment_frames(cost, temporal::Binary_split{.min_length = 0}),
                    Catch::Contains("min_length"));
  CHECK_THROWS_WITH(temporal::segment_frames(cost, temporal::Barbic_pca{.window = 1}), Catch::Contains("window >= 2"));
  CHECK_THROWS_WITH(temporal::segment_frames(cost, temporal::Barbic_pca{.energy = 1.5}),
                    Catch::Contains("energy in (0, 1]"));
  // A user's policy that leaves a gap is caught.
  const auto gap = [](const temporal::Segment_cost& c) {
    return std::vector<temporal::Frame_interval>{{0, 10}, {12, c.num_frames() - 1}};
  };
  CHECK_THROWS_WITH(temporal::segment_frames(cost, gap), Catch::Contains("frame 11"));
}

TEST_CASE("temporal segmentation: a policy of one's own", "[temporal]") {
  struct Fixed_length {
    std::size_t length = 10;
    std::vector<temporal::Frame_interval> operator()(const temporal::Segment_cost& cost) const {
      std::vector<temporal::Frame_interval> out;
      for (std::size_t m = 0; m < cost.num_frames(); m += length)
        out.push_back({m, std::min(m + length, cost.num_frames()) - 1});
      return out;
    }
  };
  STATIC_REQUIRE(temporal::TemporalSegmentationPolicy<Fixed_length>);
  STATIC_REQUIRE(!temporal::TemporalSegmentationPolicy<int>);
  const auto result = temporal::temporal_segmentation(strain::compute_strain(three_poses().animation), Fixed_length{});
  CHECK(result.segments.size() == 7);
}

TEST_CASE("temporal segmentation: the horse gallop's two cycles segment alike", "[temporal][data]") {
  const auto horse =
      io::read_frame_sequence((test::unpacked("horse-gallop/horse-gallop.tar.xz") / "horse-gallop").string());
  REQUIRE(horse.num_frames() == 48);
  const Eigen::MatrixXf distances = frame_distances(strain::compute_strain(horse));
  const temporal::Segment_cost first_cycle(distances.topLeftCorner(24, 24)),
      second_cycle(distances.bottomRightCorner(24, 24));
  const auto compare = [&](const auto& policy, const char* name, std::size_t fewest_segments) {
    const auto a = starts_of(temporal::segment_frames(first_cycle, policy));
    const auto b = starts_of(temporal::segment_frames(second_cycle, policy));
    INFO(name << ": frames 0-23 start segments at " << Catch::Detail::stringify(a) << ", frames 24-47 at "
              << Catch::Detail::stringify(b) << " (+ 24)");
    CHECK(a.size() >= fewest_segments);
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) CHECK((a[k] > b[k] ? a[k] - b[k] : b[k] - a[k]) <= 1);
  };
  compare(temporal::Optimal_partition{}, "optimal partition", 3);
  compare(temporal::Binary_split{}, "binary split", 3);
  compare(temporal::Thesis_greedy{}, "thesis greedy", 3);
  // To Barbic's detector, which looks for a change of behaviour, a gallop cycle is one behaviour.
  compare(temporal::Barbic_pca{}, "Barbic PCA", 1);

  // The optimum of the whole gallop repeats itself from one cycle to the next.
  const auto whole =
      starts_of(temporal::segment_frames(temporal::Segment_cost(distances), temporal::Optimal_partition{}));
  INFO("whole gallop: " << Catch::Detail::stringify(whole));
  REQUIRE(whole.size() % 2 == 0);
  for (std::size_t k = 0; k < whole.size() / 2; ++k) CHECK(whole[k + whole.size() / 2] == whole[k] + 24);
}
