// Tests of similarity/significance.h with the motion signatures: the shuffled copies scored from
// their alignments' scores and lengths (no path) give the full alignments' values bit for bit, for
// each alignment policy, on quantised signatures (equal dissimilarities everywhere, so ties); no
// path is traced for a copy; the z-score equals a reference that compares each copy in turn, and
// does not depend on the number of threads.
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/random.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/significance.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numeric>
#include <random>
#include <span>
#include <vector>

// In a namespace of their own, test cases too: the unity build puts this file in one unit with
// others, whose helpers (in anonymous namespaces) would otherwise be ambiguous with these.
namespace significance_test {

namespace al = deformseg::alignment;
namespace sim = deformseg::similarity;
using Description = sim::Motion_signature_description;

bool identical(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

// `rows` signatures of `width` values, each 0, 1 or 2: few distinct rows, so many equal
// dissimilarities and tied paths.
Description quantised(std::size_t rows, std::size_t width, std::mt19937& random) {
  Description d;
  d.signatures.resize(Eigen::Index(rows), Eigen::Index(width));
  for (Eigen::Index k = 0; k < d.signatures.size(); ++k) d.signatures(k) = float(random() % 3);
  d.frames.resize(rows);
  std::iota(d.frames.begin(), d.frames.end(), std::size_t(0));
  return d;
}

// The z-score as the definition says, each shuffled copy compared whole, in turn.
template <class Policy>
double reference_significance(const Policy& policy, const Description& a, const Description& b, std::size_t copies,
                              std::mt19937& random) {
  const double value = policy.compare(a, b).value;
  std::vector<std::size_t> order(sim::frame_count(b));
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::vector<double> values;
  for (std::size_t c = 0; c < copies; ++c) {
    deformseg::internal::shuffle(order.begin(), order.end(), random);
    values.push_back(policy.compare(a, sim::reordered_frames(b, order)).value);
  }
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / double(copies);
  double square = 0;
  for (const double v : values) square += (v - mean) * (v - mean);
  const double deviation = std::sqrt(square / double(copies - 1));
  return deviation > 0 ? (value - mean) / deviation : 0.0;
}

// Each shuffled copy's value from reordering_comparison is, bit for bit, the normalization of the
// full alignment of the reordered dissimilarities, and compare's value; then the z-score is the
// reference's on 1 and 2 threads, with the same draws.
template <class Alignment>
void check_policy(const Alignment& alignment, int seed) {
  const sim::Motion_signature_similarity<Alignment> policy{.scale = 1.5, .alignment = alignment};
  std::mt19937 random{unsigned(seed)};
  for (int trial = 0; trial < 12; ++trial) {
    const std::size_t width = 1 + random() % 6;
    const Description a = quantised(2 + random() % 30, width, random), b = quantised(2 + random() % 30, width, random);
    const std::size_t n = sim::frame_count(a), m = sim::frame_count(b);
    INFO("trial " << trial << ", " << n << " x " << m << ", width " << width);
    const auto comparison = policy.reordering_comparison(a, b);
    std::vector<std::size_t> order(m);
    std::iota(order.begin(), order.end(), std::size_t(0));
    for (int copy = 0; copy < 6; ++copy) {
      const Description shuffled = sim::reordered_frames(b, order);
      const Eigen::MatrixXd d = policy.frame_dissimilarities(a, shuffled);
      const double full = policy.normalization(alignment, alignment.align(n, m, al::matrix_dissimilarity(d)), n, m);
      CHECK(identical(comparison(order), full));
      CHECK(identical(comparison(order), policy.compare(a, shuffled).value));
      deformseg::internal::shuffle(order.begin(), order.end(), random);
    }
    const std::size_t copies = trial % 4 == 3 ? 70 : 20;  // 70: more than a batch of draws
    std::mt19937 one{unsigned(trial)}, two{unsigned(trial)}, reference{unsigned(trial)};
    const double z = sim::similarity_significance(policy, a, b, copies, one, 1);
    CHECK(identical(z, reference_significance(policy, a, b, copies, reference)));
    CHECK(identical(z, sim::similarity_significance(policy, a, b, copies, two, 2)));
    const auto next = reference();  // the same draws
    CHECK(one() == next);
    CHECK(two() == next);
  }
}

// Dtw counting its full alignments (paths) across copies of itself.
struct Path_counting_dtw : al::Dtw {
  std::shared_ptr<std::atomic<int>> paths = std::make_shared<std::atomic<int>>(0);
  template <al::Dissimilarity D>
  al::Alignment align(std::size_t n, std::size_t m, const D& d) const {
    ++*paths;
    return Dtw::align(n, m, d);
  }
};

// Best_score_normalization that takes whole alignments only.
struct Whole_alignment_normalization {
  double operator()(const Path_counting_dtw& p, const al::Alignment& a, std::size_t n, std::size_t m) const {
    return sim::Best_score_normalization{}(p, a, n, m);
  }
};

// Motion_signature_similarity seen through compare alone: similarity_significance compares each copy.
struct Compare_only {
  sim::Motion_signature_similarity<> policy;
  using Description = significance_test::Description;
  sim::Similarity compare(const Description& a, const Description& b) const { return policy.compare(a, b); }
};

static_assert(al::ScoreAndLengthPolicy<Path_counting_dtw>);

TEST_CASE("similarity_significance: each shuffled copy's value without a path is the full alignment's, Dtw",
          "[significance]") {
  check_policy(al::Dtw{}, 1);
  check_policy(al::Dtw{.window = 3}, 2);
  check_policy(al::Dtw{.max_trace_bytes = 0}, 3);  // full alignments in linear space
}

TEST_CASE("similarity_significance: each shuffled copy's value without a path is the full alignment's, "
          "Subsequence_dtw",
          "[significance]") {
  check_policy(al::Subsequence_dtw{}, 4);
  check_policy(al::Subsequence_dtw{.query = al::Subsequence_query::shorter}, 5);
}

TEST_CASE("similarity_significance: each shuffled copy's value without a path is the full alignment's, "
          "Smith_waterman",
          "[significance]") {
  check_policy(al::Smith_waterman{}, 6);
  check_policy(al::Smith_waterman{.mismatch = -0.5, .gap_open = 1, .gap_extend = 0.5}, 7);
  check_policy(al::Smith_waterman{.mismatch = 0, .gap_open = 0, .gap_extend = 0}, 8);
}

TEST_CASE("similarity_significance: the shuffled copies trace no path when the normalization takes a score and length",
          "[significance]") {
  std::mt19937 random(9);
  const Description a = quantised(40, 4, random), b = quantised(35, 4, random);
  const sim::Motion_signature_similarity<Path_counting_dtw> path_free;
  std::mt19937 first(3), second(3);
  const double z = sim::similarity_significance(path_free, a, b, 20, first, 2);
  CHECK(*path_free.alignment.paths == 1);  // compare's alone
  const sim::Motion_signature_similarity<Path_counting_dtw, Whole_alignment_normalization> whole;
  CHECK(identical(z, sim::similarity_significance(whole, a, b, 20, second, 2)));
  CHECK(*whole.alignment.paths == 21);
}

TEST_CASE("similarity_significance: the copies compared one by one give the same z-score on 1, 2 and 3 threads",
          "[significance]") {
  std::mt19937 random(10);
  const Description a = quantised(30, 5, random), b = quantised(25, 5, random);
  const Compare_only policy;
  std::mt19937 one(4), two(4), three(4), reference(4);
  const double z = sim::similarity_significance(policy, a, b, 67, one, 1);
  CHECK(identical(z, reference_significance(policy, a, b, 67, reference)));
  CHECK(identical(z, sim::similarity_significance(policy, a, b, 67, two, 2)));
  CHECK(identical(z, sim::similarity_significance(policy, a, b, 67, three, 3)));
  CHECK(one() == reference());
  CHECK_THROWS_AS(sim::similarity_significance(policy, a, b, 20, one, -1), deformseg::invalid_input);
}

}  // namespace significance_test
