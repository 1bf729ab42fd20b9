#include "store_staleness.h"

#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>

#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <system_error>
#include <vector>

namespace deformseg::frontend {

namespace fs = std::filesystem;

namespace {

// The files whose bytes make an input: the file itself, or the frames of a folder or glob.
std::vector<fs::path> source_files(const std::string& file) {
  std::error_code error;
  if (fs::is_regular_file(file, error)) return {fs::path(file)};
  return io::list_frame_files(file);
}

struct File_stamp {
  std::uint64_t size = 0;
  std::int64_t mtime_ns = 0;
};

File_stamp stamp(const fs::path& file) {
  struct stat status {};
  if (::stat(file.c_str(), &status) != 0)
    throw invalid_input("cannot read its size and time: no such file, or no permission", {.file = file.string()});
  return {std::uint64_t(status.st_size),
          std::int64_t(status.st_mtim.tv_sec) * 1'000'000'000 + std::int64_t(status.st_mtim.tv_nsec)};
}

// The files' stamp: their total size and latest modification time.
File_stamp stamp(const std::vector<fs::path>& files) {
  File_stamp total;
  for (const fs::path& file : files) {
    const File_stamp one = stamp(file);
    total.size += one.size;
    total.mtime_ns = std::max(total.mtime_ns, one.mtime_ns);
  }
  return total;
}

// The files' hash: `hash_file` of one file, a hash of their hashes for several.
std::uint64_t hash_files(const std::vector<fs::path>& files) {
  if (files.size() == 1) return store::hash_file(files.front());
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const fs::path& file : files) hash = (hash ^ store::hash_file(file)) * 0x100000001b3ull;
  return hash == 0 ? 1 : hash;
}

// Records the stamp of the file the input is read with as the topology: a point cache's topology,
// or a character's body (one or the other applies).
void record_companion(const Input_options& options, store::Store_record& record) {
  const std::string& companion = options.topology.empty() ? options.body : options.topology;
  if (companion.empty()) return;
  const std::string topology_path = store_path(companion);
  record.topology_path = store::escaped_name(topology_path);
  const File_stamp topology = stamp(fs::path(topology_path));
  record.topology_size = topology.size;
  record.topology_mtime_ns = topology.mtime_ns;
}

}  // namespace

std::string input_options_text(const std::string& file, const Input_options& options) {
  nlohmann::json text = {{"fps", options.fps},
                         {"topology", store::escaped_name(store_path_if_given(options.topology))},
                         {"triangulate", options.triangulate},
                         {"weld", repair_options(file, options).weld},
                         {"refuse_defects", options.refuse_defects}};
  if (!options.body.empty()) text["body"] = store::escaped_name(store_path(options.body));  // absent: before bodies
  return text.dump();
}

Input_options recorded_input_options(const store::Store_record& record) {
  Input_options options;
  const nlohmann::json o = nlohmann::json::parse(record.input_options, nullptr, false);
  try {
    options.fps = o.at("fps").get<double>();
    options.topology = store::unescaped_name(o.at("topology").get<std::string>());
    options.triangulate = o.at("triangulate").get<bool>();
    options.weld = o.at("weld").get<bool>();
    options.refuse_defects = o.at("refuse_defects").get<bool>();
    options.body = store::unescaped_name(o.value("body", std::string()));
  } catch (const nlohmann::json::exception&) {
    return {};
  }
  return options;
}

store::Store_record source_record(const Clip_source& clip, const Input_options& all_clips, bool hash) {
  const Input_options options = with_body(clip.body, all_clips);
  store::Store_record record;  // its names escaped, as the store keeps them
  record.path = store::escaped_name(clip.file);
  record.clip = store::escaped_name(clip.clip);
  record.body = store::escaped_name(clip.body);
  record.input_options = input_options_text(clip.file, options);
  const std::vector<fs::path> files = source_files(clip.file);
  const File_stamp source = stamp(files);
  record.source_size = source.size;
  record.source_mtime_ns = source.mtime_ns;
  if (hash) record.source_hash = hash_files(files);
  record_companion(options, record);
  return record;
}

bool unchanged(const store::Store_record& stored, const store::Store_record& now, bool hash) {
  const bool same_source = hash ? stored.source_hash != 0 && stored.source_hash == now.source_hash
                                : stored.source_mtime_ns == now.source_mtime_ns;
  return same_source && stored.input_options == now.input_options && stored.source_size == now.source_size &&
         stored.topology_path == now.topology_path && stored.topology_size == now.topology_size &&
         stored.topology_mtime_ns == now.topology_mtime_ns;
}

bool up_to_date(const store::Store_record& stored, const Clip_source& clip, const Input_options& options) {
  store::Store_record now = source_record(clip, options, false);
  if (unchanged(stored, now, false)) return true;
  if (stored.source_hash == 0) return false;
  now.source_hash = hash_files(source_files(clip.file));
  return unchanged(stored, now, true);
}

}  // namespace deformseg::frontend
