// How fast deformseg samples and skins glTF characters.
//
//   build-bench/test/bench/gltf [--benchmark_filter=...]
//
// - Skinning: a synthetic character made here (30000 vertices on a tube around a chain of 67
//   joints, 4 influences per vertex, every joint rotating, LINEAR keys at 30 per second over 2 s),
//   parsed once; reports skinned vertices per second (items) on 1 thread and on all.
// - KayKit: each Adventurers body of the shared data (../shared/data/characters, or
//   $DEFORMSEG_DATA_DIR/characters), read whole: parsed, then every one of its 76 clips sampled
//   at 30 fps. Skipped when the data is absent.
// - FBX and Collada: each character of ../shared/data/fbx-collada read whole (Assimp's parse, the
//   scene written as glTF, every clip sampled at 30 fps on 1 thread), against the same scene
//   saved as .glb (fbx_collada_model, then tinygltf) read by the glTF path: skinned vertices per
//   second of both, at three sizes (4734, 14643 and 19554 vertices before welding).
#include <deformseg/io/gltf.h>
#include <deformseg/threads.h>

#if DEFORMSEG_HAS_ASSIMP
#include <deformseg/io/fbx_collada.h>
#endif

#include <tiny_gltf.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr int joint_count = 67;
constexpr int rings = 300;              // along the chain
constexpr int ring_vertices = 100;      // around it: 30000 vertices
constexpr double bone_length = 0.1;

template <class T>
int add_accessor(tinygltf::Model& model, const std::vector<T>& values, int component_type, int type, int components) {
  auto& bytes = model.buffers[0].data;
  const std::size_t offset = bytes.size();
  bytes.resize(offset + values.size() * sizeof(T));
  std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
  while (bytes.size() % 4 != 0) bytes.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = values.size() * sizeof(T);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size()) - 1;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = values.size() / std::size_t(components);
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

int add_floats(tinygltf::Model& model, const std::vector<float>& values, int type, int components) {
  return add_accessor(model, values, TINYGLTF_COMPONENT_TYPE_FLOAT, type, components);
}

void add_geometry(tinygltf::Model& model) {
  const double height = joint_count * bone_length;
  std::vector<float> positions;
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
  for (int r = 0; r < rings; ++r) {
    const double y = height * r / (rings - 1);
    const double along = y / bone_length;  // in bones
    const int j = std::min(int(along), joint_count - 1);
    const double f = std::min(along - j, 1.0);
    for (int k = 0; k < ring_vertices; ++k) {
      const double a = 2 * std::numbers::pi * k / ring_vertices;
      positions.insert(positions.end(), {float(0.05 * std::cos(a)), float(y), float(0.05 * std::sin(a))});
      const auto clamp = [](int i) { return std::uint16_t(std::clamp(i, 0, joint_count - 1)); };
      joints.insert(joints.end(), {clamp(j - 1), clamp(j), clamp(j + 1), clamp(j + 2)});
      weights.insert(weights.end(), {float(0.2 * (1 - f)), float(0.6 * (1 - f) + 0.2 * f),
                                     float(0.2 * (1 - f) + 0.6 * f), float(0.2 * f)});
    }
  }
  std::vector<std::uint32_t> indices;
  for (int r = 0; r + 1 < rings; ++r)
    for (int k = 0; k < ring_vertices; ++k) {
      const auto a = std::uint32_t(r * ring_vertices + k),
                 b = std::uint32_t(r * ring_vertices + (k + 1) % ring_vertices);
      indices.insert(indices.end(), {a, b + ring_vertices, b, a, a + ring_vertices, b + ring_vertices});
    }
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] = add_floats(model, positions, TINYGLTF_TYPE_VEC3, 3);
  primitive.attributes["JOINTS_0"] =
      add_accessor(model, joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, 4);
  primitive.attributes["WEIGHTS_0"] = add_floats(model, weights, TINYGLTF_TYPE_VEC4, 4);
  primitive.indices = add_accessor(model, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, 1);
  tinygltf::Mesh mesh;
  mesh.name = "tube";
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
}

// Joints 0..66 in a chain along y, then the skinned mesh node; every joint sways about z and x.
void add_skeleton_and_clip(tinygltf::Model& model) {
  std::vector<float> inverse_bind;
  for (int j = 0; j < joint_count; ++j) {
    tinygltf::Node joint;
    joint.name = "joint" + std::to_string(j);
    if (j > 0) joint.translation = {0, bone_length, 0};
    if (j + 1 < joint_count) joint.children = {j + 1};
    model.nodes.push_back(joint);
    inverse_bind.insert(inverse_bind.end(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, float(-bone_length * j), 0, 1});
  }
  tinygltf::Node body;
  body.mesh = 0;
  body.skin = 0;
  model.nodes.push_back(body);
  tinygltf::Skin skin;
  for (int j = 0; j < joint_count; ++j) skin.joints.push_back(j);
  skin.inverseBindMatrices = add_floats(model, inverse_bind, TINYGLTF_TYPE_MAT4, 16);
  model.skins.push_back(skin);
  tinygltf::Scene scene;
  scene.nodes = {0, joint_count};
  model.scenes.push_back(scene);

  std::vector<float> times;
  for (int k = 0; k <= 60; ++k) times.push_back(float(k) / 30);
  const int input = add_floats(model, times, TINYGLTF_TYPE_SCALAR, 1);
  tinygltf::Animation sway;
  sway.name = "sway";
  for (int j = 0; j < joint_count; ++j) {
    std::vector<float> rotations;
    for (float t : times) {
      const double a = 0.1 * std::sin(2 * std::numbers::pi * t + 0.1 * j), b = 0.05 * std::cos(3 * t + 0.2 * j);
      const double n = std::sqrt(a * a + b * b + 1);
      rotations.insert(rotations.end(), {float(b / n), 0, float(a / n), float(1 / n)});
    }
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = add_floats(model, rotations, TINYGLTF_TYPE_VEC4, 4);
    sway.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = j;
    channel.target_node = j;
    channel.target_path = "rotation";
    sway.channels.push_back(channel);
  }
  model.animations.push_back(sway);
}

const fs::path& synthetic_character() {
  static const fs::path path = [] {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.buffers.resize(1);
    add_geometry(model);
    add_skeleton_and_clip(model);
    const fs::path file = fs::temp_directory_path() / "deformseg_bench_tube.glb";
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, file.string(), false, true, false, true))
      throw std::runtime_error("cannot write " + file.string());
    return file;
  }();
  return path;
}

void skinning(benchmark::State& state, int threads) {
  const deformseg::io::Gltf_file file(synthetic_character());
  std::size_t vertices = 0;
  for (auto _ : state) {
    const auto sampled = file.sample({.threads = threads});
    vertices += sampled.report.frames * sampled.num_vertices;
    benchmark::DoNotOptimize(sampled.positions.data());
  }
  state.SetItemsProcessed(std::int64_t(vertices));
  state.counters["threads"] = threads;
  state.counters["vertices"] = double(file.num_vertices());
}

void skinning_one_thread(benchmark::State& state) { skinning(state, 1); }
void skinning_all_threads(benchmark::State& state) {
  skinning(state, deformseg::thread_count(0));
}

fs::path characters() {
  const char* dir = std::getenv("DEFORMSEG_DATA_DIR");
  return fs::path(dir && *dir ? dir : DEFORMSEG_DATA_DIR) / "characters";
}

void kaykit_every_clip(benchmark::State& state, const std::string& body) {
  const fs::path path = characters() / body;
  if (!fs::exists(path)) {
    state.SkipWithError(("no " + path.string()).c_str());
    return;
  }
  std::size_t frames = 0, vertices = 0;
  for (auto _ : state) {
    const deformseg::io::Gltf_file file(path);
    for (const std::string& clip : file.clip_names()) {
      const auto sampled = file.sample({.clip = clip, .threads = 1});
      frames += sampled.report.frames;
      vertices += sampled.report.frames * sampled.num_vertices;
    }
  }
  state.SetItemsProcessed(std::int64_t(vertices));
  state.counters["frames"] = benchmark::Counter(double(frames), benchmark::Counter::kAvgIterations);
}

#if DEFORMSEG_HAS_ASSIMP
// `name` of the shared FBX and Collada characters, and the same scene saved as a .glb file.
std::pair<fs::path, fs::path> fbx_collada_and_glb(const std::string& name) {
  const char* dir = std::getenv("DEFORMSEG_DATA_DIR");
  const fs::path source = fs::path(dir && *dir ? dir : DEFORMSEG_DATA_DIR) / "fbx-collada" / name;
  const fs::path glb = fs::temp_directory_path() / ("deformseg_bench_" + name + ".glb");
  if (fs::exists(source) && !fs::exists(glb)) {
    tinygltf::Model model = deformseg::io::fbx_collada_model(source);
    if (!tinygltf::TinyGLTF().WriteGltfSceneToFile(&model, glb.string(), false, true, false, true))
      throw std::runtime_error("cannot write " + glb.string());
  }
  return {source, glb};
}

// Reads `name` whole, from its own file (`as_glb` false) or from the .glb of its scene.
void character_every_clip(benchmark::State& state, const std::string& name, bool as_glb) {
  const auto [source, glb] = fbx_collada_and_glb(name);
  if (!fs::exists(source)) {
    state.SkipWithError(("no " + source.string()).c_str());
    return;
  }
  std::size_t vertices = 0;
  for (auto _ : state) {
    const deformseg::io::Gltf_file file(as_glb ? glb : source);
    for (const std::string& clip : file.clip_names()) {
      const auto sampled = file.sample({.clip = clip, .threads = 1});
      vertices += sampled.report.frames * sampled.num_vertices;
    }
  }
  state.SetItemsProcessed(std::int64_t(vertices));
}
#endif

}  // namespace

#if DEFORMSEG_HAS_ASSIMP
BENCHMARK_CAPTURE(character_every_clip, man_fbx, std::string("quat_man.fbx"), false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(character_every_clip, man_glb, std::string("quat_man.fbx"), true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(character_every_clip, astroboy_dae, std::string("astroboy_walk_max.dae"), false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(character_every_clip, astroboy_glb, std::string("astroboy_walk_max.dae"), true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(character_every_clip, stormtrooper_dae, std::string("stormtrooper.dae"), false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(character_every_clip, stormtrooper_glb, std::string("stormtrooper.dae"), true)->Unit(benchmark::kMillisecond);
#endif
BENCHMARK(skinning_one_thread)->Unit(benchmark::kMillisecond);
BENCHMARK(skinning_all_threads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(kaykit_every_clip, Knight, std::string("Knight.glb"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kaykit_every_clip, Barbarian, std::string("Barbarian.glb"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kaykit_every_clip, Mage, std::string("Mage.glb"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kaykit_every_clip, Rogue, std::string("Rogue.glb"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(kaykit_every_clip, Rogue_Hooded, std::string("Rogue_Hooded.glb"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
