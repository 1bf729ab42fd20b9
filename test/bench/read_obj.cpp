// How fast deformseg reads OBJ frames, next to CGAL's reader on the same file.
//
//   build/test/bench/read_obj [--benchmark_filter=...]
//
// Reads the horse gallop of the shared data (../shared/data, or $DEFORMSEG_DATA_DIR), unpacked
// with tar into a temporary folder; without it, a generated animation of the same size and number
// format (8432 vertices, 16864 triangles, 48 frames, 17 significant digits). Reports bytes per
// second (MB/s) per thread, and frames per second for the whole sequence.
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/read_mesh.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr int generated_frames = 48;

// A closed grid of `rows` x `columns` vertices on a torus, turning with the frame, written with
// numbers of 17 significant digits like the horse's.
void write_generated_frame(const fs::path& path, int frame, int rows, int columns) {
  std::ofstream out(path);
  char line[128];
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      const double u = 2 * std::numbers::pi * i / rows + 0.01 * frame;
      const double v = 2 * std::numbers::pi * j / columns;
      const double r = 0.6 + 0.2 * std::cos(v);
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", r * std::cos(u), r * std::sin(u), 0.2 * std::sin(v));
      out << line;
    }
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      const int a = i * columns + j + 1;
      const int b = ((i + 1) % rows) * columns + j + 1;
      const int c = ((i + 1) % rows) * columns + (j + 1) % columns + 1;
      const int d = i * columns + (j + 1) % columns + 1;
      out << "f " << a << ' ' << b << ' ' << c << "\nf " << a << ' ' << c << ' ' << d << '\n';
    }
}

// The folder of frames the benchmarks read, made once.
const fs::path& frames_folder() {
  static const fs::path folder = [] {
    const char* from_environment = std::getenv("DEFORMSEG_DATA_DIR");
    const fs::path data =
        from_environment && *from_environment ? fs::path(from_environment) : fs::path(DEFORMSEG_DATA_DIR);
    const fs::path archive = data / "horse-gallop" / "horse-gallop.tar.xz";
    const fs::path target = fs::temp_directory_path() / "deformseg-bench-read_obj";
    fs::remove_all(target);
    fs::create_directories(target);
    if (fs::exists(archive)) {
      const std::string command = "tar xJf '" + archive.string() + "' -C '" + target.string() + "'";
      if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
      std::fprintf(stderr, "reading the horse gallop, unpacked into %s\n", target.c_str());
      return target / "horse-gallop";
    }
    std::fprintf(stderr, "%s not found: reading a generated animation in %s\n", archive.c_str(), target.c_str());
    for (int t = 0; t < generated_frames; ++t)
      write_generated_frame(target / ("frame_" + std::to_string(t) + ".obj"), t, 136,
                            62);  // 8432 vertices, 16864 triangles
    return target;
  }();
  return folder;
}

const fs::path& one_frame() {
  static const fs::path frame = deformseg::io::list_frame_files(frames_folder().string()).front();
  return frame;
}

std::int64_t bytes_of(const std::vector<fs::path>& files) {
  std::int64_t bytes = 0;
  for (const fs::path& f : files) bytes += static_cast<std::int64_t>(fs::file_size(f));
  return bytes;
}

void read_obj(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(deformseg::io::read_obj(one_frame()));
  state.SetBytesProcessed(state.iterations() * bytes_of({one_frame()}));
}

void read_mesh_points(benchmark::State& state) {
  std::vector<double> xyz(deformseg::io::read_obj(one_frame()).points.size());
  for (auto _ : state) {
    deformseg::io::read_mesh_points(one_frame(), xyz);
    benchmark::DoNotOptimize(xyz.data());
  }
  state.SetBytesProcessed(state.iterations() * bytes_of({one_frame()}));
}

void cgal_read_polygon_mesh(benchmark::State& state) {
  for (auto _ : state) {
    deformseg::mesh::Surface_mesh mesh;
    if (!CGAL::IO::read_polygon_mesh(one_frame().string(), mesh)) state.SkipWithError("CGAL could not read the frame");
    benchmark::DoNotOptimize(mesh.number_of_faces());
  }
  state.SetBytesProcessed(state.iterations() * bytes_of({one_frame()}));
}

void cgal_read_polygon_soup(benchmark::State& state) {
  for (auto _ : state) {
    std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
    std::vector<std::vector<std::size_t>> faces;
    if (!CGAL::IO::read_polygon_soup(one_frame().string(), points, faces))
      state.SkipWithError("CGAL could not read the frame");
    benchmark::DoNotOptimize(points.data());
  }
  state.SetBytesProcessed(state.iterations() * bytes_of({one_frame()}));
}

// The whole sequence, on state.range(0) threads: MB/s and frames/s of the whole (not per thread).
void read_frame_sequence(benchmark::State& state) {
  const auto files = deformseg::io::list_frame_files(frames_folder().string());
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(deformseg::io::read_frame_sequence(frames_folder().string(), {.threads = threads}));
  state.SetBytesProcessed(state.iterations() * bytes_of(files));
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations() * files.size()),
                                                  benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(read_obj)->Unit(benchmark::kMillisecond);
BENCHMARK(cgal_read_polygon_mesh)->Unit(benchmark::kMillisecond);
BENCHMARK(cgal_read_polygon_soup)->Unit(benchmark::kMillisecond);
BENCHMARK(read_mesh_points)->Unit(benchmark::kMillisecond);
BENCHMARK(read_frame_sequence)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
