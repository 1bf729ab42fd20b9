// How fast strain histograms are made and compared:
//
//   build/test/bench/histograms [--benchmark_filter=...]
//
// strain_histograms of a 100,000-triangle x 200-frame field (items_per_second: triangle-frames
// binned per second), on one and two threads; histogram_distances of 500 x 500 frames of 18 bins
// (items_per_second: distances per second), both metrics.
#include <deformseg/strain/histogram_distance.h>
#include <deformseg/strain/strain_histograms.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

constexpr std::size_t faces = 100'000, frames = 200;

// Strains spread log-uniformly from 1e-4 to 10, so that every bin (and under-, overflow) is hit.
const strain::Strain_field<float>& field() {
  static const strain::Strain_field<float> f = [] {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> exponent(-4, 1);
    strain::Strain_field<float>::Storage values(faces * frames);
    for (auto& v : values) v = std::pow(10.0f, exponent(rng));
    return strain::Strain_field<float>(faces, frames, std::move(values), {}, {}, 0);
  }();
  return f;
}

const std::vector<double>& areas() {
  static const std::vector<double> a = [] {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> area(0.5, 1.5);
    std::vector<double> v(faces);
    for (auto& x : v) x = area(rng);
    return v;
  }();
  return a;
}

void histograms(benchmark::State& state) {
  const strain::Histogram_options options{.threads = int(state.range(0))};
  for (auto _ : state) benchmark::DoNotOptimize(strain::strain_histograms(field(), areas(), options).data());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(faces * frames));
}
BENCHMARK(histograms)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void distances(benchmark::State& state) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> mass(0, 1);
  strain::Strain_histograms a(500, 18), b(500, 18);
  for (auto* h : {&a, &b}) {
    for (Eigen::Index i = 0; i < h->size(); ++i) h->data()[i] = mass(rng);
    for (Eigen::Index i = 0; i < h->rows(); ++i) h->row(i) /= h->row(i).sum();
  }
  const auto metric =
      state.range(0) == 0 ? strain::Histogram_metric::total_variation : strain::Histogram_metric::earth_movers;
  for (auto _ : state) benchmark::DoNotOptimize(strain::histogram_distances(a, b, metric, int(state.range(1))).data());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * 500 * 500);
}
BENCHMARK(distances)->ArgNames({"emd", "threads"})->Args({0, 1})->Args({1, 1})->Args({1, 2})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
