// A motion store written, appended to and read back: store::Store_append adds clips (and replaces
// one, which keeps its index) as one transaction; store::Motion_store maps them and finds a clip by
// its path and name. The values follow a pattern that python/tests/test_store_format.py
// recomputes, to check the format's Python reader bit for bit:
//   clip c (of 12) has 1 + c % 5 rows of 4 values; value (row r, dimension k) = float(1000 c + 10 k + r) / 7,
//   frame r = 2 r, summary = (float(c) / 3, -float(c) / 3); clip 5 is replaced by the same
//   pattern plus 0.5 (in float) in a second append.
// Usage: motion_store [FOLDER]   (default: a folder "store" in the working directory, made anew)
#include <deformseg/store/store_append.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace store = deformseg::store;

constexpr std::size_t width = 4;

struct Clip {
  store::Store_record record;
  std::vector<float> values;  // dimension-major: width runs of `rows` floats
  std::vector<std::uint32_t> frames;
  std::vector<float> summary;
};

Clip pattern(std::size_t c, float shift) {
  Clip clip;
  const std::size_t rows = 1 + c % 5;
  for (std::size_t k = 0; k < width; ++k)
    for (std::size_t r = 0; r < rows; ++r) clip.values.push_back(static_cast<float>(1000 * c + 10 * k + r) / 7.0f + shift);
  for (std::size_t r = 0; r < rows; ++r) clip.frames.push_back(static_cast<std::uint32_t>(2 * r));
  clip.summary = {static_cast<float>(c) / 3.0f, -static_cast<float>(c) / 3.0f};
  clip.record.path = "/motions/set" + std::to_string(c / 4) + ".glb";
  clip.record.clip = "Take" + std::to_string(c % 4);
  clip.record.input_options = "weld=1";
  clip.record.source_size = 4096 + c;
  clip.record.source_mtime_ns = 1'700'000'000'000'000'000 + static_cast<std::int64_t>(c);
  clip.record.frame_count = static_cast<std::uint32_t>(2 * rows);
  clip.record.fps = 30;
  return clip;
}

void add(store::Store_append& append, const Clip& clip) {
  append.add(clip.record, {clip.values.data(), clip.frames.size(), width}, clip.frames, clip.summary);
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path folder = argc > 1 ? argv[1] : "store";
  std::filesystem::remove_all(folder);
  const char* options = R"({"policy": "example", "width": 4})";
  const char* layout = R"({"fields": ["third", "minus third"]})";
  {
    store::Store_append append(folder, options, 2, layout);  // a new store: the folder is missing
    for (std::size_t c = 0; c < 10; ++c) add(append, pattern(c, 0));
    append.commit();
  }
  {
    store::Store_append append(folder, options, 2, layout);
    const Clip changed = pattern(5, 0.5f);
    const std::size_t index = *append.store().find(changed.record.path, changed.record.clip);
    append.replace(index, changed.record, {changed.values.data(), changed.frames.size(), width}, changed.frames,
                   changed.summary);
    for (std::size_t c = 10; c < 12; ++c) add(append, pattern(c, 0));
    append.commit();
  }
  const store::Motion_store store = store::Motion_store::open(folder, store::Verify::checksums);
  std::printf("%zu clips of %zu values per row, generation %llu\n", store.size(), store.width(),
              static_cast<unsigned long long>(store.generation()));
  const std::size_t i = *store.find("/motions/set1.glb", "Take1");
  const auto view = store.view(i);
  std::printf("clip %zu (%s#%s): %zu rows, row 0 dimension 2 = %.9g, summary %.9g\n", i, store.record(i).path.c_str(),
              store.record(i).clip.c_str(), view.rows, view(0, 2), store.summary(i)[0]);
  return store.size() == 12 && i == 5 && view(0, 2) == 5020.0f / 7.0f + 0.5f ? 0 : 1;
}
