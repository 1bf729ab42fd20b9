// BVH reader and the body made from a skeleton: small BVH files written here (frame rate, channel
// orders, malformed files), and the shared Fox's clip written as BVH (its skeleton's names and
// rest translations, every joint's translation and rotation at every frame), played back on the
// Fox's own body and on the body made from the BVH's skeleton.
#include "test_support.h"

#include <deformseg/io/config.h>

#if DEFORMSEG_HAS_ASSIMP

#include <deformseg/io/bvh.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/gltf_file.h>
#include <deformseg/io/read_animation.h>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace bvh_test {

namespace ds = deformseg;
namespace gltf = deformseg::io::internal::gltf;
namespace fs = std::filesystem;
using deformseg::test::data_dir;
using deformseg::test::write_file;
using Catch::Matchers::Contains;

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// ---- A glTF clip written as BVH ---------------------------------------------------------------

// The angles, in degrees, of the rotation `q` (x, y, z, w) about the axes `order` names in turn
// ("ZXY": R = Rz Rx Ry, as BVH composes its channels).
std::array<double, 3> euler_degrees(const std::array<double, 4>& q, const std::string& order) {
  const Eigen::Matrix3d rotation = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
  const auto axis = [&](int k) { return Eigen::Index(order[std::size_t(k)] - 'X'); };
  const Eigen::Vector3d angles = rotation.eulerAngles(axis(0), axis(1), axis(2));
  return {angles[0] * 180 / std::numbers::pi, angles[1] * 180 / std::numbers::pi, angles[2] * 180 / std::numbers::pi};
}

// A glTF file's clip as BVH: the skeleton of its first skin from its top joint (node names, rest
// translations as OFFSET), every joint with 6 channels (its translation, then its rotation as
// angles in `order`), keys at t = start + k / fps while t <= end.
class Bvh_writer {
public:
  Bvh_writer(const fs::path& character, std::size_t clip, double fps, std::string order)
      : model_(gltf::load_model(character)), rig_(gltf::read_rig(model_)), clip_(gltf::read_clip(model_, clip)),
        fps_(fps), order_(std::move(order)) {
    const std::vector<int>& joints = model_.skins.at(0).joints;
    is_joint_.assign(model_.nodes.size(), false);
    for (const int joint : joints) is_joint_[std::size_t(joint)] = true;
    for (const int joint : joints)
      if (rig_.forest.parent[std::size_t(joint)] < 0 || !is_joint_[std::size_t(rig_.forest.parent[std::size_t(joint)])])
        top_ = std::size_t(joint);
  }

  // The frames the BVH holds.
  std::size_t frames() const { return std::size_t(std::floor((clip_.end - clip_.start) * fps_ + 1e-3)) + 1; }

  std::string text() {
    std::string out = "HIERARCHY\n";
    write_joint(top_, 0, out);
    out += "MOTION\nFrames: " + std::to_string(frames()) + "\nFrame Time: " + number(1 / fps_) + "\n";
    gltf::Pose_scratch scratch;
    for (std::size_t k = 0; k < frames(); ++k) {
      gltf::pose_nodes(rig_, &clip_, clip_.start + double(k) / fps_, scratch);
      for (const std::size_t joint : order_of_joints_) {
        const gltf::Node_pose& pose = scratch.nodes[joint];
        for (const double x : pose.translation) out += number(x) + " ";
        for (const double angle : euler_degrees(pose.rotation, order_)) out += number(angle) + " ";
      }
      out.back() = '\n';
    }
    return out;
  }

private:
  void write_joint(std::size_t node, std::size_t depth, std::string& out) {
    const std::string indent(2 * depth, ' ');
    const auto& t = rig_.rest[node].translation;
    out += indent + (depth == 0 ? "ROOT " : "JOINT ") + model_.nodes[node].name + "\n" + indent + "{\n";
    out += indent + "  OFFSET " + number(t[0]) + " " + number(t[1]) + " " + number(t[2]) + "\n";
    out += indent + "  CHANNELS 6 Xposition Yposition Zposition " + std::string(1, order_[0]) + "rotation " +
           std::string(1, order_[1]) + "rotation " + std::string(1, order_[2]) + "rotation\n";
    order_of_joints_.push_back(node);
    for (const int child : model_.nodes[node].children)
      if (is_joint_[std::size_t(child)]) write_joint(std::size_t(child), depth + 1, out);
    out += indent + "}\n";
  }

  tinygltf::Model model_;
  gltf::Rig rig_;
  gltf::Clip clip_;
  double fps_;
  std::string order_;
  std::vector<bool> is_joint_{};
  std::size_t top_ = 0;
  std::vector<std::size_t> order_of_joints_{};
};

double diagonal(const ds::io::Sampled_gltf& sampled) {
  std::array<double, 3> low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < sampled.positions.size(); ++i)
    low[i % 3] = std::min(low[i % 3], sampled.positions[i]), high[i % 3] = std::max(high[i % 3], sampled.positions[i]);
  return std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
}

// The largest distance between a vertex of `a` and the same vertex of `b` over their first
// `frames` frames.
double largest_difference(const ds::io::Sampled_gltf& a, const ds::io::Sampled_gltf& b, std::size_t frames) {
  double largest = 0;
  for (std::size_t i = 0; i < 3 * a.num_vertices * frames; i += 3)
    largest = std::max(largest, std::hypot(a.positions[i] - b.positions[i], a.positions[i + 1] - b.positions[i + 1],
                                           a.positions[i + 2] - b.positions[i + 2]));
  return largest;
}

fs::path fox() { return data_dir() / "characters" / "Fox.glb"; }

// The Fox's clip `clip` written as BVH at 30 frames per second, in `order`.
fs::path fox_bvh(std::size_t clip, const std::string& order = "ZXY") {
  const std::string name = "io_bvh/fox_" + std::to_string(clip) + "_" + order + ".bvh";
  return write_file(name, Bvh_writer(fox(), clip, 30, order).text());
}

TEST_CASE("bvh: a glTF clip written as BVH plays on its own body as the glTF clip", "[bvh][data]") {
  // The Fox's joints have unit scale, as BVH's have: only translations and rotations to carry.
  const ds::io::Gltf_file own(fox());
  for (std::size_t clip = 0; clip < own.clip_names().size(); ++clip) {
    INFO(own.clip_names()[clip]);
    const ds::io::Sampled_gltf expected = own.sample({.clip = std::to_string(clip), .fps = 30, .threads = 1});
    const ds::io::Gltf_file bound(fox(), fox_bvh(clip));
    const ds::io::Sampled_gltf played = bound.sample({.fps = 30, .threads = 1});
    const std::size_t frames = Bvh_writer(fox(), clip, 30, "ZXY").frames();
    REQUIRE(played.report.frames == frames);
    CHECK(played.report.clip == "Motion");
    CHECK(played.report.animated_joints == played.report.joints);
    CHECK_FALSE(played.report.skeleton_body);
    // Assimp reads the BVH's numbers as single-precision floats, as the glTF file stores its keys.
    CHECK(largest_difference(expected, played, frames) <= 1e-6 * diagonal(expected));
  }
}

// The made body of a BVH file, with its skeleton and rig, read through the reader's internals.
struct Made_body {
  tinygltf::Model model;
  gltf::Skeleton skeleton;
  gltf::Rig rig;
  gltf::Clip clip;

  explicit Made_body(const fs::path& bvh) : model(ds::io::bvh_model(bvh)) {
    REQUIRE(gltf::add_skeleton_body(model));
    skeleton = gltf::skeleton_of(model);
    rig = gltf::read_rig(model);
    clip = gltf::read_clip(model, 0);
  }
};

double distance_to_line(const double* p, const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const Eigen::Vector3d d = Eigen::Vector3d(b[0] - a[0], b[1] - a[1], b[2] - a[2]).normalized();
  const Eigen::Vector3d v(p[0] - a[0], p[1] - a[1], p[2] - a[2]);
  return (v - v.dot(d) * d).norm();
}

TEST_CASE("bvh: on the body made from its skeleton, every tube follows its bone", "[bvh][data]") {
  const fs::path bvh = fox_bvh(1);
  const ds::io::Gltf_file file(bvh);
  const ds::io::Sampled_gltf played = file.sample({.fps = 30, .threads = 1});
  CHECK(played.report.skeleton_body);
  const Made_body made(bvh);
  const std::size_t bones = made.skeleton.bones.size();
  // Of the Fox's 24 joints, the top one ends no bone, and b_Root_00 stands where it does.
  CHECK(bones == 22);
  REQUIRE(played.num_vertices == bones * gltf::Tube_shape::vertices);
  CHECK(played.triangles.size() == bones * gltf::Tube_shape::triangles);
  const double tolerance = 1e-6 * diagonal(played);
  std::vector<double> rest(3 * played.num_vertices);
  gltf::Pose_scratch scratch;
  gltf::pose_at(made.rig, nullptr, 0, scratch, rest.data());
  std::size_t bones_of_fixed_length = 0;
  for (std::size_t t = 0; t < played.report.frames; ++t) {
    gltf::pose_nodes(made.rig, &made.clip, made.clip.start + double(t) / 30, scratch);
    const double* frame = played.positions.data() + 3 * played.num_vertices * t;
    for (std::size_t b = 0; b < bones; ++b) {
      const gltf::Bone& bone = made.skeleton.bones[b];
      const gltf::Affine motion = scratch.world[bone.joint] * gltf::inverse(made.skeleton.rest[bone.joint]);
      const std::array<double, 3> start = gltf::origin(scratch.world[bone.joint]);
      const std::array<double, 3> end = gltf::origin(scratch.world[bone.child]);
      const double length = gltf::distance(gltf::origin(made.skeleton.rest[bone.joint]),
                                           gltf::origin(made.skeleton.rest[bone.child]));
      const bool fixed_length = std::abs(gltf::distance(start, end) - length) <= tolerance;
      bones_of_fixed_length += fixed_length && t == 0;
      // The middle rings (at a quarter, half and three quarters of the bone) move with the joint.
      for (std::size_t ring = 2; ring <= 4; ++ring)
        for (std::size_t s = 0; s < gltf::Tube_shape::sides; ++s) {
          const std::size_t v = b * gltf::Tube_shape::vertices + ring * gltf::Tube_shape::sides + s;
          double expected[3];
          motion.apply(rest.data() + 3 * v, expected);
          const double* p = frame + 3 * v;
          CHECK(std::hypot(p[0] - expected[0], p[1] - expected[1], p[2] - expected[2]) <= tolerance);
          if (fixed_length)
            CHECK(std::abs(distance_to_line(p, start, end) - gltf::Tube_shape::radius * length) <= tolerance);
        }
    }
  }
  CHECK(bones_of_fixed_length >= bones - 4);  // the hips' translation stretches the bones that end there
}

TEST_CASE("bvh: the made body is closed, outward and unwelded, and every clip of a skeleton has the same",
          "[bvh][data]") {
  const ds::io::Gltf_file walk(fox_bvh(1)), run(fox_bvh(2));
  const ds::io::Repaired_triangles repaired = walk.repair();
  CHECK(repaired.report.welded_vertices == 0);
  CHECK(repaired.report.duplicated_vertices == 0);
  CHECK(repaired.report.reoriented_triangles == 0);
  CHECK(repaired.report.non_manifold_edges == 0);
  // The rest pose of each file's body: one body.
  const auto rest_of = [](const fs::path& bvh) {
    const Made_body made(bvh);
    std::vector<double> rest(3 * made.rig.geometry.vertices);
    gltf::Pose_scratch scratch;
    gltf::pose_at(made.rig, nullptr, 0, scratch, rest.data());
    return std::pair(rest, made.rig.geometry.triangles);
  };
  const auto [a, triangles] = rest_of(fox_bvh(1));
  const auto [b, same_triangles] = rest_of(fox_bvh(2));
  CHECK(a == b);
  CHECK(triangles == same_triangles);
  // Outward: the volume the triangles enclose is positive.
  double volume = 0;
  for (const auto& triangle : triangles) {
    const auto p = [&](int k) { return Eigen::Vector3d(a.data() + 3 * std::size_t(triangle[std::size_t(k)])); };
    volume += p(0).dot(p(1).cross(p(2))) / 6;
  }
  CHECK(volume > 0);
  CHECK(walk.contents().skeleton_body);
  CHECK(run.sample({.fps = 30, .threads = 1}).report.frames > 1);
}

TEST_CASE("bvh: an animation-only glTF model plays on the body made from its skeleton", "[bvh][data]") {
  tinygltf::Model model = gltf::load_model(fox());
  for (tinygltf::Node& node : model.nodes) node.mesh = -1, node.skin = -1;
  const ds::io::Gltf_file file("fox-without-mesh.glb", std::move(model));
  ds::io::Gltf_read_report report;
  const auto animation = file.read({.clip = "Walk", .fps = 30, .threads = 1}, &report);
  CHECK(report.skeleton_body);
  // The clips move b_Hip_01 and joints below it: the 21 joints below it end a bone each.
  CHECK(animation.num_vertices() == 21 * gltf::Tube_shape::vertices);
  CHECK(file.contents().skeleton_body);
}

// ---- Small BVH files written here -------------------------------------------------------------

// A root at the origin with one child 2 units up and an end site 1 unit further; the root's channels
// `root_channels`, the child's `child_channels`, and the MOTION lines `motion`.
std::string two_joints(const std::string& root_channels, const std::string& child_channels, const std::string& motion) {
  return "HIERARCHY\nROOT Root\n{\n  OFFSET 0 0 0\n  CHANNELS " + root_channels + "\n  JOINT Arm\n  {\n"
         "    OFFSET 0 2 0\n    CHANNELS " + child_channels + "\n    End Site\n    {\n      OFFSET 0 1 0\n    }\n"
         "  }\n}\nMOTION\n" + motion;
}

TEST_CASE("bvh: the clip's keys are Frame Time apart, its joints are named as in the file", "[bvh]") {
  const fs::path path = write_file("io_bvh/rate.bvh",
                                   two_joints("6 Xposition Yposition Zposition Zrotation Xrotation Yrotation",
                                              "3 Zrotation Xrotation Yrotation",
                                                         "Frames: 5\nFrame Time: 0.04\n"
                                                  "0 0 0 0 0 0 0 0 0\n0 0 0 0 0 0 10 0 0\n0 0 0 0 0 0 20 0 0\n"
                                                  "0 0 0 0 0 0 30 0 0\n0 0 0 0 0 0 40 0 0\n"));
  const ds::io::Gltf_contents contents = ds::io::gltf_contents(path, 25);
  REQUIRE(contents.clips.size() == 1);
  CHECK(contents.clips[0].name == "Motion");
  CHECK(contents.clips[0].duration == Approx(0.16).epsilon(1e-6));
  CHECK(contents.clips[0].frames == 5);
  CHECK(ds::io::gltf_contents(path, 50).clips[0].frames == 9);
  CHECK(contents.skeleton_body);
  const tinygltf::Model model = ds::io::bvh_model(path);
  std::vector<std::string> names;
  for (const tinygltf::Node& node : model.nodes) names.push_back(node.name);
  CHECK(names == std::vector<std::string>{"deformseg: metres", "Root", "Arm", "EndSite_Arm"});
  // The root's position and rotation, the arm's rotation: what Assimp makes up (a scale for every
  // joint, the arm's OFFSET as its position) is left out, so that another body keeps its own.
  REQUIRE(model.animations.size() == 1);
  std::vector<std::string> channels;
  for (const tinygltf::AnimationChannel& channel : model.animations[0].channels)
    channels.push_back(model.nodes[std::size_t(channel.target_node)].name + " " + channel.target_path);
  std::sort(channels.begin(), channels.end());
  CHECK(channels == std::vector<std::string>{"Arm rotation", "Root rotation", "Root translation"});
  // Root -> Arm and Arm -> its end site: two tubes.
  const auto animation = ds::io::read_animation(path.string(), {.fps = 25});
  CHECK(animation.num_frames() == 5);
  CHECK(animation.num_vertices() == 2 * gltf::Tube_shape::vertices);
  CHECK(ds::io::animation_format(path.string()) == "bvh");
}

TEST_CASE("bvh: rotation channels in any order compose as listed", "[bvh]") {
  // One rotation per frame, written as Z X Y angles and as the X Y Z angles of the same rotation.
  const std::vector<std::array<double, 3>> zxy = {{0, 0, 0}, {30, 20, 10}, {-45, 60, 120}, {170, -10, 80}};
  std::string as_zxy = "Frames: 4\nFrame Time: 0.1\n", as_xyz = as_zxy;
  for (const auto& [z, x, y] : zxy) {
    const auto radians = [](double degrees) { return degrees * std::numbers::pi / 180; };
    const Eigen::Quaterniond q(Eigen::AngleAxisd(radians(z), Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(radians(x), Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(radians(y), Eigen::Vector3d::UnitY()));
    const std::array<double, 3> xyz = euler_degrees({q.x(), q.y(), q.z(), q.w()}, "XYZ");
    as_zxy += "0 0 0 " + number(z) + " " + number(x) + " " + number(y) + " 0 0 0\n";
    as_xyz += "0 0 0 " + number(xyz[0]) + " " + number(xyz[1]) + " " + number(xyz[2]) + " 0 0 0\n";
  }
  const std::string channels = "6 Xposition Yposition Zposition Zrotation Xrotation Yrotation";
  const fs::path a = write_file("io_bvh/zxy.bvh", two_joints(channels, "3 Zrotation Xrotation Yrotation", as_zxy));
  const fs::path b = write_file("io_bvh/xyz.bvh",
                                two_joints("6 Xposition Yposition Zposition Xrotation Yrotation Zrotation",
                                           "3 Xrotation Yrotation Zrotation", as_xyz));
  // Both turn the root, by angles in different orders: the end site goes to the same places.
  const auto end_site = [](const fs::path& path, std::size_t frame) {
    const tinygltf::Model model = ds::io::bvh_model(path);
    const gltf::Rig rig = gltf::read_rig(model);
    const gltf::Clip clip = gltf::read_clip(model, 0);
    gltf::Pose_scratch scratch;
    gltf::pose_nodes(rig, &clip, double(frame) / 10, scratch);
    return gltf::origin(scratch.world.back());
  };
  for (std::size_t frame = 0; frame < zxy.size(); ++frame) {
    INFO("frame " << frame);
    const auto p = end_site(a, frame), q = end_site(b, frame);
    CHECK(gltf::distance(p, q) <= 1e-6);
    if (frame > 0) CHECK(gltf::distance(p, {0, 3, 0}) > 0.1);  // it turned
  }
}

TEST_CASE("bvh: malformed files are refused, naming the file and the line", "[bvh]") {
  const std::string channels = "6 Xposition Yposition Zposition Zrotation Xrotation Yrotation";
  const std::string motion = "Frames: 1\nFrame Time: 0.1\n0 0 0 0 0 0 0 0 0\n";
  const auto refused = [](const std::string& name, const std::string& text) {
    const fs::path path = write_file("io_bvh/" + name, text);
    try {
      static_cast<void>(ds::io::Gltf_file(path));
    } catch (const ds::invalid_input& e) {
      CHECK(e.where().file == path.string());
      return std::string(e.what());
    }
    FAIL("read " << name);
    return std::string();
  };
  CHECK_THAT(refused("value.bvh", two_joints(channels, "3 Zrotation Xrotation Yrotation",
                                             "Frames: 1\nFrame Time: 0.1\n0 0 0 0 0 0 0 0 zero\n")),
             Contains("value.bvh: not a valid BVH file: "));
  CHECK_THAT(refused("unknown.bvh", "HIERARCHY\nROOT A\n{\n  OFFSET 0 0 0\n  WHAT 3\n}\nMOTION\n"),
             Contains("not a valid BVH file: line 5: Unknown keyword \"WHAT\""));
  CHECK_THAT(refused("positions.bvh", two_joints(channels, "3 Xposition Yposition Zposition", motion)),
             Contains("positions.bvh:9: joint 'Arm' has 3 channels, some of them positions"));
  CHECK_THAT(refused("twice.bvh", "HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 0\n JOINT A\n {\n  OFFSET 0 1 0\n"
                                  "  CHANNELS 0\n }\n}\nMOTION\nFrames: 0\nFrame Time: 1\n"),
             Contains("twice.bvh:6: two joints are named 'A'"));
  CHECK_THAT(refused("frames.bvh", two_joints(channels, "3 Zrotation Xrotation Yrotation",
                                              "Frames: 1000000\nFrame Time: 0.1\n0 0 0\n")),
             Contains("frames.bvh:18: 1000000 frames of 9 channels claimed, more values than the file holds"));
  CHECK_THAT(refused("time.bvh", two_joints(channels, "3 Zrotation Xrotation Yrotation",
                                            "Frames: 1\nFrame Time: 0\n0 0 0 0 0 0 0 0 0\n")),
             Contains("time.bvh:18: the Frame Time must be a positive number of seconds"));
  CHECK_THAT(refused("short.bvh", two_joints(channels, "3 Zrotation Xrotation Yrotation",
                                             "Frames: 2\nFrame Time: 0.1\n0 0 0 0 0 0 0 0 0\n")),
             Contains("short.bvh:18: 2 frames of 9 channels claimed"));
  CHECK_THAT(refused("obj.bvh", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), Contains("obj.bvh:1: not a BVH file"));
  CHECK_THAT(refused("missing.bvh", ""), Contains("missing.bvh"));
}

// A damaged file's bytes (E9, a Latin-1 e acute; 1B, a terminal's escape) reach the message as \xHH,
// both in Assimp's words and in deformseg's own checks.
TEST_CASE("bvh: a message quotes a damaged file's bytes escaped, never raw", "[bvh][errors]") {
  const auto message_of = [](const std::string& name, const std::string& text) {
    try {
      static_cast<void>(ds::io::Gltf_file(write_file("io_bvh/" + name, text)));
    } catch (const ds::invalid_input& e) {
      return std::string(e.what());
    }
    FAIL("read " << name);
    return std::string();
  };
  const std::string keyword =
      message_of("keyword.bvh", "HIERARCHY\nROOT A\n{\n  OFFSET 0 0 0\n  WH\xE9\x1B 3\n}\nMOTION\n");
  CHECK_THAT(keyword, Contains("not a valid BVH file: line 5: Unknown keyword \"WH\\xE9\\x1B\""));
  const std::string count =
      message_of("count.bvh", "HIERARCHY\nROOT A\xE9\n{\n  OFFSET 0 0 0\n  CHANNELS 3\xE9\n}\n");
  CHECK_THAT(count, Contains("count.bvh:5: joint 'A\\xE9' CHANNELS count must be a whole number, not '3\\xE9'"));
  for (const std::string& message : {keyword, count})
    CHECK((message.find('\xE9') == std::string::npos && message.find('\x1B') == std::string::npos));
}

TEST_CASE("bvh: a file of no mesh and no bone is refused with the hint to give a body", "[bvh]") {
  const fs::path path = write_file("io_bvh/one_joint.bvh",
                                   "HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n}\n"
                                   "MOTION\nFrames: 2\nFrame Time: 0.1\n0 0 0\n0 0 90\n");
  CHECK_THROWS_WITH(ds::io::Gltf_file(path),
                    Contains("one_joint.bvh") && Contains("no mesh: play it on a body with --body FILE"));
  // Its clip is still listed, to be played on another body.
  const ds::io::Gltf_contents contents = ds::io::gltf_contents(path);
  CHECK(contents.clips.size() == 1);
  CHECK_FALSE(contents.skeleton_body);
}

}  // namespace bvh_test

#endif
