// What reading compressed glTF costs: each of three shared characters (Fox: 163 KB, 1,728 vertices
// before welding, 3 clips; RobotExpressive: 464 KB, 7,214, 14; Knight: 3.7 MB, 7,024, 76) from its
// own file and from its Draco and meshopt copies (test/gltf_compression.h, written once to the temporary folder), one thread:
// - parse: the file parsed, its compressed geometry decoded, its scene read (Gltf_file);
// - whole: parsed, then every clip sampled at 30 fps (skinned vertices per second).
//
//   build-bench/test/bench/gltf_compression [--benchmark_filter=...]
//
// The copies keep the original accessors' bytes besides the compressed ones (they test decoding,
// not size), so their files are larger, and their reading a little slower, than a compressor's.
#include "../gltf_compression.h"

#include <deformseg/io/gltf.h>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;

enum class Kind { original, draco, meshopt };

// The character `body`, or its compressed copy (made on first use).
fs::path character(const std::string& body, Kind kind) {
  const char* dir = std::getenv("DEFORMSEG_DATA_DIR");
  const fs::path original = fs::path(dir && *dir ? dir : DEFORMSEG_DATA_DIR) / "characters" / body;
  if (kind == Kind::original || !fs::exists(original)) return original;
  const fs::path copy =
      fs::temp_directory_path() / ("deformseg_bench_" + std::string(kind == Kind::draco ? "draco_" : "meshopt_") + body);
  if (!fs::exists(copy)) {
    if (kind == Kind::draco) deformseg::test::write_draco_copy(original, copy);
    else deformseg::test::write_meshopt_copy(original, copy);
  }
  return copy;
}

void parse(benchmark::State& state, const std::string& body, Kind kind) {
  const fs::path path = character(body, kind);
  if (!fs::exists(path)) return state.SkipWithError(("no " + path.string()).c_str());
  for (auto _ : state) benchmark::DoNotOptimize(deformseg::io::Gltf_file(path).clip_names().size());
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(fs::file_size(path)));
}

void whole(benchmark::State& state, const std::string& body, Kind kind) {
  const fs::path path = character(body, kind);
  if (!fs::exists(path)) return state.SkipWithError(("no " + path.string()).c_str());
  std::size_t vertices = 0;
  for (auto _ : state) {
    const deformseg::io::Gltf_file file(path);
    for (const std::string& clip : file.clip_names()) {
      const auto sampled = file.sample({.clip = clip, .threads = 1});
      vertices += sampled.report.frames * sampled.num_vertices;
    }
  }
  state.SetItemsProcessed(std::int64_t(vertices));
}

}  // namespace

#define DEFORMSEG_COMPRESSION_BENCHMARKS(body)                                                                   \
  BENCHMARK_CAPTURE(parse, body##_original, std::string(#body ".glb"), Kind::original)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(parse, body##_draco, std::string(#body ".glb"), Kind::draco)->Unit(benchmark::kMillisecond);       \
  BENCHMARK_CAPTURE(parse, body##_meshopt, std::string(#body ".glb"), Kind::meshopt)->Unit(benchmark::kMillisecond);   \
  BENCHMARK_CAPTURE(whole, body##_original, std::string(#body ".glb"), Kind::original)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(whole, body##_draco, std::string(#body ".glb"), Kind::draco)->Unit(benchmark::kMillisecond);       \
  BENCHMARK_CAPTURE(whole, body##_meshopt, std::string(#body ".glb"), Kind::meshopt)->Unit(benchmark::kMillisecond)

DEFORMSEG_COMPRESSION_BENCHMARKS(Fox);
DEFORMSEG_COMPRESSION_BENCHMARKS(RobotExpressive);
DEFORMSEG_COMPRESSION_BENCHMARKS(Knight);

BENCHMARK_MAIN();
