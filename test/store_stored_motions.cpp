// Tests of store/stored_motions.h: a store searched in place gives what the same clips give in
// memory, bit for bit (search, knn graph, matrix); a store of other summaries is refused; a
// corrupted clip is refused when a search reads it.
#include "test_support.h"

#include <deformseg/search/nearest_motions.h>
#include <deformseg/search/similarity_tile.h>
#include <deformseg/store/store_append.h>
#include <deformseg/store/stored_motions.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace deformseg;

namespace {

// Clips of 1 to 30 rows of 16 values; clip 7 repeats clip 2, so that values tie.
std::vector<similarity::Motion_signature_description> clips() {
  std::mt19937 random(5);
  std::normal_distribution<float> value(0.0f, 1.0f);
  std::vector<similarity::Motion_signature_description> out;
  for (std::size_t c = 0; c < 20; ++c) {
    if (c == 7) {
      out.push_back(out[2]);
      continue;
    }
    similarity::Motion_signature_description d;
    d.signatures.resize(Eigen::Index(1 + (c * 7) % 30), 16);
    for (Eigen::Index i = 0; i < d.signatures.size(); ++i) d.signatures.data()[i] = value(random);
    for (Eigen::Index r = 0; r < d.signatures.rows(); ++r) d.frames.push_back(std::size_t(r));
    out.push_back(std::move(d));
  }
  return out;
}

void write(const std::filesystem::path& folder, const std::vector<similarity::Motion_signature_description>& all,
           std::size_t chunks, const std::string& layout) {
  store::Store_append append(folder, "{}", search::summary_width(16, chunks), layout);
  for (std::size_t c = 0; c < all.size(); ++c) {
    store::Store_record record;
    record.path = "/clips/" + std::to_string(c) + ".pc2";
    record.frame_count = std::uint32_t(all[c].frames.size());
    record.fps = 30;
    const std::vector<std::uint32_t> frames(all[c].frames.begin(), all[c].frames.end());
    const auto view = similarity::view(all[c]);
    append.add(record, view, frames, search::summarize(view, chunks).floats);
  }
  append.commit();
}

}  // namespace

TEST_CASE("a store searched in place equals its clips in memory, bit for bit") {
  const auto all = clips();
  const auto folder = test::fresh_dir("stored_motions/search");
  write(folder, all, 4, store::motion_summary_layout(4));
  const store::Stored_motions stored(store::Motion_store::open(folder));
  const search::Motion_collection in_memory(all);
  REQUIRE(stored.size() == all.size());
  for (std::size_t q : {std::size_t(0), std::size_t(2), std::size_t(19)}) {
    const auto a = search::nearest_motions(stored.view(q), stored, {.k = 5});
    const auto b = search::nearest_motions(in_memory.view(q), in_memory, {.k = 5});
    CHECK(a.neighbours == b.neighbours);
    CHECK(a.pruning == b.pruning);
  }
  const auto graph = search::knn_graph(stored, {.k = 3});
  const auto expected = search::knn_graph(in_memory, {.k = 3});
  for (std::size_t i = 0; i < all.size(); ++i) CHECK(graph[i].neighbours == expected[i].neighbours);
  CHECK(search::similarity_matrix(stored) == search::similarity_matrix(in_memory));
}

TEST_CASE("a store of other summaries is refused, naming its manifest") {
  const auto all = clips();
  const auto folder = test::fresh_dir("stored_motions/other");
  write(folder, all, 2, R"({"kind": "my-summary", "chunks": 2})");
  CHECK_THROWS_WITH(store::Stored_motions(store::Motion_store::open(folder)),
                    Catch::Contains("store.json") && Catch::Contains("not motion summaries"));
  const auto wrong_width = test::fresh_dir("stored_motions/width");
  write(wrong_width, all, 2, store::motion_summary_layout(3));
  CHECK_THROWS_WITH(store::Stored_motions(store::Motion_store::open(wrong_width)), Catch::Contains("with 3 chunks"));
  CHECK(store::Stored_motions(store::Motion_store{}).size() == 0);
}

TEST_CASE("a corrupted clip is refused, naming it, the first time a search reads it") {
  const auto all = clips();
  const auto folder = test::fresh_dir("stored_motions/corrupted");
  write(folder, all, 4, store::motion_summary_layout(4));
  const store::Motion_store opened = store::Motion_store::open(folder);
  // Flip a bit of clip 5's first value in the mapped file's bytes: the structure still holds.
  const std::filesystem::path signatures = folder / "signatures-000001.npy";
  std::string bytes = test::file_text(signatures);
  const std::size_t data = bytes.find('\n', 12) + 1;  // past the .npy header, which ends with a newline
  bytes[data + opened.record(5).block.offset * 4] ^= 0x01;
  std::ofstream(signatures, std::ios::binary) << bytes;

  const store::Stored_motions stored(store::Motion_store::open(folder));
  const std::string named = "clip 5 (/clips/5.pc2): its block's checksum does not match";
  CHECK_NOTHROW(stored.view(4));
  CHECK_THROWS_WITH(stored.view(5), Catch::Contains(named) && Catch::Contains("clips-000001.npy"));
  CHECK_THROWS_WITH(stored.view(5), Catch::Contains(named));  // again: it was not marked verified
  CHECK_THROWS_WITH(search::similarity_matrix(stored), Catch::Contains(named));
  CHECK_THROWS_WITH(search::nearest_motions(stored.view(0), stored, {.k = 19}), Catch::Contains(named));
  CHECK_THROWS_WITH(store::Motion_store::open(folder, store::Verify::checksums), Catch::Contains("corrupted"));
  CHECK_NOTHROW(opened.verify_clip(4));
  CHECK_THROWS_WITH(opened.verify_clip(5), Catch::Contains(named));
}
