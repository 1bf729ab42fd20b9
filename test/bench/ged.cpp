// How fast the graph edit distance is, on seeded random labelled pairs shaped like segment graphs
// (sparse: mean degree 2.5, 3 node kinds; `dense` runs have edge probability 0.5):
//  - Exact_ged with its default node limit, 6 to 12 nodes: the time per pair; counters `exact`
//    (the fraction of pairs that finished under the limit) and `slowest_ms`;
//  - Bipartite_ged on 50 and 200 nodes: the time per pair.
// The yardstick: networkx's exact graph_edit_distance, median 0.29 s at 8 nodes, 26 s at 10.
//
//   build/test/bench/ged [--benchmark_filter=...]
#include "../ged_support.h"

#include <deformseg/ged/exact_ged.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

namespace {

using Graph = deformseg::test::Ged_graph;

// Three labels, as key-frame graphs have few kinds.
Graph random_graph(std::mt19937& rng, std::size_t nodes, double edge_probability) {
  return deformseg::test::random_labelled_graph(rng, nodes, 3, edge_probability);
}

// `count` pairs of `nodes`-node graphs; sparse unless `dense`.
std::vector<std::pair<Graph, Graph>> pairs(std::size_t nodes, bool dense, std::size_t count) {
  std::mt19937 rng(static_cast<unsigned>(1000 * nodes + (dense ? 1 : 0)));
  const double p = dense ? 0.5 : std::min(1.0, 2.5 / static_cast<double>(nodes - 1));
  std::vector<std::pair<Graph, Graph>> result;
  for (std::size_t k = 0; k < count; ++k) {
    Graph a = random_graph(rng, nodes, p);
    result.emplace_back(std::move(a), random_graph(rng, nodes, p));
  }
  return result;
}

void exact(benchmark::State& state) {
  const auto work = pairs(static_cast<std::size_t>(state.range(0)), state.range(1) != 0, 50);
  std::size_t next = 0, done = 0, finished = 0;
  double slowest = 0;
  for (auto _ : state) {
    const auto& [a, b] = work[next];
    next = (next + 1) % work.size();
    const auto start = std::chrono::steady_clock::now();
    const auto r = deformseg::ged::Exact_ged{}(a, b);
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - start;
    slowest = std::max(slowest, spent.count());
    ++done;
    finished += r.exact ? 1 : 0;
    benchmark::DoNotOptimize(r.distance);
  }
  state.counters["exact"] = static_cast<double>(finished) / static_cast<double>(done);
  state.counters["slowest_ms"] = slowest;
}

void bipartite(benchmark::State& state) {
  const auto work = pairs(static_cast<std::size_t>(state.range(0)), false, 5);
  std::size_t next = 0;
  for (auto _ : state) {
    const auto& [a, b] = work[next];
    next = (next + 1) % work.size();
    benchmark::DoNotOptimize(deformseg::ged::Bipartite_ged{}(a, b).distance);
  }
}

}  // namespace

BENCHMARK(exact)->ArgNames({"nodes", "dense"})->Args({6, 0})->Args({8, 0})->Args({10, 0})->Args({12, 0})
    ->Args({8, 1})->Args({10, 1})->Args({12, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(bipartite)->ArgName("nodes")->Arg(50)->Arg(200)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
