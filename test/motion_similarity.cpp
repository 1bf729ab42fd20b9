// Tests of motion_similarity.h and the similarity policies: self-similarity and invariance, the
// rankings the issue asks for on synthetic tubes, on the cat and lion poses and on the gallop's
// cycles, the matrix. Each ranking runs with the policies and prints their values. All pass them;
// what the strain and graph policies cannot see (which of two alike joints bends first) is checked
// as the known limitation it is, and the motion signatures, which see it, are checked to. The graph
// policy gives the same on any number of threads, and its loops take the count it is given.
#include "similarity_tubes.h"
#include "test_support.h"
#include "mesh_types.h"
#include "same_as_default_model.h"

#include <deformseg/alignment/dtw.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/any_policy.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>

#include <Eigen/Geometry>

#include <numbers>
#include <type_traits>
#include <variant>
#include <vector>

using namespace deformseg;

using namespace deformseg::test;

namespace {

std::vector<std::size_t> reversed_frames(std::size_t count) {
  std::vector<std::size_t> frames(count);
  for (std::size_t t = 0; t < count; ++t) frames[t] = count - 1 - t;
  return frames;
}

// The policy's values for the tube rankings, printed, and whether each ranking holds.
template <class Policy>
void check_tubes(const Policy& policy, const char* name) {
  const auto a = tube(bend_hold_unbend);
  const double same_motion_other_tube =
      similarity::motion_similarity(a, tube(bend_hold_unbend, other_tube), policy).value;
  const double other_timing =
      similarity::motion_similarity(a, tube({{5, {0.0}}, {3, {right_angle}}, {22, {}}, {3, {0.0}}, {5, {}}}), policy)
          .value;
  const double two_bends = similarity::motion_similarity(
      a, tube({{5, {0.0}}, {5, {right_angle}}, {4, {}}, {5, {0.0}}, {5, {right_angle}}, {4, {}}, {5, {0.0}}, {5, {}}}),
      policy).value;
  WARN(name << ": same schedule on another tube " << same_motion_other_tube << ", other timing " << other_timing
            << ", two bends " << two_bends);
  CHECK(same_motion_other_tube > other_timing);
  CHECK(same_motion_other_tube > two_bends);

  // A fast bend and a slow unbend, against the same played backwards (a slow bend and a fast
  // unbend): not the same motion, so below 1, yet nearer than a motion of other timing.
  const auto fast_slow = tube({{5, {0.0}}, {3, {right_angle}}, {6, {}}, {15, {0.0}}, {5, {}}});
  const double reversal =
      similarity::motion_similarity(fast_slow, frames_of(fast_slow, reversed_frames(fast_slow.num_frames())), policy)
          .value;
  WARN(name << ": a schedule against its time reversal " << reversal);
  CHECK(reversal < 0.999);
}

// Which of two alike joints bends first: a policy that ignores where the strain lies cannot
// tell; the value is printed either way.
template <class Policy>
double which_joint_first(const Policy& policy) {
  const std::vector<mesh::Tube_joint> joints{{.position = 0.3}, {.position = 0.7}};
  const auto lower_first =
      tube({{5, {0.0, 0.0}}, {8, {right_angle, 0.0}}, {8, {right_angle, right_angle}}, {5, {}}}, {}, {}, joints);
  const auto upper_first =
      tube({{5, {0.0, 0.0}}, {8, {0.0, right_angle}}, {8, {right_angle, right_angle}}, {5, {}}}, {}, {}, joints);
  const auto other_tube_lower_first =
      tube({{5, {0.0, 0.0}}, {8, {right_angle, 0.0}}, {8, {right_angle, right_angle}}, {5, {}}}, other_tube, {},
           joints);
  const double swapped = similarity::motion_similarity(lower_first, upper_first, policy).value;
  const double same = similarity::motion_similarity(lower_first, other_tube_lower_first, policy).value;
  WARN("which joint first: swapped " << swapped << ", same order on another tube " << same);
  return swapped - same;
}

struct Cat_lion {
  mesh::Surface_mesh_animation cat, lion, cat_reordered, samba;
};

// The nine poses of the cat and of the lion (their reference pose left out), the cat's in
// another order, and the first nine frames of the samba.
const Cat_lion& cat_lion() {
  static const Cat_lion data = [] {
    const auto cat_dir = test::unpacked("cat-lion-poses/cat-poses.tgz") / "cat-poses";
    const auto lion_dir = test::unpacked("cat-lion-poses/lion-poses.tgz") / "lion-poses";
    const auto samba_dir = test::unpacked("samba/samba.tar.xz") / "samba";
    const auto cat = io::read_frame_sequence((cat_dir / "cat-0?.obj").string());
    const auto samba = io::read_frame_sequence(samba_dir.string());
    return Cat_lion{cat, io::read_frame_sequence((lion_dir / "lion-0?.obj").string()),
                    frames_of(cat, {4, 7, 1, 8, 3, 0, 6, 2, 5}), frames_of(samba, {0, 1, 2, 3, 4, 5, 6, 7, 8})};
  }();
  return data;
}

// The cat's poses nearer the lion's than the samba, and, unless `order_matters` is false, than
// themselves reordered.
template <class Policy>
void check_cat_lion(const Policy& policy, const char* name, bool order_matters = true) {
  const Cat_lion& d = cat_lion();
  REQUIRE(d.cat.num_frames() == 9);
  REQUIRE(d.lion.num_frames() == 9);
  const double lion = similarity::motion_similarity(d.cat, d.lion, policy).value;
  const double reordered = similarity::motion_similarity(d.cat, d.cat_reordered, policy).value;
  const double samba = similarity::motion_similarity(d.cat, d.samba, policy).value;
  WARN(name << ": cat poses against the lion's " << lion << ", against themselves reordered " << reordered
            << ", against the samba " << samba);
  if (order_matters) CHECK(lion > reordered);
  CHECK(lion > samba);
}

template <class Policy>
void check_self_and_copy(const Policy& policy, const Eigen::Vector3d& turn_axis = Eigen::Vector3d(1, 1, -2)) {
  const auto a = tube(bend_hold_unbend);
  mesh::Bending_tube placed;
  placed.schedule = bend_hold_unbend;
  placed.placement = {.scale = 7.5,
                      .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(2.5, turn_axis.normalized())),
                      .translation = Eigen::Vector3d(40, -3, 9)};
  const similarity::Similarity self = similarity::motion_similarity(a, a, policy);
  CHECK(self.value == Approx(1.0));
  CHECK(self.alignment.size() == a.num_frames());
  CHECK(similarity::motion_similarity(a, mesh::make_bending_tube(placed).animation, policy).value ==
        Approx(1.0).margin(1e-9));
  CHECK(!self.compared.empty());
}

}  // namespace

TEST_CASE("motion similarity: an animation and itself, or a moved, turned, scaled copy, give 1", "[similarity]") {
  check_self_and_copy(similarity::Motion_signature_similarity<>{},
                      Eigen::Vector3d::UnitY());  // turned about its up only
  similarity::Motion_signature_similarity<> directionless;
  directionless.signatures.up = std::nullopt;
  check_self_and_copy(directionless);
  check_self_and_copy(similarity::Strain_distribution_similarity<>{});
  check_self_and_copy(similarity::Evolving_graph_similarity<>{});
  const similarity::Similarity s = similarity::motion_similarity(tube(bend_hold_unbend), tube(bend_hold_unbend));
  CHECK(s.value == Approx(1.0));
  CHECK(s.labels_a.empty());
  const similarity::Similarity g = similarity::motion_similarity(tube(bend_hold_unbend), tube(bend_hold_unbend),
                                                                 similarity::Evolving_graph_similarity<>{});
  CHECK(g.labels_a == g.labels_b);
  CHECK(g.labels_a.size() == tube(bend_hold_unbend).num_frames());
}

TEMPLATE_LIST_TEST_CASE("motion similarity: every policy on every mesh type gives the default model's value, to the "
                        "last bit",
                        "[similarity][mesh_types]", test::Mesh_types) {
  const mesh::Tube_shape small{.sectors = 8, .rings = 24};
  const auto a = tube(bend_hold_unbend, small), b = tube(other_timing, small);
  const TestType on_a(a), on_b(b);
  check_every_policy_same(on_a.model(), on_b.model(), a, b);
}

TEST_CASE("motion similarity: tubes, the same schedule on another tube is nearer than other schedules",
          "[similarity]") {
  check_tubes(similarity::Motion_signature_similarity<>{}, "motion signatures");
  check_tubes(similarity::Strain_distribution_similarity<>{}, "strain distribution");
  check_tubes(similarity::Strain_distribution_similarity<alignment::Dtw>{}, "strain distribution, DTW");
}

TEST_CASE("motion similarity: tubes, with the thesis' evolving graph policy", "[similarity]") {
  check_tubes(similarity::Evolving_graph_similarity<>{}, "evolving graph");
}

TEST_CASE("motion similarity: which joint bends first, a known limitation of the strain distribution", "[similarity]") {
  // Alike joints on one tube strain alike: the histograms of the two orders are the same.
  CHECK(which_joint_first(similarity::Strain_distribution_similarity<>{}) > -1e-9);
  // The evolving graph sees two segments one after the other either way, at the same area shares:
  // it cannot tell them apart either. (It also rates the same order on the other tube far lower,
  // 0.30 here: that tube's graphs have other shapes.)
  CHECK(which_joint_first(similarity::Evolving_graph_similarity<>{}) > -1e-9);
  // The motion signatures see it: bending the joint at 0.3 moves 70 % of the tube, the one at 0.7
  // moves 30 %, so the orders' rate distributions differ.
  CHECK(which_joint_first(similarity::Motion_signature_similarity<>{}) < -0.1);
}

TEST_CASE("motion similarity: the cat's poses are nearest the lion's same poses", "[similarity][data]") {
  check_cat_lion(similarity::Motion_signature_similarity<>{}, "motion signatures (the default)");
  check_cat_lion(similarity::Strain_distribution_similarity<>{}, "strain distribution");
}

// Frames 0-23 and 24-47 of the horse gallop against each other and against every 24-frame
// window of the samba, each described alone as a 24-frame animation: the cycles' value and the
// best of a cycle against a samba window.
template <class Policy>
std::pair<double, double> gallop_cycles_and_samba(const Policy& policy) {
  const auto horse =
      io::read_frame_sequence((test::unpacked("horse-gallop/horse-gallop.tar.xz") / "horse-gallop").string());
  const auto samba = io::read_frame_sequence((test::unpacked("samba/samba.tar.xz") / "samba").string());
  REQUIRE(horse.num_frames() == 48);
  const auto window = [](const mesh::Surface_mesh_animation& a, std::size_t first) {
    std::vector<std::size_t> frames(24);
    for (std::size_t t = 0; t < 24; ++t) frames[t] = first + t;
    return frames_of(a, frames);
  };
  const auto first = policy.describe(window(horse, 0)), second = policy.describe(window(horse, 24));
  const double cycles = policy.compare(first, second).value;
  double nearest_samba = 0;
  for (std::size_t t = 0; t + 24 <= samba.num_frames(); ++t) {
    const auto w = policy.describe(window(samba, t));
    nearest_samba = std::max({nearest_samba, policy.compare(first, w).value, policy.compare(second, w).value});
  }
  return {cycles, nearest_samba};
}

TEST_CASE("motion similarity: the gallop's two cycles are nearer each other than any samba window",
          "[similarity][data]") {
  const auto [cycles, nearest_samba] = gallop_cycles_and_samba(similarity::Default_similarity{});
  WARN("motion signatures: gallop cycle against cycle " << cycles << ", nearest samba window " << nearest_samba);
  CHECK(cycles > nearest_samba + 0.1);
}

TEST_CASE("motion similarity: the cat and the lion, and the gallop's cycles, with the evolving graph policies",
          "[similarity][data]") {
  check_cat_lion(similarity::Evolving_graph_similarity<>{}, "evolving graph (the thesis')");
  // Nine poses a frame apart are no motion: the settings tuned on the characters' motions find
  // them alike in any order.
  check_cat_lion(similarity::character_graph_similarity(), "evolving graph (tuned on characters)", false);
  const auto check_cycles = [](const auto& policy, const char* name) {
    const auto [cycles, nearest_samba] = gallop_cycles_and_samba(policy);
    WARN(name << ": gallop cycle against cycle " << cycles << ", nearest samba window " << nearest_samba);
    CHECK(cycles > nearest_samba);
  };
  check_cycles(similarity::Evolving_graph_similarity<>{}, "evolving graph (the thesis')");
  check_cycles(similarity::character_graph_similarity(), "evolving graph (tuned on characters)");
}

namespace {

struct Gallops {
  mesh::Surface_mesh_animation horse, elephant, samba;
};

// Sumner's horse gallop, the same gallop transferred to an elephant, and Vlasic's samba, whole.
const Gallops& gallops() {
  static const Gallops data = [] {
    const auto read = [](const char* archive, const char* folder) {
      return io::read_frame_sequence((test::unpacked(archive) / folder).string());
    };
    return Gallops{read("horse-gallop/horse-gallop.tar.xz", "horse-gallop"),
                   read("elephant-gallop/elephant-gallop.tar.xz", "elephant-gallop"),
                   read("samba/samba.tar.xz", "samba")};
  }();
  return data;
}

// The horse's gallop against the elephant's and against the samba under `policy`.
template <class Policy>
std::pair<double, double> horse_against_elephant_and_samba(const Policy& policy, const char* name) {
  const Gallops& d = gallops();
  REQUIRE(d.elephant.num_frames() == 48);
  const double elephant = similarity::motion_similarity(d.horse, d.elephant, policy).value;
  const double samba = similarity::motion_similarity(d.horse, d.samba, policy).value;
  WARN(name << ": horse gallop against the elephant gallop " << elephant << ", against the samba " << samba);
  return {elephant, samba};
}

}  // namespace

TEST_CASE("motion similarity: the thesis' claim, the horse's gallop nearer the elephant's than the samba",
          "[similarity][data]") {
  const auto [elephant, samba] = horse_against_elephant_and_samba(similarity::Evolving_graph_similarity<>{},
                                                                  "evolving graph (the thesis')");
  CHECK(elephant > samba + 0.5);  // 0.583 and 0.042
  const similarity::Any_policy thesis = similarity::Graph_similarity<alignment::Smith_waterman>{};
  CHECK(similarity::visit_policy(thesis, [&](const auto& policy) {
          return similarity::motion_similarity(gallops().horse, gallops().elephant, policy).value;
        }) == elephant);
  const auto [by_signatures, samba_by_signatures] =
      horse_against_elephant_and_samba(similarity::Default_similarity{}, "motion signatures (the default)");
  CHECK(by_signatures > samba_by_signatures + 0.4);  // 0.807 and 0.352
  // The settings tuned on game characters lose it (the samba comes nearer), as chapter 7 says.
  horse_against_elephant_and_samba(similarity::character_graph_similarity(), "evolving graph (tuned on characters)");
}

TEST_CASE("motion similarity: the thesis' claim on tubes, a bend nearer the same bend of a thicker tube than two bends",
          "[similarity]") {
  const similarity::Evolving_graph_similarity<> thesis;
  const auto a = tube(bend_hold_unbend);
  const double thicker = similarity::motion_similarity(a, tube(bend_hold_unbend, other_tube), thesis).value;
  const double two_bends = similarity::motion_similarity(
      a, tube({{5, {0.0}}, {5, {right_angle}}, {4, {}}, {5, {0.0}}, {5, {right_angle}}, {4, {}}, {5, {0.0}}, {5, {}}}),
      thesis).value;
  WARN("evolving graph (the thesis'): the same bend on a thicker tube " << thicker << ", two bends " << two_bends);
  CHECK(thicker > two_bends + 0.35);  // 0.897 and 0.487
}

TEST_CASE("similarity matrix: symmetric, ones on the diagonal, equal to the pairwise calls", "[similarity]") {
  const std::vector<mesh::Surface_mesh_animation> animations{
      tube(bend_hold_unbend), tube(bend_hold_unbend, other_tube),
      tube({{5, {0.0}}, {3, {right_angle}}, {22, {}}, {3, {0.0}}, {5, {}}})};
  const auto check = [&](const auto& policy) {
    const Eigen::MatrixXd m = similarity::similarity_matrix(animations, policy);
    REQUIRE(m.rows() == 3);
    CHECK(m.isApprox(m.transpose(), 0.0));
    for (Eigen::Index i = 0; i < 3; ++i) {
      CHECK(m(i, i) == Approx(1.0));
      for (Eigen::Index j = i + 1; j < 3; ++j)
        CHECK(m(i, j) ==
              similarity::motion_similarity(animations[std::size_t(i)], animations[std::size_t(j)], policy).value);
    }
  };
  check(similarity::Motion_signature_similarity<>{});
  check(similarity::Strain_distribution_similarity<>{});
  check(similarity::Evolving_graph_similarity<>{});
  CHECK(similarity::similarity_matrix(std::vector<mesh::Surface_mesh_animation>{}).size() == 0);
}

TEST_CASE("described similarity matrix: the matrix of the animations, bit for bit, on 1 or 2 threads, its steps",
          "[similarity]") {
  const std::vector<mesh::Surface_mesh_animation> animations{
      tube(bend_hold_unbend), tube(bend_hold_unbend, other_tube), tube(other_timing), tube(other_timing, other_tube)};
  const auto check = [&](const auto& policy) {
    using Description = typename std::remove_cvref_t<decltype(policy)>::Description;
    std::vector<Description> descriptions;
    for (const auto& animation : animations) descriptions.push_back(policy.describe(animation));
    const Eigen::MatrixXd whole = similarity::similarity_matrix(animations, policy, {}, 1);
    for (const int threads : {1, 2}) {
      std::size_t last_done = 0, last_total = 0;
      const Progress steps = [&](std::size_t done, std::size_t total) {
        CHECK(done > last_done);
        last_done = done, last_total = total;
        return true;
      };
      const Eigen::MatrixXd m = similarity::described_similarity_matrix(descriptions, policy, steps, threads);
      CHECK(m == whole);
      CHECK((last_done == 10 && last_total == 10));  // 4 (4 + 1) / 2 pairs
    }
  };
  check(similarity::Motion_signature_similarity<>{});
  check(similarity::Strain_distribution_similarity<>{});
  check(similarity::Self_similarity_matching<>{});
  CHECK(similarity::described_similarity_matrix(std::vector<similarity::Motion_signature_description>{},
                                                similarity::Default_similarity{}).size() == 0);
  CHECK_THROWS_AS(similarity::described_similarity_matrix(std::vector<similarity::Motion_signature_description>{},
                                                          similarity::Default_similarity{}, {}, -1),
                  invalid_input);
}

TEST_CASE("evolving graph similarity: the same descriptions and similarity on 1, 2 or all threads", "[similarity]") {
  const auto a = tube(bend_hold_unbend), b = tube(other_timing, other_tube);
  const auto check = [&](auto policy, const char* name) {
    INFO(name);
    for (const auto labels : {similarity::Label_dissimilarity::mismatch, similarity::Label_dissimilarity::medoids,
                              similarity::Label_dissimilarity::graphs}) {
      INFO("labels " << int(labels));
      policy.labels = labels;
      policy.threads = 1;
      const auto da = policy.describe(a), db = policy.describe(b);
      const similarity::Similarity one = policy.compare(da, db);
      for (const int threads : {2, 0}) {
        INFO("threads " << threads);
        policy.threads = threads;
        const auto other_a = policy.describe(a), other_b = policy.describe(b);
        CHECK(other_a.distances == da.distances);  // bit-identical
        CHECK(other_b.distances == db.distances);
        const similarity::Similarity other = policy.compare(other_a, other_b);
        CHECK(other.value == one.value);
        CHECK(other.score == one.score);
        CHECK(other.labels_a == one.labels_a);
        CHECK(other.labels_b == one.labels_b);
        CHECK(other.alignment == one.alignment);
      }
    }
  };
  check(similarity::Evolving_graph_similarity<>{}, "the thesis'");
  check(similarity::character_graph_similarity(), "tuned on characters");
}

TEST_CASE("evolving graph similarity: its loops run on the counts given, none on the environment's", "[similarity]") {
  const auto a = tube(bend_hold_unbend), b = tube(other_timing, other_tube);
  similarity::Evolving_graph_similarity<> policy;
  policy.segmentation.threads = 1;
  policy.clustering.threads = 1;
  // Only a count of 0 reads the environment, and refuses this value: any loop left on 0 throws.
  const test::Scoped_variable unreadable("DEFORMSEG_NUM_THREADS", "many");
  policy.threads = 2;
  const auto da = policy.describe(a), db = policy.describe(b);
  REQUIRE(da.graphs.size() * db.graphs.size() >= 2);  // compare's pairs shared by 2 threads
  CHECK_NOTHROW(policy.compare(da, db));
  policy.threads = 0;
  CHECK_THROWS_WITH(policy.describe(a), Catch::Contains("DEFORMSEG_NUM_THREADS is 'many'"));
  CHECK_THROWS_WITH(policy.compare(da, db), Catch::Contains("DEFORMSEG_NUM_THREADS is 'many'"));
}

TEST_CASE("evolving graph similarity: a thread count out of range is refused before any work", "[similarity]") {
  const auto a = tube(bend_hold_unbend);
  similarity::Evolving_graph_similarity<> policy;
  const auto da = policy.describe(a);
  policy.segmentation.min_area = 2;  // refused too, but after the count
  CHECK_THROWS_WITH(policy.describe(a), Catch::Contains("the minimum area share must be in [0, 1]"));
  for (const int threads : {-1, max_threads + 1}) {
    policy.threads = threads;
    const std::string refused = "Evolving_graph_similarity: threads must be 0 (the default) to " +
                                std::to_string(max_threads) + ", not " + std::to_string(threads);
    CHECK_THROWS_WITH(policy.describe(a), refused);
    CHECK_THROWS_WITH(policy.compare(da, da), refused);
  }
}

TEST_CASE("motion similarity: a motion found whole inside a longer one, by the shorter or the longer", "[similarity]") {
  // Standing still for 6 frames is all of the first 6 frames of a tube that then bends.
  const auto still = tube({{5, {}}});
  const auto bends = tube({{5, {}}, {10, {right_angle}}, {10, {}}});
  const auto check = [&](auto policy, const char* name) {
    const double by_shorter = similarity::motion_similarity(still, bends, policy).value;
    policy.normalization.length = similarity::Normalize_by::longer;
    const double by_longer = similarity::motion_similarity(still, bends, policy).value;
    WARN(name << ": still against bending, by the shorter " << by_shorter << ", by the longer " << by_longer);
    CHECK(by_shorter == Approx(1.0).margin(1e-6));
    CHECK(by_longer < 0.5);
    CHECK(similarity::motion_similarity(bends, bends, policy).value == Approx(1.0));
  };
  check(similarity::Strain_distribution_similarity<>{}, "strain distribution");
  // Only a local alignment finds a part inside a whole: the thesis' Smith–Waterman, not DTW.
  check(similarity::Evolving_graph_similarity<>{}, "evolving graph (the thesis', Smith-Waterman)");
}

TEST_CASE("Any_policy: visit_policy runs the policy held, with its alignment and options", "[similarity]") {
  const auto a = tube(bend_hold_unbend), b = tube(other_timing, other_tube);
  const auto value = [&](const similarity::Any_policy& any) {
    return similarity::visit_policy(any, [&](const auto& policy) { return similarity::motion_similarity(a, b, policy); })
        .value;
  };
  CHECK(value(similarity::Default_similarity{}) == similarity::motion_similarity(a, b).value);
  CHECK(value(similarity::Strain_distribution_similarity<alignment::Dtw>{}) ==
        similarity::motion_similarity(a, b, similarity::Strain_distribution_similarity<alignment::Dtw>{}).value);
  CHECK(value(similarity::Self_similarity_matching<>{}) ==
        similarity::motion_similarity(a, b, similarity::Self_similarity_matching<>{}).value);
  similarity::Evolving_graph_similarity<> graphs;
  graphs.segmentation.threshold = 0.2;
  CHECK(value(graphs) == similarity::motion_similarity(a, b, graphs).value);
  CHECK(value(similarity::character_graph_similarity()) ==
        similarity::motion_similarity(a, b, similarity::character_graph_similarity()).value);
  similarity::Motion_signature_similarity<alignment::Subsequence_dtw> speeds;
  speeds.signatures.up = std::nullopt;
  CHECK(value(speeds) == similarity::motion_similarity(a, b, speeds).value);
  // The thesis' graphs and those tuned on characters are one type with other parameters.
  STATIC_REQUIRE(std::is_same_v<similarity::Evolving_graph_similarity<>,
                                similarity::Graph_similarity<alignment::Smith_waterman>>);
  STATIC_REQUIRE(std::is_same_v<decltype(similarity::character_graph_similarity()),
                                similarity::Graph_similarity<alignment::Dtw>>);
  STATIC_REQUIRE(std::variant_size_v<similarity::Any_policy> == 12);  // 4 policies x 3 alignments
}
