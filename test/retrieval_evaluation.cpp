// Tests of retrieval_evaluation.h, evaluation/motion_labels.h and the query x database similarity_matrix
// (with its progress callback): figures computed by hand, the exclusion rules, ties, queries
// without a relevant candidate, a brute-force check of ROC-AUC, and some items alone as queries.
#include "similarity_tubes.h"
#include "test_support.h"

#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/strain_distribution_similarity.h>
#include <deformseg/threads.h>

#include <random>
#include <vector>

using namespace deformseg;

namespace {

evaluation::Labelled_item item(std::string motion, std::string body, std::string rig = "", std::string clip = "") {
  return {.motion = std::move(motion), .body = std::move(body), .rig = std::move(rig), .clip = std::move(clip)};
}

Eigen::MatrixXd matrix(std::initializer_list<std::initializer_list<double>> rows) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(Eigen::Index(rows.size()), Eigen::Index(rows.begin()->size()));
  Eigen::Index i = 0;
  for (const auto& row : rows) {
    Eigen::Index j = 0;
    for (const double v : row) m(i, j++) = v;
    ++i;
  }
  return m;
}

}  // namespace

TEST_CASE("evaluate_retrieval: a 5-item case computed by hand", "[evaluation]") {
  // 0 a/X, 1 a/Y, 2 b/Y, 3 b/Z, 4 distractor/Z; no rig.
  const std::vector<evaluation::Labelled_item> items{item("a", "X"), item("a", "Y"), item("b", "Y"), item("b", "Z"),
                                         item("-", "Z")};
  // Row 0: candidates 1-4 ranked 2 (.8 b), 1 (.6 a), 4 (.5 -), 3 (.4 b): NN b, wrong; AP 1/2.
  // Row 1: candidates 0, 3, 4 (2 is body Y, its .9 unseen): 0 and 3 tie at .7, the lower index 0
  //        first: NN a, right; AP 1.
  // Row 2: candidates 0, 3, 4 (1's .95 unseen): 4 (.6 -), then 0 and 3 tied at .3, 0 first: NN the
  //        distractor, wrong; AP 1/3 (3 at rank 3).
  // Row 3: candidates 0, 1, 2 (4 is body Z, its .99 unseen): 2 (.9 b): NN right; AP 1.
  // Row 4: a distractor, never a query (its values would change every figure).
  const Eigen::MatrixXd s = matrix({{1, .6, .8, .4, .5},
                                    {.7, 1, .9, .7, .2},
                                    {.3, .95, 1, .3, .6},
                                    {.5, .4, .9, 1, .99},
                                    {.9, .9, .9, .9, 1}});
  const evaluation::Retrieval_scores r = evaluation::evaluate_retrieval(s, items);
  CHECK(r.queries == 4);
  CHECK(r.queries_without_relevant == 0);
  CHECK(r.queries_without_candidate == 0);
  CHECK(*r.nn_accuracy == 0.5);
  CHECK(*r.mean_average_precision == Approx((0.5 + 1 + 1.0 / 3 + 1) / 4));  // 17/24
  // Same: .6 .7 .3 .9; different (9): .2 .3 .4 .4 .5 .5 .6 .7 .8. Beaten (ties 1/2): .3 -> 1.5,
  // .6 -> 6.5, .7 -> 7.5, .9 -> 9: 24.5 of 36.
  CHECK(r.same_pairs == 4);
  CHECK(r.different_pairs == 9);
  CHECK(*r.roc_auc == Approx(24.5 / 36));
  CHECK(*r.median_same == Approx(0.65));  // (.6 + .7) / 2
  CHECK(*r.median_different == 0.5);      // the 5th of 9
  CHECK(r.labels == std::vector<std::string>{"-", "a", "b"});
  // Rows: queries of a: NN b (0), a (1); of b: NN - (2), b (3).
  CHECK(r.confusion == std::vector<std::vector<std::size_t>>{{0, 0, 0}, {0, 1, 1}, {1, 0, 1}});
  REQUIRE(r.per_motion.size() == 2);
  CHECK(r.per_motion[0].motion == "a");
  CHECK(r.per_motion[0].queries == 2);
  CHECK(r.per_motion[0].correct == 1);
  CHECK(r.per_motion[0].nn_accuracy == 0.5);
  CHECK(r.per_motion[1].motion == "b");
  CHECK(r.per_motion[1].correct == 1);
  // Per query, from the rankings above: nearest, its value, first relevant rank, AP.
  REQUIRE(r.per_query.size() == 4);
  const auto check_query = [&](std::size_t i, std::size_t nearest, double value, std::size_t first, double ap) {
    CAPTURE(i);
    const evaluation::Query_retrieval& found = r.per_query[i];
    CHECK(found.query == i);
    CHECK(found.nearest == nearest);
    CHECK(found.nearest_similarity == value);
    CHECK(found.first_relevant_rank == first);
    CHECK(*found.average_precision == Approx(ap));
  };
  check_query(0, 2, .8, 2, 0.5);
  check_query(1, 0, .7, 1, 1);
  check_query(2, 4, .6, 3, 1.0 / 3);
  check_query(3, 2, .9, 1, 1);
}

TEST_CASE("evaluate_retrieval: the same clip on the same rig is no candidate / queries without relevant one",
          "[evaluation]") {
  const std::vector<evaluation::Labelled_item> items{item("walk", "A", "k", "Walk"), item("walk", "B", "k", "Walk"),
                                         item("walk", "B", "k", "Walk2"), item("run", "C", "", "Walk")};
  // Query 0: candidates 2 (.1, walk) and 3 (.5, run; rig empty, so its clip name does not matter);
  //          1 is clip Walk on rig k, left out although .99: NN run, AP 1/2.
  // Query 1: 0 is the same clip on rig k, 2 the same body: candidate 3 only, not relevant.
  // Query 2: candidates 0 (.2, another clip) and 3 (.3): NN run, AP 1/2.
  // Query 3: candidates 0, 1, 2 (an empty rig excludes no clip), all walk: NN 2, not relevant.
  const Eigen::MatrixXd s = matrix({{1, .99, .1, .5}, {.9, 1, .9, .4}, {.2, 0, 1, .3}, {.1, .2, .3, 1}});
  const evaluation::Retrieval_scores r = evaluation::evaluate_retrieval(s, items);
  CHECK(r.queries == 4);
  CHECK(*r.nn_accuracy == 0);
  CHECK(r.queries_without_relevant == 2);
  CHECK(*r.mean_average_precision == 0.5);
  CHECK(r.same_pairs == 2);       // (0, 2), (2, 0)
  CHECK(r.different_pairs == 6);  // (0, 3), (1, 3), (2, 3), (3, 0), (3, 1), (3, 2)
  // Same .1 .2 against different .5 .4 .3 .1 .2 .3: .1 -> 1/2, .2 -> 1 + 1/2: 2 of 12.
  CHECK(*r.roc_auc == Approx(2.0 / 12));
  CHECK(r.confusion == std::vector<std::vector<std::size_t>>{{0, 1}, {3, 0}});  // labels run, walk
  // Query 1 has no relevant candidate: no rank, no AP; query 2 finds one second.
  REQUIRE(r.per_query.size() == 4);
  CHECK(r.per_query[1].nearest == 3);
  CHECK_FALSE(r.per_query[1].first_relevant_rank);
  CHECK_FALSE(r.per_query[1].average_precision);
  CHECK(r.per_query[2].nearest == 3);
  CHECK(r.per_query[2].first_relevant_rank == 2u);
  CHECK(*r.per_query[2].average_precision == 0.5);
}

TEST_CASE("evaluate_retrieval: distractors are never queried / no candidate, no figure", "[evaluation]") {
  const std::vector<evaluation::Labelled_item> only_distractors{item("-", "A"), item("-", "B")};
  const evaluation::Retrieval_scores none =
      evaluation::evaluate_retrieval(Eigen::MatrixXd::Ones(2, 2), only_distractors);
  CHECK(none.queries == 0);
  CHECK_FALSE(none.nn_accuracy);
  CHECK_FALSE(none.mean_average_precision);
  CHECK_FALSE(none.roc_auc);
  CHECK_FALSE(none.median_same);
  CHECK(none.per_motion.empty());
  CHECK(none.per_query.empty());

  // One body: no query has a candidate.
  const std::vector<evaluation::Labelled_item> one_body{item("walk", "A"), item("walk", "A"), item("-", "A")};
  const evaluation::Retrieval_scores alone = evaluation::evaluate_retrieval(Eigen::MatrixXd::Ones(3, 3), one_body);
  CHECK(alone.queries == 0);
  CHECK(alone.queries_without_candidate == 2);
  CHECK_FALSE(alone.nn_accuracy);
  CHECK(alone.per_query.empty());  // queries without candidate are not listed

  // A walk against a distractor only: a query, no relevant candidate, no same-motion pair.
  const std::vector<evaluation::Labelled_item> against_distractor{item("walk", "A"), item("-", "B")};
  const evaluation::Retrieval_scores d =
      evaluation::evaluate_retrieval(Eigen::MatrixXd::Ones(2, 2), against_distractor);
  CHECK(d.queries == 1);
  CHECK(d.queries_without_relevant == 1);
  CHECK(*d.nn_accuracy == 0);
  CHECK_FALSE(d.mean_average_precision);
  CHECK_FALSE(d.roc_auc);
  CHECK(*d.median_different == 1);
}

TEST_CASE("evaluate_retrieval: ties go to the lower index, and count 1/2 in ROC-AUC", "[evaluation]") {
  const std::vector<evaluation::Labelled_item> items{item("a", "Q"), item("b", "X"), item("a", "Y")};
  // Query 0: 1 (b) and 2 (a) tie: 1 first, NN wrong, AP 1/2; AUC over same .5, different .5: 1/2.
  Eigen::MatrixXd s = matrix({{1, .5, .5}, {0, 1, 0}, {0, 0, 1}});
  const evaluation::Retrieval_scores r = evaluation::evaluate_retrieval(s, items);
  // Query 1 (b): candidates 0 and 2, both a; query 2 (a): 0 (0, a) before 1 (0, b): right.
  CHECK(r.confusion == std::vector<std::vector<std::size_t>>{{1, 1}, {1, 0}});  // labels a, b
  CHECK(r.per_motion[0].correct == 1);
  CHECK(r.per_motion[0].queries == 2);
  CHECK(*r.nn_accuracy == Approx(1.0 / 3));
  // Same pairs (0,2) .5, (2,0) 0; different (0,1) .5, (1,0) 0, (1,2) 0, (2,1) 0.
  // .5 beats three 0s and ties one .5: 3.5; 0 ties three 0s: 1.5; 5 of 8.
  CHECK(*r.roc_auc == 5.0 / 8);
}

TEST_CASE("evaluate_retrieval: ROC-AUC equals the count over all (same, different) pairs", "[evaluation]") {
  std::mt19937 random(7);
  const std::vector<std::string> motions{"a", "b", "c", "-"}, bodies{"P", "Q", "R"}, clips{"x", "y"},
      rigs{"", "k"};
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 6 + std::size_t(trial);
    std::vector<evaluation::Labelled_item> items;
    for (std::size_t i = 0; i < n; ++i)
      items.push_back(item(motions[random() % 4], bodies[random() % 3], rigs[random() % 2], clips[random() % 2]));
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
    for (Eigen::Index i = 0; i < s.rows(); ++i)
      for (Eigen::Index j = 0; j < s.cols(); ++j) s(i, j) = double(random() % 5) / 4;  // many ties
    std::vector<double> same, different;
    for (std::size_t q = 0; q < n; ++q)
      for (std::size_t c = 0; c < n; ++c) {
        const auto &a = items[q], &b = items[c];
        const bool same_clip_same_rig = !a.rig.empty() && a.rig == b.rig && a.clip == b.clip;
        if (a.motion == "-" || c == q || a.body == b.body || same_clip_same_rig) continue;
        (a.motion == b.motion ? same : different).push_back(s(Eigen::Index(q), Eigen::Index(c)));
      }
    double wins = 0;
    for (const double x : same)
      for (const double y : different) wins += x > y ? 1 : x == y ? 0.5 : 0;
    const evaluation::Retrieval_scores r = evaluation::evaluate_retrieval(s, items);
    CHECK(r.same_pairs == same.size());
    CHECK(r.different_pairs == different.size());
    if (same.empty() || different.empty()) CHECK_FALSE(r.roc_auc);
    else CHECK(*r.roc_auc == Approx(wins / (double(same.size()) * double(different.size()))));
  }
}

TEST_CASE("evaluate_retrieval: some items as queries are the whole evaluation's queries, against every candidate",
          "[evaluation]") {
  std::mt19937 random(11);
  const std::vector<std::string> motions{"a", "b", "c", "-"}, bodies{"P", "Q", "R"};
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 6 + std::size_t(trial);
    std::vector<evaluation::Labelled_item> items;
    for (std::size_t i = 0; i < n; ++i) items.push_back(item(motions[random() % 4], bodies[random() % 3]));
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
    for (Eigen::Index i = 0; i < s.rows(); ++i)
      for (Eigen::Index j = 0; j < s.cols(); ++j) s(i, j) = double(random() % 5) / 4;  // many ties
    std::vector<std::size_t> group;  // body P's items, as a group left out
    for (std::size_t i = 0; i < n; ++i)
      if (items[i].body == "P") group.push_back(i);
    const evaluation::Retrieval_scores whole = evaluation::evaluate_retrieval(s, items);
    const evaluation::Retrieval_scores part = evaluation::evaluate_retrieval(s, items, group);
    std::vector<evaluation::Query_retrieval> expected;
    for (const auto& q : whole.per_query)
      if (items[q.query].body == "P") expected.push_back(q);
    REQUIRE(part.per_query.size() == expected.size());
    CHECK(part.queries == expected.size());
    double correct = 0;
    std::vector<double> same, different;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      CHECK(part.per_query[k].query == expected[k].query);
      CHECK(part.per_query[k].nearest == expected[k].nearest);
      CHECK(part.per_query[k].first_relevant_rank == expected[k].first_relevant_rank);
      CHECK(part.per_query[k].average_precision == expected[k].average_precision);
      const std::size_t q = expected[k].query;
      correct += items[expected[k].nearest].motion == items[q].motion;
      for (std::size_t c = 0; c < n; ++c)
        if (items[c].body != "P")  // every candidate of a query of P
          (items[c].motion == items[q].motion ? same : different).push_back(s(Eigen::Index(q), Eigen::Index(c)));
    }
    if (expected.empty()) CHECK_FALSE(part.nn_accuracy);
    else CHECK(*part.nn_accuracy == Approx(correct / double(expected.size())));
    CHECK((part.same_pairs == same.size() && part.different_pairs == different.size()));
    CHECK(part.labels == whole.labels);
  }
  const std::vector<evaluation::Labelled_item> two{item("a", "P"), item("a", "Q")};
  const Eigen::MatrixXd s = Eigen::MatrixXd::Ones(2, 2);
  CHECK(evaluation::evaluate_retrieval(s, two, std::vector<std::size_t>{1}).queries == 1);
  CHECK_THROWS_AS(evaluation::evaluate_retrieval(s, two, std::vector<std::size_t>{2}), invalid_input);
  CHECK_THROWS_AS(evaluation::evaluate_retrieval(s, two, std::vector<std::size_t>{1, 0}), invalid_input);
}

TEST_CASE("evaluate_retrieval: a matrix of the wrong shape or with NaN is refused", "[evaluation]") {
  const std::vector<evaluation::Labelled_item> items{item("a", "X"), item("a", "Y")};
  CHECK_THROWS_WITH(evaluation::evaluate_retrieval(Eigen::MatrixXd::Ones(2, 3), items),
                    "evaluate_retrieval: the similarity matrix is 2 x 3 for 2 items");
  CHECK_THROWS_AS(evaluation::evaluate_retrieval(Eigen::MatrixXd::Ones(3, 3), items), invalid_input);
  Eigen::MatrixXd s = Eigen::MatrixXd::Ones(2, 2);
  s(1, 0) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(evaluation::evaluate_retrieval(s, items),
                    "evaluate_retrieval: entry (1, 0) of the similarity matrix is not finite");
}

TEST_CASE("read_motion_labels: columns by name, defaults, files relative to the CSV", "[evaluation]") {
  const auto path = test::write_file("labels/set/labels.csv",
                                     "# a comment\nfile, clip,motion,rig\r\nKnight.glb,Walking_A,walk,kaykit\r\n\n"
                                     "frames/horse,,gallop,\n");
  const auto rows = evaluation::read_motion_labels(path);
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].file == path.parent_path() / "Knight.glb");
  CHECK(rows[0].item.clip == "Walking_A");
  CHECK(rows[0].item.motion == "walk");
  CHECK(rows[0].item.rig == "kaykit");
  CHECK(rows[0].item.body == "Knight.glb");
  CHECK(rows[1].file == path.parent_path() / "frames/horse");
  CHECK(rows[1].item.clip.empty());
  CHECK(rows[1].item.rig.empty());

  const auto with_body = test::write_file("labels/body.csv", "body,motion,file,clip\nfox,-,/abs/Fox.glb,Survey\n");
  const auto b = evaluation::read_motion_labels(with_body);
  CHECK(b[0].item.body == "fox");
  CHECK(b[0].item.motion == "-");
  CHECK(b[0].file == "/abs/Fox.glb");
  CHECK(b[0].body_file.empty());

  // A clip library bound to bodies: each row's body file, relative to the CSV like its file.
  const auto bodies = test::write_file("labels/set/bodies.csv",
                                       "file,clip,motion,body_file\nclips/walk.glb,Walk,walk,avatars/A.glb\n"
                                       "clips/walk.glb,Run,run,/abs/B.fbx\nclips/idle.glb,,idle,\n");
  const auto r = evaluation::read_motion_labels(bodies);
  CHECK(r[0].body_file == bodies.parent_path() / "avatars/A.glb");
  CHECK(r[1].body_file == "/abs/B.fbx");
  CHECK(r[2].body_file.empty());
  CHECK(r[0].item.body == "avatars/A.glb");  // the body label: the body file's field, else the file's
  CHECK(r[2].item.body == "clips/idle.glb");
}

TEST_CASE("read_motion_labels: quoted fields as spreadsheets and R write them, after a byte order mark",
          "[evaluation]") {
  const auto path = test::write_file("labels/quoted.csv",
                                     "\xEF\xBB\xBF\"file\",\"clip\",\"motion\"\r\n"
                                     "\"Knight.glb\",\"Walk, then \"\"run\"\"\",\"walk\"\r\n"
                                     " \" spaced .glb\" , \"\" ,-\n"
                                     "a.glb,\"x\",\"\"\"\"\n");
  const auto rows = evaluation::read_motion_labels(path);
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].file == path.parent_path() / "Knight.glb");
  CHECK(rows[0].item.clip == "Walk, then \"run\"");
  CHECK(rows[0].item.motion == "walk");
  CHECK(rows[1].file == path.parent_path() / " spaced .glb");
  CHECK(rows[1].item.clip.empty());
  CHECK(rows[1].item.motion == "-");
  CHECK(rows[2].item.motion == "\"");
}

TEST_CASE("read_motion_labels: one clip on two bodies is two rows", "[evaluation]") {
  // A library of animation-only clips lists each clip once per body it plays on.
  const auto path = test::write_file("labels/bodies.csv",
                                     "file,clip,motion,body_file\nclips/walk.fbx,,walk,x_bot.fbx\n"
                                     "clips/walk.fbx,,walk,y_bot.fbx\nclips/walk.fbx,,walk,\n");
  const std::vector<evaluation::Labelled_clip> rows = evaluation::read_motion_labels(path);
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].file == rows[1].file);
  CHECK(rows[0].body_file == path.parent_path() / "x_bot.fbx");
  CHECK(rows[1].body_file == path.parent_path() / "y_bot.fbx");
  CHECK(rows[2].body_file.empty());
  CHECK(rows[1].item.body == "y_bot.fbx");
}

TEST_CASE("read_motion_labels: errors name the file and the line", "[evaluation]") {
  const auto fails = [](const std::string& name, const std::string& text, const std::string& message) {
    const auto path = test::write_file("labels/" + name, text);
    CHECK_THROWS_WITH(evaluation::read_motion_labels(path), path.string() + message);
  };
  fails("unknown.csv", "file,clip,motion,colour\n",
        ":1: unknown column 'colour': the header is file,clip,motion[,rig][,body][,body_file]");
  fails("no_motion.csv", "\nfile,clip\n",
        ":2: the header has no 'motion' column: it is file,clip,motion[,rig][,body][,body_file]");
  fails("twice.csv", "file,clip,motion,clip\n", ":1: column 'clip' appears twice");
  fails("fields.csv", "file,clip,motion\na.glb,x,walk\nb.glb,y\n", ":3: 2 fields where the header has 3");
  fails("empty_motion.csv", "file,clip,motion\na.glb,x,\n", ":2: the motion field is empty (a distractor is '-')");
  fails("empty_file.csv", "file,clip,motion\n,x,walk\n", ":2: the file field is empty");
  fails("repeated.csv", "file,clip,motion\na.glb,x,walk\na.glb,x,run\n", ":3: clip 'x' of a.glb is listed twice");
  fails("repeated_on_body.csv", "file,clip,motion,body_file\na.glb,x,walk,b.glb\na.glb,x,walk,\na.glb,x,run,b.glb\n",
        ":4: clip 'x' of a.glb on b.glb is listed twice");
  fails("no_rows.csv", "file,clip,motion\n", ": the labels file lists no animation");
  fails("open_quote.csv", "file,clip,motion\na.glb,\"x,walk\n",
        ":2: field 2 opens a quote that the line does not close");
  fails("after_quote.csv", "file,clip,motion\na.glb,\"x\"y,walk\n", ":2: field 2 has text after its closing quote");
  CHECK_THROWS_WITH(evaluation::read_motion_labels(test::scratch_dir() / "labels/missing.csv"),
                    Catch::Contains("missing.csv: cannot open the labels file"));
}

namespace {

std::vector<mesh::Surface_mesh_animation> some_tubes() {
  using test::right_angle, test::tube;
  return {tube({{5, {0.0}}, {10, {right_angle}}, {8, {}}}),
          tube({{5, {0.0}}, {10, {right_angle}}, {8, {}}}, {.radius = 0.15}),
          tube({{5, {0.0}}, {3, {right_angle}}, {12, {}}, {3, {0.0}}}), tube({{4, {0.0}}, {6, {-right_angle}}})};
}

}  // namespace

TEST_CASE("similarity_matrix: queries x database equals the pairwise calls, whatever the threads",
          "[evaluation][similarity]") {
  const auto tubes = some_tubes();
  const std::vector<mesh::Surface_mesh_animation> queries{tubes[0], tubes[3]}, database{tubes[1], tubes[2], tubes[0]};
  const similarity::Strain_distribution_similarity<> policy;
  const Eigen::MatrixXd m = similarity::similarity_matrix(queries, database, policy);
  REQUIRE(m.rows() == 2);
  REQUIRE(m.cols() == 3);
  for (Eigen::Index q = 0; q < 2; ++q)
    for (Eigen::Index d = 0; d < 3; ++d)
      CHECK(m(q, d) == similarity::motion_similarity(queries[std::size_t(q)], database[std::size_t(d)], policy).value);
  CHECK(m(0, 2) == Approx(1.0));  // tube 0 against itself
  const Eigen::MatrixXd one_thread = similarity::similarity_matrix(queries, database, policy, {}, 1);
  const Eigen::MatrixXd all_one_thread = similarity::similarity_matrix(tubes, policy, {}, 1);
  for (const int threads : {2, 7}) {
    CHECK(one_thread == similarity::similarity_matrix(queries, database, policy, {}, threads));
    CHECK(all_one_thread == similarity::similarity_matrix(tubes, policy, {}, threads));
  }
  CHECK_THROWS_WITH(similarity::similarity_matrix(tubes, policy, {}, -1),
                    "similarity_matrix: threads must be 0 (the default) to 1024, not -1");
  CHECK(similarity::similarity_matrix(std::vector<mesh::Surface_mesh_animation>{}, database, policy).size() == 0);
}

TEST_CASE("similarity_matrix: progress reports every step and can stop", "[evaluation][similarity]") {
  const auto tubes = some_tubes();
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  const auto record = [&](std::size_t done, std::size_t total) {
    calls.emplace_back(done, total);
    return true;
  };
  // 4 descriptions and 10 pairs (i <= j): one batch each (batches hold at least 16 steps).
  const Eigen::MatrixXd all =
      similarity::similarity_matrix(tubes, similarity::Strain_distribution_similarity<>{}, record);
  CHECK(calls == std::vector<std::pair<std::size_t, std::size_t>>{{4, 14}, {14, 14}});
  CHECK(all == similarity::similarity_matrix(tubes, similarity::Strain_distribution_similarity<>{}));
  calls.clear();
  // 2 + 4 descriptions and 8 pairs: the queries', the database's, the pairs' batches.
  similarity::similarity_matrix(std::span(tubes).first(2), tubes, similarity::Strain_distribution_similarity<>{},
                                record);
  CHECK(calls == std::vector<std::pair<std::size_t, std::size_t>>{{2, 14}, {6, 14}, {14, 14}});
  std::size_t calls_before_stop = 0;
  CHECK_THROWS_MATCHES(similarity::similarity_matrix(tubes, similarity::Strain_distribution_similarity<>{},
                                    [&](std::size_t, std::size_t) { return ++calls_before_stop < 1; }),
                  cancelled, Catch::Message("the computation was stopped by its progress callback"));
  CHECK(calls_before_stop == 1);  // stopped after the descriptions, no pair compared
}

TEST_CASE("similarity_matrix: an animation the policy cannot describe is named, the first in index order",
          "[evaluation][similarity]") {
  auto tubes = some_tubes();
  const auto pose = test::frames_of(tubes[0], {3});  // one frame: no motion to describe
  tubes.insert(tubes.begin() + 2, pose);
  tubes.push_back(pose);  // at 2 and 5
  const auto refused = [](const auto& compute, std::size_t index, bool in_database) {
    try {
      compute();
      FAIL("no animation_not_described");
    } catch (const similarity::animation_not_described& e) {
      CHECK(e.index() == index);
      CHECK(e.in_database() == in_database);
      CHECK(std::string(e.what()) == (in_database ? "database animation " : "animation ") + std::to_string(index) +
                                         ": " + e.reason());
      CHECK_THAT(e.reason(), Catch::Contains("a motion needs at least 2"));
    }
  };
  refused([&] { similarity::similarity_matrix(tubes); }, 2, false);
  refused([&] { similarity::similarity_matrix(std::span(tubes).first(2), tubes); }, 2, true);
  refused([&] { similarity::similarity_matrix(std::span(tubes).last(2), tubes); }, 1, false);  // queries first
  tubes.erase(tubes.begin() + 2);
  tubes.pop_back();
  CHECK_NOTHROW(similarity::similarity_matrix(tubes));
}
