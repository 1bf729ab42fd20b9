// Motion store figures: appending clips (written, flushed, committed) and opening a store, with
// the structure checked (the default) and with every checksum (Verify::checksums), at a few sizes
// of clips of 150 rows x 64 floats (38 KB each), the shape of the issue's search benchmark.
//   build/test/bench/store_append_open --store-dir /tmp/ds-bench-store
// (its name is not motion_store: that is the example program's target)
// (the stores are made below that folder, default the system's temporary folder, and removed.)
#include <deformseg/store/store_append.h>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace store = deformseg::store;

fs::path store_root = fs::temp_directory_path() / "deformseg-bench-store";
constexpr std::size_t rows = 150, width = 64, summary_width = 13 * 64;

void write_store(const fs::path& folder, std::size_t clips) {
  std::vector<float> values(rows * width), summary(summary_width, 0.5f);
  std::vector<std::uint32_t> frames(rows);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = static_cast<float>(k % 977) / 977.0f;
  for (std::size_t r = 0; r < rows; ++r) frames[r] = static_cast<std::uint32_t>(r);
  store::Store_append append(folder, R"({"policy": "bench"})", summary_width);
  store::Store_record record;
  record.fps = 30;
  record.frame_count = rows;
  for (std::size_t c = 0; c < clips; ++c) {
    record.path = "/bench/clip" + std::to_string(c) + ".pc2";
    values[0] = static_cast<float>(c);
    append.add(record, {values.data(), rows, width}, frames, summary);
  }
  append.commit();
}

void append_clips(benchmark::State& state) {
  const auto clips = static_cast<std::size_t>(state.range(0));
  const fs::path folder = store_root / ("append-" + std::to_string(clips));
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(folder);
    state.ResumeTiming();
    write_store(folder, clips);
  }
  const double bytes = double(clips) * (rows * width + rows + summary_width) * 4;
  state.counters["clips/s"] = benchmark::Counter(double(clips), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["bytes/s"] = benchmark::Counter(bytes, benchmark::Counter::kIsIterationInvariantRate);
  fs::remove_all(folder);
}

void open_store(benchmark::State& state, store::Verify verify) {
  const auto clips = static_cast<std::size_t>(state.range(0));
  const fs::path folder = store_root / ("open-" + std::to_string(clips));
  if (!fs::exists(folder / "store.json")) write_store(folder, clips);
  for (auto _ : state) {
    const store::Motion_store store = store::Motion_store::open(folder, verify);
    benchmark::DoNotOptimize(store.view(store.size() - 1).values);
  }
  state.counters["clips/s"] = benchmark::Counter(double(clips), benchmark::Counter::kIsIterationInvariantRate);
}

void open_structure(benchmark::State& state) { open_store(state, store::Verify::structure); }
void open_checksums(benchmark::State& state) { open_store(state, store::Verify::checksums); }

}  // namespace

BENCHMARK(append_clips)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(open_structure)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(open_checksums)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--store-dir") == 0) store_root = argv[i + 1];
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--store-dir") == 0) {
      ++i;
      continue;
    }
    rest.push_back(argv[i]);
  }
  int count = static_cast<int>(rest.size());
  benchmark::Initialize(&count, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  fs::remove_all(store_root);
  return 0;
}
