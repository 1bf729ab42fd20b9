// Peak memory and time of describing a long point cache frame by frame
// (`motion_signatures_streamed` through a `Point_cache_frame_source`) against reading it whole
// (`read_animation`, double precision, then `motion_signatures`), as the tool does today:
//
//   cd build/test/bench && for n in 1000 4000 16000; do for p in streamed in_memory; do
//     ./signature_stream --benchmark_filter="^$p/$n/"; done; done
//
// One benchmark per run: `peak_rss_MB` is the process's peak resident memory (getrusage's
// ru_maxrss), which only means the benchmark's own peak when it is the only one that ran.
// `ring_MB` is what the stream's ring holds, `positions_MB` what the whole animation holds.
//
// The animation: a tube of 3,122 vertices (48 sectors x 64 rings, capped) bending its two joints
// on a 120-frame cycle while drifting sideways, at 30 fps, written once here as
// stream_tube_<frames>.pc2 (37 KB a frame) with stream_tube.obj, reused by later runs.
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signature_stream.h>
#include <deformseg/signatures/motion_signatures.h>

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <span>
#include <string>
#include <vector>

using namespace deformseg;

namespace {

namespace fs = std::filesystem;

constexpr std::size_t cycle_frames = 120;

mesh::Surface_mesh_animation cycle() {
  mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 48, .rings = 64, .caps = true};
  spec.joints = {{.position = 0.3, .blend_width = 0.2}, {.position = 0.7, .blend_width = 0.2}};
  const double right = std::numbers::pi / 2;
  spec.schedule = {{30, {right, 0.0}}, {30, {0.0, -right}}, {30, {0.5, 0.5}}, {29, {0.0, 0.0}}};
  return mesh::make_bending_tube(spec).animation;
}

// The tube of `frames` frames as a PC2 file, written frame by frame (no more than a cycle in memory).
fs::path tube_cache(std::size_t frames) {
  const fs::path cache = "stream_tube_" + std::to_string(frames) + ".pc2";
  const auto tube = cycle();
  const std::size_t vertices = tube.num_vertices();
  if (!fs::exists("stream_tube.obj")) io::write_obj(tube, 0, "stream_tube.obj");
  if (fs::exists(cache) && fs::file_size(cache) == 32 + 12 * vertices * frames) return cache;
  std::vector<char> bytes(32 + 12 * vertices);
  const auto little = std::endian::little;
  std::copy_n("POINTCACHE2", 12, bytes.data());
  io::internal::store_word<little>(bytes.data() + 12, std::int32_t{1});
  io::internal::store_word<little>(bytes.data() + 16, std::int32_t(vertices));
  io::internal::store_word<little>(bytes.data() + 20, 0.0f);
  io::internal::store_word<little>(bytes.data() + 24, 1.0f);
  io::internal::store_word<little>(bytes.data() + 28, std::int32_t(frames));
  std::ofstream out(cache, std::ios::binary);
  out.write(bytes.data(), 32);
  for (std::size_t t = 0; t < frames; ++t) {
    const auto xyz = tube.frame_positions(t % cycle_frames);
    const double drift = 0.3 * std::sin(double(t) / 97.0);
    for (std::size_t i = 0; i < xyz.size(); ++i)
      io::internal::store_word<little>(bytes.data() + 4 * i, float(xyz[i] + (i % 3 == 0 ? drift : 0.0)));
    out.write(bytes.data(), std::streamsize(12 * vertices));
  }
  return cache;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

void streamed(benchmark::State& state) {
  const fs::path cache = tube_cache(std::size_t(state.range(0)));
  io::Point_cache_frame_source source(cache, {.topology = "stream_tube.obj"});
  const auto instants = signatures::frame_instants(source.num_frames(), 30);
  const signatures::Motion_signature_options options;
  Eigen::MatrixXd out;
  for (auto _ : state) {
    out = signatures::motion_signatures_streamed(source, options, std::span<const double>(instants));
    benchmark::DoNotOptimize(out.data());
  }
  const std::size_t ring = signatures::streamed_ring_frames(options, 30, source.num_frames(), instants);
  state.counters["ring_MB"] = double(ring * 12 * source.num_vertices()) / 1e6;
  state.counters["rows"] = double(out.rows());
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

void in_memory(benchmark::State& state) {
  const fs::path cache = tube_cache(std::size_t(state.range(0)));
  Eigen::MatrixXd out;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto animation = io::read_animation(cache.string(), {.topology = "stream_tube.obj"});
    out = signatures::motion_signatures(animation);
    bytes = animation.all_positions().size_bytes();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["positions_MB"] = double(bytes) / 1e6;
  state.counters["rows"] = double(out.rows());
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

}  // namespace

BENCHMARK(streamed)->Arg(1000)->Arg(4000)->Arg(16000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(in_memory)->Arg(1000)->Arg(4000)->Arg(16000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

BENCHMARK_MAIN();
