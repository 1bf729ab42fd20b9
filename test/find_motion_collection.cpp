// Tests of search/find_motion_in_collection.h: the windows over a collection equal find_motion_in
// run on each clip alone and merged (stably sorted by value, cut at the count), on one and two
// threads; a query cut from a clip finds that clip at the right frames (its stored frames), at 1;
// errors name what is wrong.
#include "test_support.h"

#include <deformseg/search/find_motion_in_collection.h>
#include <deformseg/similarity/motion_similarity.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

using namespace deformseg;
using similarity::Motion_signature_description;

namespace {

// A description of `rows` rows of `width` drifting values; row r is frame `stride` r.
Motion_signature_description drifting_clip(std::mt19937& random, std::size_t rows, std::size_t width,
                                           std::size_t stride) {
  std::normal_distribution<float> step(0.0f, 0.5f);
  Motion_signature_description d;
  d.signatures.resize(Eigen::Index(rows), Eigen::Index(width));
  for (std::size_t k = 0; k < width; ++k) {
    float x = step(random);
    for (std::size_t r = 0; r < rows; ++r) d.signatures(Eigen::Index(r), Eigen::Index(k)) = x += step(random);
  }
  for (std::size_t r = 0; r < rows; ++r) d.frames.push_back(stride * r);
  return d;
}

std::vector<Motion_signature_description> drifting_clips(std::uint32_t seed, std::size_t count) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::size_t> rows(3, 60);
  std::vector<Motion_signature_description> clips;
  for (std::size_t i = 0; i < count; ++i) clips.push_back(drifting_clip(random, rows(random), 8, 1 + i % 3));
  return clips;
}

bool same_match(const similarity::Motion_match& x, const similarity::Motion_match& y) {
  return x.first == y.first && x.last == y.last && x.value == y.value && x.alignment == y.alignment;
}

}  // namespace

TEST_CASE("find_motion_in_collection equals find_motion_in on each clip, merged, on any number of threads") {
  const similarity::Default_similarity policy;
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    const auto clips = drifting_clips(seed, 25);
    const search::Motion_collection collection(clips);
    std::mt19937 random(seed + 50);
    const auto query = drifting_clip(random, 4 + 6 * seed, 8, 1);
    for (std::size_t count : {std::size_t(1), std::size_t(3), std::size_t(200)})
      for (double shortest : {0.5, 1.0}) {
        INFO("seed " << seed << ", count " << count << ", shortest " << shortest);
        std::vector<search::Clip_match> expected;
        for (std::size_t i = 0; i < clips.size(); ++i)
          for (auto& m : similarity::find_motion_in(policy, query, clips[i], {.count = count, .shortest = shortest}))
            expected.push_back({i, m});
        std::stable_sort(expected.begin(), expected.end(),
                         [](const auto& x, const auto& y) { return x.match.value > y.match.value; });
        expected.resize(std::min(count, expected.size()));
        for (int threads : {1, 2}) {
          const auto found = search::find_motion_in_collection(
              query, collection, {.count = count, .shortest = shortest, .threads = threads});
          REQUIRE(found.size() == expected.size());
          for (std::size_t r = 0; r < found.size(); ++r) {
            CHECK(found[r].clip == expected[r].clip);
            CHECK(same_match(found[r].match, expected[r].match));
          }
        }
      }
  }
}

TEST_CASE("find_motion_in_collection finds a query cut from a clip in that clip, at its frames") {
  const auto clips = drifting_clips(9, 20);
  const search::Motion_collection collection(clips);
  const std::size_t first_row = 10, rows = 30;
  // The first clip long enough whose frames are not its rows.
  std::size_t source = 0;
  while (source < clips.size() &&
         (std::size_t(clips[source].signatures.rows()) < first_row + rows || source % 3 == 0))
    ++source;
  REQUIRE(source < clips.size());
  Motion_signature_description query;
  query.signatures = clips[source].signatures.middleRows(Eigen::Index(first_row), Eigen::Index(rows));
  query.frames.assign(clips[source].frames.begin() + std::ptrdiff_t(first_row),
                      clips[source].frames.begin() + std::ptrdiff_t(first_row + rows));
  const auto found = search::find_motion_in_collection(query, collection, {.count = 2});
  REQUIRE(found.size() == 2);
  CHECK(found[0].clip == source);
  CHECK(found[0].match.value == 1.0);
  // The clip's frames, not its rows: its row r is frame (1 + source % 3) r.
  CHECK(found[0].match.first == clips[source].frames[first_row]);
  CHECK(found[0].match.last == clips[source].frames[first_row + rows - 1]);
  CHECK(found[0].match.first == (1 + source % 3) * first_row);
  CHECK(found[0].match.alignment.front() == std::pair{found[0].match.first, found[0].match.first});
  CHECK(found[1].match.value < 1.0);
}

TEST_CASE("find_motion_in_collection: an empty collection finds nothing, and errors name what is wrong") {
  std::mt19937 random(3);
  const auto query = drifting_clip(random, 10, 8, 1);
  CHECK(search::find_motion_in_collection(query, search::Motion_collection{}).empty());
  const search::Motion_collection collection(drifting_clips(4, 3));
  CHECK_THROWS_WITH(search::find_motion_in_collection(drifting_clip(random, 10, 4, 1), collection),
                    Catch::Contains("4 values, the collection's 8"));
  CHECK_THROWS_WITH(search::find_motion_in_collection(query, collection, {.shortest = 0}),
                    Catch::Contains("shortest must be in (0, 1]"));
  CHECK_THROWS_WITH(search::find_motion_in_collection(Motion_signature_description{}, collection),
                    Catch::Contains("no signature"));
}
