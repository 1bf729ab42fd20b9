// Describing a motion library as `deformseg describe` does, on one thread: frames per second read,
// described and stored, by stage, against reading the same clips alone in the same run.
//
//   build/test/bench/describe_library [--benchmark_filter=animals/12]
//
// Libraries: the animals of ../shared/data/library (12 bodies of 4,000 to 4,900 vertices, 1,000 to
// 1,300 after welding; 150 clips) and the shared characters (../shared/data/characters, 7 files);
// or $DEFORMSEG_DATA_DIR/... Three sizes of each: its first body (`/1`), three (`/3`), every one
// (`/12`, `/7`).
// Every clip of 2 frames or more at 30 fps, with the tool's policy (`Default_similarity`).
//
// Counters, each in frames per second of the clips (frames over the stage's processor time):
// - `read`: reading alone, as describe reads: each file parsed (`Gltf_file`), its connectivity
//   welded and repaired once (`Gltf_connectivity`), every frame of every clip posed once
//   (`Gltf_frame_source`: the welded vertices alone; a clip that fits the ring is read once).
// - `whole`: read, described and stored, as describe runs it: the description streamed from the
//   frame source (`describe_stream`), summarised and appended to a store, committed at the end.
// - the stages of `whole`, timed apart: `parse`, `weld` (the connectivity), `pose` (the frames),
//   `describe` (the same frames streamed from memory), `store` (summaries, appends, commit).
// - `whole_over_read`: whole's time over read's (the goal: at most 2).
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/signatures/motion_signature_stream.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/store/store_append.h>
#include <deformseg/store/stored_motions.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace ds = deformseg;

constexpr double fps = 30;
constexpr std::size_t summary_chunks = 4;  // the tool's

fs::path data_dir() {
  const char* dir = std::getenv("DEFORMSEG_DATA_DIR");
  return fs::path(dir && *dir ? dir : DEFORMSEG_DATA_DIR);
}

// The first `count` glTF files of a folder, by name.
std::vector<fs::path> bodies(const fs::path& folder, std::size_t count) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".glb") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  files.resize(std::min(count, files.size()));
  return files;
}

// Processor seconds since `start` (the benchmark runs on one thread).
double since(std::clock_t start) { return double(std::clock() - start) / CLOCKS_PER_SEC; }

ds::similarity::Default_similarity tool_policy() {
  ds::similarity::Default_similarity policy;
  policy.signatures.threads = 1;
  return policy;
}

// The clips of a file that describe takes: those of 2 frames or more.
std::vector<std::string> clips_of(const ds::io::Gltf_file& file) {
  std::vector<std::string> clips;
  for (const std::string& clip : file.clip_names())
    if (file.frame_sampler({.clip = clip, .fps = fps}).num_frames() >= 2) clips.push_back(clip);
  return clips;
}

// Calls `f(file, clip, source)` for every clip describe takes, each file parsed and its
// connectivity made once, as describe reads them; gives the clips' frames.
template <class F>
std::size_t each_clip(const std::vector<fs::path>& files, const F& f) {
  std::size_t frames = 0;
  for (const fs::path& path : files) {
    const ds::io::Gltf_file file(path);
    const auto connectivity = std::make_shared<const ds::io::Gltf_connectivity>(file);
    for (const std::string& clip : clips_of(file)) {
      ds::io::Gltf_frame_source source(connectivity, {.clip = clip, .fps = fps});
      frames += source.num_frames();
      f(path, clip, source);
    }
  }
  return frames;
}

// Reading alone: parsed, welded, every frame posed once. Gives the frames read.
std::size_t read_alone(const std::vector<fs::path>& files) {
  return each_clip(files, [](const fs::path&, const std::string&, ds::io::Gltf_frame_source& source) {
    std::vector<double> frame(3 * source.num_vertices());
    for (std::size_t t = 0; t < source.num_frames(); ++t) source.read_frame(frame);
    benchmark::DoNotOptimize(frame.data());
  });
}

// A store of the descriptions, as describe appends them.
struct Store {
  Store(const fs::path& folder, std::size_t width)
      : append(folder, R"({"policy": "motion-signature", "bench": true})",
               ds::search::summary_width(width, summary_chunks),
               ds::store::motion_summary_layout(summary_chunks)) {}

  void add(const std::string& file, const std::string& clip, std::size_t frames,
           const ds::similarity::Motion_signature_description& description) {
    const auto view = ds::similarity::view(description);
    const auto summary = ds::search::summarize(view, summary_chunks);
    ds::store::Store_record record;
    record.path = file, record.clip = clip, record.fps = fps, record.frame_count = std::uint32_t(frames);
    const std::vector<std::uint32_t> rows(description.frames.begin(), description.frames.end());
    append.add(record, view, rows, summary.floats);
  }

  ds::store::Store_append append;
};

std::size_t signature_width(const ds::similarity::Default_similarity& policy) {
  const auto& s = policy.signatures;
  return (s.up ? 2 : 1) * s.lags.size() * s.quantiles;
}

// Read, described and stored, as describe runs: gives the frames.
std::size_t read_describe_store(const std::vector<fs::path>& files, const fs::path& folder) {
  const auto policy = tool_policy();
  fs::remove_all(folder);
  Store store(folder, signature_width(policy));
  const std::size_t frames =
      each_clip(files, [&](const fs::path& path, const std::string& clip, ds::io::Gltf_frame_source& source) {
        store.add(path.string(), clip, source.num_frames(), policy.describe_stream(source));
      });
  store.append.commit();
  return frames;
}

// The stages of `read_describe_store`, timed apart (processor seconds, added to `seconds`).
struct Stage_seconds {
  double parse = 0, weld = 0, pose = 0, describe = 0, store = 0;
};

void stages(const std::vector<fs::path>& files, const fs::path& folder, Stage_seconds& seconds) {
  const auto policy = tool_policy();
  fs::remove_all(folder);
  std::clock_t start = std::clock();
  Store store(folder, signature_width(policy));
  seconds.store += since(start);
  for (const fs::path& path : files) {
    start = std::clock();
    const ds::io::Gltf_file file(path);
    const std::vector<std::string> clips = clips_of(file);
    seconds.parse += since(start);
    start = std::clock();
    const auto connectivity = std::make_shared<const ds::io::Gltf_connectivity>(file);
    seconds.weld += since(start);
    for (const std::string& clip : clips) {
      start = std::clock();
      ds::io::Gltf_frame_source source(connectivity, {.clip = clip, .fps = fps});
      const std::size_t block = 3 * source.num_vertices();
      std::vector<double> positions(source.num_frames() * block);
      for (std::size_t t = 0; t < source.num_frames(); ++t)
        source.read_frame(std::span<double>(positions).subspan(t * block, block));
      seconds.pose += since(start);
      start = std::clock();
      ds::signatures::Positions_frame_source<double> frames(positions, source.num_vertices(), source.triangles(), fps);
      const auto description = policy.describe_stream(frames);
      seconds.describe += since(start);
      start = std::clock();
      store.add(path.string(), clip, source.num_frames(), description);
      seconds.store += since(start);
    }
  }
  start = std::clock();
  store.append.commit();
  seconds.store += since(start);
}

void describe_library(benchmark::State& state, const std::string& library) {
  const fs::path folder = data_dir() / library;
  if (!fs::exists(folder)) {
    state.SkipWithError(("no " + folder.string()).c_str());
    return;
  }
  const std::vector<fs::path> files = bodies(folder, std::size_t(state.range(0)));
  const fs::path store = fs::temp_directory_path() / "deformseg-bench-describe";
  double read = 0, whole = 0;
  Stage_seconds seconds;
  std::size_t frames = 0;
  for (auto _ : state) {
    std::clock_t start = std::clock();
    frames = read_alone(files);
    read += since(start);
    start = std::clock();
    benchmark::DoNotOptimize(read_describe_store(files, store));
    whole += since(start);
    stages(files, store, seconds);
  }
  fs::remove_all(store);
  const auto rate = [&](double s) { return double(frames) * double(state.iterations()) / s; };
  state.counters["files"] = double(files.size());
  state.counters["frames"] = double(frames);
  state.counters["read"] = rate(read);
  state.counters["whole"] = rate(whole);
  state.counters["whole_over_read"] = whole / read;
  state.counters["parse"] = rate(seconds.parse);
  state.counters["weld"] = rate(seconds.weld);
  state.counters["pose"] = rate(seconds.pose);
  state.counters["describe"] = rate(seconds.describe);
  state.counters["store"] = rate(seconds.store);
}

}  // namespace

BENCHMARK_CAPTURE(describe_library, animals, std::string("library/animals_pack"))
    ->Arg(1)->Arg(3)->Arg(12)->Iterations(3)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(describe_library, characters, std::string("characters"))
    ->Arg(1)->Arg(3)->Arg(7)->Iterations(3)->Unit(benchmark::kSecond);

BENCHMARK_MAIN();
