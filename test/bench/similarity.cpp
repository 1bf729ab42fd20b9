// How long the similarity of two animations takes end to end (description to score), and where
// the time goes, for the policies; and a 10 x 10 similarity matrix:
//
//   build/test/bench/similarity [--benchmark_filter=...]
//
// The animations: tubes of 20,200 triangles (100 sectors x 100 rings) and 500 frames, bending at
// two joints on schedules of their own, made here (each with a seed of its own for the angles).
// `describe` is one animation's description (motion signatures; strain and histograms; or strain,
// segments, evolving graph and the GEDs of its key frames), `compare` the comparison of two descriptions,
// `end_to_end` motion_similarity (two describes and a compare), `matrix` similarity_matrix of 10.
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/mesh/synthetic.h>

#include <benchmark/benchmark.h>

#include <numbers>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

// A tube bending its two joints to random angles, phase after phase, 500 frames in all.
mesh::Surface_mesh_animation tube(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> angle(-90, 90), length(10, 40);
  mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 100, .rings = 100, .caps = true};
  spec.joints = {{.position = 0.3, .blend_width = 0.2}, {.position = 0.7, .blend_width = 0.2}};
  std::size_t frames = 1;
  while (frames < 500) {
    const std::size_t phase = std::min<std::size_t>(std::size_t(length(random)), 500 - frames);
    const double a = angle(random) * std::numbers::pi / 180, b = angle(random) * std::numbers::pi / 180;
    spec.schedule.push_back({phase, {a, b}});
    frames += phase;
  }
  return mesh::make_bending_tube(spec).animation;
}

const std::vector<mesh::Surface_mesh_animation>& tubes() {
  static const std::vector<mesh::Surface_mesh_animation> all = [] {
    std::vector<mesh::Surface_mesh_animation> made;
    for (unsigned seed = 1; seed <= 10; ++seed) made.push_back(tube(seed));
    return made;
  }();
  return all;
}

template <class Policy>
void describe(benchmark::State& state) {
  const Policy policy;
  const auto& animation = tubes()[0];  // made before the clock starts
  for (auto _ : state) benchmark::DoNotOptimize(policy.describe(animation));
}

template <class Policy>
void compare(benchmark::State& state) {
  const Policy policy;
  const auto a = policy.describe(tubes()[0]), b = policy.describe(tubes()[1]);
  for (auto _ : state) benchmark::DoNotOptimize(policy.compare(a, b));
  state.counters["value"] = policy.compare(a, b).value;
}

template <class Policy>
void end_to_end(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(similarity::motion_similarity(tubes()[0], tubes()[1], Policy{}));
}

template <class Policy>
void matrix(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(similarity::similarity_matrix(tubes(), Policy{}));
}

using Signatures = similarity::Motion_signature_similarity<>;
using Histograms = similarity::Strain_distribution_similarity<>;
using Graphs = similarity::Evolving_graph_similarity<>;

}  // namespace

BENCHMARK(describe<Signatures>)->Name("signatures/describe")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(compare<Signatures>)->Name("signatures/compare")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(end_to_end<Signatures>)->Name("signatures/end_to_end")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(matrix<Signatures>)->Name("signatures/matrix_10")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(describe<Histograms>)->Name("histograms/describe")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(compare<Histograms>)->Name("histograms/compare")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(end_to_end<Histograms>)->Name("histograms/end_to_end")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(matrix<Histograms>)->Name("histograms/matrix_10")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(describe<Graphs>)->Name("graphs/describe")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(compare<Graphs>)->Name("graphs/compare")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(end_to_end<Graphs>)->Name("graphs/end_to_end")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(matrix<Graphs>)->Name("graphs/matrix_10")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
