// DTW's path through a byte per cell against its linear-space traceback (Dtw::max_trace_bytes),
// on square grids of 1,000, 3,000 and 6,601 frames of real-like signatures (random walks of 64
// floats, compared by the kernel `compare` uses, Motion_signature_dissimilarity): the time, the
// cells per second (items: n m grid cells), the peak of the heap during `align` (peak_heap_MB,
// counted by this program's operator new), and the ratio of its processor time to the byte per
// cell's in the same run (ratio_to_whole). Four variants of each size, in this order:
//   whole      max_trace_bytes unlimited: n m trace bytes
//   default    max_trace_bytes 2^25 (32 MiB): the byte per cell up to 5,792 x 5,792, above it linear
//   16 MiB     max_trace_bytes 2^24: linear space from 4,097 x 4,097
//   256 KiB    max_trace_bytes 2^18: linear space at every size here, in blocks of at most 256 KiB
//
//   build/test/bench/dtw_path_memory [--benchmark_filter=...]
#include <deformseg/alignment/dtw.h>
#include <deformseg/signatures/motion_signature_kernel.h>

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <ctime>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <map>
#include <new>
#include <random>
#include <vector>

namespace {

std::atomic<std::size_t> heap_now{0}, heap_peak{0};

void* counted(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  const std::size_t now = heap_now += malloc_usable_size(p);
  std::size_t peak = heap_peak.load();
  while (now > peak && !heap_peak.compare_exchange_weak(peak, now)) {
  }
  return p;
}

void uncounted(void* p) {
  if (p == nullptr) return;
  heap_now -= malloc_usable_size(p);
  std::free(p);
}

}  // namespace

void* operator new(std::size_t size) { return counted(size); }
void* operator new[](std::size_t size) { return counted(size); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }

namespace {

namespace al = deformseg::alignment;
namespace sig = deformseg::signatures;

constexpr std::size_t width = 64;

// Signatures of `rows` instants: each dimension a random walk (a motion's statistics drift
// slowly), stored as Motion_signature_view wants them, a block of rows per dimension.
std::vector<float> signatures(std::size_t rows, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<float> step(0.0f, 0.05f);
  std::vector<float> values(rows * width);
  for (std::size_t k = 0; k < width; ++k) {
    float x = 0;
    for (std::size_t r = 0; r < rows; ++r) values[k * rows + r] = x += step(random);
  }
  return values;
}

// Seconds per align of the byte per cell, by size, for the ratios of the later variants.
std::map<std::size_t, double> whole_seconds;

// Arguments: the frames n (= m) and max_trace_bytes as log2 (64: unlimited).
void dtw_path(benchmark::State& state) {
  const std::size_t n = std::size_t(state.range(0));
  const std::size_t limit =
      state.range(1) >= 64 ? std::numeric_limits<std::size_t>::max() : std::size_t(1) << state.range(1);
  const std::vector<float> a = signatures(n, 1), b = signatures(n, 2);
  const sig::Motion_signature_dissimilarity d({a.data(), n, width}, {b.data(), n, width},
                                       sig::frame_dissimilarity_unit(width, 1.77));
  const al::Dtw dtw{.max_trace_bytes = limit};
  std::size_t peak = 0;
  const std::clock_t start = std::clock();  // processor time: align runs on one thread
  for (auto _ : state) {
    const std::size_t before = heap_now.load();
    heap_peak = before;
    const al::Alignment result = dtw.align(n, n, d);
    benchmark::DoNotOptimize(result.pairs.data());
    peak = std::max(peak, heap_peak.load() - before);
  }
  const double seconds = double(std::clock() - start) / CLOCKS_PER_SEC / double(state.iterations());
  if (state.range(1) >= 64) whole_seconds[n] = seconds;
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n * n));
  state.counters["peak_heap_MB"] = double(peak) / 1e6;
  if (whole_seconds.count(n) != 0) state.counters["ratio_to_whole"] = seconds / whole_seconds[n];
}

void sizes(benchmark::internal::Benchmark* b) {
  for (const long n : {1000L, 3000L, 6601L})
    for (const long limit : {64L, 25L, 24L, 18L}) b->Args({n, limit});
}

}  // namespace

BENCHMARK(dtw_path)->Apply(sizes)->Unit(benchmark::kMillisecond)->Iterations(2);

BENCHMARK_MAIN();
