// How fast compute_strain is, in triangle-frames per second (items_per_second), on one and two
// threads, with and without the Gaussian normalisation, and where the time goes.
//
//   build/test/bench/strain [--benchmark_filter=...]
//
// Animations: the horse gallop of the shared data (../shared/data, or $DEFORMSEG_DATA_DIR),
// unpacked with tar into a temporary folder (skipped when absent), and a bending tube of 100,500
// triangles and 200 frames made here. The `stage` benchmarks run the kernel's loops one thread
// one at a time over the tube, to show what limits it: gathering the edges through the index
// table, the double transform to C - I, the float measure, the normalisation's statistic and map.
#include <deformseg/io/frame_sequence.h>
#include <deformseg/strain/strain.h>
#include <deformseg/mesh/synthetic.h>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace deformseg;

namespace {

const mesh::Surface_mesh_animation& tube() {
  static const mesh::Surface_mesh_animation animation = [] {
    mesh::Bending_tube spec;
    spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 250, .rings = 200, .caps = true};
    spec.joints = {{.position = 0.3, .blend_width = 0.2}, {.position = 0.7, .blend_width = 0.2}};
    const double right = std::numbers::pi / 2;
    spec.schedule = {{50, {right, 0.0}}, {50, {right, right}}, {50, {}}, {49, {0.0, 0.0}}};
    return mesh::make_bending_tube(spec).animation;  // 100,500 triangles, 200 frames
  }();
  return animation;
}

const std::optional<mesh::Surface_mesh_animation>& horse() {
  static const std::optional<mesh::Surface_mesh_animation> animation =
      []() -> std::optional<mesh::Surface_mesh_animation> {
    const char* from_environment = std::getenv("DEFORMSEG_DATA_DIR");
    const fs::path data =
        from_environment && *from_environment ? fs::path(from_environment) : fs::path(DEFORMSEG_DATA_DIR);
    const fs::path archive = data / "horse-gallop" / "horse-gallop.tar.xz";
    if (!fs::exists(archive)) {
      std::fprintf(stderr, "%s not found: no horse benchmarks\n", archive.c_str());
      return std::nullopt;
    }
    const fs::path target = fs::temp_directory_path() / "deformseg-bench-strain";
    fs::remove_all(target);
    fs::create_directories(target);
    const std::string command = "tar xJf '" + archive.string() + "' -C '" + target.string() + "'";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
    return io::read_frame_sequence((target / "horse-gallop").string());
  }();
  return animation;
}

void report(benchmark::State& state, const mesh::Surface_mesh_animation& a) {
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(a.num_faces() * a.num_frames()));
  state.counters["triangles"] = double(a.num_faces());
  state.counters["frames"] = double(a.num_frames());
}

// compute_strain, rest pose; range(0): threads, range(1): 1 with the Gaussian normalisation.
void run(benchmark::State& state, const mesh::Surface_mesh_animation& a) {
  const int threads = int(state.range(0));
  const bool normalised = state.range(1) != 0;
  for (auto _ : state) {
    if (normalised)
      benchmark::DoNotOptimize(strain::compute_strain(a, {.threads = threads}));
    else
      benchmark::DoNotOptimize(strain::compute_strain(
          a, strain::Strain_options{.normalization = strain::No_normalization{}, .threads = threads}));
  }
  report(state, a);
}

void tube_strain(benchmark::State& state) { run(state, tube()); }

void horse_strain(benchmark::State& state) {
  if (!horse()) {
    state.SkipWithError("no horse gallop data");
    for (auto _ : state) {
    }
    return;
  }
  run(state, *horse());
}

void previous_pose_strain(benchmark::State& state) {
  const auto& a = tube();
  for (auto _ : state)
    benchmark::DoNotOptimize(strain::compute_strain(
        a, {.reference = strain::Strain_reference::previous_pose, .threads = int(state.range(0))}));
  report(state, a);
}

void strain_with_directions(benchmark::State& state) {
  const auto& a = tube();
  for (auto _ : state)
    benchmark::DoNotOptimize(strain::compute_strain(a, {.principal_directions = true, .threads = int(state.range(0))}));
  report(state, a);
}

void double_strain(benchmark::State& state) {
  const auto& a = tube();
  for (auto _ : state) benchmark::DoNotOptimize(strain::compute_strain<double>(a, {.threads = int(state.range(0))}));
  report(state, a);
}

// The kernel's stages, one thread, over every frame of the tube: range(0) = how many stages run
// (1: gather the edges; 2: and transform them to C - I in double; 3: and measure, in float).
void stage(benchmark::State& state) {
  const auto& a = tube();
  const auto triangles = deformseg::strain::internal::canonical_triangles(a.triangles());
  const auto bases = deformseg::strain::internal::reference_bases(
      a.frame_positions(0).data(), std::span<const deformseg::strain::internal::Triangle_indices>(triangles), 1e-12, 1);
  const auto stages = state.range(0);
  deformseg::strain::internal::Edge_block edges;
  deformseg::strain::internal::Cauchy_green_block<float> green;
  std::vector<float> strain(a.num_faces());
  for (auto _ : state)
    for (std::size_t t = 0; t < a.num_frames(); ++t) {
      const double* xyz = a.frame_positions(t).data();
      for (std::size_t j = 0; j < triangles.size(); j += deformseg::strain::internal::strain_block) {
        const std::size_t n = std::min(deformseg::strain::internal::strain_block, triangles.size() - j);
        deformseg::strain::internal::gather_edges(xyz, triangles.data() + j, n, edges);
        if (stages >= 2)
          deformseg::strain::internal::cauchy_green<false>(edges, bases.alpha.data() + j, bases.beta.data() + j,
                                                           bases.gamma.data() + j, n, green);
        if (stages >= 3)
          deformseg::strain::internal::measure_block<false>(green, n, strain::Max_principal_strain{},
                                                            {strain.data() + j});
        benchmark::ClobberMemory();
      }
    }
  report(state, a);
}

// The Gaussian normalisation alone, one thread: range(0) 0 = sigma (the 95th percentile), 1 = the
// map 1 - exp(-s^2 / 2 sigma^2).
void normalisation(benchmark::State& state) {
  const auto& a = tube();
  const auto raw = strain::compute_strain(a, strain::Strain_options{.normalization = strain::No_normalization{}});
  std::vector<float> values(raw.values().begin(), raw.values().end());
  const strain::Raw_strain_field<float> field{values, raw.num_faces(), 0, 1};
  for (auto _ : state) {
    if (state.range(0) == 0)
      benchmark::DoNotOptimize(strain::Gaussian_normalization{}.sigma_of(field));
    else
      benchmark::DoNotOptimize(strain::Gaussian_normalization{.sigma = 0.5}.normalize(field));
  }
  report(state, a);
}

}  // namespace

BENCHMARK(tube_strain)
    ->ArgsProduct({{1, 2}, {0, 1}})
    ->ArgNames({"threads", "normalised"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(horse_strain)
    ->ArgsProduct({{1, 2}, {0, 1}})
    ->ArgNames({"threads", "normalised"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(previous_pose_strain)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(strain_with_directions)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(double_strain)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(stage)->DenseRange(1, 3)->ArgName("stages")->Unit(benchmark::kMillisecond);
BENCHMARK(normalisation)->DenseRange(0, 1)->ArgName("step")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
