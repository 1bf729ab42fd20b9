// glTF reader: hand-made files with positions computed by hand, and the shared characters.
#include "gltf_writer.h"
#include "test_support.h"

#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/gltf_file.h>
#include <deformseg/io/outlying_vertices.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/strain/strain.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using deformseg::invalid_input;
using deformseg::io::Gltf_read_options;
using deformseg::io::Sampled_gltf;
using deformseg::io::sample_gltf;
using deformseg::test::Gltf_writer;
using Catch::Matchers::Contains;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const double half_root2 = std::sqrt(0.5);

// Checks vertex `v` of frame `t` against (x, y, z), to `eps` absolute.
void check_point(const Sampled_gltf& s, std::size_t t, std::size_t v, double x, double y, double z,
                 double eps = 1e-12) {
  INFO("frame " << t << " vertex " << v);
  REQUIRE(t < s.report.frames);
  const double* p = s.positions.data() + (t * s.num_vertices + v) * 3;
  CHECK(p[0] == Approx(x).margin(eps).epsilon(0));
  CHECK(p[1] == Approx(y).margin(eps).epsilon(0));
  CHECK(p[2] == Approx(z).margin(eps).epsilon(0));
}

// Some vertices sampled alone (every vertex backwards, every third twice) give, bit for bit, the
// same vertices of `sample` (every vertex skinned); and `read` and a frame source, which pose only
// the vertices the welding keeps, give every vertex skinned, then welded.
void check_posed_alone(const deformseg::io::Gltf_file& file, const Gltf_read_options& options) {
  const Sampled_gltf all = file.sample(options);
  std::vector<std::uint32_t> some;
  for (std::size_t v = all.num_vertices; v-- > 0;) {
    some.push_back(std::uint32_t(v));
    if (v % 3 == 0) some.push_back(std::uint32_t(v));
  }
  auto sampler = file.frame_sampler(options, some);
  REQUIRE(sampler.num_vertices() == some.size());
  REQUIRE(sampler.num_frames() == all.report.frames);
  std::vector<double> frame(3 * some.size());
  std::size_t differ = 0;
  for (std::size_t t = 0; t < sampler.num_frames(); ++t) {
    sampler.sample_frame(t, frame);
    for (std::size_t i = 0; i < some.size(); ++i) {
      const double* expected = &all.positions[(t * all.num_vertices + some[i]) * 3];
      differ += std::memcmp(&frame[3 * i], expected, 3 * sizeof(double)) != 0;
    }
  }
  CHECK(differ == 0);
  const std::vector<std::uint32_t> kept = file.repair(options.repair).source_vertex;
  const auto welded = deformseg::io::internal::positions_of_sources<double>(
      std::span<const double>(all.positions), all.num_vertices, kept);
  const auto animation = file.read(options);
  REQUIRE(animation.num_vertices() == kept.size());
  const auto read = animation.all_positions();
  REQUIRE(read.size() == welded.size());
  CHECK(std::memcmp(read.data(), welded.data(), welded.size() * sizeof(double)) == 0);
  deformseg::io::Gltf_frame_source source(file, options);
  REQUIRE(source.num_vertices() == kept.size());
  REQUIRE(source.num_frames() == all.report.frames);
  frame.resize(3 * source.num_vertices());
  for (std::size_t t = 0; t < source.num_frames(); ++t) {
    source.read_frame(frame);
    differ += std::memcmp(frame.data(), welded.data() + t * frame.size(), frame.size() * sizeof(double)) != 0;
  }
  CHECK(differ == 0);
}

fs::path write(const Gltf_writer& w, const std::string& name) {
  const fs::path path = deformseg::test::scratch_dir() / "gltf" / name;
  fs::create_directories(path.parent_path());
  if (path.extension() == ".glb")
    w.write_glb(path);
  else
    w.write_gltf(path);
  return path;
}

// A triangle (0,0,0), (1,0,0), (0,1,0) as mesh `name`; gives the mesh index.
int add_triangle_mesh(Gltf_writer& w, const std::string& name = "triangle") {
  const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  return w.push("meshes", {{"name", name}, {"primitives", json::array({{{"attributes", {{"POSITION", position}}}}})}});
}

// A channel of `node`'s `path` with keys at `times` and `values` (of `type`).
void add_channel(json& animation, Gltf_writer& w, int node, const std::string& path, const std::vector<float>& times,
                 const std::vector<float>& values, const std::string& type,
                 const std::string& interpolation = "LINEAR") {
  const int input = w.floats(times, "SCALAR");
  const int output = w.floats(values, type);
  animation["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
  animation["channels"].push_back(
      {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
}

json new_animation(const std::string& name) {
  return {{"name", name}, {"samplers", json::array()}, {"channels", json::array()}};
}

// Three clips moving one node that shows a triangle: "linear", "step", "cubic".
Gltf_writer sampler_scene() {
  Gltf_writer w;
  const int mesh = add_triangle_mesh(w);
  w.push("nodes", {{"name", "mover"}, {"mesh", mesh}});
  w.push("scenes", {{"nodes", {0}}});
  // Translation keys 0..1 s; rotation keys 0.5..1.5 s, the second stored negated (the same
  // rotation, 90 degrees about z): the shortest path turns by +90 degrees, not -270.
  json linear = new_animation("linear");
  add_channel(linear, w, 0, "translation", {0, 1}, {0, 0, 0, 2, 4, 0}, "VEC3");
  const float s = float(half_root2);
  add_channel(linear, w, 0, "rotation", {0.5f, 1.5f}, {0, 0, 0, 1, 0, 0, -s, -s}, "VEC4");
  w.push("animations", linear);
  json step = new_animation("step");
  add_channel(step, w, 0, "translation", {0, 1, 2}, {0, 0, 0, 1, 0, 0, 5, 0, 0}, "VEC3", "STEP");
  w.push("animations", step);
  // CUBICSPLINE: per key in-tangent, value, out-tangent; keys at 0 and 2 s.
  json cubic = new_animation("cubic");
  add_channel(cubic, w, 0, "translation", {0, 2}, {9, 9, 9, 0, 0, 0, 3, 0, 0, -1, 0, 0, 1, 0, 0, 7, 7, 7}, "VEC3",
              "CUBICSPLINE");
  add_channel(cubic, w, 0, "rotation", {0, 2}, {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},
              "VEC4", "CUBICSPLINE");
  w.push("animations", cubic);
  return w;
}

}  // namespace

TEST_CASE("split_clip_suffix: FILE.glb#CLIP names a clip, other inputs stay whole", "[gltf]") {
  using Split = std::pair<std::string, std::optional<std::string>>;
  CHECK(deformseg::io::split_clip_suffix("Fox.glb#Walk") == Split("Fox.glb", "Walk"));
  CHECK(deformseg::io::split_clip_suffix("a#b/Fox.GLTF#Run") == Split("a#b/Fox.GLTF", "Run"));
  CHECK(deformseg::io::split_clip_suffix("Fox.glb#") == Split("Fox.glb", ""));
  CHECK(deformseg::io::split_clip_suffix("Fox.glb") == Split("Fox.glb", std::nullopt));
  CHECK(deformseg::io::split_clip_suffix("frames#1/") == Split("frames#1/", std::nullopt));
}

TEST_CASE("gltf: LINEAR translation and shortest-path slerp rotation, clamped outside their keys", "[gltf]") {
  const fs::path path = write(sampler_scene(), "samplers.gltf");
  const Sampled_gltf s = sample_gltf(path, {.clip = "linear", .fps = 2});
  REQUIRE(s.num_vertices == 3);
  REQUIRE(s.triangles.size() == 1);
  CHECK(s.report.clip == "linear");
  CHECK(s.report.clip_index == 0);
  CHECK(s.report.start == 0);
  CHECK(s.report.end == 1.5);
  REQUIRE(s.report.frames == 4);  // 0, 0.5, 1, 1.5 s
  // Vertex 1 at (1,0,0): the translation, plus (1,0,0) rotated.
  check_point(s, 0, 1, 1, 0, 0);              // rotation clamped before its first key
  check_point(s, 1, 1, 2, 2, 0);              // translation (1,2,0), rotation at its first key
  check_point(s, 2, 1, 2 + half_root2, 4 + half_root2, 0, 1e-6);  // 45 degrees; float keys
  check_point(s, 3, 1, 2, 5, 0, 1e-6);        // translation clamped after its last key; 90 degrees
  check_point(s, 3, 2, 1, 4, 0, 1e-6);        // (0,1,0) turned to (-1,0,0)
}

TEST_CASE("gltf: STEP holds each key until the next", "[gltf]") {
  const fs::path path = write(sampler_scene(), "samplers.gltf");
  const Sampled_gltf s = sample_gltf(path, {.clip = "step", .fps = 2});
  REQUIRE(s.report.frames == 5);
  const double x[] = {0, 0, 1, 1, 5};
  for (std::size_t t = 0; t < 5; ++t) check_point(s, t, 0, x[t], 0, 0);
}

TEST_CASE("gltf: CUBICSPLINE Hermite with tangents scaled by the key interval, quaternions normalised", "[gltf]") {
  const fs::path path = write(sampler_scene(), "samplers.gltf");
  const Sampled_gltf s = sample_gltf(path, {.clip = "2", .fps = 2});  // the clip by index
  CHECK(s.report.clip == "cubic");
  REQUIRE(s.report.frames == 5);
  // x(u) = h10 * 2 * 3 + h01 * 1 + h11 * 2 * (-1), by hand at u = 0, 1/4, 1/2, 3/4, 1.
  const double x[] = {0, 1.09375, 1.5, 1.40625, 1};
  for (std::size_t t = 0; t < 5; ++t) check_point(s, t, 0, x[t], 0, 0);
  // Rotation halfway between identity and 180 degrees about z, no tangents: (0,0,1/2,1/2)
  // normalised is 90 degrees, so vertex 1 (1,0,0) goes to (0,1,0).
  check_point(s, 2, 1, 1.5, 1, 0);
  check_point(s, 4, 1, 1 - 1, 0, 0);  // 180 degrees at the last key: (1,0,0) -> (-1,0,0)
}

TEST_CASE("gltf: two-bone skinned strip, the skinned mesh node's own scale ignored", "[gltf]") {
  Gltf_writer w;
  // Six vertices: x = 0, 1, 2 on y = 0, then on y = 1. Joint 0 (root) at the origin, joint 1
  // (tip) at x = 1; the middle column is half on each.
  const int position = w.floats({0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0}, "VEC3");
  const int joints = w.values(std::vector<std::uint8_t>{0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0,
                                                        1, 0, 0, 0},
                              Gltf_writer::ubyte_type, "VEC4");
  // Weights not summing to 1 (2 and 1 + 1): they are normalised.
  const int weights = w.floats({2, 0, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0}, "VEC4");
  const int indices = w.indices({0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4});
  const int ibm = w.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,    //
                            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1},  // translate(-1, 0, 0)
                           "MAT4");
  w.push("meshes", {{"name", "strip"},
                    {"primitives", json::array({{{"attributes", {{"POSITION", position}, {"JOINTS_0", joints},
                                                                 {"WEIGHTS_0", weights}}},
                                                 {"indices", indices}}})}});
  w.push("nodes", {{"name", "root"}, {"children", {1}}});
  w.push("nodes", {{"name", "tip"}, {"translation", {1, 0, 0}}});
  w.push("nodes", {{"name", "body"}, {"mesh", 0}, {"skin", 0}, {"scale", {5, 5, 5}}, {"translation", {7, 0, 0}}});
  w.push("skins", {{"joints", {0, 1}}, {"inverseBindMatrices", ibm}});
  w.push("scenes", {{"nodes", {0, 2}}});
  json bend = new_animation("bend");
  const float s = float(half_root2);
  add_channel(bend, w, 1, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, s, s}, "VEC4");
  w.push("animations", bend);
  const fs::path path = write(w, "strip.gltf");

  const Sampled_gltf s30 = sample_gltf(path);
  REQUIRE(s30.report.frames == 31);
  REQUIRE(s30.num_vertices == 6);
  REQUIRE(s30.triangles.size() == 4);
  // Rest pose: the file's positions, the node's scale and translation not applied.
  const double rest[6][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  for (std::size_t v = 0; v < 6; ++v) check_point(s30, 0, v, rest[v][0], rest[v][1], rest[v][2]);
  // At 1 s the tip turned 90 degrees about z around (1,0,0): (2,0,0) -> (1,1,0), (2,1,0) ->
  // (0,1,0); (1,1,0) half rigid, half turned to (0,0,0): (0.5,0.5,0).
  const double bent[6][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0, 1, 0}};
  for (std::size_t v = 0; v < 6; ++v) check_point(s30, 30, v, bent[v][0], bent[v][1], bent[v][2], 1e-6);
  // At 0.5 s, 45 degrees: (2,0,0) -> (1 + c, c, 0); (1,1,0) -> ((1 + 1 - c) / 2, (1 + c) / 2, 0).
  const double c = half_root2;
  check_point(s30, 15, 2, 1 + c, c, 0, 1e-6);
  check_point(s30, 15, 4, (2 - c) / 2, (1 + c) / 2, 0, 1e-6);

  SECTION("the same as a .glb, and on one thread or two") {
    const fs::path glb = write(w, "strip.glb");
    const Sampled_gltf one = sample_gltf(glb, {.threads = 1});
    const Sampled_gltf two = sample_gltf(glb, {.threads = 2});
    CHECK(one.positions == s30.positions);
    CHECK(two.positions == s30.positions);
    CHECK(one.triangles == s30.triangles);
  }
  SECTION("the same as a .gltf with an external .bin; refused when the .bin is missing") {
    const fs::path external = deformseg::test::scratch_dir() / "gltf" / "strip_external.gltf";
    w.write_gltf_with_bin(external, "strip_external.bin");
    CHECK(sample_gltf(external).positions == s30.positions);
    fs::remove(external.parent_path() / "strip_external.bin");
    CHECK_THROWS_WITH(sample_gltf(external), Contains(external.string()));
  }
  SECTION("read_gltf gives a Deforming_mesh with the report") {
    deformseg::io::Gltf_read_report report;
    const auto animation = deformseg::io::read_gltf(path, {.repair = {.weld = false}}, &report);
    CHECK(animation.num_frames() == 31);
    CHECK(animation.num_vertices() == 6);
    CHECK(animation.num_faces() == 4);
    CHECK(report.clip == "bend");
    CHECK(report.repair.input_vertices == 6);
    CHECK(animation.frame_positions(30)[3 * 2 + 1] == Approx(1).margin(1e-6));
  }
}

TEST_CASE("gltf: 8 influences with normalised byte weights / no weight at all stays with the mesh node", "[gltf]") {
  Gltf_writer w;
  const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const auto ubytes = [&w](const std::vector<std::uint8_t>& v, bool normalized) {
    return w.values(v, Gltf_writer::ubyte_type, "VEC4", normalized);
  };
  const int joints_0 = ubytes({0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, false);
  const int joints_1 = ubytes({1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}, false);
  // Vertex 0: 1 on joint 0 and 1 on joint 1, halved; vertex 1: none; vertex 2: 0.2 and 0.8.
  const int weights_0 = ubytes({255, 0, 0, 0, 0, 0, 0, 0, 51, 0, 0, 0}, true);
  const int weights_1 = ubytes({255, 0, 0, 0, 0, 0, 0, 0, 204, 0, 0, 0}, true);
  w.push("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", position}, {"JOINTS_0", joints_0},
                                                                 {"WEIGHTS_0", weights_0}, {"JOINTS_1", joints_1},
                                                                 {"WEIGHTS_1", weights_1}}}}})}});
  w.push("nodes", {{"name", "a"}});
  w.push("nodes", {{"name", "b"}, {"translation", {10, 0, 0}}});
  w.push("nodes", {{"mesh", 0}, {"skin", 0}, {"translation", {0, 0, 7}}});
  w.push("skins", {{"joints", {0, 1}}});  // no inverseBindMatrices: identity
  const Sampled_gltf s = sample_gltf(write(w, "eight.gltf"));
  check_point(s, 0, 0, 5, 0, 0);
  check_point(s, 0, 1, 1, 0, 7);  // rigid to the mesh node, whose transform then applies
  check_point(s, 0, 2, 8, 1, 0);
  check_posed_alone(deformseg::io::Gltf_file(write(w, "eight.gltf")), {});
}

TEST_CASE("gltf: a weighted joint that is negative, fractional or past the skin is dropped, or refused, named",
          "[gltf]") {
  // glTF's JOINTS are unsigned bytes or shorts; a file may still store them signed or as floats.
  const auto skinned = [](int joints_type, const std::vector<float>& joints) {
    Gltf_writer w;
    const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    const int joint_values =
        joints_type == Gltf_writer::float_type
            ? w.floats(joints, "VEC4")
            : w.values(std::vector<std::int8_t>(joints.begin(), joints.end()), joints_type, "VEC4");
    // Vertex 0 weighs on its first two joints, the others on their first only.
    const int weights = w.floats({0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
    w.push("meshes", {{"name", "arm"},
                      {"primitives", json::array({{{"attributes", {{"POSITION", position}, {"JOINTS_0", joint_values},
                                                                   {"WEIGHTS_0", weights}}}}})}});
    w.push("nodes", {{"name", "a"}});
    w.push("nodes", {{"mesh", 0}, {"skin", 0}});
    w.push("skins", {{"joints", {0}}});
    return w;
  };
  // Joints past the first two of vertex 0 weigh nothing: whatever they hold is not read.
  const std::vector<float> fine{0, 0, -7, 1e30f, 0, 5, 0, 0, 0, 0, 0, 0};
  CHECK(sample_gltf(write(skinned(Gltf_writer::float_type, fine), "fine.gltf")).num_vertices == 3);
  // Repaired by default, as engines load them (the influence dropped; a vertex left without
  // weight follows its mesh's node), counted; refused with Defect_policy::refuse.
  const auto refused = [&](int type, const std::vector<float>& joints, std::size_t unweighted,
                           const std::string& message) {
    const fs::path path = write(skinned(type, joints), "bad-joint.gltf");
    const deformseg::io::Gltf_file file(path);
    deformseg::io::Gltf_read_report report;
    CHECK(file.read({.repair = {.weld = false}}, &report).num_vertices() == 3);
    CHECK(report.repair.dropped_influences == 1);
    CHECK(report.repair.unweighted_vertices == unweighted);
    CHECK_THROWS_WITH(file.read({.repair = {.weld = false, .defects = deformseg::io::Defect_policy::refuse}}),
                      Contains(path.string()) && Contains(message));
  };
  refused(Gltf_writer::byte_type, {0, -128, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 0,
          "mesh 'arm' primitive 0 vertex 0 refers to joint -128 of a skin with 1 joints");
  refused(Gltf_writer::float_type, {0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0, 0, 0}, 1, "vertex 1 refers to joint 0.5");
  refused(Gltf_writer::float_type, {0, 0, 0, 0, 0, 0, 0, 0, 1e30f, 0, 0, 0}, 1,
          "vertex 2 refers to joint 1.0000000150474662e+30");  // the float 1e30 exactly, as read
  refused(Gltf_writer::byte_type, {0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 0,
          "vertex 0 refers to joint 1 of a skin with 1");
}

TEST_CASE("gltf: NaN, infinite and negative weights are dropped, the rest renormalised, or refused", "[gltf]") {
  // The Wasp of the shared library has weights of NaN; three.js and Blender load it.
  Gltf_writer w;
  const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int joints = w.values(std::vector<std::uint8_t>{0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, Gltf_writer::ubyte_type,
                              "VEC4");
  // Vertex 0: NaN on joint 0, 1 on joint 1; vertex 1: -1 and infinity; vertex 2: a half each.
  const float nan = std::numeric_limits<float>::quiet_NaN(), infinity = std::numeric_limits<float>::infinity();
  const int weights = w.floats({nan, 1, 0, 0, -1, infinity, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4");
  w.push("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", position}, {"JOINTS_0", joints},
                                                                 {"WEIGHTS_0", weights}}}}})}});
  w.push("nodes", {{"name", "a"}});
  w.push("nodes", {{"name", "b"}, {"translation", {10, 0, 0}}});
  w.push("nodes", {{"mesh", 0}, {"skin", 0}, {"translation", {0, 0, 7}}});
  w.push("skins", {{"joints", {0, 1}}});
  const fs::path path = write(w, "bad-weights.gltf");
  const Sampled_gltf s = sample_gltf(path);
  check_point(s, 0, 0, 10, 0, 0);  // on joint 1 alone
  check_point(s, 0, 1, 1, 0, 7);   // no weight left: rigid to the mesh node
  check_point(s, 0, 2, 5, 1, 0);
  const deformseg::io::Gltf_file file(path);
  deformseg::io::Gltf_read_report report;
  file.read({.repair = {.weld = false}}, &report);
  CHECK(report.repair.dropped_influences == 3);
  CHECK(report.repair.unweighted_vertices == 1);
  CHECK(report.repair.changed());
  CHECK_THROWS_WITH(file.read({.repair = {.defects = deformseg::io::Defect_policy::refuse}}),
                    Contains(path.string()) && Contains("vertex 0 has weight nan; glTF needs finite weights >= 0"));
}

TEST_CASE("gltf: the shared library's bodies with NaN weights read, repaired, every clip", "[gltf][data]") {
  for (const char* name : {"easy_enemies_pack/Wasp.glb", "platformer_game_pack/Bee.glb", "platformer_game_pack/Crab.glb"}) {
    INFO(name);
    const deformseg::io::Gltf_file file(deformseg::test::data_dir() / "library" / name);
    for (const std::string& clip : file.clip_names()) {
      deformseg::io::Gltf_read_report report;
      const auto animation = file.read({.clip = clip}, &report);
      CHECK(report.repair.dropped_influences > 0);
      CHECK(animation.num_vertices() > 0);
    }
    CHECK_THROWS_WITH(file.read({.repair = {.defects = deformseg::io::Defect_policy::refuse}}), Contains("has weight"));
  }
}

TEST_CASE("gltf: animated morph target weights, node and mesh weights at rest", "[gltf]") {
  Gltf_writer w;
  const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int lift = w.floats({0, 0, 0, 0, 0, 0, 0, 0, 1}, "VEC3");     // target 0: vertex 2 up
  const int stretch = w.floats({0, 0, 0, 1, 0, 0, 0, 0, 0}, "VEC3");  // target 1: vertex 1 out
  w.push("meshes",
         {{"name", "face"},
          {"weights", {0.25, 0.75}},
          {"primitives", json::array({{{"attributes", {{"POSITION", position}}},
                                       {"targets", json::array({{{"POSITION", lift}}, {{"POSITION", stretch}}})}}})}});
  w.push("nodes", {{"mesh", 0}, {"translation", {1, 2, 3}}});
  w.push("scenes", {{"nodes", {0}}});

  SECTION("the mesh's weights without an animation") {
    const Sampled_gltf s = sample_gltf(write(w, "morph_mesh.gltf"));
    REQUIRE(s.report.frames == 1);
    CHECK(s.report.clip_index == deformseg::io::Gltf_read_report::no_clip);
    check_point(s, 0, 1, 1 + 1.75, 2, 3);
    check_point(s, 0, 2, 1, 3, 3.25);
  }
  SECTION("the node's weights before the mesh's") {
    w.doc["nodes"][0]["weights"] = {1, 0};
    const Sampled_gltf s = sample_gltf(write(w, "morph_node.gltf"));
    check_point(s, 0, 1, 2, 2, 3);
    check_point(s, 0, 2, 1, 3, 4);
  }
  SECTION("the animated weights before both") {
    w.doc["nodes"][0]["weights"] = {1, 0};
    json talk = new_animation("talk");
    add_channel(talk, w, 0, "weights", {0, 1}, {0, 0, 1, 0.5f}, "SCALAR");
    w.push("animations", talk);
    const Sampled_gltf s = sample_gltf(write(w, "morph_animated.gltf"), {.fps = 2});
    REQUIRE(s.report.frames == 3);
    check_point(s, 0, 1, 2, 2, 3);
    check_point(s, 0, 2, 1, 3, 3);
    check_point(s, 1, 1, 2.25, 2, 3);  // weights (0.5, 0.25)
    check_point(s, 1, 2, 1, 3, 3.5);
    check_point(s, 2, 1, 2.5, 2, 3);
    check_point(s, 2, 2, 1, 3, 4);
    check_posed_alone(deformseg::io::Gltf_file(write(w, "morph_animated.gltf")), {.fps = 2});
  }
}

TEST_CASE("gltf: a matrix node, and a rigid mesh child of an animated node", "[gltf]") {
  Gltf_writer w;
  const int mesh = add_triangle_mesh(w);
  // Column-major: rotation by 90 degrees about z, scale 2, translation (1,2,3).
  w.push("nodes",
         {{"name", "frame"}, {"matrix", {0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1}}, {"children", {1}}});
  w.push("nodes", {{"name", "arm"}, {"translation", {1, 0, 0}}, {"children", {2}}});
  w.push("nodes", {{"name", "hand"}, {"mesh", mesh}, {"translation", {0, 0, 1}}});
  w.push("scenes", {{"nodes", {0}}});

  SECTION("static") {
    const Sampled_gltf s = sample_gltf(write(w, "matrix.gltf"));
    // hand (x,y,z) -> arm (x + 1, y, z + 1) -> frame (1 - 2y, 2 (x + 1) + 2, 2 (z + 1) + 3)
    check_point(s, 0, 0, 1, 4, 5);
    check_point(s, 0, 1, 1, 6, 5);
    check_point(s, 0, 2, -1, 4, 5);
  }
  SECTION("the arm moving carries the hand") {
    json lift = new_animation("lift");
    add_channel(lift, w, 1, "translation", {0, 1}, {1, 0, 0, 1, 0, 2}, "VEC3");
    w.push("animations", lift);
    const Sampled_gltf s = sample_gltf(write(w, "matrix_animated.gltf"), {.fps = 2});
    REQUIRE(s.report.frames == 3);
    check_point(s, 1, 0, 1, 4, 7);  // arm at (1,0,1): z doubled by the frame's scale
    check_point(s, 2, 1, 1, 6, 9);
  }
}

TEST_CASE("gltf: normalised, strided and sparse accessors (KHR_mesh_quantization)", "[gltf]") {
  Gltf_writer w;
  w.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  w.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  // Normalised shorts, 8 bytes apart (6 of data, 2 of padding).
  const std::vector<std::int16_t> interleaved = {0, 0, 0, 99, 32767, 0, 0, 99, 0, 16384, 0, 99, 5, 5, 5, 99};
  const int view = w.view(interleaved.data(), interleaved.size() * 2, 8);
  const int position = w.accessor(view, Gltf_writer::short_type, 4, "VEC3", true);
  // Vertex 3 replaced by (-32767, -32768, 0): (-1, -1, 0), -32768 clamped to -1.
  const std::vector<std::uint8_t> sparse_index = {3};
  const std::vector<std::int16_t> sparse_value = {-32767, -32768, 0};
  const int index_view = w.view(sparse_index.data(), 1);
  const int value_view = w.view(sparse_value.data(), 6);
  w.doc["accessors"][position]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", index_view}, {"componentType", Gltf_writer::ubyte_type}}},
      {"values", {{"bufferView", value_view}}}};
  const int indices = w.values(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}, Gltf_writer::ushort_type, "SCALAR");
  w.push("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", position}}}, {"indices", indices}}})}});
  w.push("nodes", {{"mesh", 0}});
  w.push("scenes", {{"nodes", {0}}});
  // A rotation stored as normalised shorts: (0,0,1,1) / sqrt 2 after normalisation.
  json turn = new_animation("turn");
  const int input = w.floats({0, 1}, "SCALAR");
  const int output =
      w.values(std::vector<std::int16_t>{0, 0, 0, 32767, 0, 0, 32767, 32767}, Gltf_writer::short_type, "VEC4", true);
  turn["samplers"].push_back({{"input", input}, {"output", output}});
  turn["channels"].push_back({{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}});
  w.push("animations", turn);

  const Sampled_gltf s = sample_gltf(write(w, "quantized.gltf"), {.fps = 1});
  REQUIRE(s.report.frames == 2);
  REQUIRE(s.num_vertices == 4);
  check_point(s, 0, 1, 1, 0, 0);
  check_point(s, 0, 2, 0, 16384.0 / 32767.0, 0);
  check_point(s, 0, 3, -1, -1, 0);
  check_point(s, 1, 1, 0, 1, 0);  // turned 90 degrees about z
  check_point(s, 1, 3, 1, -1, 0);
}

TEST_CASE("gltf: an accessor without buffer view is zeros, at most one element per byte of the buffers", "[gltf]") {
  // Target 0 lifts vertex 2: an accessor of zeros without buffer view, its vertex 2 substituted.
  Gltf_writer w;
  const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int lift = w.accessor(-1, Gltf_writer::float_type, 3, "VEC3");
  const std::vector<std::uint8_t> sparse_index = {2};
  const std::vector<float> sparse_value = {0, 0, 1};
  w.doc["accessors"][lift]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", w.view(sparse_index.data(), 1)}, {"componentType", Gltf_writer::ubyte_type}}},
      {"values", {{"bufferView", w.view(sparse_value.data(), 12)}}}};
  w.push("meshes", {{"name", "face"},
                    {"weights", {1}},
                    {"primitives", json::array({{{"attributes", {{"POSITION", position}}},
                                                 {"targets", json::array({{{"POSITION", lift}}})}}})}});
  w.push("nodes", {{"mesh", 0}});
  w.push("scenes", {{"nodes", {0}}});
  const Sampled_gltf s = sample_gltf(write(w, "zeros.gltf"));
  check_point(s, 0, 1, 1, 0, 0);
  check_point(s, 0, 2, 0, 1, 1);

  // The fuzzer's input (test/fuzz/regressions/gltf): 3,777,777 zeros from a file of 636 bytes,
  // which the reader would weld and sample, vertex after vertex. The buffers hold 52 bytes.
  w.doc["accessors"][lift]["count"] = 3777777;
  const fs::path path = write(w, "many_zeros.gltf");
  CHECK_THROWS_WITH(sample_gltf(path), Contains(path.string()) && Contains("target 0 POSITION") &&
                                           Contains("no buffer view and 3777777 elements") &&
                                           Contains("per byte of the file's buffers (52 bytes)"));
}

TEST_CASE("gltf: the frame count rule", "[gltf]") {
  const auto frames_for = [](float end, const std::string& name) {
    Gltf_writer w;
    add_triangle_mesh(w);
    w.push("nodes", {{"mesh", 0}});
    json move = new_animation("move");
    add_channel(move, w, 0, "translation", {0, end}, {0, 0, 0, end, 0, 0}, "VEC3");
    w.push("animations", move);
    return sample_gltf(write(w, name));
  };
  CHECK(frames_for(1, "frames_1.gltf").report.frames == 31);
  const Sampled_gltf longer = frames_for(1.05f, "frames_1_05.gltf");
  REQUIRE(longer.report.frames == 33);  // 0, 1/30, ..., 31/30, then 1.05 itself
  check_point(longer, 31, 0, 31.0 / 30, 0, 0, 1e-6);
  check_point(longer, 32, 0, 1.05, 0, 0, 1e-6);
  CHECK(frames_for(float(10.0 / 30), "frames_float.gltf").report.frames == 11);  // no spurious 12th
  CHECK(frames_for(0, "frames_0.gltf").report.frames == 1);
  CHECK(deformseg::io::gltf_contents(write(Gltf_writer(sampler_scene()), "samplers.gltf"), 2).clips.at(2).frames == 5);
}

TEST_CASE("gltf: a non-TRIANGLES primitive is skipped and reported", "[gltf]") {
  Gltf_writer w;
  const int position = w.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  w.push("meshes", {{"name", "wire"},
                    {"primitives", json::array({{{"attributes", {{"POSITION", position}}}},
                                                {{"attributes", {{"POSITION", position}}}, {"mode", 1}}})}});
  w.push("nodes", {{"mesh", 0}});
  const Sampled_gltf s = sample_gltf(write(w, "lines.gltf"));  // no scene: every root node
  CHECK(s.num_vertices == 3);
  REQUIRE(s.report.skipped.size() == 1);
  CHECK(s.report.skipped[0] == "mesh 'wire' primitive 1: mode LINES, skipped");
  const auto contents = deformseg::io::gltf_contents(write(w, "lines.gltf"));
  REQUIRE(contents.meshes.size() == 1);
  CHECK(contents.meshes[0].primitives.at(1).mode == "LINES");
  CHECK(contents.meshes[0].instances == 1);
  CHECK(contents.vertices == 3);
  CHECK(contents.triangles == 1);
}

TEST_CASE("gltf: refusals name the file and what is wrong", "[gltf]") {
  SECTION("a clip that does not exist lists the clips that do") {
    const fs::path path = write(sampler_scene(), "samplers.gltf");
    CHECK_THROWS_WITH(sample_gltf(path, {.clip = "dance"}),
                      Contains(path.string()) && Contains("no clip 'dance'") && Contains("'linear', 'step', 'cubic'"));
    CHECK_THROWS_AS(sample_gltf(path, {.clip = "3"}), invalid_input);
    CHECK_THROWS_WITH(sample_gltf(path, {.clip = "Linear"}),
                      Contains("no clip 'Linear' (clip names are case-sensitive: did you mean 'linear'?)"));
  }
  SECTION("an unknown required extension (compressed data: io_gltf_compression.cpp)") {
    Gltf_writer w = sampler_scene();
    w.doc["extensionsUsed"] = w.doc["extensionsRequired"] = {"EXT_unheard_of"};
    const fs::path path = write(w, "unknown.gltf");
    CHECK_THROWS_WITH(sample_gltf(path), Contains(path.string()) && Contains("requires the glTF extension EXT_unheard_of"));
  }
  SECTION("no triangle") {
    Gltf_writer w;
    w.push("nodes", {{"name", "empty"}});
    CHECK_THROWS_WITH(sample_gltf(write(w, "empty.gltf")), Contains("no triangle"));
  }
  SECTION("a missing file, a parse error, a truncated GLB") {
    const fs::path missing = deformseg::test::scratch_dir() / "gltf" / "missing.glb";
    CHECK_THROWS_WITH(sample_gltf(missing), Contains(missing.string()));
    const fs::path broken = deformseg::test::write_file("gltf/broken.gltf", "{\"asset\": {\"version\": \"2.0\"");
    CHECK_THROWS_WITH(sample_gltf(broken), Contains(broken.string()) && Contains("not a valid glTF"));
    const fs::path glb = write(sampler_scene(), "whole.glb");
    const std::string bytes = deformseg::test::file_text(glb);
    for (std::size_t cut : {std::size_t(10), bytes.size() / 2, bytes.size() - 4}) {
      const fs::path truncated = deformseg::test::write_file("gltf/truncated.glb", bytes.substr(0, cut));
      CHECK_THROWS_WITH(sample_gltf(truncated), Contains(truncated.string()));
    }
  }
  SECTION("accessors and indices outside their buffers") {
    Gltf_writer w = sampler_scene();
    w.doc["accessors"][0]["count"] = 4;  // 48 bytes from a view of 36
    CHECK_THROWS_WITH(sample_gltf(write(w, "bounds.gltf")), Contains("bounds.gltf") && Contains("accessor 0"));
    w.doc["accessors"][0]["count"] = std::size_t(1) << 62;  // an overflow, not an allocation
    CHECK_THROWS_AS(sample_gltf(write(w, "huge.gltf")), invalid_input);
    w = sampler_scene();
    w.doc["bufferViews"][0]["byteLength"] = 1000000;
    CHECK_THROWS_WITH(sample_gltf(write(w, "view.gltf")), Contains("buffer view 0"));
    w = sampler_scene();
    const int indices = w.indices({0, 1, 3});
    w.doc["meshes"][0]["primitives"][0]["indices"] = indices;
    CHECK_THROWS_WITH(sample_gltf(write(w, "index.gltf")),
                      Contains("mesh 'triangle' primitive 0") && Contains("index 2"));
    w = sampler_scene();
    w.doc["animations"][0]["samplers"][0]["input"] = 99;
    CHECK_THROWS_WITH(sample_gltf(write(w, "sampler.gltf")), Contains("accessor 99"));
  }
  SECTION("a node hierarchy with a cycle") {
    Gltf_writer w = sampler_scene();
    w.doc["scenes"][0]["nodes"] = json::array();
    w.push("nodes", {{"children", {2}}});
    w.push("nodes", {{"children", {1}}});
    CHECK_THROWS_WITH(sample_gltf(write(w, "cycle.gltf")), Contains("cycle"));
  }
}

namespace {

// Two quads side by side, x = 0..1 and x = 1..2, skinned on a root joint and a tip joint at x = 1,
// each quad with its own copies of the seam's vertices (as glTF splits a mesh along a UV seam),
// half on each joint: vertices 1 and 4 at (1, 0, 0) (vertex 4's weights 1 and 1, halved), 2 and 7
// at (1, 1, 0). Then a triangle apart, 8 to 10, its vertex 8 at (1, 1, 0) too but a quarter on the
// root and three quarters on the tip. Clip "still" does not move the tip; clip "bend" turns it by
// 90 degrees about z, which takes vertex 8 away from vertices 2 and 7.
Gltf_writer seam_scene() {
  Gltf_writer w;
  const int position = w.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0,  //
                                 1, 1, 0, 1.5f, 2, 0, 0.5f, 2, 0},
                                "VEC3");
  const std::vector<std::uint8_t> joint_values{0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0,
                                               0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const int joints = w.values(joint_values, Gltf_writer::ubyte_type, "VEC4");
  const int weights = w.floats({1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0,      //
                                1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0,            //
                                0.25f, 0.75f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
                               "VEC4");
  const int indices = w.indices({0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10});
  const int ibm = w.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,    //
                            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1},  // translate(-1, 0, 0)
                           "MAT4");
  w.push("meshes", {{"name", "quads"},
                    {"primitives", json::array({{{"attributes", {{"POSITION", position}, {"JOINTS_0", joints},
                                                                 {"WEIGHTS_0", weights}}},
                                                 {"indices", indices}}})}});
  w.push("nodes", {{"name", "root"}, {"children", {1}}});
  w.push("nodes", {{"name", "tip"}, {"translation", {1, 0, 0}}});
  w.push("nodes", {{"name", "body"}, {"mesh", 0}, {"skin", 0}});
  w.push("skins", {{"joints", {0, 1}}, {"inverseBindMatrices", ibm}});
  w.push("scenes", {{"nodes", {0, 2}}});
  json still = new_animation("still");
  add_channel(still, w, 1, "translation", {0, 1}, {1, 0, 0, 1, 0, 0}, "VEC3");
  w.push("animations", still);
  json bend = new_animation("bend");
  const float s = float(half_root2);
  add_channel(bend, w, 1, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, s, s}, "VEC4");
  w.push("animations", bend);
  return w;
}

// The positions of output vertex `v` in every frame.
std::vector<double> trajectory(const deformseg::mesh::Surface_mesh_animation& a, std::size_t v) {
  std::vector<double> xyz;
  for (std::size_t t = 0; t < a.num_frames(); ++t)
    for (std::size_t k = 0; k < 3; ++k) xyz.push_back(a.frame_positions(t)[3 * v + k]);
  return xyz;
}

}  // namespace

TEST_CASE("gltf: welded by what the file fixes, so that every clip has one mesh", "[gltf][repair][weld]") {
  Gltf_writer w = seam_scene();
  SECTION("the same skin weights (after normalisation) are welded, other weights are not, in every clip") {
    const deformseg::io::Gltf_file file(write(w, "seam.gltf"));
    deformseg::io::Gltf_read_report still_report, bend_report;
    const auto still = file.read({.clip = "still"}, &still_report);
    const auto bend = file.read({.clip = "bend"}, &bend_report);
    // Vertices 4 and 7 welded to 1 and 2; vertex 8 not, although it coincides with vertex 2 in
    // every frame of "still": the triangle apart stays apart in both clips.
    for (const auto* report : {&still_report, &bend_report}) {
      CHECK(report->repair.welded_vertices == 2);
      CHECK(report->repair.duplicated_vertices == 0);
    }
    CHECK(still.num_vertices() == 9);
    CHECK(bend.num_vertices() == 9);
    CHECK(std::ranges::equal(still.triangles(), bend.triangles()));
    CHECK(std::ranges::equal(file.repair().triangles, bend.triangles()));
    const std::vector<std::uint32_t> sources{0, 1, 2, 3, 5, 6, 8, 9, 10};
    CHECK(file.repair().source_vertex == sources);
    // A welded vertex moves as all its copies; vertex 8 leaves vertex 2 when the tip turns.
    const Sampled_gltf sampled = file.sample({.clip = "bend"});
    for (std::size_t t = 0; t < sampled.report.frames; ++t)
      for (std::size_t k = 0; k < 3; ++k) {
        const auto at = [&](std::size_t v) { return sampled.positions[(t * 11 + v) * 3 + k]; };
        CHECK(at(4) == Approx(at(1)).margin(1e-12));
        CHECK(at(7) == Approx(at(2)).margin(1e-12));
      }
    CHECK(trajectory(bend, 2) != trajectory(bend, 6));
    CHECK(trajectory(still, 2) == trajectory(still, 6));
  }
  SECTION("the same weights with different morph target deltas are not welded") {
    const std::vector<float> up{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
                                0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0};  // vertices 4 and 7 up
    w.doc["meshes"][0]["primitives"][0]["targets"] = json::array({{{"POSITION", w.floats(up, "VEC3")}}});
    const deformseg::io::Gltf_file file(write(w, "seam_morph.gltf"));
    // The target's weight is 0 in both clips, but a clip may set it: vertices 4 and 7 stay apart.
    for (const char* clip : {"still", "bend"}) CHECK(file.read({.clip = clip}).num_vertices() == 11);
  }
  SECTION("without welding, the file's vertices") {
    const deformseg::io::Gltf_file file(write(w, "seam_unwelded.gltf"));
    CHECK(file.read({.clip = "still", .repair = {.weld = false}}).num_vertices() == 11);
  }
}

TEST_CASE("read_animation: FILE.glb#CLIP names the clip / a file of several clips needs one", "[gltf][io]") {
  const std::string path = write(seam_scene(), "seam_clips.glb").string();
  deformseg::io::Repair_report report;
  const auto bend = deformseg::io::read_animation(path + "#bend", {}, &report);
  CHECK(bend.num_frames() == 31);
  CHECK(report.welded_vertices == 2);
  const auto by_option = deformseg::io::read_animation(path, {.clip = "bend"});
  CHECK(std::ranges::equal(bend.all_positions(), by_option.all_positions()));
  CHECK(std::ranges::equal(bend.all_positions(), deformseg::io::read_animation(path + "#1").all_positions()));
  CHECK(deformseg::io::animation_format(path + "#bend") == "glb");
  CHECK_THROWS_WITH(deformseg::io::read_animation(path + "#bend", {.clip = "still"}), Contains("given twice"));
  CHECK_THROWS_WITH(deformseg::io::read_animation(path + "#walk"),
                    Contains("no clip 'walk'") && Contains("'still', 'bend'") && Contains(path));
  // No clip named: refused, naming the clips and how to choose, where the first was read unsaid.
  CHECK_THROWS_WITH(deformseg::io::read_animation(path),
                    Contains("holds 2 clips") && Contains("seam_clips.glb#still") && Contains("'still', 'bend'") &&
                        Contains(path));
  // A file of one clip gives it; a file of none its rest pose.
  Gltf_writer one = seam_scene();
  one.doc["animations"].erase(0);
  CHECK(deformseg::io::read_animation(write(one, "seam_one_clip.glb").string()).num_frames() == 31);
  one.doc.erase("animations");
  CHECK(deformseg::io::read_animation(write(one, "seam_no_clip.glb").string()).num_frames() == 1);
}

// ---- The shared characters (../shared/data/characters, SOURCE.md and motions.csv) ------------

namespace {

fs::path characters() { return deformseg::test::data_dir() / "characters"; }

struct Source_clip {
  double start = 0, end = 0;
  std::size_t channels = 0;
};

struct Source_file {
  std::size_t vertices = 0, triangles = 0;
  std::map<std::string, Source_clip> clips;
};

// SOURCE.md: per file a "## NAME.glb: ..." section with a "- totals: V vertices, F triangles"
// line and a table "| clip | start s | end s | duration s | channels | ...".
std::map<std::string, Source_file> read_source_md() {
  std::ifstream in(characters() / "SOURCE.md");
  std::map<std::string, Source_file> files;
  std::string line, current;
  while (std::getline(in, line)) {
    if (line.starts_with("## ") && line.find(".glb:") != std::string::npos) {
      current = line.substr(3, line.find(".glb:") + 1);
    } else if (!current.empty() && line.starts_with("- totals: ")) {
      std::istringstream(line.substr(10)) >> files[current].vertices;
      std::istringstream(line.substr(line.find("vertices, ") + 10)) >> files[current].triangles;
    } else if (!current.empty() && line.starts_with("| ") && !line.starts_with("| clip") && !line.starts_with("|--")) {
      std::vector<std::string> cells;
      std::stringstream row(line.substr(1));
      for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell.substr(1, cell.size() - 2));
      if (cells.size() < 5) continue;
      files[current].clips[cells[0]] = {std::stod(cells[1]), std::stod(cells[2]), std::stoul(cells[4])};
    }
  }
  return files;
}

// motions.csv: file -> the clips it lists.
std::map<std::string, std::vector<std::string>> read_motions_csv() {
  std::ifstream in(characters() / "motions.csv");
  std::map<std::string, std::vector<std::string>> clips;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const std::size_t comma = line.find(','), second = line.find(',', comma + 1);
    if (second != std::string::npos) clips[line.substr(0, comma)].push_back(line.substr(comma + 1, second - comma - 1));
  }
  return clips;
}

// The sampling rule counted frame by frame: t = start + k / fps while t <= end (to a thousandth
// of a frame), then the end when it is off the grid.
std::size_t frames_by_rule(double start, double end, double fps) {
  std::size_t k = 0;
  while (start + double(k + 1) / fps <= end + 1e-3 / fps) ++k;
  return k + 1 + (end - (start + double(k) / fps) > 1e-3 / fps ? 1 : 0);
}

}  // namespace

TEST_CASE("gltf: every clip of motions.csv reads, with the frames of the sampling rule", "[gltf][data]") {
  const auto source = read_source_md();
  const auto motions = read_motions_csv();
  REQUIRE(motions.size() == 7);
  std::size_t clips_read = 0;
  for (const auto& [name, clips] : motions) {
    INFO(name);
    const fs::path path = characters() / name;
    const Source_file& expected = source.at(name);
    const auto contents = deformseg::io::gltf_contents(path);
    CHECK(contents.vertices == expected.vertices);
    CHECK(contents.triangles == expected.triangles);
    std::map<std::string, deformseg::io::Gltf_clip_info> info;
    for (const auto& clip : contents.clips) info[clip.name] = clip;
    CHECK(info.size() == expected.clips.size());
    const deformseg::io::Gltf_file file(path);
    for (const std::string& clip : clips) {
      INFO(clip);
      const Source_clip& times = expected.clips.at(clip);
      const auto& listed = info.at(clip);
      CHECK(std::abs(listed.start - times.start) <= 5e-4);  // SOURCE.md has 3 decimals
      CHECK(std::abs(listed.end - times.end) <= 5e-4);
      CHECK(listed.channels == times.channels);
      const Sampled_gltf s = file.sample({.clip = clip});
      CHECK(s.report.clip == clip);
      CHECK(s.report.frames == frames_by_rule(listed.start, listed.end, 30));
      CHECK(s.report.frames == listed.frames);
      CHECK(s.num_vertices == expected.vertices);
      CHECK(s.triangles.size() == expected.triangles);
      CHECK(s.positions.size() == s.report.frames * 3 * s.num_vertices);
      CHECK(std::all_of(s.positions.begin(), s.positions.end(), [](double x) { return std::isfinite(x); }));
      ++clips_read;
    }
  }
  CHECK(clips_read == 362);
}

TEST_CASE("gltf: the five KayKit bodies give the same frames per clip", "[gltf][data]") {
  const auto knight = deformseg::io::gltf_contents(characters() / "Knight.glb");
  REQUIRE(knight.clips.size() == 76);
  std::size_t zero_second = 0;
  for (const auto& clip : knight.clips) zero_second += clip.duration == 0 ? 1 : 0;
  CHECK(zero_second == 7);
  for (const char* body : {"Barbarian.glb", "Mage.glb", "Rogue.glb", "Rogue_Hooded.glb"}) {
    INFO(body);
    const auto other = deformseg::io::gltf_contents(characters() / body);
    REQUIRE(other.clips.size() == knight.clips.size());
    for (std::size_t c = 0; c < knight.clips.size(); ++c) {
      CHECK(other.clips[c].name == knight.clips[c].name);
      CHECK(other.clips[c].frames == knight.clips[c].frames);
    }
    REQUIRE(other.skins.size() == 1);
    CHECK(other.skins[0].joints == 41);
  }
}

TEST_CASE("gltf: every clip of a shared character has the file's one mesh, seams welded",
          "[gltf][data][repair][weld]") {
  // Vertices and triangles after welding and repair: the same for every clip of a file. The KayKit
  // props that overlap (the Knight's shields, the Rogue's crossbows, on nodes of their own) stay
  // apart, where welding per clip merged some of their vertices and dropped triangles.
  const std::map<std::string, std::pair<std::size_t, std::size_t>> expected{
      {"Barbarian.glb", {3423, 6543}}, {"Fox.glb", {290, 576}},      {"Knight.glb", {3665, 6952}},
      {"Mage.glb", {2951, 5683}},      {"RobotExpressive.glb", {1820, 3234}}, {"Rogue.glb", {3326, 6373}},
      {"Rogue_Hooded.glb", {3144, 6035}}};
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(characters())) {
    if (!deformseg::io::is_gltf(entry.path())) continue;
    const std::string name = entry.path().filename().string();
    INFO(name);
    ++files;
    const deformseg::io::Gltf_file file(entry.path());
    const auto mesh = file.repair();
    CHECK(std::pair(mesh.source_vertex.size(), mesh.triangles.size()) == expected.at(name));
    CHECK(mesh.report.welded_vertices > 0);
    for (const std::string& clip : file.clip_names()) {
      INFO(clip);
      const auto animation = file.read({.clip = clip});
      CHECK(animation.num_vertices() == mesh.source_vertex.size());
      CHECK(std::ranges::equal(animation.triangles(), mesh.triangles));
      // Real characters, root motion and all, have no vertex beyond their own scale.
      const deformseg::io::Outlier_check outliers(animation.frame_positions(0));
      for (std::size_t t = 0; t < animation.num_frames(); ++t) CHECK(!outliers(animation.frame_positions(t), t));
    }
  }
  CHECK(files == expected.size());
}

namespace {

bool keep_no_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                   void*) {
  return true;
}

// A copy of the shared character `from`, its geometry only (no texture to write back), changed by
// `edit(model)`, written as scratch/gltf/name.
template <class Edit>
fs::path edited_copy(const fs::path& from, const std::string& name, const Edit& edit) {
  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(&keep_no_image, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  REQUIRE(gltf.LoadBinaryFromFile(&model, &err, &warn, from.string()));
  model.images.clear();
  model.textures.clear();
  model.materials.clear();
  for (auto& mesh : model.meshes)
    for (auto& primitive : mesh.primitives) primitive.material = -1;
  edit(model);
  const fs::path to = deformseg::test::scratch_dir() / "gltf" / name;
  fs::create_directories(to.parent_path());
  REQUIRE(gltf.WriteGltfSceneToFile(&model, to.string(), false, true, false, true));
  return to;
}

// A copy of `from` without its meshes and skins: its nodes and clips alone, as an animation
// library exports them.
fs::path animation_only_copy(const fs::path& from, const std::string& name) {
  return edited_copy(from, name, [](tinygltf::Model& model) {
    for (auto& node : model.nodes) node.mesh = node.skin = -1;
    model.meshes.clear();
    model.skins.clear();
  });
}

// A copy of `from` whose scene roots hang below a new node that rotates, moves and scales them.
fs::path moved_copy(const fs::path& from, const std::string& name) {
  return edited_copy(from, name, [](tinygltf::Model& model) {
    tinygltf::Node parent;
    parent.name = "moved";
    parent.translation = {3, -2, 5};
    parent.rotation = {0.2, -0.4, 0.1, std::sqrt(1 - 0.04 - 0.16 - 0.01)};
    parent.scale = {2.5, 2.5, 2.5};
    auto& scene = model.scenes.at(std::size_t(std::max(model.defaultScene, 0)));
    parent.children = scene.nodes;
    model.nodes.push_back(parent);
    scene.nodes = {int(model.nodes.size()) - 1};
  });
}

// A new float accessor of `values` (of `type`), appended to buffer 0; gives its index.
int append_floats(tinygltf::Model& model, const std::vector<double>& values, const std::string& type) {
  std::vector<unsigned char>& data = model.buffers.at(0).data;
  while (data.size() % 4 != 0) data.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = values.size() * 4;
  for (const double v : values) {
    const float f = float(v);
    const auto* p = reinterpret_cast<const unsigned char*>(&f);
    data.insert(data.end(), p, p + 4);
  }
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size()) - 1;
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = type == "VEC3" ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
  accessor.count = values.size() / (type == "VEC3" ? 3 : 4);
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

// A copy of `from` without its meshes whose clips are in centimetres with Z up, as another tool
// exports them: a new root turns Z up into Y up and scales by 0.01; below it every translation,
// at rest and in the keys, is in centimetres, and the former roots are turned to Z up.
fs::path centimetres_z_up_copy(const fs::path& from, const std::string& name) {
  return edited_copy(from, name, [](tinygltf::Model& model) {
    for (auto& node : model.nodes) node.mesh = node.skin = -1;
    model.meshes.clear();
    model.skins.clear();
    const double c = std::sqrt(0.5);
    const std::array<double, 4> to_z_up{c, 0, 0, c};  // +90 degrees about x
    auto& scene = model.scenes.at(std::size_t(std::max(model.defaultScene, 0)));
    const std::set<int> roots(scene.nodes.begin(), scene.nodes.end());
    const auto convert = [&](double* t, double* q, bool root) {  // either may be null
      if (t) {
        for (int k = 0; k < 3; ++k) t[k] *= 100;
        if (root) deformseg::io::internal::gltf::rotate(to_z_up, t);
      }
      if (q && root) deformseg::io::internal::gltf::turn(to_z_up, q);
    };
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      tinygltf::Node& node = model.nodes[i];
      REQUIRE(node.matrix.empty());
      if (node.translation.empty()) node.translation = {0, 0, 0};
      if (node.rotation.empty()) node.rotation = {0, 0, 0, 1};
      convert(node.translation.data(), node.rotation.data(), roots.count(int(i)) > 0);
    }
    for (auto& animation : model.animations)
      for (const auto& channel : animation.channels) {
        auto& sampler = animation.samplers.at(std::size_t(channel.sampler));
        const bool translation = channel.target_path == "translation", rotation = channel.target_path == "rotation";
        if (!translation && !rotation) continue;
        REQUIRE(sampler.interpolation != "CUBICSPLINE");
        auto values = deformseg::io::internal::gltf::read_accessor(model, sampler.output, "test").values;
        const std::size_t width = translation ? 3 : 4;
        for (std::size_t k = 0; k < values.size(); k += width)
          convert(translation ? &values[k] : nullptr, rotation ? &values[k] : nullptr, roots.count(channel.target_node) > 0);
        sampler.output = append_floats(model, values, translation ? "VEC3" : "VEC4");
      }
    tinygltf::Node units;
    units.name = "centimetres, Z up";
    units.rotation = {-c, 0, 0, c};
    units.scale = {0.01, 0.01, 0.01};
    units.children = scene.nodes;
    model.nodes.push_back(units);
    scene.nodes = {int(model.nodes.size()) - 1};
  });
}

}  // namespace

TEST_CASE("gltf: the vertices a clip's frame source poses alone are those of every vertex skinned, then welded",
          "[gltf][data]") {
  // Skinned bodies of 4 influences (the library's animals, the KayKit characters), rigid parts
  // on bones and morph targets (the robot), a triangle soup welded to a fifth (the Fox).
  const fs::path data = deformseg::test::data_dir();
  for (const fs::path& path : {data / "library" / "animals_pack" / "Alpaca.glb", data / "characters" / "Knight.glb",
                               data / "characters" / "RobotExpressive.glb", data / "characters" / "Fox.glb"}) {
    REQUIRE(fs::exists(path));  // [data]: run only where the shared data are
    const deformseg::io::Gltf_file file(path);
    const std::vector<std::string> clips = file.clip_names();
    for (std::size_t c = 0; c < clips.size(); c += 4) {
      INFO(path.filename().string() << "#" << clips[c]);
      check_posed_alone(file, {.clip = clips[c]});
    }
  }
}

TEST_CASE("gltf: a rotated, moved, scaled copy of the Fox gives the same strain", "[gltf][data]") {
  const fs::path fox = characters() / "Fox.glb";
  const fs::path moved = moved_copy(fox, "fox_moved.glb");
  const auto original = deformseg::io::read_gltf(fox, {.clip = "Walk"});
  const auto copy = deformseg::io::read_gltf(moved, {.clip = "Walk"});
  REQUIRE(original.num_frames() == 23);
  REQUIRE(copy.num_frames() == original.num_frames());
  REQUIRE(copy.num_faces() == original.num_faces());
  // The copy's positions really moved.
  CHECK(std::abs(copy.all_positions()[0] - original.all_positions()[0]) > 1e-3);
  const auto a = deformseg::strain::compute_strain(original);
  const auto b = deformseg::strain::compute_strain(copy);
  double largest = 0;
  for (std::size_t t = 0; t < a.num_frames(); ++t)
    for (std::size_t f = 0; f < a.num_faces(); ++f) {
      CHECK(b(f, t) == Approx(a(f, t)).margin(1e-6));
      largest = std::max(largest, double(std::abs(a(f, t))));
    }
  CHECK(largest > 1e-3);  // the Fox does deform
}

TEST_CASE("gltf: the RobotExpressive robot reads: rigid parts on bones, skinned hands, morph targets", "[gltf][data]") {
  const deformseg::io::Gltf_file file(characters() / "RobotExpressive.glb");
  const Sampled_gltf s = file.sample({.clip = "Wave"});
  CHECK(s.num_vertices == 7214);
  CHECK(s.triangles.size() == 3237);
  CHECK(s.report.frames == frames_by_rule(s.report.start, s.report.end, 30));
  std::size_t repeating = 0;  // triangles that repeat a vertex, as SOURCE.md says
  for (const auto& t : s.triangles) repeating += (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) ? 1 : 0;
  CHECK(repeating == 3);
  // The hands move: some vertex travels during the wave.
  double travel = 0;
  for (std::size_t i = 0; i < 3 * s.num_vertices; ++i)
    travel = std::max(travel, std::abs(s.positions[(s.report.frames / 2) * 3 * s.num_vertices + i] - s.positions[i]));
  CHECK(travel > 0.1);
}

TEST_CASE("gltf: the robot's 3 degenerate triangles are reported by the repair", "[gltf][data][repair]") {
  deformseg::io::Gltf_read_report report;
  const auto robot = deformseg::io::read_gltf(characters() / "RobotExpressive.glb", {.clip = "Wave"}, &report);
  CHECK(report.repair.degenerate_triangles == 3);
  CHECK(robot.num_faces() <= 3237 - 3);
}

TEST_CASE("gltf: the Fox, a triangle soup, is welded to 290 vertices", "[gltf][data][repair]") {
  deformseg::io::Gltf_read_report report;
  const auto fox = deformseg::io::read_gltf(characters() / "Fox.glb", {.clip = "Run"}, &report);
  CHECK(report.repair.input_vertices == 1728);
  CHECK(report.repair.welded_vertices == 1728 - 290);
  CHECK(fox.num_vertices() == 290);
  CHECK(fox.num_faces() == 576);
}

TEST_CASE("gltf: unwelded, the file's vertices in order / written as OBJ frames they read back the same",
          "[gltf][data][repair]") {
  const fs::path fox = characters() / "Fox.glb";
  const Sampled_gltf sampled = sample_gltf(fox, {.clip = "Walk"});
  deformseg::io::Repair_report report;
  const auto unwelded = deformseg::io::read_animation(
      fox.string(), {.repair = deformseg::io::Repair_options{.weld = false}, .clip = "Walk"}, &report);
  CHECK_FALSE(report.changed());
  REQUIRE(unwelded.num_vertices() == 1728);
  CHECK(std::ranges::equal(unwelded.all_positions(), sampled.positions));
  CHECK(std::ranges::equal(unwelded.triangles(), sampled.triangles));

  const fs::path folder = deformseg::test::fresh_dir("io_gltf/fox_walk_obj");
  deformseg::io::write_sequence(unwelded, folder, {.format = deformseg::io::Mesh_format::obj});
  const auto frames = deformseg::io::read_frame_sequence(folder.string());
  REQUIRE(frames.num_frames() == 23);
  CHECK(std::ranges::equal(frames.all_positions(), sampled.positions));
  const auto welded = deformseg::io::read_frame_sequence(folder.string(), {.repair = {.weld = true}});
  CHECK(welded.num_vertices() == 290);
}

TEST_CASE("gltf: read_animation reads a clip, welded by default, and refuses a topology", "[gltf][data][repair]") {
  const std::string fox = (characters() / "Fox.glb").string();
  const auto run = deformseg::io::read_animation(fox, {.clip = "Run", .fps = 15});
  CHECK(run.num_vertices() == 290);
  CHECK(run.num_frames() == 19);  // 1.158 s at 15 fps: 0 to 17 / 15 s, then the end
  CHECK(deformseg::io::animation_format(fox) == "glb");
  CHECK_THROWS_WITH(deformseg::io::read_animation(fox, {.topology = fox}), Contains("no topology mesh applies"));
}

TEST_CASE("gltf: a character's clips, stripped of its meshes, played on its body give its frames", "[gltf][data]") {
  // Exactly: the stripped copy keeps the clips' bytes, and each channel finds its node by name.
  for (const char* name : {"Fox.glb", "Knight.glb"}) {
    INFO(name);
    const fs::path body = characters() / name;
    const fs::path clips = animation_only_copy(body, std::string("moves-") + name);
    const deformseg::io::Gltf_file own(body), bound(body, clips);
    REQUIRE(bound.clip_names() == own.clip_names());
    for (const std::string& clip : own.clip_names()) {
      INFO(clip);
      deformseg::io::Gltf_read_report report;
      const auto played = bound.read({.clip = clip}, &report);
      CHECK(std::ranges::equal(played.all_positions(), own.read({.clip = clip}).all_positions()));
      CHECK(report.joints > 0);
      CHECK(report.animated_joints > 0);
      CHECK(report.animated_joints <= report.joints);
    }
  }
}

TEST_CASE("gltf: clips in centimetres with Z up, played on a body in metres with Y up, give its frames",
          "[gltf][data]") {
  for (const std::string name : {"Fox.glb", "Knight.glb"}) {
    const fs::path body = characters() / name;
    const deformseg::io::Gltf_file own(body), bound(body, centimetres_z_up_copy(body, "cm-z-up-" + name));
    for (const std::string& clip : {own.clip_names().front(), own.clip_names().back()}) {
      INFO(name << " clip " << clip);
      const Sampled_gltf a = own.sample({.clip = clip}), b = bound.sample({.clip = clip});
      REQUIRE(a.report.frames == b.report.frames);
      double gap = 0, size = 0;
      for (std::size_t i = 0; i < a.positions.size(); ++i) {
        gap = std::max(gap, std::abs(a.positions[i] - b.positions[i]));
        size = std::max(size, std::abs(a.positions[i]));
      }
      CHECK(gap <= 1e-5 * size);  // the copy's keys are floats: centimetres rounded to 24 bits
    }
  }
}

TEST_CASE("gltf: the Knight's clips on the Barbarian's body are the Barbarian's own", "[gltf][data]") {
  // The KayKit characters share one rig and byte-identical clips.
  const fs::path barbarian = characters() / "Barbarian.glb", knight = characters() / "Knight.glb";
  const deformseg::io::Gltf_file own(barbarian), bound(barbarian, knight);
  const std::vector<std::string> names = own.clip_names();
  std::size_t shared = 0;
  for (const std::string& clip : bound.clip_names()) {
    if (std::find(names.begin(), names.end(), clip) == names.end()) continue;
    INFO(clip);
    ++shared;
    CHECK(std::ranges::equal(bound.read({.clip = clip}).all_positions(), own.read({.clip = clip}).all_positions()));
  }
  CHECK(shared == 76);
}

TEST_CASE("gltf: clips that move nothing of the body are refused, naming both files and joints", "[gltf][data]") {
  const fs::path knight = characters() / "Knight.glb", fox = characters() / "Fox.glb";
  const deformseg::io::Gltf_file bound(knight, fox);
  CHECK(bound.clip_names() == deformseg::io::Gltf_file(fox).clip_names());
  CHECK_THROWS_WITH(bound.read({.clip = "Walk"}), Contains(knight.string()) && Contains(fox.string()) &&
                                                       Contains("moves nothing of the body") &&
                                                       Contains("it animates 'b_") && Contains("more"));
  // The other way round: the Knight's walk names a node or two of the fox, none of them a joint.
  CHECK_THROWS_WITH(deformseg::io::Gltf_file(fox, knight).read({.clip = "Walking_A"}),
                    Contains(knight.string()) && Contains("moves nothing of the body " + fox.string()) &&
                        Contains("the body's joints are '_rootJoint', 'b_Root_00'"));
  CHECK_THROWS_WITH(deformseg::io::Gltf_file(knight, characters() / "missing.glb"), Contains("missing.glb"));
}

TEST_CASE("gltf: joints named with a namespace play on a body named without", "[gltf][data]") {
  // FBX writes a rig's namespace before its joints' names ("mixamorig:Hips"); one body's joints
  // match another's clips whatever the namespace, when one joint alone has the name without it.
  const fs::path fox = characters() / "Fox.glb";
  const fs::path clips = edited_copy(fox, "namespaced-fox.glb", [](tinygltf::Model& model) {
    for (auto& node : model.nodes)
      if (!node.name.empty()) node.name = "mixamorig:" + node.name;
  });
  const deformseg::io::Gltf_file own(fox), bound(fox, clips);
  for (const std::string& clip : own.clip_names()) {
    INFO(clip);
    CHECK(std::ranges::equal(bound.sample({.clip = clip}).positions, own.sample({.clip = clip}).positions));
  }
}
