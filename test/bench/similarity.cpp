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
//
// The frame dissimilarities of the motion signatures, in cells (frame pairs) per second on one
// core, `cells_per_second`, for two sequences of N x N rows of 64 random values (N = 37, the shared
// clips' typical length, 150 and 1000):
//   kernel_rows/N     Motion_signature_dissimilarity::row over every row (the float kernel);
//   kernel_cells/N    its operator() cell by cell (what an alignment reads until it reads rows);
//   double_scalar/N   the double code the kernel replaced, 1 - exp(-|a_i - b_j|^2 unit) per cell
//                     from Eigen rows: the baseline, measured in the same run.
// `significance/shared` and `significance/per_copy`: similarity_significance with 20 shuffled
// copies on two tubes' descriptions, on one thread, the dissimilarities computed once and each
// copy's value without its path (reordering_comparison) or the policy compared afresh on each copy
// (the generic path, as before).
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signature_kernel.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/similarity/strain_distribution_similarity.h>

#include <benchmark/benchmark.h>

#include <cmath>
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

// N x 64 signatures of normal random values (the kernel's cost does not depend on them).
Eigen::MatrixXf random_signatures(std::size_t rows, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<float> normal(0, 1.5f);
  Eigen::MatrixXf s{Eigen::Index(rows), 64};
  for (Eigen::Index k = 0; k < s.size(); ++k) s(k) = normal(random);
  return s;
}

signatures::Motion_signature_view view_of(const Eigen::MatrixXf& s) {
  return {s.data(), std::size_t(s.rows()), std::size_t(s.cols())};
}

const double unit = signatures::frame_dissimilarity_unit(64, Signatures{}.scale);

void set_cells_per_second(benchmark::State& state, std::size_t n) {
  state.counters["cells_per_second"] =
      benchmark::Counter(double(state.iterations()) * double(n * n), benchmark::Counter::kIsRate);
}

void kernel_rows(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(0));
  const Eigen::MatrixXf a = random_signatures(n, 1), b = random_signatures(n, 2);
  const signatures::Motion_signature_dissimilarity d(view_of(a), view_of(b), unit);
  std::vector<double> row(n);
  for (auto _ : state)
    for (std::size_t i = 0; i < n; ++i) {
      d.row(i, 0, n, row.data());
      benchmark::DoNotOptimize(row.data());
      benchmark::ClobberMemory();
    }
  set_cells_per_second(state, n);
}

void kernel_cells(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(0));
  const Eigen::MatrixXf a = random_signatures(n, 1), b = random_signatures(n, 2);
  const signatures::Motion_signature_dissimilarity d(view_of(a), view_of(b), unit);
  for (auto _ : state)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) benchmark::DoNotOptimize(d(i, j));
  set_cells_per_second(state, n);
}

void double_scalar(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(0));
  const Eigen::MatrixXd a = random_signatures(n, 1).cast<double>(), b = random_signatures(n, 2).cast<double>();
  for (auto _ : state)
    for (Eigen::Index i = 0; i < Eigen::Index(n); ++i)
      for (Eigen::Index j = 0; j < Eigen::Index(n); ++j)
        benchmark::DoNotOptimize(1.0 - std::exp(-(a.row(i) - b.row(j)).squaredNorm() * unit));
  set_cells_per_second(state, n);
}

// Motion_signature_similarity seen through compare alone: similarity_significance compares each copy.
struct Compare_only {
  Signatures policy;
  using Description = Signatures::Description;
  similarity::Similarity compare(const Description& a, const Description& b) const { return policy.compare(a, b); }
};

template <class Policy>
void significance(benchmark::State& state) {
  const Signatures signatures;
  const auto a = signatures.describe(tubes()[0]), b = signatures.describe(tubes()[1]);
  const Policy policy{signatures};
  for (auto _ : state) {
    std::mt19937 random(1);
    benchmark::DoNotOptimize(similarity::similarity_significance(policy, a, b, 20, random, 1));
  }
}

}  // namespace

BENCHMARK(kernel_rows)->Name("signatures/kernel_rows")->Arg(37)->Arg(150)->Arg(1000);
BENCHMARK(kernel_cells)->Name("signatures/kernel_cells")->Arg(37)->Arg(150)->Arg(1000);
BENCHMARK(double_scalar)->Name("signatures/double_scalar")->Arg(37)->Arg(150)->Arg(1000);
BENCHMARK(significance<Signatures>)->Name("signatures/significance/shared")->Unit(benchmark::kMillisecond);
BENCHMARK(significance<Compare_only>)->Name("signatures/significance/per_copy")->Unit(benchmark::kMillisecond);

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
