// The nearest motions of a query among clips kept in a motion store: tubes bending on their own
// schedules are described once and written into a store with their summaries; the store, opened
// later (by another program, say), is searched in place through store::Stored_motions, and gives the
// values and order the same clips give in memory.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/search/nearest_motions.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/store/store_append.h>
#include <deformseg/store/stored_motions.h>

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <string>

int main() {
  using namespace deformseg;
  const std::filesystem::path folder = "tubes.store";
  std::filesystem::remove_all(folder);
  const similarity::Default_similarity policy;
  search::Motion_collection in_memory;
  {
    // [write]
    constexpr std::size_t chunks = 4;
    store::Store_append append(folder, R"({"policy": "motion-signature"})", search::summary_width(64, chunks),
                            store::motion_summary_layout(chunks));
    for (std::size_t i = 0; i < 10; ++i) {
      mesh::Bending_tube spec;  // tube i bends in 2 + i frames, holds, unbends
      spec.schedule = {{5, {0.0}}, {2 + i, {std::numbers::pi / 2}}, {6, {}}, {2 + i, {0.0}}, {5, {}}};
      const auto description = policy.describe(mesh::make_bending_tube(spec).animation);
      store::Store_record record;
      record.path = "/tubes/tube" + std::to_string(i) + ".pc2";
      record.frame_count = std::uint32_t(description.frames.size());
      record.fps = 30;
      const std::vector<std::uint32_t> frames(description.frames.begin(), description.frames.end());
      const auto view = similarity::view(description);
      append.add(record, view, frames, search::summarize(view, chunks).floats);
      in_memory.add(description);
    }
    append.commit();
    // [write]
  }
  // [search]
  const store::Stored_motions stored(store::Motion_store::open(folder));
  const auto found = search::nearest_motions(stored.view(3), stored, {.k = 3});
  // [search]
  const auto expected = search::nearest_motions(in_memory.view(3), in_memory, {.k = 3});
  std::cout << "nearest to tube 3 in the store:";
  for (const auto& n : found.neighbours)
    std::cout << ' ' << stored.store().record(n.index).path << " (" << n.value << ")";
  std::cout << "\nthe same in memory: " << (found.neighbours == expected.neighbours ? "yes" : "no") << '\n';
  return found.neighbours == expected.neighbours ? 0 : 1;
}
