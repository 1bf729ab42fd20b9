// Tests of the front end's parse cache (frontend/clip_cache.h), which `describe` and `evaluate`
// share: a character file parsed once serves all its clips, and is held only while they are read.
#include "../gltf_writer.h"

#include <frontend/clip_cache.h>

#include <deformseg/exceptions.h>
#include <deformseg/io/gltf.h>

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace {

namespace fs = std::filesystem;
using deformseg::frontend::Character_on_body;
using deformseg::frontend::Clip_cache;
using deformseg::frontend::Listed_parses;
using deformseg::test::Gltf_writer;
using json = nlohmann::json;

// A folder removed, with what the tests wrote into it, when the program ends.
struct Removed_at_exit {
  fs::path folder;
  ~Removed_at_exit() {
    std::error_code error;
    fs::remove_all(folder, error);
  }
};

// This process's folder for the files the tests write.
fs::path clip_cache_folder() {
  static const Removed_at_exit made{fs::temp_directory_path() / ("deformseg-clip-cache-" + std::to_string(::getpid()))};
  fs::create_directories(made.folder);
  return made.folder;
}

// A triangle moved by two clips, "right" and "up", of 1 s each, written as `name` (.gltf).
std::string two_clip_file(const std::string& name) {
  Gltf_writer w;
  const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  w.push("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", position}}}}})}});
  w.push("nodes", {{"name", "mover"}, {"mesh", 0}});
  w.push("scenes", {{"nodes", {0}}});
  const int times = w.floats({0, 1}, "SCALAR");
  for (const auto& [clip, end] : {std::pair{"right", std::vector<float>{0, 0, 0, 2, 0, 0}},
                                  std::pair{"up", std::vector<float>{0, 0, 0, 0, 2, 0}}}) {
    const int moves = w.floats(end, "VEC3");
    w.push("animations", {{"name", clip},
                          {"samplers", {{{"input", times}, {"output", moves}, {"interpolation", "LINEAR"}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}});
  }
  const fs::path path = clip_cache_folder() / name;
  w.write_gltf(path);
  return path.string();
}

}  // namespace

TEST_CASE("Clip_cache: a file parsed once serves all its clips, and is freed after the last", "[frontend]") {
  const Character_on_body first{two_clip_file("first.gltf")}, second{two_clip_file("second.gltf")};
  // Three clips of the first file, one of the second; a file that is not a character file is not counted.
  Clip_cache cache({first, first, second, first, {"frames/"}}, {});
  CHECK(cache.parses_held() == 0);
  const std::shared_ptr<const deformseg::io::Gltf_file> parsed = cache.acquire(first);
  CHECK(cache.acquire(first) == parsed);
  CHECK(cache.acquire(first) == parsed);
  CHECK(cache.connectivity(first) == cache.connectivity(first));
  CHECK(&cache.connectivity(first)->file() == parsed.get());
  CHECK(cache.parses_held() == 1);
  // Both clips read from the one parse, with the one repair.
  for (const char* clip : {"right", "up"})
    CHECK(parsed->read(cache.connectivity(first)->repaired(), {.clip = clip, .fps = 10}).num_frames() > 2);

  cache.release(first);
  cache.release(first);
  CHECK(cache.parses_held() == 1);  // a clip of it is still being read
  {
    const Clip_cache::Release released(cache, second);
    CHECK(cache.acquire(second) != parsed);
    CHECK(cache.parses_held() == 2);
  }
  CHECK(cache.parses_held() == 1);  // the second file's only clip read
  cache.release(first);
  CHECK(cache.parses_held() == 0);  // the memory held is the files whose clips are being read
  CHECK(parsed->clip_names() == std::vector<std::string>{"right", "up"});  // the holder's copy lives on
}

TEST_CASE("Clip_cache: a file that cannot be parsed fails each of its clips", "[frontend]") {
  const Character_on_body missing{(clip_cache_folder() / "missing.glb").string()};
  Clip_cache cache({missing, missing}, {});
  std::string first_error;
  try {
    cache.acquire(missing);
  } catch (const deformseg::invalid_input& e) {
    first_error = e.what();
  }
  CHECK(first_error.find("missing.glb") != std::string::npos);
  CHECK_THROWS_WITH(cache.acquire(missing), first_error);  // the same error, not parsed again
  CHECK(cache.parses_held() == 0);
}

TEST_CASE("Listed_parses: the files parsed to list their clips are kept within a budget, then adopted",
          "[frontend]") {
  const std::string first = two_clip_file("listed-first.gltf"), second = two_clip_file("listed-second.gltf");
  const std::uintmax_t size = fs::file_size(first);
  REQUIRE(fs::file_size(second) == size);
  Listed_parses listed(size + size / 2);  // room for one file of the two
  const std::shared_ptr<const deformseg::io::Gltf_file> kept = listed.parse(first, first);
  CHECK(kept != nullptr);
  CHECK(listed.parse(second, second) == nullptr);  // beyond the budget: parsed again when read
  CHECK(listed.bytes() == size);
  CHECK(listed.size() == 1);

  // The clips' cache takes the parse of a file it reads, and the listing frees the others.
  Clip_cache cache({{first}, {first}}, {});
  cache.adopt(listed);
  CHECK(listed.size() == 0);
  CHECK(listed.bytes() == 0);
  CHECK(cache.parses_held() == 1);
  CHECK(cache.acquire({first}) == kept);
}

TEST_CASE("Clip_cache: a parse listed without a body is not taken for clips on a body", "[frontend]") {
  const std::string file = two_clip_file("bodies.gltf");
  Listed_parses listed;
  const std::shared_ptr<const deformseg::io::Gltf_file> kept = listed.parse(file, file);
  REQUIRE(kept != nullptr);
  Clip_cache cache({{file, "body.glb"}}, {});
  cache.adopt(listed);
  CHECK(cache.parses_held() == 0);
  CHECK(listed.size() == 0);
}
