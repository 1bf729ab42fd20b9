// How fast the alignment policies are on 5000 x 5000 label sequences (the goal: under
// 0.1 s each, 250 million cells per second): Smith–Waterman with linear and affine gaps, DTW
// without and with a Sakoe–Chiba window (500 cells, a tenth of the length), subsequence DTW; each
// with its pairs (`align`, a byte per cell for the traceback) and as the score alone (`score`,
// one row). Items are grid cells visited (within the window when there is one).
//
// Then DTW's three passes on square grids of random real dissimilarities (64, 256 and 1024
// frames, the sizes of motion descriptions) read from a row-major matrix: `align`, `score` and
// `mean_cost` (the value pass: score and path length), in cells per second.
//
//   build-bench/test/bench/alignment [--benchmark_filter=...]
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/alignment/subsequence_dtw.h>

#include <benchmark/benchmark.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <vector>

namespace al = deformseg::alignment;

namespace {

constexpr std::size_t length = 5000;

// Key-frame labels expanded by their durations: runs of 1 to 40 frames of one of 6 labels.
std::vector<int> label_sequence(unsigned seed) {
  std::mt19937 random(seed);
  std::vector<int> labels;
  while (labels.size() < length) {
    const int label = int(random() % 6);
    for (std::size_t run = 1 + random() % 40; run > 0 && labels.size() < length; --run) labels.push_back(label);
  }
  return labels;
}

const std::vector<int>& sequence_a() {
  static const std::vector<int> a = label_sequence(1);
  return a;
}
const std::vector<int>& sequence_b() {
  static const std::vector<int> b = label_sequence(2);
  return b;
}

std::int64_t cells(std::optional<std::size_t> window) {
  if (!window) return std::int64_t(length * length);
  std::int64_t count = 0;  // |i - j| <= w on a square grid
  for (std::size_t i = 0; i < length; ++i)
    count += std::int64_t(std::min(length - 1, i + *window) - (i > *window ? i - *window : 0) + 1);
  return count;
}

template <class Policy>
void run(benchmark::State& state, const Policy& policy, bool with_pairs, std::int64_t cells_per_run) {
  const auto& a = sequence_a();
  const auto& b = sequence_b();
  const auto d = al::label_mismatch(a, b);
  for (auto _ : state) {
    if (with_pairs) {
      const al::Alignment result = policy.align(a.size(), b.size(), d);
      benchmark::DoNotOptimize(result.pairs.data());
    } else {
      benchmark::DoNotOptimize(policy.score(a.size(), b.size(), d));
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * cells_per_run);
}

// Argument: 1 for align (with the pairs), 0 for score alone.
void smith_waterman_linear(benchmark::State& state) { run(state, al::Smith_waterman{}, state.range(0), cells({})); }
void smith_waterman_affine(benchmark::State& state) {
  run(state, al::Smith_waterman{.gap_open = 2, .gap_extend = 0.5}, state.range(0), cells({}));
}
void dtw(benchmark::State& state) { run(state, al::Dtw{}, state.range(0), cells({})); }
void dtw_window_500(benchmark::State& state) { run(state, al::Dtw{.window = 500}, state.range(0), cells(500)); }
void subsequence_dtw(benchmark::State& state) { run(state, al::Subsequence_dtw{}, state.range(0), cells({})); }

// A size x size matrix of uniform random values in [0, 1), one per size.
const Eigen::MatrixXd& random_matrix(std::size_t size) {
  static std::map<std::size_t, Eigen::MatrixXd> matrices;
  auto [at, added] = matrices.try_emplace(size);
  if (added) {
    std::mt19937 random(static_cast<unsigned>(size));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    at->second.resize(Eigen::Index(size), Eigen::Index(size));
    for (Eigen::Index k = 0; k < at->second.size(); ++k) at->second(k) = unit(random);
  }
  return at->second;
}

// The matrix's entries by rows, as a comparison kernel gives them: each row contiguous, so that
// the passes' reading of d costs little beside their dynamic programme.
struct Rows_of {
  std::vector<double> values;
  std::size_t cols;
  explicit Rows_of(const Eigen::MatrixXd& m) : values(std::size_t(m.size())), cols(std::size_t(m.cols())) {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(values.data(), m.rows(),
                                                                                      m.cols()) = m;
  }
  double operator()(std::size_t i, std::size_t j) const { return values[i * cols + j]; }
};

// Argument: the side of the square grid.
template <class Pass>
void dtw_pass_on_matrix(benchmark::State& state, const Pass& pass) {
  const std::size_t size = std::size_t(state.range(0));
  const Rows_of d(random_matrix(size));
  for (auto _ : state) pass(size, d);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(size * size));
}

void dtw_align_matrix(benchmark::State& state) {
  dtw_pass_on_matrix(state, [](std::size_t size, const auto& d) {
    const al::Alignment result = al::Dtw{}.align(size, size, d);
    benchmark::DoNotOptimize(result.pairs.data());
  });
}
void dtw_score_matrix(benchmark::State& state) {
  dtw_pass_on_matrix(state, [](std::size_t size, const auto& d) {
    benchmark::DoNotOptimize(al::Dtw{}.score(size, size, d));
  });
}
void dtw_mean_cost_matrix(benchmark::State& state) {
  dtw_pass_on_matrix(state, [](std::size_t size, const auto& d) {
    const al::Dtw_mean_cost value = al::Dtw{}.mean_cost(size, size, d);
    benchmark::DoNotOptimize(value.score);
    benchmark::DoNotOptimize(value.length);
  });
}

}  // namespace

BENCHMARK(smith_waterman_linear)->ArgName("align")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(smith_waterman_affine)->ArgName("align")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(dtw)->ArgName("align")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(dtw_window_500)->ArgName("align")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(subsequence_dtw)->ArgName("align")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(dtw_align_matrix)->ArgName("size")->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(dtw_score_matrix)->ArgName("size")->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(dtw_mean_cost_matrix)->ArgName("size")->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
