// Tests of motion_signatures.h and similarity/motion_signature_similarity.h: the weighted quantiles
// against brute force, exact signatures of a uniform motion, invariances (a moved, rotated, scaled
// copy), rigid parts on a joint, thread independence, a time-shifted cyclic motion, a motion inside
// a longer one, tube rankings, errors, [data] figures on the shared characters; and the float
// comparison kernel (motion_signature_kernel.h): one value per cell, its accuracy, the significance's
// shared dissimilarities.
#include "similarity_tubes.h"
#include "test_support.h"
#include "mesh_types.h"

#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signature_kernel.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/strain/strain_histograms.h>
#include <deformseg/threads.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <span>
#include <string>
#include <vector>

using deformseg::signatures::internal::frame_at;
using deformseg::signatures::internal::weighted_quantiles;

// The descriptions whose frames similarity_significance shuffles; the tool and the Python module
// ask this concept for the z-score, so a description that lost it would lose the z-score silently.
static_assert(deformseg::similarity::ReorderableDescription<deformseg::similarity::Motion_signature_description>);
static_assert(deformseg::similarity::ReorderableDescription<deformseg::similarity::Self_similarity_description>);
static_assert(deformseg::similarity::ReorderableDescription<deformseg::strain::Strain_histograms>);
static_assert(!deformseg::similarity::ReorderableDescription<int>);

using namespace deformseg;

using namespace deformseg::test;

TEST_CASE("weighted_quantiles: the smallest value whose cumulative weight reaches each level", "[motion_signature]") {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(0, 1);
  // Small sets (sorted whole) and large ones (split around medians first), values with ties.
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t n = trial < 50 ? 1 + std::size_t(trial % 9) : 100 + 97 * std::size_t(trial - 50);
    const std::size_t k = trial < 50 ? 1 + std::size_t(trial % 5) : 1 + std::size_t(trial % 17);
    std::vector<std::pair<double, double>> items(n);
    double total = 0;
    const double distinct = n < 10 ? 10 : double(n) / 3;
    for (auto& [value, weight] : items)
      total += (weight = uniform(random)), value = std::floor(distinct * uniform(random));
    for (auto& item : items) item.second /= total;
    const auto brute = items;
    std::vector<double> out(k);
    weighted_quantiles(items, k, out.data());
    for (std::size_t q = 0; q < k; ++q) {
      const double level = (double(q) + 0.5) / double(k);
      // Brute force: the smallest value v with (weight of the values <= v) >= level, up to rounding.
      double expected = 0;
      bool found = false;
      std::vector<double> values;
      for (auto& item : brute) values.push_back(item.first);
      std::sort(values.begin(), values.end());
      for (double v : values) {
        double below = 0;
        for (auto& item : brute) below += item.first <= v ? item.second : 0;
        if (!found && below >= level - 1e-12) expected = v, found = true;
      }
      CHECK(out[q] == expected);
    }
  }
}

TEST_CASE("weighted_quantiles: rates of many magnitudes and signs, as a sort and a walk give them", "[motion_signature]") {
  // Speeds spread over orders of magnitude (log-normal), signed rates, exact zeros of both signs
  // and repeated values, in sets large enough for several rounds of the radix selection.
  std::mt19937 random(5);
  std::lognormal_distribution<double> magnitude(-3, 4);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 33 + std::size_t(trial) * 523, k = trial == 39 ? 150 : 1 + std::size_t(trial % 12);
    std::vector<std::pair<double, double>> items(n);
    double total = 0;
    for (auto& [value, weight] : items) {
      const double u = uniform(random);
      value = u < 0.1 ? 0.0 : u < 0.15 ? -0.0 : u < 0.3 ? 1.5 : magnitude(random) * (trial % 2 && u < 0.6 ? -1 : 1);
      total += (weight = trial % 3 ? uniform(random) : 1.0);
    }
    for (auto& item : items) item.second /= total;
    auto sorted = items;
    std::sort(sorted.begin(), sorted.end());
    std::vector<double> out(k);
    weighted_quantiles(items, k, out.data());
    // The walk up the sorted rates to a level: the first rate whose cumulative weight reaches it.
    const auto reaching = [&](double level) {
      double below = 0;
      for (const auto& [value, weight] : sorted)
        if ((below += weight) >= level) return value;
      return sorted.back().first;
    };
    for (std::size_t q = 0; q < k; ++q) {
      // Up to the rounding of sums in another order: equal weights put some levels exactly on a
      // cumulative weight (1/20 of 4,740 rates), where either neighbour is right.
      const double level = (double(q) + 0.5) / double(k);
      CHECK(out[q] >= reaching(level - 1e-12));
      CHECK(out[q] <= reaching(level + 1e-12));
    }
  }
}

TEST_CASE("motion_signatures: a uniform translation has the exact rate everywhere", "[motion_signature]") {
  // Four points at unit distance from their centroid (RMS radius 1), moving 0.02 per frame at 30
  // fps, 0.6 per second: inside the animation every vertex's rate at lags 1, 4 and 16 thirtieths of
  // a second is 0.6; near the ends the spans are cut, and at lag 128/30 s they are cut at both ends
  // in every frame: 39 frames of travel over 256.
  const std::vector<Eigen::Vector3d> points{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  const std::size_t frames = 40;
  std::vector<double> positions;
  for (std::size_t t = 0; t < frames; ++t)
    for (const auto& p : points) {
      const Eigen::Vector3d q = p + 0.02 * double(t) * Eigen::Vector3d(0.6, 0.8, 0);
      positions.insert(positions.end(), {q.x(), q.y(), q.z()});
    }
  const std::vector<double> weights(4, 0.25);
  const Eigen::MatrixXd s = signatures::motion_signatures(std::span<const double>(positions), weights);
  REQUIRE(s.rows() == 40);
  REQUIRE(s.cols() == 64);
  // Speeds first (4 lags x 8 quantiles), then the rates along up, +Y: 0.8 of the speed, rising.
  const auto rising = [](double speed) { return std::sqrt(0.2) * std::asinh(0.8 * speed / 9e-3); };
  const double whole = 0.6 * 39 / 256;
  for (Eigen::Index t : {0, 16, 20, 23, 39})
    for (Eigen::Index c = 0; c < 8; ++c) {
      CHECK(s(t, 24 + c) == Approx(std::log(whole)).epsilon(1e-12));
      CHECK(s(t, 56 + c) == Approx(rising(whole)).epsilon(1e-12));
    }
  for (Eigen::Index t : {16, 20, 23})
    for (Eigen::Index c = 0; c < 24; ++c) {
      CHECK(s(t, c) == Approx(std::log(0.6)).epsilon(1e-12));
      CHECK(s(t, 32 + c) == Approx(rising(0.6)).epsilon(1e-12));
    }
  // Without an up direction, the speeds alone.
  const Eigen::MatrixXd speeds =
      signatures::motion_signatures(std::span<const double>(positions), weights, {.up = std::nullopt});
  REQUIRE(speeds.cols() == 32);
  CHECK(speeds == s.leftCols(32));
  // Frame 0 at lag 16: from frame 0 to frame 16, over 32 frames: half the rate; frame 39 at lag 4:
  // from frame 35 to 39, over 8: half too; lag 1 is whole at frame 1.
  CHECK(s(0, 16) == Approx(std::log(0.3)).epsilon(1e-12));
  CHECK(s(39, 8) == Approx(std::log(0.3)).epsilon(1e-12));
  CHECK(s(1, 0) == Approx(std::log(0.6)).epsilon(1e-12));
  // Lags of whole frames read the frames themselves; spans are cut at the ends.
  CHECK(frame_at(20.0 / 30 - 4.0 / 30, 30, 40) ==
        std::pair<std::size_t, double>(16, 0.0));
  CHECK(frame_at(1.0 / 30 - 4.0 / 30, 30, 40) ==
        std::pair<std::size_t, double>(0, 0.0));
  CHECK(frame_at(38.0 / 30 + 4.0 / 30, 30, 40) ==
        std::pair<std::size_t, double>(39, 0.0));
  CHECK(frame_at(0.25, 10, 40) == std::pair<std::size_t, double>(2, 0.5));
  // Standing still gives the floor.
  std::vector<double> still(positions.begin(), positions.begin() + 12);
  still.insert(still.end(), positions.begin(), positions.begin() + 12);
  const Eigen::MatrixXd standing = signatures::motion_signatures(std::span<const double>(still), weights);
  CHECK(standing.leftCols(32).maxCoeff() == Approx(std::log(3e-3)));
  CHECK(standing.rightCols(32).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("motion_signatures: rigid parts moving on a joint are seen", "[motion_signature]") {
  // No strain anywhere, yet the upper half (9 of 20 points) moves and the lower does not.
  const std::size_t points = 20;
  const std::vector<double> positions = jointed_points(9, points);
  const std::vector<double> weights(points, 1.0 / points);
  const Eigen::MatrixXd s =
      signatures::motion_signatures(std::span<const double>(positions), weights, {.lags = {1.0 / 30}, .quantiles = 4});
  // The lower half (the first quantiles) stands still, the upper half moves.
  CHECK(s(4, 0) == Approx(std::log(3e-3)));
  CHECK(s(4, 3) > std::log(0.3));
}

TEST_CASE("motion_signature_similarity: an animation against itself and a moved, scaled copy turned about up is 1",
          "[motion_signature]") {
  const similarity::Motion_signature_similarity<> policy;
  const auto [a, b] = check_moved_copy_is_one(policy, Eigen::Vector3d::UnitY());
  const Eigen::MatrixXd exact_a = signatures::motion_signatures(a), exact_b = signatures::motion_signatures(b);
  CHECK((exact_a - exact_b).cwiseAbs().maxCoeff() < 1e-9);
  // The descriptions keep those signatures rounded to float: as close, or one float apart where
  // the two doubles fall either side of a rounding boundary.
  const Eigen::MatrixXf kept_a = policy.describe(a).signatures, kept_b = policy.describe(b).signatures;
  CHECK(kept_a == exact_a.cast<float>());
  for (Eigen::Index k = 0; k < kept_a.size(); ++k) {
    const float magnitude = std::abs(kept_a(k));
    CHECK(std::abs(double(kept_a(k)) - double(kept_b(k))) <=
          1e-9 + double(std::nextafter(magnitude, INFINITY) - magnitude));
  }
  // Without an up direction, turned about any axis.
  similarity::Motion_signature_similarity<> directionless;
  directionless.signatures.up = std::nullopt;
  check_moved_copy_is_one(directionless);
}

TEST_CASE("motion_signatures: the up direction turns with the animation", "[motion_signature]") {
  const Eigen::AngleAxisd turn(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  const auto a = tube(bend_hold_unbend);
  const auto b = tube(bend_hold_unbend, {}, {.scale = 2.5, .rotation = Eigen::Quaterniond(turn)});
  const Eigen::MatrixXd turned =
      signatures::motion_signatures(b, {.up = turn * Eigen::Vector3d(0, 3, 0)});  // any length
  CHECK((signatures::motion_signatures(a) - turned).cwiseAbs().maxCoeff() < 1e-9);
  // Another up sees other rises and falls.
  CHECK((signatures::motion_signatures(a) - signatures::motion_signatures(b)).cwiseAbs().maxCoeff() > 0.1);
}

TEST_CASE("motion_signature_similarity: rising and falling at one speed are told apart by the up direction",
          "[motion_signature]") {
  // A bending tube lifted, then lowered, against its mirror image lowered, then lifted: the same
  // speeds, opposite rises.
  const auto moved = mesh::make_deforming_mesh<double>(tube(bend_hold_unbend));
  const std::size_t frames = moved.num_frames(), vertices = moved.num_vertices();
  const auto lifted = [&](double mirror) {
    std::vector<double> positions(moved.all_positions().begin(), moved.all_positions().end());
    for (std::size_t t = 0; t < frames; ++t)
      for (std::size_t v = 0; v < vertices; ++v) {
        double& y = positions[3 * (t * vertices + v) + 1];
        y = mirror * (y + 0.05 * double(std::min(t, frames - 1 - t)));
      }
    return positions;
  };
  const std::vector<double> up_then_down = lifted(1.0), down_then_up = lifted(-1.0);
  const std::vector<double> weights = deformseg::signatures::vertex_area_weights(
      std::span<const double>(up_then_down.data(), 3 * vertices), moved.triangles(), vertices);
  const similarity::Motion_signature_similarity<> policy;
  const auto describe = [&](const std::vector<double>& p) {
    return policy.describe_positions(std::span<const double>(p), std::span<const double>(weights));
  };
  const double told = policy.compare(describe(up_then_down), describe(down_then_up)).value;
  similarity::Motion_signature_similarity<> directionless;
  directionless.signatures.up = std::nullopt;
  const auto speeds = [&](const std::vector<double>& p) {
    return directionless.describe_positions(std::span<const double>(p), std::span<const double>(weights));
  };
  const double blind = directionless.compare(speeds(up_then_down), speeds(down_then_up)).value;
  WARN("lifted then lowered against lowered then lifted: " << told << " with up, " << blind << " without");
  CHECK(blind == Approx(1.0).margin(1e-12));
  CHECK(told < 0.5);
}

TEST_CASE("motion_signature_similarity: a motion and its left-right mirror image are one motion",
          "[motion_signature]") {
  // A tube bending towards one side, turned about the up axis, against the same tube mirrored
  // across a vertical plane (x to -x): a left kick and a right kick. The signatures are
  // distributions over the surface of speeds and vertical rates, which a mirror keeps; the
  // self-similarity's distances between frames are kept too.
  const mesh::Placement turned{.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitY()))};
  const auto a = tube(bend_hold_unbend, {}, turned);
  std::vector<double> mirrored(a.all_positions().begin(), a.all_positions().end());
  for (std::size_t k = 0; k < mirrored.size(); k += 3) mirrored[k] = -mirrored[k];
  const mesh::Surface_mesh_animation b(a.face_graph(), mirrored);
  // Not the same animation: the bend goes the other way.
  CHECK((Eigen::Map<const Eigen::VectorXd>(mirrored.data(), Eigen::Index(mirrored.size())) -
         Eigen::Map<const Eigen::VectorXd>(a.all_positions().data(), Eigen::Index(mirrored.size())))
            .cwiseAbs()
            .maxCoeff() > 0.1);
  CHECK(similarity::motion_similarity(a, b, similarity::Motion_signature_similarity<>{}).value ==
        Approx(1.0).margin(1e-6));
  CHECK(similarity::motion_similarity(a, b, similarity::Self_similarity_matching<>{}).value ==
        Approx(1.0).margin(1e-6));
}

TEST_CASE("motion_signatures: the same whatever the number of threads", "[motion_signature]") {
  const auto a = tube(bend_hold_unbend);
  const Eigen::MatrixXd one = signatures::motion_signatures(a, {.threads = 1});
  const Eigen::MatrixXd seven = signatures::motion_signatures(a, {.threads = 7});
  CHECK(one == seven);
  CHECK(one == signatures::motion_signatures(a));  // 0, the default: all the hardware's threads
  CHECK_THROWS_WITH(signatures::motion_signatures(a, {.threads = 2000}),
                    "motion_signatures: threads must be 0 (the default) to 1024, not 2000");
}

TEST_CASE("motion_signature_similarity: a time-shifted cyclic motion scores near 1", "[motion_signature]") {
  const similarity::Motion_signature_similarity<alignment::Subsequence_dtw> policy;
  const auto a = cycles(16, 48, 0), shifted = cycles(16, 64, 5);
  const double value = similarity::motion_similarity(a, shifted, policy).value;
  const double other = similarity::motion_similarity(a, tube(other_timing), policy).value;
  WARN("cycles against themselves shifted by 5 of 16 frames " << value << ", against another motion " << other);
  // Measured 0.931 and 0.688: not 1, as each animation's first and last 16 frames see its ends
  // (the spans are cut there, as if the tube stood still before and after), and its lag of 128
  // frames spans it whole: from a first frame and to a last frame at other phases of the cycle
  // (0.960 and 0.652 with lags up to 16 only).
  CHECK(value > 0.9);
  CHECK(value > other + 0.2);
}

TEST_CASE("motion_signature_similarity: a motion inside a longer one is found at its frames", "[motion_signature]") {
  const similarity::Motion_signature_similarity<alignment::Subsequence_dtw> policy;
  const auto longer = tube({{6, {right_angle / 2}}, {6, {0.0}}, {10, {right_angle}}, {8, {}}, {10, {0.0}},
                            {6, {right_angle / 2}}, {7, {0.0}}});
  // Its frames 12 to 40 (the bend, the hold and the unbend), cut out.
  std::vector<std::size_t> cut;
  for (std::size_t t = 12; t <= 40; ++t) cut.push_back(t);
  const auto motion = frames_of(longer, cut);
  const similarity::Similarity found = similarity::motion_similarity(motion, longer, policy);
  WARN("a motion inside a longer one: " << found.value);
  // Inside, away from the cut's ends (where the lags see past them), the signatures are those of
  // the longer animation's frames: measured 0.933.
  CHECK(found.value > 0.8);
  REQUIRE(!found.alignment.empty());
  std::size_t on_place = 0;
  for (auto [i, j] : found.alignment) on_place += (j + 2 >= i + 12 && j <= i + 12 + 2);
  CHECK(on_place >= found.alignment.size() * 3 / 4);
}

TEST_CASE("motion_signature_similarity: the same motion on another tube ranks above other motions",
          "[motion_signature]") {
  const similarity::Motion_signature_similarity<> policy;
  const auto a = tube(bend_hold_unbend);
  const double same = similarity::motion_similarity(a, tube(bend_hold_unbend, other_tube), policy).value;
  const double timing = similarity::motion_similarity(a, tube(other_timing, other_tube), policy).value;
  const double small_bend = similarity::motion_similarity(
      a, tube({{5, {0.0}}, {10, {right_angle / 3}}, {8, {}}, {10, {0.0}}, {5, {}}}, other_tube), policy).value;
  WARN("same motion on another tube " << same << ", other timing " << timing << ", a third of the bend "
                                      << small_bend);
  // Measured 0.998, 0.851 and 0.947 (0.1 apart or more before the scale of 1.44 became 1.77,
  // which the shared characters chose: a larger scale draws every value nearer 1).
  CHECK(same > 0.9);
  CHECK(same > timing + 0.1);
  CHECK(same > small_bend + 0.05);
}

TEST_CASE("motion_signature_similarity: bad input is refused with a reason", "[motion_signature]") {
  const auto a = tube(bend_hold_unbend);
  CHECK_THROWS_WITH(signatures::motion_signatures(frames_of(a, {3})), Catch::Contains("at least 2"));
  CHECK_THROWS_WITH(signatures::motion_signatures(a, {.lags = {1, 0}}), Catch::Contains("lag of 0"));
  CHECK_THROWS_WITH(signatures::motion_signatures(a, {.quantiles = 0}), Catch::Contains("0 quantiles"));
  CHECK_THROWS_WITH(signatures::motion_signatures(a, {.floor = 0}), Catch::Contains("floor"));
  CHECK_THROWS_WITH(signatures::motion_signatures(a, {.up = Eigen::Vector3d::Zero()}), Catch::Contains("up direction"));
  CHECK_THROWS_WITH(signatures::motion_signatures(a, {.vertical_unit = 0}), Catch::Contains("vertical unit"));
  CHECK_THROWS_WITH(signatures::motion_signatures(a, {.vertical_weight = -1}), Catch::Contains("vertical weight"));
  CHECK_NOTHROW(signatures::motion_signatures(a, {.up = std::nullopt, .vertical_unit = 0}));  // unused without up
  const std::vector<double> points(24, 1.0), weights(4, 0.25);
  CHECK_THROWS_WITH(signatures::motion_signatures(std::span<const double>(points), weights),
                    Catch::Contains("no extent"));
  similarity::Motion_signature_similarity<> coarse;
  coarse.signatures.quantiles = 4;
  const similarity::Motion_signature_similarity<> policy;
  CHECK_THROWS_AS(policy.compare(policy.describe(a), coarse.describe(a)), invalid_input);
}

TEST_CASE("find_motion: a motion embedded twice in a longer one is found at its frames", "[motion_signature]") {
  // Half bends, the motion (frames 12-50), a long hold, half bends, the motion again (frames
  // 80-118), a hold: the two windows are found, best first, each within 4 frames of where it is
  // (measured: 15-49 and 83-117; the motion starts standing still for 5 frames, and which of the
  // still frames after the half bends match them best depends on how far the lags see).
  std::vector<mesh::Tube_phase> schedule{{6, {right_angle / 2}}, {6, {0.0}}};
  schedule.insert(schedule.end(), bend_hold_unbend.begin(), bend_hold_unbend.end());
  schedule.insert(schedule.end(), {{18, {}}, {6, {right_angle / 2}}, {6, {0.0}}});
  schedule.insert(schedule.end(), bend_hold_unbend.begin(), bend_hold_unbend.end());
  schedule.push_back({10, {}});
  const auto longer = tube(schedule);
  const auto motion = tube(bend_hold_unbend, other_tube);
  REQUIRE(motion.num_frames() == 39);
  const auto found = similarity::find_motion(motion, longer, {.count = 3});
  REQUIRE(found.size() >= 2);
  std::vector<std::size_t> firsts{found[0].first, found[1].first};
  std::sort(firsts.begin(), firsts.end());
  WARN("found at " << found[0].first << "-" << found[0].last << " (" << found[0].value << "), " << found[1].first
                   << "-" << found[1].last << " (" << found[1].value << ")");
  CHECK(firsts[0] + 4 >= 12);
  CHECK(firsts[0] <= 12 + 4);
  CHECK(firsts[1] + 4 >= 80);
  CHECK(firsts[1] <= 80 + 4);
  CHECK(found[0].value >= found[1].value);
  // The windows of a step are described on the threads: the same result on 1 and on 3.
  for (const int threads : {1, 3}) {
    const auto again = similarity::find_motion(motion, longer, {.count = 3, .threads = threads});
    REQUIRE(again.size() == found.size());
    for (std::size_t i = 0; i < found.size(); ++i) {
      CHECK(again[i].first == found[i].first);
      CHECK(again[i].last == found[i].last);
      CHECK(again[i].value == found[i].value);
      CHECK(again[i].alignment == found[i].alignment);
    }
  }
  CHECK(found[1].value > 0.9);
  for (const auto& m : found) {
    CHECK(m.alignment.front().first == 0);
    CHECK(m.alignment.back().first == motion.num_frames() - 1);
    CHECK(m.alignment.front().second == m.first);
    CHECK(m.alignment.back().second == m.last);
  }
  // Windows never overlap.
  for (std::size_t x = 0; x < found.size(); ++x)
    for (std::size_t y = x + 1; y < found.size(); ++y)
      CHECK((found[x].last < found[y].first || found[y].last < found[x].first));
  CHECK_THROWS_AS(similarity::find_motion(motion, longer, {.shortest = 0}), invalid_input);
}

TEMPLATE_LIST_TEST_CASE("find_motion: every mesh type gives the default model's matches, to the last bit",
                        "[motion_signature][mesh_types]", test::Mesh_types) {
  const mesh::Tube_shape small{.sectors = 8, .rings = 24};
  std::vector<mesh::Tube_phase> schedule{{6, {right_angle / 2}}, {6, {0.0}}};
  schedule.insert(schedule.end(), bend_hold_unbend.begin(), bend_hold_unbend.end());
  schedule.push_back({8, {}});
  const auto longer = tube(schedule, small);
  const auto motion = tube(bend_hold_unbend, other_tube);
  const TestType on_longer(longer), on_motion(motion);
  const auto expected = similarity::find_motion(motion, longer, {.count = 2});
  const auto found = similarity::find_motion(on_motion.model(), on_longer.model(), {.count = 2});
  REQUIRE(!expected.empty());
  REQUIRE(found.size() == expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    CHECK(found[i].first == expected[i].first);
    CHECK(found[i].last == expected[i].last);
    CHECK(found[i].value == expected[i].value);
    CHECK(found[i].alignment == expected[i].alignment);
  }
}

TEST_CASE("similarity_significance: ordered frames stand out from shuffled ones", "[motion_signature]") {
  const similarity::Motion_signature_similarity<> policy;
  const auto a = policy.describe(tube(bend_hold_unbend));
  const auto same = policy.describe(tube(bend_hold_unbend, other_tube));
  std::mt19937 random(7);
  const double z_same = similarity::similarity_significance(policy, a, same, 20, random);
  WARN("z-score of the same motion on another tube against shuffled copies: " << z_same);
  CHECK(z_same > 3);
  std::mt19937 again(7);
  CHECK(similarity::similarity_significance(policy, a, same, 20, again) == z_same);
  CHECK_THROWS_AS(similarity::similarity_significance(policy, a, same, 1, again), invalid_input);
  // A description in another order: row t is row order[t].
  const std::vector<std::size_t> order{2, 0, 1};
  const Eigen::MatrixXf three = a.signatures.topRows(3);
  const Eigen::MatrixXf reordered = similarity::reordered_frames(three, std::span<const std::size_t>(order));
  CHECK(reordered.row(0) == three.row(2));
  CHECK(reordered.row(1) == three.row(0));
  CHECK(similarity::frame_count(reordered) == 3);
}

// --- Issue 25: the value does not depend on the sampling rate; find_motion finds copies. ---

namespace {

/// Frames `first` to `last` of `a` (inclusive), as `frames_of`.
mesh::Surface_mesh_animation frame_range(const mesh::Surface_mesh_animation& a, std::size_t first, std::size_t last) {
  std::vector<std::size_t> frames;
  for (std::size_t t = first; t <= last; ++t) frames.push_back(t);
  return frames_of(a, frames);
}

/// The frames of the animations one after the other (all of one mesh), at the first one's rate.
mesh::Surface_mesh_animation joined(const std::vector<const mesh::Surface_mesh_animation*>& parts) {
  std::vector<double> positions;
  for (const auto* part : parts)
    positions.insert(positions.end(), part->all_positions().begin(), part->all_positions().end());
  mesh::Surface_mesh_animation out(parts.front()->face_graph(), std::move(positions));
  out.set_frames_per_second(parts.front()->frames_per_second());
  return out;
}

/// Checks that `query` is found first in `long_animation` at `first` (within one frame), as long
/// as it is (within one frame), with a value of at least 0.95, and that no window is shorter than
/// `shortest` times the query.
void check_found(const mesh::Surface_mesh_animation& query, const mesh::Surface_mesh_animation& long_animation,
                 std::size_t first, double shortest = 0.5) {
  const auto found = similarity::find_motion(query, long_animation, {.count = 3, .shortest = shortest});
  REQUIRE(!found.empty());
  const std::size_t n = query.num_frames(), last = first + n - 1;
  WARN("copy at " << first << "-" << last << " found at " << found[0].first << "-" << found[0].last << " ("
                  << found[0].value << ")" << (found.size() > 1 ? ", then " + std::to_string(found[1].first) + "-" +
                                                                      std::to_string(found[1].last) + " (" +
                                                                      std::to_string(found[1].value) + ")"
                                                                : std::string()));
  CHECK(found[0].first + 1 >= first);
  CHECK(found[0].first <= first + 1);
  CHECK(found[0].last + 1 >= last);
  CHECK(found[0].last <= last + 1);
  CHECK(found[0].value >= 0.95);
  for (const auto& m : found) {
    CHECK(double(m.last - m.first + 1) >= std::ceil(shortest * double(n)));
    CHECK(m.alignment.front() == std::pair<std::size_t, std::size_t>(0, m.first));
    CHECK(m.alignment.back() == std::pair<std::size_t, std::size_t>(n - 1, m.last));
  }
}

}  // namespace

TEST_CASE("motion_signature_similarity: a tube's motion sampled at 15, 30 or 60 fps is the same motion",
          "[motion_signature]") {
  // The bend at 30 fps; every other frame of it at 15 fps; its schedule at twice the frames at
  // 60 fps. Played faster (the 30 fps frames shown at 60 fps) it is a faster motion.
  const auto at_30 = tube(bend_hold_unbend);
  std::vector<std::size_t> even;
  for (std::size_t t = 0; t < at_30.num_frames(); t += 2) even.push_back(t);
  auto at_15 = frames_of(at_30, even);
  at_15.set_frames_per_second(15);
  std::vector<mesh::Tube_phase> doubled = bend_hold_unbend;
  for (auto& phase : doubled) phase.frames *= 2;
  auto at_60 = tube(doubled, other_tube);
  at_60.set_frames_per_second(60);
  auto faster = at_30;
  faster.set_frames_per_second(60);
  const similarity::Motion_signature_similarity<> policy;
  const similarity::Similarity slow = similarity::motion_similarity(at_15, at_30, policy),
                               fine = similarity::motion_similarity(at_60, at_30, policy);
  const double played_faster = similarity::motion_similarity(faster, at_30, policy).value;
  WARN("15 fps against 30: " << slow.value << ", 60 fps (another tube) against 30: " << fine.value
                             << ", played twice as fast: " << played_faster);
  CHECK(slow.value >= 0.95);
  CHECK(fine.value >= 0.95);
  CHECK(played_faster < 0.9);
  // The alignment names each animation's own frames, every one of them.
  CHECK(slow.alignment.front() == std::pair<std::size_t, std::size_t>(0, 0));
  CHECK(slow.alignment.back() == std::pair<std::size_t, std::size_t>(at_15.num_frames() - 1, at_30.num_frames() - 1));
  for (std::size_t k = 1; k < slow.alignment.size(); ++k) {
    CHECK(slow.alignment[k].first - slow.alignment[k - 1].first <= 1);
    CHECK(slow.alignment[k].second - slow.alignment[k - 1].second <= 1);
  }
  // Described every 1/30 s below 30 fps, at the frames from 30 fps up.
  CHECK(policy.describe(at_15).signatures.rows() == Eigen::Index(at_30.num_frames()));
  CHECK(policy.describe(at_60).signatures.rows() == Eigen::Index(at_60.num_frames()));
  // At 30 fps the signatures are those of the frames themselves.
  CHECK(policy.describe(at_30).signatures == signatures::motion_signatures(at_30).cast<float>());
  CHECK_THROWS_WITH(at_15.set_frames_per_second(0), Catch::Contains("frame rate"));
}

TEST_CASE("motion_signature_similarity: a shared clip read at 15, 24, 30 or 60 fps is the same motion, walk and "
          "run stay apart",
          "[motion_signature][data]") {
  const auto dir = test::data_dir() / "characters";
  const auto read = [&](const std::string& file, const std::string& clip, double fps) {
    auto a = io::read_animation((dir / file).string(), {.clip = clip, .fps = fps});
    CHECK(a.frames_per_second() == fps);
    return a;
  };
  const similarity::Motion_signature_similarity<> policy;
  double lowest_self = 1;
  for (const auto& [file, clip] : std::vector<std::pair<std::string, std::string>>{
           {"Knight.glb", "Walking_A"}, {"Knight.glb", "Running_A"}, {"RobotExpressive.glb", "Running"},
           {"Mage.glb", "Jump_Full_Short"}, {"Fox.glb", "Walk"}}) {
    const auto at_30 = policy.describe(read(file, clip, 30));
    for (const double fps : {15.0, 24.0, 30.0, 60.0}) {
      const double value = policy.compare(policy.describe(read(file, clip, fps)), at_30).value;
      WARN(file << "#" << clip << " at " << fps << " fps against 30: " << value);
      CHECK(value >= 0.95);
      if (file == "Knight.glb") lowest_self = std::min(lowest_self, value);
    }
  }
  const double walk_run =
      similarity::motion_similarity(read("Knight.glb", "Walking_A", 30), read("Knight.glb", "Running_A", 15), policy)
          .value;
  WARN("Knight Walking_A against Running_A at 15 fps: " << walk_run);
  CHECK(walk_run < lowest_self - 0.3);
}

TEST_CASE("find_motion: a copy of the query at the start, middle or end of a longer animation is found at its frames",
          "[motion_signature]") {
  // A bend in 38 frames inside other motions of the same tube: half bends, holds, a double bend.
  const auto query = tube(bend_hold_unbend);
  const auto before = tube({{6, {right_angle / 2}}, {6, {0.0}}, {8, {right_angle / 3}}, {10, {0.0}}, {6, {}}});
  const auto after = tube({{4, {right_angle / 3}}, {12, {right_angle}}, {3, {0.0}}, {9, {}}, {7, {right_angle / 2}}});
  const std::size_t n = query.num_frames(), b = before.num_frames();
  check_found(query, joined({&query, &after}), 0);
  check_found(query, joined({&before, &query, &after}), b);
  check_found(query, joined({&before, &query}), b, 1.0);
  // A moved, scaled copy of the query, in the middle.
  const auto moved = tube(bend_hold_unbend, {}, {.scale = 1.7, .translation = Eigen::Vector3d(2, -1, 3)});
  check_found(moved, joined({&before, &query, &after}), b);
  // The query is the whole long animation: exactly 1, every frame.
  const auto whole = similarity::find_motion(query, query);
  REQUIRE(whole.size() == 1);
  CHECK(whole[0].value == 1.0);
  CHECK(whole[0].first == 0);
  CHECK(whole[0].last == n - 1);
  // With shortest 1 every window is as long as the query.
  for (const auto& m : similarity::find_motion(query, joined({&before, &query, &after}), {.count = 3, .shortest = 1.0}))
    CHECK(m.last - m.first + 1 == n);
}

TEST_CASE("find_motion: copies inside the shared animations are found at their frames", "[motion_signature][data]") {
  const auto dir = test::data_dir() / "characters";
  const io::Animation_read_options unwelded{.repair = io::Repair_options{.weld = false}};
  SECTION("the Knight's Walking_A between its Idle and Running_A") {
    auto options = unwelded;
    options.clip = "Walking_A";
    const auto walk = io::read_animation((dir / "Knight.glb").string(), options);
    options.clip = "Idle";
    const auto idle = frame_range(io::read_animation((dir / "Knight.glb").string(), options), 0, 29);
    options.clip = "Running_A";
    const auto run = io::read_animation((dir / "Knight.glb").string(), options);
    REQUIRE(idle.num_vertices() == walk.num_vertices());
    REQUIRE(run.num_vertices() == walk.num_vertices());
    check_found(walk, joined({&walk, &run}), 0);
    check_found(walk, joined({&idle, &walk, &run}), idle.num_frames());
    check_found(walk, joined({&idle, &run, &walk}), idle.num_frames() + run.num_frames());
  }
  SECTION("the robot's Running frames 10-19 in the whole clip") {
    const auto running = io::read_animation((dir / "RobotExpressive.glb").string(), {.clip = "Running"});
    check_found(frame_range(running, 10, 19), running, 10);
  }
  SECTION("the samba's frames 50-59 in the whole dance") {
    const auto samba = io::read_frame_sequence((test::unpacked("samba/samba.tar.xz") / "samba").string());
    check_found(frame_range(samba, 50, 59), samba, 50);
  }
}

// --- Issue 27: the float comparison kernel, one value per cell however it is reached. ---

namespace {

/// `rows x width` signatures of normal values times `spread`, drawn from `random`.
Eigen::MatrixXf random_signatures(std::size_t rows, std::size_t width, float spread, std::mt19937& random) {
  std::normal_distribution<float> normal(0, spread);
  Eigen::MatrixXf s{Eigen::Index(rows), Eigen::Index(width)};
  for (Eigen::Index k = 0; k < s.size(); ++k) s(k) = normal(random);
  return s;
}

signatures::Motion_signature_view kernel_view_of(const Eigen::MatrixXf& s) {
  return {s.data(), std::size_t(s.rows()), std::size_t(s.cols())};
}

/// Whether two doubles have the same bits (== would let 0 equal -0).
bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

/// The squared distance of row i of `a` and row j of `b`, in double (exact but for the last bits).
double exact_squared_distance(const Eigen::MatrixXf& a, std::size_t i, const Eigen::MatrixXf& b, std::size_t j) {
  return (a.row(Eigen::Index(i)).cast<double>() - b.row(Eigen::Index(j)).cast<double>()).squaredNorm();
}

/// Checks the kernel's contract with the search's lower bounds for every cell of (a, b): within
/// 2^-12 f + 2^-22 of the double reference f, in [0, 1]; returns the largest error relative to f.
double check_kernel_accuracy(const Eigen::MatrixXf& a, const Eigen::MatrixXf& b, double unit) {
  const signatures::Motion_signature_dissimilarity d(kernel_view_of(a), kernel_view_of(b), unit);
  std::vector<double> row(d.cols());
  double worst = 0;
  std::size_t failures = 0;
  for (std::size_t i = 0; i < d.rows(); ++i) {
    d.row(i, 0, d.cols(), row.data());
    for (std::size_t j = 0; j < d.cols(); ++j) {
      const double f = signatures::frame_dissimilarity(exact_squared_distance(a, i, b, j), unit);
      const double error = std::abs(row[j] - f);
      const bool ok = row[j] >= 0 && row[j] <= 1 && error <= std::ldexp(f, -12) + std::ldexp(1.0, -22);
      if (!ok && ++failures <= 5)
        FAIL_CHECK("cell (" << i << ", " << j << "): kernel " << row[j] << ", reference " << f);
      if (f > 0) worst = std::max(worst, error / f);
    }
  }
  CHECK(failures == 0);
  return worst;
}

}  // namespace

TEST_CASE("Motion_signature_dissimilarity: a cell has one value, read alone or within any row", "[motion_signature]") {
  std::mt19937 random(27);
  const double unit = signatures::frame_dissimilarity_unit(64, 1.77);
  // Lengths about the kernel's 16 columns: padded, exact, one over, several chunks and a tail.
  for (const std::size_t m : {1, 5, 15, 16, 17, 37, 40})
    for (const std::size_t width : {1, 7, 64}) {
      const std::size_t n = 1 + (m * 7) % 19;
      const Eigen::MatrixXf a = random_signatures(n, width, 1.5f, random), b = random_signatures(m, width, 1.5f, random);
      const signatures::Motion_signature_dissimilarity d(kernel_view_of(a), kernel_view_of(b), unit),
          back(kernel_view_of(b), kernel_view_of(a), unit);
      REQUIRE(d.rows() == n);
      REQUIRE(d.cols() == m);
      std::vector<double> row(m);
      std::size_t mismatches = 0;
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t first = 0; first < m; ++first)
          for (std::size_t count = 1; first + count <= m; count += 1 + count / 3) {
            d.row(i, first, count, row.data());
            for (std::size_t k = 0; k < count; ++k) mismatches += !same_bits(row[k], d(i, first + k));
          }
      CHECK(mismatches == 0);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j) {
          CHECK(same_bits(d(i, j), back(j, i)));  // (a, b) and (b, a) agree
          CHECK((d(i, j) > 0 && d(i, j) < 1));
        }
    }
  // Equal rows give exactly 0, wherever they fall in a chunk.
  const Eigen::MatrixXf a = random_signatures(40, 64, 2.0f, random);
  const signatures::Motion_signature_dissimilarity self(kernel_view_of(a), kernel_view_of(a), unit);
  std::vector<double> row(40);
  for (std::size_t i = 0; i < 40; ++i) {
    self.row(i, 0, 40, row.data());
    CHECK(same_bits(row[i], 0.0));
    CHECK(same_bits(self(i, i), 0.0));
  }
  CHECK_THROWS_WITH(signatures::Motion_signature_dissimilarity(kernel_view_of(a), kernel_view_of(a.leftCols(63)), unit),
                    Catch::Contains("64 and 63"));
  CHECK_THROWS_WITH(signatures::Motion_signature_dissimilarity(kernel_view_of(a), kernel_view_of(a), 0.0),
                    Catch::Contains("unit"));
  CHECK_THROWS_WITH(signatures::Motion_signature_dissimilarity(kernel_view_of(a), kernel_view_of(a), 1e300),
                    Catch::Contains("unit"));
}

TEST_CASE("Motion_signature_dissimilarity: within 2^-12 f + 2^-22 of the double reference f, in [0, 1]",
          "[motion_signature]") {
  std::mt19937 random(12);
  const double unit = signatures::frame_dissimilarity_unit(64, 1.77);
  // Random rows at distances from tiny to far beyond where the value rounds to 1.
  for (const float spread : {1e-6f, 1e-3f, 0.1f, 1.0f, 3.0f, 30.0f, 1e4f}) {
    const Eigen::MatrixXf a = random_signatures(23, 64, spread, random), b = random_signatures(41, 64, spread, random);
    const double worst = check_kernel_accuracy(a, b, unit);
    WARN("rows spread " << spread << ": largest error " << worst << " of the reference");
  }
  // Each reference value f = 1 - exp(-x), x = s unit from 2e-35 to 60,000, from one dimension:
  // s = b^2, exact but for one rounding; relatively within a few float roundings.
  const Eigen::MatrixXf zero = Eigen::MatrixXf::Zero(1, 1);
  std::vector<float> distances;
  for (double e = -40; e < 5.5; e += 0.001) distances.push_back(float(std::exp(e) / std::sqrt(unit)));
  distances.push_back(0.0f);
  const Eigen::MatrixXf line = Eigen::Map<const Eigen::MatrixXf>(distances.data(), Eigen::Index(distances.size()), 1);
  CHECK(check_kernel_accuracy(zero, line, unit) < 4e-7);
  // Rows near one another, the difference in a few dimensions (tiny s, where 1 - exp would fail).
  Eigen::MatrixXf near = random_signatures(30, 64, 1.0f, random), moved = near;
  for (Eigen::Index r = 0; r < near.rows(); ++r) moved(r, r % 64) = std::nextafter(near(r, r % 64), INFINITY);
  check_kernel_accuracy(near, moved, unit);
  // Infinite and NaN distances give 1.
  Eigen::MatrixXf huge(3, 1);
  huge << 1e30f, INFINITY, NAN;
  const signatures::Motion_signature_dissimilarity d(kernel_view_of(zero), kernel_view_of(huge), unit);
  CHECK(d(0, 0) == 1.0);
  CHECK(d(0, 1) == 1.0);
  CHECK(d(0, 2) == 1.0);
}

TEST_CASE("Motion_signature_dissimilarity: real rows within 2^-12 f + 2^-22 of the reference, and compare aligns them",
          "[motion_signature]") {
  const similarity::Motion_signature_similarity<> policy;
  const auto a = policy.describe(tube(bend_hold_unbend));
  const auto b = policy.describe(tube(other_timing, other_tube));
  const double unit = signatures::frame_dissimilarity_unit(std::size_t(a.signatures.cols()), policy.scale);
  WARN("tube rows: largest error " << check_kernel_accuracy(a.signatures, b.signatures, unit) << " of the reference");
  check_kernel_accuracy(a.signatures, a.signatures, unit);
  // The matrix is the lazy dissimilarity's values, and compare aligns exactly them.
  const Eigen::MatrixXd matrix = policy.frame_dissimilarities(a, b);
  const auto lazy = policy.dissimilarity(a, b);
  for (Eigen::Index i = 0; i < matrix.rows(); ++i)
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) CHECK(same_bits(matrix(i, j), lazy(std::size_t(i), std::size_t(j))));
  const similarity::Similarity lazily = policy.compare(a, b);
  const alignment::Alignment aligned =
      alignment::Dtw{}.align(std::size_t(matrix.rows()), std::size_t(matrix.cols()), alignment::matrix_dissimilarity(matrix));
  CHECK(same_bits(lazily.score, aligned.score));
  CHECK(same_bits(lazily.value, 1.0 - aligned.score / double(aligned.pairs.size())));
  CHECK(policy.compare(a, a).value == 1.0);
  CHECK(similarity::view(a).values == a.signatures.data());
  CHECK(similarity::view(a).rows == std::size_t(a.signatures.rows()));
  CHECK(similarity::view(a).width == 64);
}

namespace {

/// Motion_signature_similarity seen through compare alone: similarity_significance then compares
/// every shuffled copy, as it did before the shared dissimilarities.
struct Compare_only {
  similarity::Motion_signature_similarity<> policy;
  using Description = similarity::Motion_signature_description;
  similarity::Similarity compare(const Description& a, const Description& b) const { return policy.compare(a, b); }
};

}  // namespace

TEST_CASE("similarity_significance: the shared dissimilarities give the values of compare on each shuffled copy",
          "[motion_signature]") {
  static_assert(similarity::ReorderingComparison<similarity::Motion_signature_similarity<>,
                                                 similarity::Motion_signature_description>);
  static_assert(!similarity::ReorderingComparison<Compare_only, similarity::Motion_signature_description>);
  const similarity::Motion_signature_similarity<> policy;
  const auto a = policy.describe(tube(bend_hold_unbend));
  auto b = policy.describe(tube(bend_hold_unbend, other_tube));
  std::mt19937 random(5);
  for (const std::size_t rows : {std::size_t(b.signatures.rows()), std::size_t(11)}) {  // 11: a padded b
    b.signatures.conservativeResize(Eigen::Index(rows), Eigen::NoChange);
    b.frames.resize(rows);
    const auto comparison = policy.reordering_comparison(a, b);
    const Eigen::MatrixXd d = policy.frame_dissimilarities(a, b);  // floats: the copies keep them so, exactly
    CHECK((d.cast<float>().cast<double>().array() == d.array()).all());
    std::vector<std::size_t> order(rows);
    std::iota(order.begin(), order.end(), std::size_t(0));
    for (int copy = 0; copy < 8; ++copy) {
      const std::span<const std::size_t> o(order);
      CHECK(same_bits(comparison(o), policy.compare(a, similarity::reordered_frames(b, o)).value));
      std::shuffle(order.begin(), order.end(), random);
    }
    std::mt19937 shared(9), compared(9);
    const double z = similarity::similarity_significance(policy, a, b, 20, shared);
    CHECK(same_bits(z, similarity::similarity_significance(Compare_only{policy}, a, b, 20, compared)));
    CHECK(shared() == compared());  // the same draws
  }
}

TEST_CASE("Motion_signature_dissimilarity: shared clips' rows within 2^-12 f + 2^-22 of the reference",
          "[motion_signature][data]") {
  const auto dir = test::data_dir() / "characters";
  const similarity::Motion_signature_similarity<> policy;
  const auto walk = policy.describe(io::read_animation((dir / "Knight.glb").string(), {.clip = "Walking_A"}));
  const auto run = policy.describe(io::read_animation((dir / "RobotExpressive.glb").string(), {.clip = "Running"}));
  const double unit = signatures::frame_dissimilarity_unit(std::size_t(walk.signatures.cols()), policy.scale);
  WARN("Knight's Walking_A against the robot's Running: largest error "
       << check_kernel_accuracy(walk.signatures, run.signatures, unit) << " of the reference");
  check_kernel_accuracy(walk.signatures, walk.signatures, unit);
  CHECK(policy.compare(walk, walk).value == 1.0);
}
