// Tests of search/nearest_motions.h: the pruned search equals the brute-force ranking (the
// matrix row, stably sorted) on random collections with exact ties, for every k, on one and two
// threads; the k-nearest-neighbour graph equals the per-row brute force in the matrix's
// orientation, and each of its rows is nearest_others, the matrix's row less its diagonal; the
// collection's matrix equals compare's values; the bounds prune on real clips.
#include "test_support.h"

#include <deformseg/search/nearest_motions.h>
#include <deformseg/search/similarity_tile.h>
#include <deformseg/similarity/motion_similarity.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

using namespace deformseg;
using similarity::Motion_signature_description;
using search::Neighbour;

namespace {

// A random description of `rows` rows of `width` values around `centre`: rows drift like a motion.
Motion_signature_description random_clip(std::mt19937& random, std::size_t rows, std::size_t width, float centre) {
  std::normal_distribution<float> step(0.0f, 0.6f);
  Motion_signature_description d;
  d.signatures.resize(Eigen::Index(rows), Eigen::Index(width));
  for (std::size_t k = 0; k < width; ++k) {
    float x = centre + step(random);
    for (std::size_t r = 0; r < rows; ++r) d.signatures(Eigen::Index(r), Eigen::Index(k)) = x += step(random);
  }
  for (std::size_t r = 0; r < rows; ++r) d.frames.push_back(r);
  return d;
}

// Clips of 1 to 40 rows in a few families; every third is a copy of an earlier one, so that
// values tie exactly.
std::vector<Motion_signature_description> random_collection(std::uint32_t seed, std::size_t count, std::size_t width) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::size_t> rows(1, 40), family(0, 3);
  std::vector<Motion_signature_description> clips;
  for (std::size_t i = 0; i < count; ++i) {
    if (i % 3 == 2) {
      clips.push_back(clips[std::uniform_int_distribution<std::size_t>(0, i - 1)(random)]);
      continue;
    }
    clips.push_back(random_clip(random, rows(random), width, 1.5f * float(family(random))));
  }
  return clips;
}

// The brute force: every value by compare, oriented by `first`, stably sorted, cut at k.
template <class Value>
std::vector<Neighbour> brute_force(std::size_t count, std::size_t k, std::optional<std::size_t> self,
                                   const Value& value) {
  std::vector<Neighbour> all;
  for (std::size_t c = 0; c < count; ++c)
    if (c != self) all.push_back({c, value(c)});
  std::stable_sort(all.begin(), all.end(), [](const Neighbour& x, const Neighbour& y) { return x.value > y.value; });
  all.resize(std::min(k, all.size()));
  return all;
}

}  // namespace

TEST_CASE("nearest_motions equals the brute-force ranking, ties included, for every k and thread count") {
  const similarity::Default_similarity policy;
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    const auto clips = random_collection(seed, 60, seed % 2 ? 8 : 64);
    const search::Motion_collection collection(clips);
    std::mt19937 random(seed + 100);
    const auto query = random_clip(random, 1 + seed * 5, clips.front().signatures.cols(), 1.5f);
    for (std::size_t k : {std::size_t(0), std::size_t(1), std::size_t(10), clips.size(), clips.size() + 5}) {
      const auto expected = brute_force(clips.size(), k, std::nullopt,
                                        [&](std::size_t c) { return policy.compare(query, clips[c]).value; });
      const auto one = search::nearest_motions(similarity::view(query), collection, {.k = k, .threads = 1});
      const auto two = search::nearest_motions(similarity::view(query), collection, {.k = k, .threads = 2});
      INFO("seed " << seed << ", k " << k);
      CHECK(one.neighbours == expected);
      CHECK(two.neighbours == expected);
      CHECK(one.pruning == two.pruning);
      const auto& p = one.pruning;
      CHECK(p.candidates == clips.size());
      CHECK(p.pruned_by_summary + p.pruned_by_rows + p.abandoned + p.aligned == p.candidates);
    }
  }
}

TEST_CASE("nearest_motions finds a clip of the collection itself first, at value 1, and prunes the rest") {
  const auto clips = random_collection(7, 200, 64);
  const search::Motion_collection collection(clips);
  const auto found = search::nearest_motions(collection.view(4), collection, {.k = 1});
  REQUIRE(found.neighbours.size() == 1);
  CHECK(found.neighbours.front().index == 4);
  CHECK(found.neighbours.front().value == 1.0);
  // A copy of clip 4 elsewhere ties with it and ranks after it: not ruled out, so aligned.
  CHECK(found.pruning.aligned >= 1);
  CHECK(found.pruning.aligned < clips.size() / 2);
}

TEST_CASE("knn_graph equals the brute force in similarity_matrix's orientation, itself left out") {
  const similarity::Default_similarity policy;
  const auto clips = random_collection(11, 45, 16);
  const search::Motion_collection collection(clips);
  const auto value = [&](std::size_t i, std::size_t j) {
    return policy.compare(clips[std::min(i, j)], clips[std::max(i, j)]).value;
  };
  for (std::size_t k : {std::size_t(1), std::size_t(5), clips.size() + 1}) {
    const auto graph = search::knn_graph(collection, {.k = k, .threads = 2});
    const auto serial = search::knn_graph(collection, {.k = k, .threads = 1});
    REQUIRE(graph.size() == clips.size());
    for (std::size_t i = 0; i < clips.size(); ++i) {
      INFO("clip " << i << ", k " << k);
      CHECK(graph[i].neighbours == brute_force(clips.size(), k, i, [&](std::size_t c) { return value(i, c); }));
      CHECK(graph[i].pruning == serial[i].pruning);
      CHECK(graph[i].pruning.candidates == clips.size() - 1);
    }
  }
}

TEST_CASE("nearest_others is similarity_matrix's row i, stably sorted, itself left out, for i at the edges") {
  const auto clips = random_collection(13, 40, 8);
  const search::Motion_collection collection(clips);
  const Eigen::MatrixXd matrix = search::similarity_matrix(collection);
  const std::size_t n = clips.size();
  for (std::size_t i : {std::size_t(0), std::size_t(1), n / 2, n - 2, n - 1})
    for (std::size_t k : {std::size_t(0), std::size_t(1), std::size_t(7), n - 1, n, n + 3}) {
      INFO("clip " << i << ", k " << k);
      const auto expected =
          brute_force(n, k, i, [&](std::size_t c) { return matrix(Eigen::Index(i), Eigen::Index(c)); });
      const auto one = search::nearest_others(collection, i, {.k = k, .threads = 1});
      const auto two = search::nearest_others(collection, i, {.k = k, .threads = 2});
      CHECK(one.neighbours == expected);
      CHECK(two.neighbours == expected);
      CHECK(one.neighbours.size() == std::min(k, n - 1));
      CHECK(one.pruning == two.pruning);
      const auto& p = one.pruning;
      CHECK(p.candidates == n - 1);
      CHECK(p.pruned_by_summary + p.pruned_by_rows + p.abandoned + p.aligned == p.candidates);
    }
}

TEST_CASE("nearest_others and the row of knn_graph are one search: same neighbours, values and counts") {
  const auto clips = random_collection(17, 70, 16);
  const search::Motion_collection collection(clips);
  for (std::size_t k : {std::size_t(1), std::size_t(4), std::size_t(80)}) {
    const auto graph = search::knn_graph(collection, {.k = k, .threads = 2});
    for (std::size_t i = 0; i < clips.size(); ++i) {
      INFO("clip " << i << ", k " << k);
      const auto row = search::nearest_others(collection, i, {.k = k});
      CHECK(row.neighbours == graph[i].neighbours);
      CHECK(row.pruning == graph[i].pruning);
    }
  }
}

TEST_CASE("nearest_others of a collection of one clip finds nothing, and refuses a clip it does not hold") {
  const auto clips = random_collection(19, 1, 8);
  const search::Motion_collection collection(clips);
  const auto found = search::nearest_others(collection, 0, {.k = 3});
  CHECK(found.neighbours.empty());
  CHECK(found.pruning == search::Pruning_report{});
  CHECK_THROWS_WITH(search::nearest_others(collection, 1), Catch::Contains("no clip 1: the collection holds 1"));
  CHECK_THROWS_WITH(search::nearest_others(search::Motion_collection{}, 0), Catch::Contains("holds 0"));
  similarity::Default_similarity windowed;
  windowed.alignment.window = 3;
  CHECK_THROWS_WITH(search::nearest_others(collection, 0, {}, windowed), Catch::Contains("without a window"));
}

TEST_CASE("a collection's similarity_matrix is compare's values, bit for bit, in the matrix's orientation") {
  const similarity::Default_similarity policy;
  const auto clips = random_collection(3, 25, 64);
  const auto values = search::similarity_matrix(search::Motion_collection(clips));
  for (std::size_t i = 0; i < clips.size(); ++i)
    for (std::size_t j = i; j < clips.size(); ++j) {
      const double v = policy.compare(clips[i], clips[j]).value;
      CHECK(values(Eigen::Index(i), Eigen::Index(j)) == v);
      CHECK(values(Eigen::Index(j), Eigen::Index(i)) == v);
    }
}

TEST_CASE("nearest_motions refuses a query of another width, and a policy with a window") {
  const auto clips = random_collection(5, 10, 8);
  const search::Motion_collection collection(clips);
  std::mt19937 random(1);
  const auto wide = random_clip(random, 5, 16, 0);
  CHECK_THROWS_WITH(search::nearest_motions(similarity::view(wide), collection),
                    Catch::Contains("16 values, the collection's 8"));
  similarity::Default_similarity windowed;
  windowed.alignment.window = 3;
  CHECK_THROWS_WITH(search::nearest_motions(collection.view(0), collection, {}, windowed),
                    Catch::Contains("without a window"));
}

namespace {

// The blocks of `size` clips (the last one shorter) that cover n clips.
std::vector<search::Clip_range> blocks_of(std::size_t n, std::size_t size) {
  std::vector<search::Clip_range> blocks;
  for (std::size_t begin = 0; begin < n; begin += size) blocks.push_back({begin, std::min(n, begin + size)});
  return blocks;
}

}  // namespace

TEST_CASE("similarity_tile is the matrix's block, bit for bit, for tiles of 1, 3 and 7 clips, on and off the diagonal") {
  const auto clips = random_collection(23, 20, 16);
  const search::Motion_collection collection(clips);
  const Eigen::MatrixXd matrix = search::similarity_matrix(collection);
  for (std::size_t size : {std::size_t(1), std::size_t(3), std::size_t(7)})
    for (const auto rows : blocks_of(clips.size(), size))
      for (const auto columns : blocks_of(clips.size(), size)) {
        INFO("rows [" << rows.begin << ", " << rows.end << "), columns [" << columns.begin << ", " << columns.end << ")");
        const Eigen::MatrixXd tile = search::similarity_tile(collection, rows, columns, {}, {}, int(size % 2) + 1);
        CHECK(tile == matrix.block(rows.begin, columns.begin, rows.size(), columns.size()));
      }
  // Overlapping blocks: a pair with both entries in the tile is aligned once, and counted once.
  std::size_t steps = 0;
  const Eigen::MatrixXd tile = search::similarity_tile(collection, {2, 9}, {5, 12}, {},
                                                           [&](std::size_t done, std::size_t total) {
                                                             steps = total;
                                                             return done <= total;
                                                           });
  CHECK(tile == matrix.block(2, 5, 7, 7));
  CHECK(steps == 7 * 7 - 4 * 3 / 2);  // the 4 x 4 overlap [5, 9) has 6 pairs below its diagonal
  CHECK(search::similarity_tile(collection, {4, 4}, {0, 20}).size() == 0);
  CHECK_THROWS_WITH(search::similarity_tile(collection, {0, 21}, {0, 1}),
                    Catch::Contains("the rows [0, 21) are not clips of the collection, which holds 20"));
  CHECK_THROWS_WITH(search::similarity_tile(collection, {0, 1}, {3, 2}), Catch::Contains("the columns [3, 2)"));
}

TEST_CASE("searches among blocks of candidates, merged, equal the search among all: rows of 1, 3 and 7 clips") {
  const auto clips = random_collection(29, 30, 8);
  const search::Motion_collection collection(clips);
  const std::size_t n = clips.size();
  std::mt19937 random(31);
  const auto query = random_clip(random, 12, 8, 1.5f);
  for (std::size_t k : {std::size_t(1), std::size_t(4), n + 2}) {
    const auto whole = search::knn_graph(collection, {.k = k});
    const auto found = search::nearest_motions(similarity::view(query), collection, {.k = k});
    for (std::size_t size : {std::size_t(1), std::size_t(3), std::size_t(7)}) {
      INFO("k " << k << ", blocks of " << size);
      std::vector<search::Nearest_motions> query_parts;
      for (const auto candidates : blocks_of(n, size))
        query_parts.push_back(search::nearest_motions(similarity::view(query), collection,
                                                          {.k = k, .candidates = candidates}));
      const auto merged_query = search::merge_nearest(query_parts, k);
      CHECK(merged_query.neighbours == found.neighbours);
      CHECK(merged_query.pruning.candidates == n);
      for (const auto rows : blocks_of(n, size)) {
        const auto block = search::knn_graph(collection, rows, {.k = k, .threads = 2});
        REQUIRE(block.size() == rows.size());
        std::vector<std::vector<search::Nearest_motions>> parts;
        for (const auto candidates : blocks_of(n, size))
          parts.push_back(search::knn_graph(collection, rows, {.k = k, .candidates = candidates}));
        for (std::size_t r = 0; r < rows.size(); ++r) {
          const std::size_t i = rows.begin + r;
          CHECK(block[r].neighbours == whole[i].neighbours);
          CHECK(block[r].pruning == whole[i].pruning);
          std::vector<search::Nearest_motions> row;
          for (const auto& part : parts) row.push_back(part[r]);
          const auto merged = search::merge_nearest(row, k);
          CHECK(merged.neighbours == whole[i].neighbours);
          CHECK(merged.pruning.candidates == n - 1);
        }
      }
    }
  }
  CHECK_THROWS_WITH(search::knn_graph(collection, search::Clip_range{28, 31}),
                    Catch::Contains("knn_graph: the rows [28, 31)"));
  CHECK_THROWS_WITH(search::nearest_others(collection, 0, {.candidates = search::Clip_range{0, 40}}),
                    Catch::Contains("the candidates [0, 40)"));
}

TEST_CASE("merge_nearest ranks by value, then index, cuts at k and sums the counts") {
  using search::Nearest_motions;
  const Nearest_motions a{{{4, 0.9}, {7, 0.5}}, {.candidates = 3, .pruned_by_summary = 1, .aligned = 2}};
  const Nearest_motions b{{{2, 0.5}, {1, 0.2}}, {.candidates = 5, .pruned_by_rows = 3, .aligned = 2}};
  const std::vector<Nearest_motions> parts{a, b};
  const Nearest_motions merged = search::merge_nearest(parts, 3);
  CHECK(merged.neighbours == std::vector<Neighbour>{{4, 0.9}, {2, 0.5}, {7, 0.5}});
  CHECK(merged.pruning == search::Pruning_report{.candidates = 8, .pruned_by_summary = 1, .pruned_by_rows = 3,
                                                     .aligned = 4});
  CHECK(search::merge_nearest({}, 3).neighbours.empty());
}
