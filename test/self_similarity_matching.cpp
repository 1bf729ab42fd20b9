// Tests of similarity/self_similarity_matching.h: exact invariances (itself, a moved, rotated,
// scaled copy, a remeshed tube), a time-shifted cyclic motion, a motion inside a longer one,
// tubes of other meshes ranking the same motion first, the Procrustes self-dissimilarity on a
// rigid motion, and [data] rankings and retrieval figures on the shared characters.
#include "similarity_tubes.h"
#include "test_support.h"

#include <deformseg/io/gltf.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/mesh/synthetic.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace deformseg;

using namespace deformseg::test;

TEST_CASE("self_similarity_matching: an animation against itself and a moved, rotated, scaled copy is 1",
          "[self_similarity]") {
  const similarity::Self_similarity_matching<> policy;
  const auto [a, b] = check_moved_copy_is_one(policy);
  // The description itself is invariant: the Procrustes distances agree to rounding (the square
  // root of the Gram formula's rounding, 1e-8 between frames of one held pose).
  CHECK((policy.describe(a).distances - policy.describe(b).distances).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("self_similarity_matching: a rigid motion has a zero self-dissimilarity matrix", "[self_similarity]") {
  // A tube standing still yet turning and travelling frame after frame: nothing moves relative
  // to the body, so every Procrustes distance is 0 (a deformation-only measure sees nothing
  // either, but for the opposite reason a rigid *part* is seen: see the next test).
  const auto still = tube({{1, {0.0}}});
  std::vector<double> positions;
  for (int t = 0; t < 6; ++t) {
    const Eigen::AngleAxisd turn(0.3 * t, Eigen::Vector3d::UnitY());
    for (std::size_t v = 0; v < still.num_vertices(); ++v) {
      const Eigen::Vector3d p(still.frame_positions(0).data() + 3 * v);
      const Eigen::Vector3d q = turn * p + Eigen::Vector3d(t, 0, 0);
      positions.insert(positions.end(), {q.x(), q.y(), q.z()});
    }
  }
  const mesh::Surface_mesh_animation moving(still.face_graph(), std::move(positions));
  CHECK(similarity::Self_similarity_matching<>{}.describe(moving).distances.cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("self_similarity_matching: rigid parts moving on a joint are seen", "[self_similarity]") {
  // No strain anywhere, yet frame 0 and the last frame are far apart (a robot's limbs).
  const std::size_t frames = 5, points = 20;
  const std::vector<double> positions = jointed_points(frames, points);
  const std::vector<double> weights(points, 1.0 / points);
  const auto d = similarity::Self_similarity_matching<>{}.describe_positions(positions, weights);
  CHECK(d.distances(0, frames - 1) > 0.3);
  for (std::size_t t = 1; t < frames; ++t) CHECK(d.distances(0, Eigen::Index(t)) > d.distances(0, Eigen::Index(t - 1)));
}

TEST_CASE("self_similarity_matching: a time-shifted cyclic motion scores near 1", "[self_similarity]") {
  const similarity::Self_similarity_matching<> policy;
  const auto a = cycles(16, 64, 0), shifted = cycles(16, 64, 5);
  const double value = similarity::motion_similarity(a, shifted, policy).value;
  const double other = similarity::motion_similarity(a, tube(other_timing), policy).value;
  WARN("cycles against themselves shifted by 5 of 16 frames " << value << ", against another motion " << other);
  CHECK(value > 0.8);
  CHECK(value > other + 0.3);
}

TEST_CASE("self_similarity_matching: a motion inside a longer one is found", "[self_similarity]") {
  similarity::Self_similarity_matching<> policy;
  const auto motion = tube(bend_hold_unbend);
  // 12 frames of another motion (a half bend and back), then the motion, then 12 more.
  std::vector<mesh::Tube_phase> longer{{6, {right_angle / 2}}, {6, {0.0}}};
  longer.insert(longer.end(), bend_hold_unbend.begin() + 1, bend_hold_unbend.end());
  longer.insert(longer.end(), {{6, {right_angle / 2}}, {7, {0.0}}});
  const auto inside = tube(longer);
  const std::size_t before = 12 - 5;  // the longer one has 12 frames first, the motion's 5-frame hold none
  const similarity::Similarity by_longer = similarity::motion_similarity(motion, inside, policy);
  policy.normalization.length = similarity::Normalize_by::shorter;
  const similarity::Similarity by_shorter = similarity::motion_similarity(motion, inside, policy);
  WARN("a motion inside a longer one: " << by_shorter.value << " by the shorter's self-score, " << by_longer.value
                                        << " by the longer's");
  CHECK(by_shorter.value > 0.75);
  CHECK(by_longer.value < by_shorter.value);
  REQUIRE(!by_shorter.alignment.empty());
  // Aligned on the diagonal where the motion sits, give or take the profiles' window.
  std::size_t on_place = 0;
  for (auto [i, j] : by_shorter.alignment) on_place += (j >= i + before - 3 && j <= i + before + 3);
  CHECK(on_place >= by_shorter.alignment.size() * 3 / 4);
}

TEST_CASE("self_similarity_matching: the same motion on another tube ranks above other motions",
          "[self_similarity]") {
  const similarity::Self_similarity_matching<> policy;
  const auto a = tube(bend_hold_unbend);
  const double same = similarity::motion_similarity(a, tube(bend_hold_unbend, other_tube), policy).value;
  const double timing = similarity::motion_similarity(a, tube(other_timing, other_tube), policy).value;
  const double two_bends = similarity::motion_similarity(
      a,
      tube({{5, {0.0}}, {5, {right_angle}}, {4, {}}, {5, {0.0}}, {5, {right_angle}}, {4, {}}, {5, {0.0}}, {5, {}}},
           other_tube),
      policy).value;
  const double small_bend = similarity::motion_similarity(
      a, tube({{5, {0.0}}, {10, {right_angle / 3}}, {8, {}}, {10, {0.0}}, {5, {}}}, other_tube), policy).value;
  WARN("same motion on another tube " << same << ", other timing " << timing << ", two bends " << two_bends
                                      << ", a third of the bend " << small_bend);
  CHECK(same > 0.9);
  CHECK(same > timing + 0.1);
  CHECK(same > two_bends + 0.1);
  CHECK(same > small_bend + 0.2);
}

TEST_CASE("self_similarity_significance: ordered frames stand out from shuffled ones", "[self_similarity]") {
  const similarity::Self_similarity_matching<> policy;
  const auto a = policy.describe(tube(bend_hold_unbend));
  const auto same = policy.describe(tube(bend_hold_unbend, other_tube));
  const auto still = policy.describe(tube({{38, {0.0}}}, other_tube));
  std::mt19937 random(7);
  const double z_same = similarity::self_similarity_significance(policy, a, same, 20, random);
  const double z_still = similarity::self_similarity_significance(policy, a, still, 20, random);
  WARN("z-scores: same motion on another tube " << z_same << ", standing still " << z_still);
  CHECK(z_same > 3);
  CHECK(std::abs(z_still) < 2);  // a still tube's shuffled copies are itself, up to rounding
  std::mt19937 again(7);
  CHECK(similarity::self_similarity_significance(policy, a, same, 20, again) == z_same);
  CHECK_THROWS_AS(similarity::self_similarity_significance(policy, a, same, 1, again), invalid_input);
}

TEST_CASE("self_similarity_matching: descriptions of other quantile counts are refused", "[self_similarity]") {
  similarity::Self_similarity_matching<> coarse;
  coarse.options.quantiles = 4;
  const auto a = tube(bend_hold_unbend);
  CHECK_THROWS_AS(similarity::Self_similarity_matching<>{}.compare(similarity::Self_similarity_matching<>{}.describe(a),
                                                                   coarse.describe(a)),
                  invalid_input);
}

namespace {

struct Character_clip {
  std::string file, clip, motion;
  similarity::Self_similarity_description description;
};

// The labelled clips of `files` (motions.csv), described from their raw samples.
std::vector<Character_clip> character_clips(const std::vector<std::string>& files) {
  const auto dir = test::data_dir() / "characters";
  std::ifstream csv(dir / "motions.csv");
  std::string line;
  std::getline(csv, line);
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> wanted;
  while (std::getline(csv, line)) {
    const auto a = line.find(','), b = line.find(',', a + 1), c = line.find(',', b + 1);
    const std::string file = line.substr(0, a);
    if (std::find(files.begin(), files.end(), file) != files.end())
      wanted[file].push_back({line.substr(a + 1, b - a - 1), line.substr(b + 1, c - b - 1)});
  }
  const similarity::Self_similarity_matching<> policy;
  std::vector<Character_clip> clips;
  for (const std::string& file : files) {
    io::Gltf_file gltf((dir / file).string());
    for (const auto& [clip, motion] : wanted[file]) {
      const io::Sampled_gltf s = gltf.sample(io::Gltf_read_options{.clip = clip, .fps = 30});
      const std::span<const double> first(s.positions.data(), 3 * s.num_vertices);
      clips.push_back({file, clip, motion,
                       policy.describe_positions(s.positions, deformseg::signatures::vertex_area_weights(
                                                                  first, std::span(s.triangles), s.num_vertices))});
    }
  }
  return clips;
}

}  // namespace

TEST_CASE("self_similarity_matching: Knight queries against the Barbarian's clips", "[self_similarity][data]") {
  // A subset of motions.csv (two of the five KayKit bodies, 69 clips each) to stay fast; the
  // whole set is test/bench/similarity_evaluation. Same-name clips are left out (identical data).
  const auto clips = character_clips({"Knight.glb", "Barbarian.glb"});
  const similarity::Self_similarity_matching<> policy;
  std::vector<const Character_clip*> knight, barbarian;
  for (const auto& c : clips) (c.file == "Knight.glb" ? knight : barbarian).push_back(&c);
  REQUIRE(knight.size() == 69);
  std::vector<double> same, different;
  double nn = 0, queries = 0, concordant = 0, pairs = 0;
  for (const auto* q : knight) {
    if (q->motion == "-") continue;
    std::vector<std::pair<double, bool>> ranked;
    for (const auto* c : barbarian)
      if (c->clip != q->clip)
        ranked.push_back({policy.compare(q->description, c->description).value, c->motion == q->motion});
    if (std::none_of(ranked.begin(), ranked.end(), [](auto& r) { return r.second; })) continue;
    std::stable_sort(ranked.begin(), ranked.end(), [](auto& x, auto& y) { return x.first > y.first; });
    nn += ranked.front().second;
    queries += 1;
    for (auto [v, relevant] : ranked) (relevant ? same : different).push_back(v);
  }
  for (double s : same)
    for (double d : different) concordant += s > d ? 1.0 : s == d ? 0.5 : 0.0, pairs += 1;
  std::sort(same.begin(), same.end());
  std::sort(different.begin(), different.end());
  const double auc = concordant / pairs, median_same = same[same.size() / 2],
               median_different = different[different.size() / 2];
  WARN("Knight against Barbarian: " << queries << " queries, NN " << nn / queries << ", AUC " << auc
                                    << ", median same " << median_same << ", different " << median_different);
  // Measured: 59 queries, NN 0.32, AUC 0.72, medians 0.49 and 0.32 (far from the goals).
  CHECK(nn / queries > 0.25);
  CHECK(auc > 0.68);
  CHECK(median_same > median_different + 0.1);
}
