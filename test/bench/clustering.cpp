// How fast the clustering policies are on n x n distance matrices of n = 200 and n = 2000 points
// in 8 random blobs of the plane (Euclidean distances): each policy with k = 8 given and with k
// chosen by the best silhouette over 2..10, through cluster(); and silhouette() alone.
//
//   build-bench/test/bench/clustering [--benchmark_filter=...]
#include <deformseg/clustering/agglomerative.h>
#include <deformseg/clustering/clustering.h>
#include <deformseg/clustering/k_means.h>
#include <deformseg/clustering/k_medoids.h>

#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <vector>

namespace dc = deformseg::clustering;

namespace {

// n points in 8 blobs of radius 3, their centres uniform in a 100 x 100 square; and the blob of each.
struct Data {
  Eigen::MatrixXd distances;
  std::vector<std::size_t> blob;
};

const Data& blobs(std::size_t n) {
  static std::map<std::size_t, Data> cache;
  Data& data = cache[n];
  if (data.distances.size() == 0) {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> square(0.0, 100.0), disc(-3.0, 3.0);
    std::vector<Eigen::Vector2d> centres(8), points(n);
    for (auto& c : centres) c = Eigen::Vector2d(square(random), square(random));
    for (std::size_t i = 0; i < n; ++i) {
      data.blob.push_back(i % 8);
      points[i] = centres[i % 8] + Eigen::Vector2d(disc(random), disc(random));
    }
    data.distances.resize(Eigen::Index(n), Eigen::Index(n));
    for (Eigen::Index i = 0; i < Eigen::Index(n); ++i)
      for (Eigen::Index j = 0; j < Eigen::Index(n); ++j)
        data.distances(i, j) = (points[std::size_t(i)] - points[std::size_t(j)]).norm();
  }
  return data;
}

template <class Policy>
void run(benchmark::State& state, const Policy& policy) {
  const Data& data = blobs(std::size_t(state.range(0)));
  dc::Clustering c;
  for (auto _ : state) {
    c = dc::cluster(data.distances, policy);
    benchmark::DoNotOptimize(c.labels.data());
  }
  state.counters["k"] = double(c.clusters);
  state.counters["silhouette"] = c.silhouette;
  state.counters["iterations"] = double(c.iterations);
}

void k_medoids(benchmark::State& s) { run(s, dc::K_medoids{.clusters = 8}); }
void k_medoids_by_silhouette(benchmark::State& s) { run(s, dc::K_medoids{}); }
void agglomerative_average(benchmark::State& s) { run(s, dc::Agglomerative{.clusters = 8}); }
void agglomerative_complete(benchmark::State& s) {
  run(s, dc::Agglomerative{.linkage = dc::Linkage::complete, .clusters = 8});
}
void agglomerative_by_silhouette(benchmark::State& s) { run(s, dc::Agglomerative{}); }
void k_means(benchmark::State& s) { run(s, dc::K_means{.clusters = 8}); }
void k_means_by_silhouette(benchmark::State& s) { run(s, dc::K_means{}); }

void silhouette(benchmark::State& state) {
  const Data& data = blobs(std::size_t(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(dc::silhouette(data.distances, data.blob));
}

}  // namespace

BENCHMARK(k_medoids)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(k_medoids_by_silhouette)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(agglomerative_average)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(agglomerative_complete)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(agglomerative_by_silhouette)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(k_means)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(k_means_by_silhouette)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(silhouette)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
