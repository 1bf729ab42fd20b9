// Tests of store/motion_store.h: round trips bit for bit, appends and replaces, lookups, refusals,
// every kind of damage named in its message, and appends killed with SIGKILL at several points.
#include "test_support.h"
#include "mesh_types.h"

#include <deformseg/mesh/synthetic.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/store/store_append.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <functional>
#include <optional>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using namespace deformseg;

// A clip of a deterministic pattern: its record, signatures (dimension-major), frames, summary.
struct Store_test_clip {
  store::Store_record record;
  std::vector<float> values;
  std::vector<std::uint32_t> frames;
  std::vector<float> summary;
  std::size_t width = 0;

  signatures::Motion_signature_view view() const { return {values.data(), frames.size(), width}; }
};

std::uint64_t store_test_mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Floats of every exponent and sign (all finite), so that any rounding on the way would show.
float store_test_float(std::uint64_t seed) {
  const std::uint64_t bits = store_test_mix(seed);
  return std::ldexp(static_cast<float>(bits & 0xFFFFFF) / float(1 << 24) - 0.5f, static_cast<int>((bits >> 32) % 40) - 20);
}

Store_test_clip store_test_clip(std::size_t seed, std::size_t width = 5, std::size_t summary_width = 3,
                                std::size_t variant = 0) {
  Store_test_clip c;
  c.width = width;
  const std::size_t rows = 1 + seed % 9;
  for (std::size_t k = 0; k < rows * width; ++k) c.values.push_back(store_test_float(seed * 100003 + k + variant * 7919));
  for (std::size_t r = 0; r < rows; ++r) c.frames.push_back(static_cast<std::uint32_t>(2 * r + seed % 3));
  for (std::size_t k = 0; k < summary_width; ++k) c.summary.push_back(store_test_float(seed * 31 + k + 1000000));
  store::Store_record& r = c.record;
  r.path = "/data/set " + std::to_string(seed / 3) + "/clip\xc3\xa9.glb";
  r.clip = seed % 3 == 0 ? "" : "Take " + std::to_string(seed);
  r.input_options = "weld=1;triangulate=0;fps=";
  r.source_size = 1000 + seed;
  r.source_mtime_ns = 1700000000000000000 + static_cast<std::int64_t>(seed) - static_cast<std::int64_t>(variant);
  r.source_hash = seed % 2 ? store_test_mix(seed) : 0;
  if (seed % 4 == 1) {
    r.topology_path = "/data/mesh.obj";
    r.topology_size = 77;
    r.topology_mtime_ns = -5;
  }
  r.frame_count = static_cast<std::uint32_t>(2 * rows + 3);
  r.fps = 30 + 0.5 * double(seed % 2);
  return c;
}

const char* const store_test_options = R"({"policy": "motion-signature", "lags": [0.1, 0.2], "floor": 3e-3, "up": null})";

std::size_t store_test_add(store::Store_append& append, const Store_test_clip& c) {
  return append.add(c.record, c.view(), c.frames, c.summary);
}

void store_test_write(const fs::path& folder, std::size_t first, std::size_t count) {
  store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
  for (std::size_t seed = first; seed < first + count; ++seed) store_test_add(append, store_test_clip(seed));
  append.commit();
}

// Checks that clip `i` of `store` is `c`, bit for bit, the block fields aside.
void store_test_check_clip(const store::Motion_store& store, std::size_t i, const Store_test_clip& c) {
  const signatures::Motion_signature_view v = store.view(i);
  REQUIRE(v.rows == c.frames.size());
  REQUIRE(v.width == c.width);
  CHECK(std::memcmp(v.values, c.values.data(), c.values.size() * sizeof(float)) == 0);
  CHECK(reinterpret_cast<std::uintptr_t>(v.values) % 64 == 0);
  const auto frames = store.frames(i);
  CHECK(std::vector<std::uint32_t>(frames.begin(), frames.end()) == c.frames);
  const auto summary = store.summary(i);
  REQUIRE(summary.size() == c.summary.size());
  if (!summary.empty()) CHECK(std::memcmp(summary.data(), c.summary.data(), c.summary.size() * sizeof(float)) == 0);
  const store::Store_record r = store.record(i);
  CHECK(r.path == c.record.path);
  CHECK(r.clip == c.record.clip);
  CHECK(r.body == c.record.body);
  CHECK(r.input_options == c.record.input_options);
  CHECK(r.source_size == c.record.source_size);
  CHECK(r.source_mtime_ns == c.record.source_mtime_ns);
  CHECK(r.source_hash == c.record.source_hash);
  CHECK(r.topology_path == c.record.topology_path);
  CHECK(r.topology_size == c.record.topology_size);
  CHECK(r.topology_mtime_ns == c.record.topology_mtime_ns);
  CHECK(r.frame_count == c.record.frame_count);
  CHECK(std::memcmp(&r.fps, &c.record.fps, sizeof(double)) == 0);
  CHECK(r.rows == c.frames.size());
}

void store_test_check_seeds(const store::Motion_store& store, std::size_t count) {
  REQUIRE(store.size() == count);
  for (std::size_t i = 0; i < count; ++i) store_test_check_clip(store, i, store_test_clip(i));
}

std::string store_test_bytes(const fs::path& path) { return test::file_text(path); }

void store_test_put(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// Replaces `name`'s bytes and makes the manifest agree (its size, data checksum and own
// checksum), so that only what the new bytes say is wrong remains to be found.
void store_test_rewrite(const fs::path& folder, const std::string& name, const std::string& bytes, std::size_t header) {
  store_test_put(folder / name, bytes);
  std::string manifest = store_test_bytes(folder / "store.json");
  const std::size_t entry = manifest.find("\"name\": \"" + name + "\"");
  REQUIRE(entry != std::string::npos);
  const std::size_t end = manifest.find('}', entry);
  const std::string data = bytes.substr(std::min(header, bytes.size()));
  manifest.replace(entry, end - entry,
                   "\"name\": \"" + name + "\", \"bytes\": " + std::to_string(bytes.size()) + ", \"data_crc32\": " +
                       std::to_string(store::internal::crc32(data.data(), data.size())) + "\n  ");
  const std::size_t checksum = manifest.rfind("\"checksum\"");
  manifest = manifest.substr(0, checksum) + "\"checksum\": \"" + store::internal::checksum_text(manifest.substr(0, checksum)) + "\"}\n";
  store_test_put(folder / "store.json", manifest);
}

// The message of the invalid_input that opening `folder` throws ("" when it opens).
std::string store_test_open_error(const fs::path& folder, store::Verify verify = store::Verify::structure) {
  try {
    store::Motion_store::open(folder, verify);
  } catch (const invalid_input& e) {
    return e.what();
  }
  return "";
}

std::set<std::string> store_test_listing(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("crc32 is zlib's") {
  const std::string text = "123456789";
  CHECK(store::internal::crc32(text.data(), text.size()) == 0xCBF43926u);
  CHECK(store::internal::crc32(text.data() + 4, 5, store::internal::crc32(text.data(), 4)) == 0xCBF43926u);
  const std::string long_text(1000, 'a');
  CHECK(store::internal::crc32(long_text.data(), long_text.size()) == 0x9A38DA03u);  // Python: zlib.crc32(b"a" * 1000)
  CHECK(store::internal::crc32(nullptr, 0) == 0);
}

TEST_CASE("motion store: a round trip gives the same floats, frames, summaries and records") {
  const fs::path folder = test::fresh_dir("motion_store/round_trip") / "S";  // missing: created
  store_test_write(folder, 0, 40);
  for (const store::Verify verify : {store::Verify::structure, store::Verify::checksums}) {
    const store::Motion_store store = store::Motion_store::open(folder, verify);
    CHECK(store.generation() == 1);
    CHECK(store.width() == 5);
    CHECK(store.summary_width() == 3);
    CHECK(store.description() == R"({"policy":"motion-signature","lags":[0.1,0.2],"floor":0.003,"up":null})");
    CHECK(store.summary_layout() == R"({"fields":["lo","hi","mean"]})");
    store_test_check_seeds(store, 40);
  }
}

TEST_CASE("motion store: a second append adds at the end, a replace keeps the index") {
  const fs::path folder = test::fresh_dir("motion_store/appends");
  store_test_write(folder, 0, 10);
  store_test_write(folder, 10, 5);
  store::Motion_store store = store::Motion_store::open(folder, store::Verify::checksums);
  store_test_check_seeds(store, 15);
  CHECK(store.record(3).block.generation == 1);
  CHECK(store.record(12).block.generation == 2);

  const Store_test_clip changed = store_test_clip(3, 5, 3, 1);
  {
    store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
    append.replace(3, changed.record, changed.view(), changed.frames, changed.summary);
    CHECK(store_test_add(append, store_test_clip(15)) == 15);
    append.commit();
  }
  const store::Motion_store after = store::Motion_store::open(folder, store::Verify::checksums);
  REQUIRE(after.size() == 16);
  store_test_check_clip(after, 3, changed);
  CHECK(after.record(3).block.generation == 3);
  for (std::size_t i = 0; i < 16; ++i)
    if (i != 3) store_test_check_clip(after, i, store_test_clip(i));
  // The store opened before the append still reads its own clips (its mappings hold them).
  store_test_check_clip(store, 3, store_test_clip(3));

  SECTION("a replace names the same clip") {
    store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
    const Store_test_clip other = store_test_clip(4);
    CHECK_THROWS_WITH(append.replace(3, other.record, other.view(), other.frames, other.summary),
                      Catch::Contains("clip 3 (/data/set 1/clip\xc3\xa9.glb)") && Catch::Contains("another clip"));
    CHECK_THROWS_WITH(append.replace(16, other.record, other.view(), other.frames, other.summary),
                      Catch::Contains("cannot replace clip 16"));
    CHECK_THROWS_WITH(store_test_add(append, store_test_clip(4)), Catch::Contains("already holds this clip"));
  }
}

TEST_CASE("motion store: clips are found by path and clip") {
  const fs::path folder = test::fresh_dir("motion_store/find");
  store_test_write(folder, 0, 30);
  const store::Motion_store store = store::Motion_store::open(folder);
  for (std::size_t i = 0; i < 30; ++i) {
    const Store_test_clip c = store_test_clip(i);
    CHECK(store.find(c.record.path, c.record.clip) == i);
  }
  CHECK_FALSE(store.find("/data/set 0/clip\xc3\xa9.glb", "Take 3"));  // Take 3 is in set 1
  CHECK_FALSE(store.find("/nowhere", ""));
  CHECK_FALSE(store::Motion_store().find("/data", ""));
}

TEST_CASE("motion store: one clip on two bodies is two clips, each found by its body") {
  const fs::path folder = test::fresh_dir("motion_store/bodies");
  const auto on_body = [](std::size_t seed, const std::string& body) {
    Store_test_clip c = store_test_clip(seed);
    c.record.body = body;
    c.record.topology_path = body;  // the body file's staleness stamp
    return c;
  };
  const std::vector<std::string> bodies{"", "/data/x_bot.fbx", "/data/y b\xc3\xb6t.glb"};
  {
    store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
    for (const std::string& body : bodies) store_test_add(append, on_body(1, body));
    CHECK_THROWS_WITH(store_test_add(append, on_body(1, bodies[1])),
                      Catch::Contains("clip 3 (/data/set 0/clip\xc3\xa9.glb#Take 1 on /data/x_bot.fbx)") &&
                          Catch::Contains("already holds this clip"));
    append.commit();
  }
  const store::Motion_store store = store::Motion_store::open(folder, store::Verify::checksums);
  REQUIRE(store.size() == 3);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    store_test_check_clip(store, i, on_body(1, bodies[i]));
    CHECK(store.find("/data/set 0/clip\xc3\xa9.glb", "Take 1", bodies[i]) == i);
  }
  CHECK(store.find("/data/set 0/clip\xc3\xa9.glb", "Take 1") == 0);  // no body: the clip on its own
  CHECK_FALSE(store.find("/data/set 0/clip\xc3\xa9.glb", "Take 1", "/data/z_bot.fbx"));

  store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
  const Store_test_clip moved = on_body(1, bodies[2]);
  CHECK_THROWS_WITH(append.replace(1, moved.record, moved.view(), moved.frames, moved.summary),
                    Catch::Contains("clip 1 (/data/set 0/clip\xc3\xa9.glb#Take 1 on /data/x_bot.fbx): cannot be "
                                    "replaced by clip 1 (/data/set 0/clip\xc3\xa9.glb#Take 1 on /data/y b\xc3\xb6t.glb)"));
}

namespace {

// The store in `folder` (of one append) rewritten as version 1 of the format wrote it: 4 strings
// per clip (path, clip, input options, topology path), no body.
void store_test_as_version_1(const fs::path& folder) {
  namespace si = store::internal;
  const std::size_t clips = store::Motion_store::open(folder).size();
  const std::string table_name = "clips-000001.npy", strings_name = "strings-000001.npy";
  std::string table = store_test_bytes(folder / table_name);
  const std::string strings = store_test_bytes(folder / strings_name);
  const std::size_t table_header = table.size() - clips * si::clip_row_bytes;
  std::uint64_t string_bytes = 0;
  for (std::size_t i = 0; i < clips; ++i)
    string_bytes += si::decode_clip_row(table.data() + table_header + i * si::clip_row_bytes).strings_length;
  const std::size_t strings_header = strings.size() - string_bytes;
  std::string old_strings;
  for (std::size_t i = 0; i < clips; ++i) {
    char* at = table.data() + table_header + i * si::clip_row_bytes;
    si::Clip_row row = si::decode_clip_row(at);
    std::string_view text(strings.data() + strings_header + row.strings, row.strings_length);
    text.remove_suffix(text.size() - text.rfind('\0', text.size() - 2) - 1);  // the body and its NUL
    row.strings = old_strings.size();
    row.strings_length = static_cast<std::uint32_t>(text.size());
    old_strings.append(text);
    si::encode_clip_row(at, row);
  }
  const std::uint64_t shape[1] = {old_strings.size()};
  const std::string header = si::npy_header("'|u1'", shape);
  store_test_rewrite(folder, strings_name, header + old_strings, header.size());
  store_test_rewrite(folder, table_name, table, table_header);
  std::string manifest = store_test_bytes(folder / "store.json");
  manifest.replace(manifest.find("\"version\": 2"), 12, "\"version\": 1");
  const std::size_t checksum = manifest.rfind("\"checksum\"");
  const std::string covered = manifest.substr(0, checksum);
  store_test_put(folder / "store.json", covered + si::checksum_suffix(covered));
}

}  // namespace

TEST_CASE("motion store: a store of version 1 is read, a character file's topology its body, appended as version 2") {
  const fs::path folder = test::fresh_dir("motion_store/version_1");
  const auto clip = [](std::size_t seed, const std::string& path, const std::string& topology, bool body) {
    Store_test_clip c = store_test_clip(seed);
    c.record.path = path;
    c.record.topology_path = topology;
    if (body) c.record.body = topology;
    return c;
  };
  // Version 1 kept the body a character file's clip played on as its topology, the topology of a
  // point cache alike.
  const std::vector<Store_test_clip> clips{clip(1, "/data/walk.fbx", "/data/x_bot.fbx", true),
                                           clip(2, "/data/Walk.GLB", "", false),
                                           clip(3, "/data/tube.pc2", "/data/tube.obj", false)};
  {
    store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
    for (const Store_test_clip& c : clips) store_test_add(append, c);
    append.commit();
  }
  store_test_as_version_1(folder);
  const store::Motion_store old = store::Motion_store::open(folder, store::Verify::checksums);
  CHECK(old.version() == 1);
  REQUIRE(old.size() == 3);
  for (std::size_t i = 0; i < clips.size(); ++i) store_test_check_clip(old, i, clips[i]);
  CHECK(old.find("/data/walk.fbx", clips[0].record.clip, "/data/x_bot.fbx") == 0);

  store_test_write(folder, 10, 2);  // appends to it, as version 2
  const store::Motion_store upgraded = store::Motion_store::open(folder, store::Verify::checksums);
  CHECK(upgraded.version() == 2);
  REQUIRE(upgraded.size() == 5);
  for (std::size_t i = 0; i < clips.size(); ++i) store_test_check_clip(upgraded, i, clips[i]);
  store_test_check_clip(upgraded, 4, store_test_clip(11));
}

TEST_CASE("motion store: names of any bytes are kept escaped as UTF-8, and read back exactly") {
  CHECK(store::escaped_name("/data/caf\xE9.glb") == "/data/caf\\xE9.glb");  // Latin-1: the byte E9
  CHECK(store::escaped_name("/data/caf\xC3\xA9.glb") == "/data/caf\xC3\xA9.glb");  // UTF-8: kept
  CHECK(store::escaped_name("a\\b\\xE9") == "a\\\\b\\\\xE9");
  CHECK(store::escaped_name(std::string("\xC3\0\xFF", 3)) == std::string("\\xC3\0\\xFF", 9));
  CHECK(store::unescaped_name("\\x4g\\q\\") == "\\x4g\\q\\");  // other backslashes kept
  std::string bytes;
  for (std::size_t seed = 0; seed < 2000; ++seed) {
    bytes.push_back(static_cast<char>(store_test_mix(seed) % 7 == 0 ? '\\' : store_test_mix(seed) & 0xFF));
    const std::string text = store::escaped_name(bytes);
    CHECK(store::is_utf8(text));
    CHECK(store::unescaped_name(text) == bytes);
  }
  // A store keeps a clip of a Latin-1 name escaped, and finds it by that.
  const fs::path folder = test::fresh_dir("motion_store/names");
  Store_test_clip c = store_test_clip(1);
  c.record.path = store::escaped_name("/data/Kn\xE9ight.glb");
  c.record.clip = store::escaped_name("Gr\xFC\xDF");
  {
    store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
    store_test_add(append, c);
    Store_test_clip raw = store_test_clip(2);
    raw.record.path = "/data/Kn\xE9ight.glb";
    CHECK_THROWS_WITH(store_test_add(append, raw), Catch::Contains("a string that is not UTF-8"));
    append.commit();
  }
  const store::Motion_store store = store::Motion_store::open(folder);
  CHECK(store.find("/data/Kn\\xE9ight.glb", "Gr\\xFC\\xDF") == 0);
  CHECK(store::unescaped_name(store.record(0).path) == "/data/Kn\xE9ight.glb");
}

TEST_CASE("motion store: an append with other options is refused, naming the option") {
  const fs::path folder = test::fresh_dir("motion_store/options");
  store_test_write(folder, 0, 2);
  const std::string manifest = store_test_bytes(folder / "store.json");
  CHECK_THROWS_WITH(store::Store_append(folder, R"({"policy": "motion-signature", "lags": [0.1, 0.3], "floor": 0.003, "up": null})",
                                     3, R"({"fields": ["lo", "hi", "mean"]})"),
                    Catch::Contains("store.json") && Catch::Contains("\"lags\" is [0.1,0.2] in the store, [0.1,0.3]"));
  CHECK_THROWS_WITH(store::Store_append(folder, R"({"policy": "motion-signature", "lags": [0.1, 0.2], "up": null})", 3,
                                     R"({"fields": ["lo", "hi", "mean"]})"),
                    Catch::Contains("\"floor\" is 0.003 in the store, not given in this append"));
  CHECK_THROWS_WITH(store::Store_append(folder, store_test_options, 4, R"({"fields": ["lo", "hi", "mean"]})"),
                    Catch::Contains("summaries are of another layout"));
  CHECK_THROWS_WITH(store::Store_append(folder, "[1]", 3), Catch::Contains("must be a JSON object"));
  // Equal values written otherwise are the same options.
  store::Store_append same(folder, R"({"up": null, "floor": 0.003, "lags": [1e-1, 0.2], "policy": "motion-signature"})", 3,
                        R"({"fields": ["lo", "hi", "mean"]})");
  CHECK(store_test_bytes(folder / "store.json") == manifest);
}

TEST_CASE("motion store: an uncommitted append changes nothing") {
  const fs::path folder = test::fresh_dir("motion_store/uncommitted");
  store_test_write(folder, 0, 6);
  const std::set<std::string> files = store_test_listing(folder);
  const std::string manifest = store_test_bytes(folder / "store.json");
  {
    store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
    for (std::size_t seed = 6; seed < 20; ++seed) store_test_add(append, store_test_clip(seed));
    const Store_test_clip changed = store_test_clip(2, 5, 3, 1);
    append.replace(2, changed.record, changed.view(), changed.frames, changed.summary);
  }
  CHECK(store_test_listing(folder) == files);
  CHECK(store_test_bytes(folder / "store.json") == manifest);
  store_test_check_seeds(store::Motion_store::open(folder, store::Verify::checksums), 6);

  SECTION("a store never committed is no store") {
    const fs::path fresh = test::fresh_dir("motion_store/never_committed");
    { store::Store_append append(fresh, store_test_options, 3); store_test_add(append, store_test_clip(0)); }
    CHECK_THAT(store_test_open_error(fresh), Catch::Contains("not a motion store: the folder has no store.json"));
  }
}

TEST_CASE("motion store: an empty store, a summary of no float, one writer at a time") {
  const fs::path folder = test::fresh_dir("motion_store/empty");
  { store::Store_append append(folder, "{}", 0); append.commit(); }
  const store::Motion_store empty = store::Motion_store::open(folder, store::Verify::checksums);
  CHECK(empty.size() == 0);
  CHECK(empty.width() == 0);
  {
    store::Store_append append(folder, "{}", 0);
    CHECK_THROWS_WITH(store::Store_append(folder, "{}", 0), Catch::Contains("another append to this store is running") &&
                                                               Catch::Contains((folder / "lock").string()));
    store_test_add(append, store_test_clip(5, 64, 0));
    store_test_add(append, store_test_clip(6, 64, 0));
    const Store_test_clip narrow = store_test_clip(7, 4, 0);
    CHECK_THROWS_WITH(store_test_add(append, narrow), Catch::Contains("4 values per row, the store's 64"));
    append.commit();
  }
  const store::Motion_store store = store::Motion_store::open(folder, store::Verify::checksums);
  REQUIRE(store.size() == 2);
  store_test_check_clip(store, 1, store_test_clip(6, 64, 0));
  CHECK(store.summary(0).empty());

  SECTION("a folder holding other files is not made a store") {
    const fs::path other = test::fresh_dir("motion_store/other_files");
    test::write_file("motion_store/other_files/notes.txt", "mine");
    CHECK_THROWS_WITH(store::Store_append(other, "{}", 0), Catch::Contains("holds other files (notes.txt)"));
  }
}

TEST_CASE("motion store: a truncated or longer file is named") {
  const fs::path folder = test::fresh_dir("motion_store/truncated");
  store_test_write(folder, 0, 8);
  const fs::path signatures = folder / "signatures-000001.npy";
  const std::string bytes = store_test_bytes(signatures);
  store_test_put(signatures, bytes.substr(0, bytes.size() - 10));
  CHECK(store_test_open_error(folder) == signatures.string() + ": " + std::to_string(bytes.size() - 10) +
                                             " bytes, the manifest says " + std::to_string(bytes.size()) + ": truncated");
  store_test_put(signatures, bytes + "x");
  CHECK_THAT(store_test_open_error(folder), Catch::EndsWith("the manifest says " + std::to_string(bytes.size()) +
                                                            ": longer than written"));
  fs::remove(signatures);
  CHECK_THAT(store_test_open_error(folder),
             Catch::StartsWith(signatures.string() + ": cannot open: no such file, though the manifest lists it"));
  const std::string manifest = store_test_bytes(folder / "store.json");
  store_test_put(folder / "store.json", manifest.substr(0, manifest.size() / 2));
  CHECK_THAT(store_test_open_error(folder), Catch::StartsWith((folder / "store.json").string() + ": not valid JSON at byte"));
}

TEST_CASE("motion store: a flipped byte is caught, in the data with Verify::checksums") {
  const fs::path folder = test::fresh_dir("motion_store/flipped");
  store_test_write(folder, 0, 8);
  const auto flip = [&](const std::string& name, std::size_t from_end) {
    const std::string original = store_test_bytes(folder / name);
    std::string bytes = original;
    bytes[bytes.size() - from_end] ^= 0x10;
    store_test_put(folder / name, bytes);
    return original;
  };
  SECTION("the manifest, in a value the structure allows") {
    std::string manifest = store_test_bytes(folder / "store.json");
    const std::size_t at = manifest.find("0.003");
    manifest[at + 4] = '4';
    store_test_put(folder / "store.json", manifest);
    CHECK(store_test_open_error(folder) == (folder / "store.json").string() +
                                               ": its checksum does not match its contents: the manifest is corrupted");
  }
  SECTION("the clip table and the strings, always") {
    for (const std::string name : {"clips-000001.npy", "strings-000001.npy"}) {
      const std::string original = flip(name, 3);
      CHECK(store_test_open_error(folder) ==
            (folder / name).string() + ": its checksum does not match the manifest's: the file is corrupted");
      store_test_put(folder / name, original);
    }
    CHECK(store_test_open_error(folder).empty());
  }
  SECTION("a data file, with Verify::checksums") {
    for (const std::string name : {"signatures-000001.npy", "frames-000001.npy", "summaries-000001.npy"}) {
      const std::string original = flip(name, 2);
      CHECK(store_test_open_error(folder).empty());
      CHECK(store_test_open_error(folder, store::Verify::checksums) ==
            (folder / name).string() + ": its checksum does not match the manifest's: the file is corrupted");
      store_test_put(folder / name, original);
    }
  }
  SECTION("a block, its file's checksum made to agree") {
    std::string bytes = store_test_bytes(folder / "signatures-000001.npy");
    bytes[128] ^= 0x01;  // the first float of clip 0
    store_test_rewrite(folder, "signatures-000001.npy", bytes, 128);
    CHECK(store_test_open_error(folder).empty());
    CHECK(store_test_open_error(folder, store::Verify::checksums) ==
          (folder / "clips-000001.npy").string() + ": clip 0 (/data/set 0/clip\xc3\xa9.glb): its block's checksum does not " +
              "match: its data in generation 1 is corrupted");
  }
}

TEST_CASE("motion store: a bad manifest, an unknown format and a newer version are named") {
  const fs::path folder = test::fresh_dir("motion_store/manifest");
  store_test_write(folder, 0, 3);
  const fs::path manifest_path = folder / "store.json";
  const std::string manifest = store_test_bytes(manifest_path);
  const auto with_checksum = [](std::string text) {
    const std::size_t checksum = text.rfind("\"checksum\"");
    return text.substr(0, checksum) + "\"checksum\": \"" + store::internal::checksum_text(text.substr(0, checksum)) + "\"}\n";
  };
  store_test_put(manifest_path, "{\"format\": \"deformseg-motion-store\", \"version\": 1,}");
  CHECK_THAT(store_test_open_error(folder),
             Catch::StartsWith(manifest_path.string() + ": not valid JSON at byte 50: syntax error while parsing "
                                                        "object key - unexpected '}'; expected string literal"));
  store_test_put(manifest_path, "{\"format\": \"something else\"}");
  CHECK(store_test_open_error(folder) ==
        manifest_path.string() + ": not a motion store: its manifest has no \"format\": \"deformseg-motion-store\"");
  std::string newer = manifest;
  newer.replace(newer.find("\"version\": 2"), 12, "\"version\": 3");
  store_test_put(manifest_path, with_checksum(newer));
  CHECK(store_test_open_error(folder) ==
        manifest_path.string() + ": store version 3 is newer than this deformseg, which reads version 2");
  std::string lying = manifest;
  lying.replace(lying.find("\"clips\": 3"), 10, "\"clips\": 4");
  store_test_put(manifest_path, with_checksum(lying));
  CHECK(store_test_open_error(folder) == (folder / "clips-000001.npy").string() + ": it holds 3 clips, the manifest says 4");
  std::string unlisted = manifest;
  unlisted.replace(unlisted.find("frames-000001.npy"), 17, "../../etc/passwd");
  store_test_put(manifest_path, with_checksum(unlisted));
  CHECK_THAT(store_test_open_error(folder), Catch::Contains("the manifest lists \"../../etc/passwd\", which is not one"));
  CHECK_THAT(store_test_open_error(folder / "nothing"), Catch::EndsWith("nothing: not a motion store: no such folder"));
}

TEST_CASE("motion store: JSON nested too deep is refused, in the manifest and in the options") {
  const fs::path folder = test::fresh_dir("motion_store/nesting");
  const auto nested = [](std::size_t depth) {
    std::string json = "1";
    for (std::size_t k = depth; k > 0; --k) json = (k % 2 ? "{\"a\": " : "[") + json + (k % 2 ? "}" : "]");
    return json;
  };
  // Options of 63 levels, in a manifest of 64, are options like any others: written, read back, compared equal.
  {
    store::Store_append append(folder, nested(63), 0);
    append.add(store_test_clip(0).record, store_test_clip(0).view(), store_test_clip(0).frames, {});
    append.commit();
  }
  const std::string options = store::Motion_store::open(folder, store::Verify::checksums).description();
  CHECK(options == store::internal::json_text(nlohmann::ordered_json::parse(nested(63))));
  CHECK_NOTHROW(store::Store_append(folder, nested(63), 0));
  CHECK_THROWS_WITH(store::Store_append(folder, nested(64), 0),
                    Catch::StartsWith(folder.string() + ": not valid here: JSON nested more than 63 deep"));
  // The manifest's options nested 64 deep, the manifest 65, its checksum made to agree.
  const fs::path manifest_path = folder / "store.json";
  nlohmann::ordered_json manifest = nlohmann::ordered_json::parse(store_test_bytes(manifest_path));
  manifest.erase("checksum");
  manifest["description"] = nlohmann::ordered_json::parse(nested(64));
  store_test_put(manifest_path, store::internal::with_checksum(manifest));
  CHECK(store_test_open_error(folder) == manifest_path.string() + ": not valid here: JSON nested more than 64 deep");
  // A manifest of the most bytes a manifest may have, every one of them an opening bracket: refused
  // at the 65th, without recursing.
  store_test_put(manifest_path, std::string(store::internal::max_manifest_bytes, '['));
  CHECK(store_test_open_error(folder) == manifest_path.string() + ": not valid here: JSON nested more than 64 deep");
}

TEST_CASE("motion store: the checksum in another form, and a number no double holds, are refused") {
  const fs::path folder = test::fresh_dir("motion_store/json_forms");
  store_test_write(folder, 0, 1);
  const fs::path manifest_path = folder / "store.json";
  const std::string manifest = store_test_bytes(manifest_path);
  // Valid JSON, the right CRC-32, but not the checksum's one form (no space after the colon).
  const std::size_t at = manifest.rfind("\"checksum\"");
  store_test_put(manifest_path, manifest.substr(0, at) + "\"checksum\":\"" +
                                    store::internal::checksum_text(manifest.substr(0, at)) + "\"}\n");
  CHECK(store_test_open_error(folder) ==
        manifest_path.string() + ": its checksum does not match its contents: the manifest is corrupted");
  store_test_put(manifest_path, manifest);
  CHECK(store_test_open_error(folder).empty());
  CHECK_THROWS_WITH(store::Store_append(folder, R"({"floor": 1e400})", 3),
                    Catch::StartsWith(folder.string() + ": not valid JSON: number overflow parsing '1e400'"));
}

TEST_CASE("motion store: a .npy header that does not match is named") {
  const fs::path folder = test::fresh_dir("motion_store/headers");
  store_test_write(folder, 0, 3);
  const std::string name = "frames-000001.npy";
  const std::string original = store_test_bytes(folder / name);
  const auto with_header = [&](const std::string& dict) {
    std::string header = dict;
    header.append(128 - 10 - header.size() - 1, ' ').push_back('\n');
    std::string bytes = original.substr(0, 8) + char(118) + char(0) + header + original.substr(128);
    store_test_rewrite(folder, name, bytes, 128);
    return store_test_open_error(folder);
  };
  const std::string rows = std::to_string((original.size() - 128) / 4);
  CHECK(with_header("{'descr': '<u4', 'fortran_order': False, 'shape': (" + rows + ",), }").empty());
  CHECK(with_header("{'descr': '<f4', 'fortran_order': False, 'shape': (" + rows + ",), }") ==
        (folder / name).string() + ": its dtype is '<f4', not '<u4'");
  CHECK(with_header("{'descr': '<u4', 'fortran_order': False, 'shape': (7,), }") ==
        (folder / name).string() + ": its shape (7,) does not match its " + std::to_string(original.size() - 128) +
            " bytes of data");
  CHECK(with_header("{'descr': '<u4', 'fortran_order': True, 'shape': (" + rows + ",), }") ==
        (folder / name).string() + ": its array is in Fortran order; the store's arrays are in C order");
  CHECK_THAT(with_header("{'descr': '<u4', 'shape': (" + rows + ",), }"),
             Catch::Contains("'descr', 'fortran_order' and 'shape' are not all given"));
  CHECK_THAT(with_header("{'descr': '<u4', 'fortran_order': False, 'shape': (" + rows + ", 1), }"),
             Catch::Contains("its array has 2 dimensions, not 1"));
  std::string not_npy = original;
  not_npy[1] = 'X';
  store_test_rewrite(folder, name, not_npy, 128);
  CHECK_THAT(store_test_open_error(folder), Catch::Contains("not a .npy file"));
}

TEST_CASE("motion store: an out-of-range record is named with its clip") {
  const fs::path folder = test::fresh_dir("motion_store/records");
  store_test_write(folder, 0, 4);
  const std::string name = "clips-000001.npy";
  const std::string original = store_test_bytes(folder / name);
  const std::size_t header = original.size() - 4 * store::internal::clip_row_bytes;
  const std::string clip2 = (folder / name).string() + ": clip 2 (/data/set 0/clip\xc3\xa9.glb#Take 2)";
  const auto with_row = [&](auto change) {
    store::internal::Clip_row row = store::internal::decode_clip_row(original.data() + header + 2 * store::internal::clip_row_bytes);
    change(row);
    std::string bytes = original;
    store::internal::encode_clip_row(bytes.data() + header + 2 * store::internal::clip_row_bytes, row);
    store_test_rewrite(folder, name, bytes, header);
    return store_test_open_error(folder);
  };
  const std::uint64_t floats = (fs::file_size(folder / "signatures-000001.npy") - 128) / 4;
  const std::uint64_t last_block = (floats + 15) / 16 * 16;  // aligned, at or past the end
  CHECK(with_row([&](store::internal::Clip_row& r) { r.numbers.block.offset = last_block; }) ==
        clip2 + ": 3 rows of 5 floats at float " + std::to_string(last_block) + " run past the end of " +
            (folder / "signatures-000001.npy").string());
  CHECK_THAT(with_row([](store::internal::Clip_row& r) { r.numbers.block.offset = 3; }), Catch::Contains("is not 64-byte aligned"));
  CHECK(with_row([](store::internal::Clip_row& r) { r.numbers.rows = 0; }) == clip2 + ": 0 rows; a clip has at least one");
  CHECK(with_row([](store::internal::Clip_row& r) { r.numbers.fps = -30; }) == clip2 + ": its fps is not positive and finite");
  CHECK_THAT(with_row([](store::internal::Clip_row& r) { r.numbers.block.frames_offset = 1u << 31; }),
             Catch::Contains("3 frame numbers at 2147483648 run past the end of"));
  CHECK_THAT(with_row([](store::internal::Clip_row& r) { r.numbers.block.summary_row = 4; }),
             Catch::Contains("its summary row 4 would run past the end of"));
  CHECK_THAT(with_row([](store::internal::Clip_row& r) { r.numbers.block.generation = 9; }),
             Catch::Contains("its generation 9 is not among the store's segments"));
  CHECK_THAT(with_row([](store::internal::Clip_row& r) { r.strings += 1u << 20; }),
             Catch::Contains("clip 2: its strings at byte") && Catch::Contains("run past the end of"));
  CHECK_THAT(with_row([](store::internal::Clip_row& r) { r.strings_length -= 1; }),
             Catch::Contains("clip 2: its strings are not 5 NUL-terminated strings"));
  const store::internal::Clip_row clip0 = store::internal::decode_clip_row(original.data() + header);
  CHECK(with_row([&](store::internal::Clip_row& r) {  // clip 0's strings: the same clip twice
          r.strings = clip0.strings;
          r.strings_length = clip0.strings_length;
        }) == (folder / name).string() + ": clip 2 (/data/set 0/clip\xc3\xa9.glb): the same clip as clip 0");
}

TEST_CASE("motion store: an append killed at any point leaves the store as it was") {
  const fs::path folder = test::fresh_dir("motion_store/killed");
  store_test_write(folder, 0, 5);
  const std::string manifest = store_test_bytes(folder / "store.json");
  constexpr std::size_t before = 5, appended = 150;

  // The child appends `appended` clips, writing a byte into the pipe after each one and before its
  // commit; the parent kills it after `signals` bytes. With `wait_after` the child then stops
  // (reading a pipe nobody writes), so that the kill lands at that point; otherwise it goes on, and
  // the kill lands wherever the child has got to.
  const auto killed_append = [&](std::size_t signals, bool wait_after) {
    int report[2], never[2];
    REQUIRE(::pipe(report) == 0);
    REQUIRE(::pipe(never) == 0);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      ::close(report[0]);
      try {
        store::Store_append append(folder, store_test_options, 3, R"({"fields": ["lo", "hi", "mean"]})");
        for (std::size_t seed = before; seed < before + appended; ++seed) {
          store_test_add(append, store_test_clip(seed, 5, 3));
          (void)!::write(report[1], "a", 1);
          char c;
          if (seed - before + 1 == signals && wait_after) (void)!::read(never[0], &c, 1);
        }
        (void)!::write(report[1], "c", 1);
        append.commit();
      } catch (...) {
        ::_exit(2);
      }
      ::_exit(0);
    }
    ::close(report[1]);
    for (std::size_t k = 0; k < signals; ++k) {
      char c;
      REQUIRE(::read(report[0], &c, 1) == 1);
    }
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ::close(report[0]);
    ::close(never[0]);
    ::close(never[1]);
    return status;
  };

  // Kills at fixed points: the store is as it was, the data files half written beside it.
  for (const std::size_t signals : {1, 40, 150}) {
    const int status = killed_append(signals, true);
    CHECK((WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL));
    CHECK(store_test_bytes(folder / "store.json") == manifest);
    store_test_check_seeds(store::Motion_store::open(folder, store::Verify::checksums), before);
  }
  bool orphans = false;
  for (const std::string& name : store_test_listing(folder)) orphans |= name.find(".partial-") != std::string::npos;
  CHECK(orphans);

  // Kills wherever the child has got to, the commit included: the store is as before or as after.
  for (const std::size_t signals : {1, 75, 151}) {
    killed_append(signals, false);
    const store::Motion_store store = store::Motion_store::open(folder, store::Verify::checksums);
    INFO("killed after " << signals << " signals: the store holds " << store.size() << " clips");
    CHECK((store.size() == before || store.size() == before + appended));
    store_test_check_seeds(store, store.size());
    if (store.size() != before) break;  // committed before the kill: the next kill would start from there
  }

  // The next append succeeds and removes what the killed ones left.
  const std::size_t held = store::Motion_store::open(folder).size();
  store_test_write(folder, held, 1);
  const store::Motion_store store = store::Motion_store::open(folder, store::Verify::checksums);
  store_test_check_seeds(store, held + 1);
  const std::string listed = store_test_bytes(folder / "store.json");
  for (const std::string& name : store_test_listing(folder)) {
    INFO(name);
    CHECK(name.find(".partial-") == std::string::npos);
    // Beside the manifest's files: the lock, and the previous generation's tables (for readers).
    const bool previous_table = name == store::internal::store_file_name("clips", store.generation() - 1) ||
                                name == store::internal::store_file_name("strings", store.generation() - 1);
    CHECK((name == "store.json" || name == "lock" || previous_table || listed.find('"' + name + '"') != std::string::npos));
  }
}

TEST_CASE("motion store: any one flipped byte of any file is caught with Verify::checksums") {
  const fs::path folder = test::fresh_dir("motion_store/every_byte");
  store_test_write(folder, 0, 3);
  for (const std::string name : {"store.json", "clips-000001.npy", "strings-000001.npy", "signatures-000001.npy",
                                 "frames-000001.npy", "summaries-000001.npy"}) {
    const std::string original = store_test_bytes(folder / name);
    std::size_t caught = 0;
    for (std::size_t at = 0; at < original.size(); ++at) {
      std::string bytes = original;
      bytes[at] ^= 0x10;
      store_test_put(folder / name, bytes);
      const std::string error = store_test_open_error(folder, store::Verify::checksums);
      INFO(name << ", byte " << at << ": " << error);
      CHECK_THAT(error, Catch::StartsWith(folder.string()));
      caught += !error.empty();
    }
    CHECK(caught == original.size());
    // The manifest and the tables are checked without Verify::checksums too.
    if (name == "store.json" || name.starts_with("clips-") || name.starts_with("strings-")) {
      std::string bytes = original;
      bytes[bytes.size() / 2] ^= 0x10;
      store_test_put(folder / name, bytes);
      CHECK_FALSE(store_test_open_error(folder).empty());
    }
    store_test_put(folder / name, original);
  }
  CHECK(store_test_open_error(folder, store::Verify::checksums).empty());
}

// ---- Describing into a store, on every mesh type ----------------------------------------------
namespace described_store {

// Describes the animations `animations` (motion signatures, summaries of 4 chunks) into a new store
// in `folder`, one clip each, as a describing tool does, and opens it.
template <class Animations>
store::Motion_store describe_into(const fs::path& folder, const Animations& animations) {
  const similarity::Motion_signature_similarity<> policy;
  constexpr std::size_t chunks = 4;
  std::optional<store::Store_append> append;
  for (std::size_t i = 0; i < animations.size(); ++i) {
    const auto& animation = animations[i].get();
    const similarity::Motion_signature_description description = policy.describe(animation);
    const signatures::Motion_signature_view view = similarity::view(description);
    if (!append) append.emplace(folder, R"({"policy": "motion-signature"})", search::summary_width(view.width, chunks));
    const search::Motion_summary summary = search::summarize(view, chunks);
    const std::vector<std::uint32_t> frames(description.frames.begin(), description.frames.end());
    store::Store_record record;
    record.path = "clip" + std::to_string(i);
    record.frame_count = std::uint32_t(animation.num_frames());
    record.fps = mesh::frames_per_second(animation);
    append->add(record, view, frames, summary.floats);
  }
  append->commit();
  return store::Motion_store::open(folder, store::Verify::checksums);
}

// Clip i of `a` and of `b` alike to the last bit: rows, frames and summary.
bool same_clip(const store::Motion_store& a, const store::Motion_store& b, std::size_t i) {
  const auto x = a.view(i), y = b.view(i);
  return x.rows == y.rows && x.width == y.width && std::equal(x.values, x.values + x.rows * x.width, y.values) &&
         std::ranges::equal(a.frames(i), b.frames(i)) && std::ranges::equal(a.summary(i), b.summary(i)) &&
         a.record(i).frame_count == b.record(i).frame_count && a.record(i).fps == b.record(i).fps;
}

}  // namespace described_store

TEMPLATE_LIST_TEST_CASE("motion store: every mesh type describes into the default model's store, to the last bit",
                        "[motion_store][mesh_types]", test::Mesh_types) {
  using namespace described_store;
  const mesh::Tube_shape small{.sectors = 8, .rings = 24};
  mesh::Bending_tube spec;
  spec.shape = small;
  spec.schedule = {{4, {0.0}}, {8, {test::right_angle}}, {6, {}}, {8, {0.0}}};
  const auto bend = mesh::make_bending_tube(spec).animation;
  spec.schedule = {{3, {test::right_angle / 2}}, {3, {0.0}}, {3, {test::right_angle / 2}}, {3, {0.0}}};
  const auto wave = mesh::make_bending_tube(spec).animation;
  const TestType on_bend(bend), on_wave(wave);
  const auto& bend_model = on_bend.model();
  const auto& wave_model = on_wave.model();

  const fs::path dir = test::fresh_dir("motion_store/mesh_types");
  const store::Motion_store expected = describe_into(dir / "default", std::array{std::cref(bend), std::cref(wave)});
  const store::Motion_store stored = describe_into(dir / "model", std::array{std::cref(bend_model), std::cref(wave_model)});
  REQUIRE(stored.size() == 2);
  REQUIRE(expected.size() == 2);
  CHECK(same_clip(stored, expected, 0));
  CHECK(same_clip(stored, expected, 1));
}
