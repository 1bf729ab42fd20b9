// The 8 area-weighted quantiles of a frame's rates, as motion signatures take them twice per lag
// and frame: the radix selection (signatures::internal::weighted_quantiles) and one round of its
// buckets checked against rounding (Bucket_quantiles, which motion signatures use) against a sort
// of the rates and a walk up to each level (the reference they equal), at 1,000, 10,000 and 100,000
// rates (a game character, a captured body, a dense scan). The rates are log-normal, spread over
// about 16 octaves, a fifth of them exactly 0 (vertices that stand still); `items` counts rates,
// and `ratio_to_sort` is the selection's processor time over the sort's in the same run.
//
//   build/test/bench/weighted_quantiles [--benchmark_filter=...]
#include <deformseg/signatures/motion_signatures.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <ctime>
#include <map>
#include <random>
#include <vector>

namespace {

using deformseg::signatures::internal::Keyed_rate;
using deformseg::signatures::internal::key_value;
using deformseg::signatures::internal::order_key;

constexpr std::size_t quantiles = 8;

// 16 sets of n rates, their weights summing to 1 in each.
std::vector<std::vector<Keyed_rate>> rate_sets(std::size_t n) {
  std::mt19937 random(1);
  std::lognormal_distribution<double> magnitude(-3, 1.5);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<std::vector<Keyed_rate>> sets(16, std::vector<Keyed_rate>(n));
  for (auto& set : sets) {
    double total = 0;
    for (Keyed_rate& r : set) {
      r.key = order_key(uniform(random) < 0.2 ? 0.0 : magnitude(random));
      total += (r.weight = uniform(random));
    }
    for (Keyed_rate& r : set) r.weight /= total;
  }
  return sets;
}

void sort_and_walk(std::vector<Keyed_rate>& rates, double* out) {
  std::sort(rates.begin(), rates.end(), [](const Keyed_rate& a, const Keyed_rate& b) { return a.key < b.key; });
  std::size_t at = 0;
  double cumulative = rates[0].weight;
  for (std::size_t q = 0; q < quantiles; ++q) {
    while (cumulative < (double(q) + 0.5) / double(quantiles) && at + 1 < rates.size())
      cumulative += rates[++at].weight;
    out[q] = key_value(rates[at].key);
  }
}

std::map<long, double> sort_seconds_per_call;  // per size, for the ratio

enum class Way { sort, radix, buckets };

// The timed loop copies a set of rates before each call (every variant alike), since the sort and
// the radix selection reorder them; the buckets read the keys and weights apart, as a frame's
// rates give them, and keep their bucket span from call to call.
template <Way way>
void quantiles_of(benchmark::State& state) {
  const auto n = std::size_t(state.range(0));
  const auto sets = rate_sets(n);
  std::vector<Keyed_rate> rates(n), spare(n);
  std::vector<std::uint64_t> keys(n);
  std::vector<double> weights(n);
  deformseg::signatures::internal::Bucket_quantiles buckets;
  deformseg::signatures::internal::Bucket_quantiles::Bucket_span span;
  double out[quantiles];
  std::size_t i = 0;
  const std::clock_t start = std::clock();
  for (auto _ : state) {
    const auto& set = sets[i++ % sets.size()];
    if constexpr (way == Way::buckets) {
      std::uint64_t low = set[0].key, high = low;
      for (std::size_t r = 0; r < n; ++r) {
        keys[r] = set[r].key, weights[r] = set[r].weight;
        low = std::min(low, keys[r]), high = std::max(high, keys[r]);
      }
      buckets.quantiles(keys, low, high, weights, quantiles, out, span, rates, spare);
    } else {
      rates = set;
      if constexpr (way == Way::radix)
        deformseg::signatures::internal::weighted_quantiles(rates, spare, quantiles, out);
      else
        sort_and_walk(rates, out);
    }
    benchmark::DoNotOptimize(out);
  }
  const double per_call = double(std::clock() - start) / CLOCKS_PER_SEC / double(state.iterations());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n));
  if (way == Way::sort) sort_seconds_per_call[state.range(0)] = per_call;
  else if (sort_seconds_per_call.count(state.range(0)))
    state.counters["ratio_to_sort"] = per_call / sort_seconds_per_call[state.range(0)];
}

void sort(benchmark::State& state) { quantiles_of<Way::sort>(state); }
void radix_selection(benchmark::State& state) { quantiles_of<Way::radix>(state); }
void bucket_selection(benchmark::State& state) { quantiles_of<Way::buckets>(state); }

}  // namespace

BENCHMARK(sort)->Arg(1000)->Arg(10000)->Arg(100000)->MeasureProcessCPUTime();
BENCHMARK(radix_selection)->Arg(1000)->Arg(10000)->Arg(100000)->MeasureProcessCPUTime();
BENCHMARK(bucket_selection)->Arg(1000)->Arg(10000)->Arg(100000)->MeasureProcessCPUTime();

BENCHMARK_MAIN();
