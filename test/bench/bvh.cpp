// How fast deformseg reads a BVH clip onto the body made from its skeleton: the file parsed
// (deformseg's checks, Assimp's reader, the adapter into glTF's structures), the body made (a
// tube along each bone), every frame sampled, skinned and stored, on one thread.
//
//   build-bench/test/bench/bvh [--benchmark_filter=...]
//
// The clip is written here: a body of 23 joints as motion capture records one (hips; a spine of
// 4, a neck and a head; two arms of a collar, shoulder, elbow and wrist; two legs of a hip, knee,
// ankle and toe; end sites at the head, hands and toes: 27 bones, 1,566 vertices), every joint
// turning on three channels and the hips moving, at 120 frames per second, for 1, 10 and 100 s
// (120, 1,200 and 12,000 frames). Reports frames read per second (items) on one core; the goal of
// issue 56 is 10,000.
#include <deformseg/io/gltf.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr double frames_per_second = 120;

// A joint of the body: its name, its offset from its parent, and its chain of children.
struct Joint {
  std::string name;
  double x, y, z;
  std::vector<Joint> children{};
};

// A chain of joints, each `step` below the one before, the last with an end site.
Joint chain(const std::vector<std::string>& names, double x, double y, double z, double dx, double dy, double dz) {
  Joint first{names.front(), x, y, z};
  Joint* at = &first;
  for (std::size_t k = 1; k < names.size(); ++k) {
    at->children.push_back({names[k], dx, dy, dz});
    at = &at->children.back();
  }
  return first;
}

Joint body() {
  Joint hips{"Hips", 0, 0.95, 0};
  Joint spine = chain({"Spine", "Spine1", "Spine2", "Spine3", "Neck", "Head"}, 0, 0.1, 0, 0, 0.1, 0);
  Joint* chest = &spine.children[0].children[0].children[0];
  for (const double side : {1.0, -1.0}) {
    const std::string name = side > 0 ? "Left" : "Right";
    chest->children.push_back(chain({name + "Collar", name + "Shoulder", name + "Elbow", name + "Wrist"}, 0.05 * side,
                                    0.05, 0, 0.15 * side, 0, 0));
  }
  hips.children.push_back(spine);
  for (const double side : {1.0, -1.0}) {
    const std::string name = side > 0 ? "Left" : "Right";
    hips.children.push_back(chain({name + "Hip", name + "Knee", name + "Ankle", name + "Toe"}, 0.1 * side, -0.05, 0, 0,
                                  -0.3, 0.02));
  }
  return hips;
}

void write_hierarchy(const Joint& joint, int depth, std::string& out, int& joints) {
  const std::string indent(std::size_t(2 * depth), ' ');
  char offset[96];
  std::snprintf(offset, sizeof offset, "OFFSET %g %g %g\n", joint.x, joint.y, joint.z);
  out += indent + (depth == 0 ? "ROOT " : "JOINT ") + joint.name + "\n" + indent + "{\n" + indent + "  " + offset;
  out += indent + (depth == 0 ? "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                              : "  CHANNELS 3 Zrotation Xrotation Yrotation\n");
  ++joints;
  for (const Joint& child : joint.children) write_hierarchy(child, depth + 1, out, joints);
  if (joint.children.empty())
    out += indent + "  End Site\n" + indent + "  {\n" + indent + "    OFFSET 0 0.05 0\n" + indent + "  }\n";
  out += indent + "}\n";
}

// The clip of `frames` frames: every angle a sine of its own phase, the hips walking forwards.
fs::path write_clip(std::size_t frames) {
  std::string text = "HIERARCHY\n";
  int joints = 0;
  write_hierarchy(body(), 0, text, joints);
  text += "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: " + std::to_string(1 / frames_per_second) + "\n";
  char value[32];
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = double(f) / frames_per_second;
    std::snprintf(value, sizeof value, "%.6f 0.95 0 ", t);
    text += value;
    for (int c = 0; c < 3 * joints; ++c) {
      std::snprintf(value, sizeof value, c + 1 < 3 * joints ? "%.4f " : "%.4f\n", 20 * std::sin(2 * t + 0.7 * c));
      text += value;
    }
  }
  const fs::path path = fs::temp_directory_path() / ("deformseg-bench-" + std::to_string(frames) + ".bvh");
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

void read_onto_made_body(benchmark::State& state) {
  const auto frames = std::size_t(state.range(0));
  const fs::path path = write_clip(frames);
  std::size_t vertices = 0;
  for (auto _ : state) {
    const deformseg::io::Gltf_file file(path);
    const auto animation = file.read({.fps = frames_per_second, .threads = 1});
    vertices = animation.num_vertices();
    benchmark::DoNotOptimize(animation.frame_positions(animation.num_frames() - 1).data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(frames));
  state.counters["vertices"] = double(vertices);
  fs::remove(path);
}

}  // namespace

BENCHMARK(read_onto_made_body)->Arg(120)->Arg(1200)->Arg(12000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
