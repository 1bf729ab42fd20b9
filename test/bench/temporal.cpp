// How fast temporal segmentation is:
//  - the frame distance matrix of T = 2000 frames of a 50k-triangle field, next to a plain Eigen
//    float product X^T X of the same shape in the same run (the `ratio` to read: distances /
//    product);
//  - Segment_cost and each policy on a given T x T distance matrix (T = 10000; Barbic_pca, whose
//    cost grows with the cube of a segment's length, on T = 1000).
//
//   build-bench/test/bench/temporal [--benchmark_filter=...]
#include <deformseg/temporal/temporal_segmentation.h>

#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

// A field of F x T random strains in [0, 1).
const strain::Strain_field<float>& field() {
  static const strain::Strain_field<float> f = [] {
    const std::size_t faces = 50000, frames = 2000;
    std::mt19937 random(1);
    std::uniform_real_distribution<float> strain(0.0f, 1.0f);
    strain::Strain_field<float>::Storage values(faces * frames);
    for (auto& v : values) v = strain(random);
    return strain::Strain_field<float>(faces, frames, std::move(values), {}, std::nullopt, 0);
  }();
  return f;
}

void plain_product(benchmark::State& state) {
  const auto x = field().matrix();
  for (auto _ : state) {
    Eigen::MatrixXf gram = x.transpose() * x;
    benchmark::DoNotOptimize(gram.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * 2000 * 2000);
}

void distances(benchmark::State& state) {
  const auto metric = strain::Frame_metric(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(frame_distances(field(), {.metric = metric}).data());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * 2000 * 2000);
}

// A T x T distance matrix of segments of 100 to 300 frames: distance |a - b| between their
// levels, plus noise.
const Eigen::MatrixXf& given_matrix(std::size_t frames) {
  static std::map<std::size_t, Eigen::MatrixXf> matrices;
  auto& d = matrices[frames];
  if (d.size() == 0) {
    std::mt19937 random(2);
    std::vector<float> level(frames);
    for (std::size_t t = 0; t < frames;) {
      const std::size_t length = 100 + random() % 201;
      const float value = float(random() % 1000) / 100.0f;
      for (std::size_t k = t; k < std::min(frames, t + length); ++k) level[k] = value;
      t += length;
    }
    std::uniform_real_distribution<float> noise(0.0f, 0.2f);
    d.resize(Eigen::Index(frames), Eigen::Index(frames));
    for (Eigen::Index i = 0; i < d.rows(); ++i)
      for (Eigen::Index j = 0; j <= i; ++j)
        d(i, j) = d(j, i) = i == j ? 0.0f : std::abs(level[std::size_t(i)] - level[std::size_t(j)]) + noise(random);
  }
  return d;
}

void cost_table(benchmark::State& state) {
  const auto& d = given_matrix(10000);
  for (auto _ : state) benchmark::DoNotOptimize(temporal::Segment_cost(d).num_frames());
}

template <class Policy>
void policy(benchmark::State& state, Policy p) {
  const temporal::Segment_cost cost(given_matrix(std::size_t(state.range(0))));
  std::size_t segments = 0;
  for (auto _ : state) segments = temporal::segment_frames(cost, p).segments.size();
  state.counters["segments"] = double(segments);
}

}  // namespace

BENCHMARK(plain_product)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(distances)
    ->Arg(int(strain::Frame_metric::euclidean))
    ->Arg(int(strain::Frame_metric::cosine))
    ->ArgName("metric")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK(cost_table)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK_CAPTURE(policy, optimal_partition, temporal::Optimal_partition{})
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK_CAPTURE(policy, optimal_50_segments, temporal::Optimal_partition{.segments = 50})
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK_CAPTURE(policy, binary_split, temporal::Binary_split{})
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK_CAPTURE(policy, thesis_greedy, temporal::Thesis_greedy{})
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK_CAPTURE(policy, barbic_pca, temporal::Barbic_pca{})
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

BENCHMARK_MAIN();
