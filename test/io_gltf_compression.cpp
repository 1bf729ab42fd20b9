// Compressed glTF (io/gltf.h with io/internal/gltf_decompression.h): copies of the shared
// characters compressed here with libdraco's and libmeshoptimizer's encoders read as the originals,
// within the quantisation step; damaged or absurd compressed data are refused, named.
#include <deformseg/io/config.h>

#if DEFORMSEG_HAS_DRACO && DEFORMSEG_HAS_MESHOPT
#include "gltf_compression.h"
#include "gltf_writer.h"
#include "test_support.h"

#include <deformseg/io/gltf.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace gltf_compression_test {

using deformseg::io::Gltf_file;
using deformseg::io::Sampled_gltf;
using Catch::Matchers::Contains;
using Json = nlohmann::json;
namespace fs = std::filesystem;

fs::path character(const std::string& name) {
  return deformseg::test::data_dir() / "characters" / name;
}

fs::path scratch(const std::string& name) {
  const fs::path path = deformseg::test::scratch_dir() / "gltf-compression" / name;
  fs::create_directories(path.parent_path());
  return path;
}

const double* position(const Sampled_gltf& s, std::size_t t, std::size_t v) {
  return s.positions.data() + (t * s.num_vertices + v) * 3;
}

double diagonal(const Sampled_gltf& s) {
  std::array<double, 3> low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t v = 0; v < s.num_vertices; ++v)
    for (int c = 0; c < 3; ++c) {
      low[c] = std::min(low[c], position(s, 0, v)[c]);
      high[c] = std::max(high[c], position(s, 0, v)[c]);
    }
  return std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
}

double distance(const double* p, const double* q) { return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]); }

// The largest distance, over the vertices of `a`, from a vertex's path to the nearest path of `b`
// (the one nearest over all frames, among the vertices of `b` within `cell` of it in frame 0):
// Draco reorders and splits vertices, so they are matched by where they go, not by index.
double largest_path_gap(const Sampled_gltf& a, const Sampled_gltf& b, double cell) {
  std::map<std::array<long, 3>, std::vector<std::size_t>> grid;
  const auto key = [&](const double* p) {
    return std::array<long, 3>{std::lround(p[0] / cell), std::lround(p[1] / cell), std::lround(p[2] / cell)};
  };
  for (std::size_t v = 0; v < b.num_vertices; ++v) grid[key(position(b, 0, v))].push_back(v);
  double gap = 0;
  for (std::size_t v = 0; v < a.num_vertices; ++v) {
    const auto k = key(position(a, 0, v));
    double nearest = INFINITY;
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == grid.end()) continue;
          for (const std::size_t w : it->second) {
            double path = 0;
            for (std::size_t t = 0; t < a.report.frames; ++t)
              path = std::max(path, distance(position(a, t, v), position(b, t, w)));
            nearest = std::min(nearest, path);
          }
        }
    gap = std::max(gap, nearest);
  }
  return gap;
}

// The total area of each frame's triangles.
std::vector<double> areas(const Sampled_gltf& s) {
  std::vector<double> out;
  for (std::size_t t = 0; t < s.report.frames; ++t) {
    double area = 0;
    for (const auto& tri : s.triangles) {
      const double *p = position(s, t, tri[0]), *q = position(s, t, tri[1]), *r = position(s, t, tri[2]);
      const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      area += 0.5 * std::hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]);
    }
    out.push_back(area);
  }
  return out;
}

// Reads `clips` of the original and of the compressed copy; checks that every vertex path of each
// has one of the other within `tolerance` of the diagonal in every frame, and that the surfaces'
// areas agree to `area_tolerance`. Gives the largest gap found, over the diagonal.
double compare(const fs::path& original, const fs::path& compressed, const std::vector<std::string>& clips,
               double tolerance, double area_tolerance) {
  const Gltf_file a_file(original), b_file(compressed);
  CHECK(b_file.clip_names() == a_file.clip_names());
  double largest = 0;
  for (const std::string& clip : clips) {
    INFO(compressed.filename().string() << " clip " << clip);
    const Sampled_gltf a = a_file.sample({.clip = clip, .fps = 30}), b = b_file.sample({.clip = clip, .fps = 30});
    REQUIRE(a.report.frames == b.report.frames);
    const double size = diagonal(a), cell = 2 * tolerance * size;
    const double gap = std::max(largest_path_gap(a, b, cell), largest_path_gap(b, a, cell)) / size;
    CHECK(gap <= tolerance);
    const std::vector<double> area_a = areas(a), area_b = areas(b);
    for (std::size_t t = 0; t < area_a.size(); ++t) CHECK(area_b[t] == Approx(area_a[t]).epsilon(area_tolerance));
    largest = std::max(largest, gap);
  }
  return largest;
}

const std::vector<std::pair<std::string, std::vector<std::string>>> characters = {
    {"Fox.glb", {"Survey", "Walk", "Run"}},
    {"RobotExpressive.glb", {"Dance", "Wave"}},
    {"Knight.glb", {"Walking_A", "Jump_Full_Long"}},
};

TEST_CASE("gltf compression: Draco copies of the shared characters read as the originals", "[gltf][draco][data]") {
  for (const auto& [name, clips] : characters) {
    const fs::path copy = scratch("draco-" + name);
    deformseg::test::write_draco_copy(character(name), copy, 14);
    // Positions on 14 bits of each primitive's extent: half a step is 3e-5 of it, moved by the
    // joints; the copies measure at most 6e-5 of the diagonal.
    const double gap = compare(character(name), copy, clips, 1e-4, 1e-3);
    std::printf("Draco %s: largest gap %.3g of the diagonal\n", name.c_str(), gap);
  }
}

TEST_CASE("gltf compression: Draco's quantisation shows, and its step bounds the gap", "[gltf][draco][data]") {
  const fs::path coarse = scratch("draco-coarse-Fox.glb");
  deformseg::test::write_draco_copy(character("Fox.glb"), coarse, 8);
  const Sampled_gltf a = Gltf_file(character("Fox.glb")).sample({.clip = "Walk"});
  const Sampled_gltf b = Gltf_file(coarse).sample({.clip = "Walk"});
  const double size = diagonal(a);
  const double gap = std::max(largest_path_gap(a, b, 0.02 * size), largest_path_gap(b, a, 0.02 * size)) / size;
  CHECK(gap > 1e-3);  // 8 bits: the copy is not the original
  CHECK(gap < 1e-2);  // but within a step (1/255 of the extent)
}

TEST_CASE("gltf compression: meshopt copies of the shared characters read as the originals, filtered and quantised",
          "[gltf][meshopt][data]") {
  for (const auto& [name, clips] : characters) {
    const fs::path copy = scratch("meshopt-" + name);
    deformseg::test::write_meshopt_copy(character(name), copy);
    // Positions with 18-bit mantissas, rotations on 16 bits a component (2e-5 each), errors that
    // add up along the joints: the copies measure at most 1e-4 of the diagonal.
    const double gap = compare(character(name), copy, clips, 1.5e-4, 1e-3);
    std::printf("meshopt %s: largest gap %.3g of the diagonal\n", name.c_str(), gap);
  }
}

// ---- Refusals ----------------------------------------------------------------------------------

// A .glb with one triangle whose POSITION and indices come from the compressed data `payload`.
fs::path compressed_triangle(const std::string& name, const Json& extension_of_primitive, const Json& views,
                             const std::vector<unsigned char>& payload) {
  Json doc = {{"asset", {{"version", "2.0"}}},
              {"buffers", {{{"byteLength", payload.size()}}}},
              {"bufferViews", views},
              {"accessors",
               {{{"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                {{"componentType", 5125}, {"count", 3}, {"type", "SCALAR"}}}},
              {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"scenes", {{{"nodes", {0}}}}}};
  if (!extension_of_primitive.is_null()) {
    doc["meshes"][0]["primitives"][0]["extensions"] = {{"KHR_draco_mesh_compression", extension_of_primitive}};
    doc["extensionsUsed"] = doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  } else {  // the views decode from buffer 0 into a fallback buffer without bytes
    doc["buffers"].push_back({{"byteLength", 36}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    doc["extensionsUsed"] = doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  }
  const auto bytes = deformseg::io::internal::gltf::glb_bytes(doc, payload);
  const fs::path path = scratch(name);
  deformseg::io::internal::write_file_bytes(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  return path;
}

TEST_CASE("gltf compression: damaged or absurd compressed data are refused, named", "[gltf][draco][meshopt]") {
  const std::vector<unsigned char> garbage(64, 0x5a);
  SECTION("Draco data that are not Draco's, of another bitstream, claiming billions of faces, or damaged") {
    const auto draco = [](std::vector<unsigned char> header) {
      header.resize(64, 0x5a);
      return header;
    };
    const std::vector<std::pair<std::vector<unsigned char>, std::string>> cases = {
        {garbage, "the data are not Draco's"},
        {draco({'D', 'R', 'A', 'C', 'O', 1, 2, 1, 1, 0, 0}), "Draco bitstream 1.2, not the 2.2"},
        {draco({'D', 'R', 'A', 'C', 'O', 2, 2, 1, 0, 0, 0, 0xff, 0xff, 0xff, 0xff, 0x0f, 4}), "claims more than 16777216"},
        {draco({'D', 'R', 'A', 'C', 'O', 2, 2, 1, 1, 0, 0, 0, 4, 4, 0, 3, 0}), "the Draco data do not decode"}};
    for (const auto& [payload, message] : cases) {
      const fs::path path = compressed_triangle("draco-bad.glb", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}},
                                                {{{"buffer", 0}, {"byteLength", 64}}}, payload);
      CHECK_THROWS_WITH(Gltf_file(path), Contains(path.string()) && Contains("meshes[0].primitives[0]") &&
                                             Contains(message));
    }
  }
  SECTION("a Draco view outside its buffer") {
    const fs::path path = compressed_triangle("draco-outside.glb", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}},
                                              {{{"buffer", 0}, {"byteOffset", 32}, {"byteLength", 64}}}, garbage);
    CHECK_THROWS_WITH(Gltf_file(path), Contains(path.string()) && Contains("bufferViews[0] takes bytes 32 to 96"));
  }
  const auto meshopt_views = [](const Json& extension) {
    Json position = {{"buffer", 1}, {"byteLength", 36}, {"extensions", {{"EXT_meshopt_compression", extension}}}};
    return Json{position, {{"buffer", 0}, {"byteLength", 12}}};
  };
  SECTION("meshopt data that do not decode, a mode or filter that does not exist, an absurd count") {
    const Json good = {{"buffer", 0}, {"byteLength", 64}, {"byteStride", 12}, {"count", 3}, {"mode", "ATTRIBUTES"}};
    Json bad_mode = good, bad_filter = good, huge = good;
    bad_mode["mode"] = "VERTICES";
    bad_filter["filter"] = "QUATERNION";  // needs byteStride 8
    huge["count"] = std::uint64_t(1) << 40;
    const std::vector<std::pair<Json, std::string>> cases = {
        {good, "the ATTRIBUTES data do not decode"},
        {bad_mode, "mode must be ATTRIBUTES, TRIANGLES or INDICES, not 'VERTICES'"},
        {bad_filter, "filter 'QUATERNION' is unknown or does not fit byteStride 12"},
        {huge, "more than 64 times the file's size allows"}};
    for (const auto& [extension, message] : cases) {
      const fs::path path = compressed_triangle("meshopt-bad.glb", nullptr, meshopt_views(extension), garbage);
      CHECK_THROWS_WITH(Gltf_file(path), Contains(path.string()) &&
                                             Contains("bufferViews[0].extensions.EXT_meshopt_compression") &&
                                             Contains(message));
    }
  }
}

}  // namespace gltf_compression_test

#endif  // DEFORMSEG_HAS_DRACO && DEFORMSEG_HAS_MESHOPT
