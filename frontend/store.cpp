#include "store.h"

#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/motion_labels.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/similarity/motion_bounds.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <utility>

namespace deformseg::frontend {

namespace fs = std::filesystem;

namespace {

bool is_labels_file(const std::string& input) {
  const std::string ext = fs::path(input).extension().string();
  return ext == ".csv" || ext == ".CSV";
}

// The path as a store records it: canonical when it exists (a file, a folder), else (a glob)
// absolute and normal.
std::string canonical_path(const std::string& path) {
  std::error_code error;
  const fs::path canonical = fs::canonical(path, error);
  if (!error) return canonical.string();
  return fs::absolute(path).lexically_normal().string();
}

// The clips of a glTF file: `clip` when given, else every clip of the file of 2 frames or more at
// `fps` (the others, poses, go to `poses`); a file without clips gives its one animation under "".
void add_gltf_clips(const std::string& file, const std::string& clip, double fps, std::vector<Clip_source>& out,
                    std::vector<std::string>& poses) {
  if (!clip.empty()) {
    out.push_back({canonical_path(file), clip});
    return;
  }
  const io::Gltf_contents contents = io::gltf_contents(file, fps);
  if (contents.clips.empty()) out.push_back({canonical_path(file), ""});
  for (std::size_t k = 0; k < contents.clips.size(); ++k) {
    const Clip_source source{canonical_path(file),
                             contents.clips[k].name.empty() ? std::to_string(k) : contents.clips[k].name};
    if (contents.clips[k].frames < 2) poses.push_back(source.name());
    else out.push_back(source);
  }
}

}  // namespace

std::vector<Clip_source> labelled_clips(const std::string& labels, const Input_options& options) {
  std::vector<Clip_source> out;
  std::map<fs::path, std::size_t> rows_of_file;
  const std::vector<io::Labelled_clip> rows = io::read_motion_labels(labels);
  for (const io::Labelled_clip& row : rows) ++rows_of_file[row.file];
  for (const io::Labelled_clip& row : rows) {
    const std::string file = row.file.string();
    if (!io::is_gltf(row.file)) {
      if (rows_of_file[row.file] > 1)
        throw invalid_input("lists " + std::to_string(rows_of_file[row.file]) + " clips of " + file +
                                ", which is not a glTF file and holds one animation",
                            {.file = labels});
      out.push_back({canonical_path(file), ""});
      continue;
    }
    std::string clip = row.item.clip.empty() ? options.clip : row.item.clip;
    if (clip.empty()) {  // the file's only clip, as evaluate reads it
      const io::Gltf_file gltf(row.file);
      io::require_clip_choice(gltf, clip);
      const std::vector<std::string> names = gltf.clip_names();
      clip = names.empty() ? "" : names.front().empty() ? "0" : names.front();
    }
    out.push_back({canonical_path(file), clip});
  }
  return out;
}

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
  if (files.size() == 1) return io::hash_file(files.front());
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const fs::path& file : files) hash = (hash ^ io::hash_file(file)) * 0x100000001b3ull;
  return hash == 0 ? 1 : hash;
}

nlohmann::json up_json(const std::optional<Eigen::Vector3d>& up) {
  if (!up) return nullptr;
  return {(*up)[0], (*up)[1], (*up)[2]};
}

// Reads the clips of one file, in `indices` of `clips`, as `read_input` reads them (a glTF file
// parsed once), and gives each to `take`.
template <class Take>
void read_file_clips(const std::vector<Clip_source>& clips, const std::vector<std::size_t>& indices,
                     const Input_options& options, const Take& take) {
  const std::string& file = clips[indices.front()].file;
  if (!io::is_gltf(file)) {
    Input_options frames = options;
    frames.clip.clear();
    take(indices.front(), read_input(file, frames, Front::command_line).animation);
    return;
  }
  const io::Gltf_file gltf(file);
  for (const std::size_t i : indices)
    take(i, gltf.read({.clip = clips[i].clip, .fps = options.fps, .repair = repair_options(file, options),
                       .threads = options.threads}));
}

}  // namespace

std::vector<Clip_source> clip_sources(const std::vector<std::string>& inputs, const Input_options& options,
                                      std::vector<std::string>& poses) {
  check_clip_applies(inputs, options, Front::command_line);
  std::vector<Clip_source> all;
  for (const std::string& input : inputs) {
    if (is_labels_file(input)) {
      for (Clip_source& clip : labelled_clips(input, options)) all.push_back(std::move(clip));
      continue;
    }
    const Input_name name = input_name(input, options, Front::command_line);
    if (io::is_gltf(name.file)) add_gltf_clips(name.file, name.clip, options.fps, all, poses);
    else all.push_back({canonical_path(name.file), ""});
  }
  std::vector<Clip_source> once;  // a clip named twice is described once
  std::set<std::pair<std::string, std::string>> seen;
  for (Clip_source& clip : all)
    if (seen.insert({clip.file, clip.clip}).second) once.push_back(std::move(clip));
  return once;
}

similarity::Default_similarity store_policy(const similarity::Policy_choice& choice, Front front) {
  check(choice, front);
  if (choice.policy != "motion-signature" || similarity::alignment_name(choice) != "dtw")
    throw invalid_input("a motion store holds the motion signatures aligned by dtw, not " +
                        spelled("policy", choice.policy, front) + " with " +
                        spelled("alignment", similarity::alignment_name(choice), front));
  similarity::Default_similarity policy;
  policy.signatures.up = similarity::up_direction(choice.up);
  return policy;
}

std::string store_description(const similarity::Default_similarity& policy) {
  const signatures::Motion_signature_options& s = policy.signatures;
  const std::size_t width = (s.up ? 2 : 1) * s.lags.size() * s.quantiles;
  const nlohmann::json description = {
      {"policy", "motion-signature"}, {"alignment", "dtw"},         {"lags", s.lags},
      {"quantiles", s.quantiles},     {"floor", s.floor},           {"up", up_json(s.up)},
      {"vertical_unit", s.vertical_unit}, {"vertical_weight", s.vertical_weight},
      {"signature_rate", policy.signature_rate}, {"scale", policy.scale}, {"width", width}};
  return description.dump();
}

similarity::Policy_choice stored_policy_choice(const io::Motion_store& store) {
  const std::string manifest = (store.folder() / "store.json").string();
  const nlohmann::json stored = nlohmann::json::parse(store.description(), nullptr, false);
  if (!stored.is_object() || !stored.contains("up"))
    throw invalid_input("the store's description is not one of motion signatures: " + store.description(),
                        {.file = manifest});
  similarity::Policy_choice choice;
  if (stored["up"].is_null()) choice.up = "none";
  else
    for (const std::string_view name : similarity::up_names)
      if (name != "none" && up_json(similarity::up_direction(std::string(name))) == stored["up"]) choice.up = name;
  const nlohmann::json expected = nlohmann::json::parse(store_description(store_policy(choice, Front::command_line)));
  for (const auto& [key, value] : expected.items())
    if (!stored.contains(key) || stored[key] != value)
      throw invalid_input("the store was described with other options than this deformseg uses: its \"" + key +
                              "\" is " + (stored.contains(key) ? stored[key].dump() : "missing") + ", not " +
                              value.dump() + "; describe the clips again into a new store",
                          {.file = manifest});
  return choice;
}

std::string input_options_text(const std::string& file, const Input_options& options) {
  const nlohmann::json text = {{"fps", options.fps},
                               {"topology", options.topology.empty() ? "" : canonical_path(options.topology)},
                               {"triangulate", options.triangulate},
                               {"weld", repair_options(file, options).weld},
                               {"refuse_defects", options.refuse_defects}};
  return text.dump();
}

io::Store_record source_record(const Clip_source& clip, const Input_options& options, bool hash) {
  io::Store_record record;
  record.path = clip.file;
  record.clip = clip.clip;
  record.input_options = input_options_text(clip.file, options);
  const std::vector<fs::path> files = source_files(clip.file);
  const File_stamp source = stamp(files);
  record.source_size = source.size;
  record.source_mtime_ns = source.mtime_ns;
  if (hash) record.source_hash = hash_files(files);
  if (!options.topology.empty()) {
    record.topology_path = canonical_path(options.topology);
    const File_stamp topology = stamp(fs::path(record.topology_path));
    record.topology_size = topology.size;
    record.topology_mtime_ns = topology.mtime_ns;
  }
  return record;
}

bool unchanged(const io::Store_record& stored, const io::Store_record& now, bool hash) {
  const bool same_source = hash ? stored.source_hash != 0 && stored.source_hash == now.source_hash
                                : stored.source_mtime_ns == now.source_mtime_ns;
  return same_source && stored.input_options == now.input_options && stored.source_size == now.source_size &&
         stored.topology_path == now.topology_path && stored.topology_size == now.topology_size &&
         stored.topology_mtime_ns == now.topology_mtime_ns;
}

bool up_to_date(const io::Store_record& stored, const Clip_source& clip, const Input_options& options) {
  io::Store_record now = source_record(clip, options, false);
  if (unchanged(stored, now, false)) return true;
  if (stored.source_hash == 0) return false;
  now.source_hash = hash_files(source_files(clip.file));
  return unchanged(stored, now, true);
}

Describe_report describe_into_store(const std::string& folder, const std::vector<Clip_source>& clips,
                                    const Input_options& options, const similarity::Default_similarity& policy,
                                    bool hash, const std::function<void(const std::string&)>& say) {
  const std::size_t width = nlohmann::json::parse(store_description(policy))["width"].get<std::size_t>();
  io::Store_append append(folder, store_description(policy),
                          similarity::summary_width(width, store_summary_chunks),
                          io::motion_summary_layout(store_summary_chunks));
  Describe_report report;
  std::vector<io::Store_record> records(clips.size());
  std::map<std::string, std::vector<std::size_t>> to_read;  // by file, in the clips' order
  std::vector<std::string> files;
  for (std::size_t i = 0; i < clips.size(); ++i) {
    records[i] = source_record(clips[i], options, hash);
    const std::optional<std::size_t> at = append.store().find(clips[i].file, clips[i].clip);
    if (at && unchanged(append.store().record(*at), records[i], hash)) {
      report.skipped.push_back(clips[i].name());
      continue;
    }
    if (!to_read.count(clips[i].file)) files.push_back(clips[i].file);
    to_read[clips[i].file].push_back(i);
  }
  for (const std::string& file : files) {
    say("describing " + std::to_string(to_read[file].size()) + " clip(s) of " + file);
    read_file_clips(clips, to_read[file], options, [&](std::size_t i, const mesh::Surface_mesh_animation& animation) {
      require_motion(animation, clips[i].name());
      io::Store_record& record = records[i];
      record.frame_count = std::uint32_t(animation.num_frames());
      record.fps = mesh::frames_per_second(animation);
      similarity::Motion_signature_description description;
      try {
        description = policy.describe(animation);
      } catch (const invalid_input& e) {
        throw invalid_input(clips[i].name() + ": " + e.what());
      }
      const similarity::Motion_signature_view view = similarity::view(description);
      const std::vector<std::uint32_t> frames(description.frames.begin(), description.frames.end());
      const similarity::Motion_summary summary = similarity::summarize(view, store_summary_chunks);
      if (const std::optional<std::size_t> at = append.store().find(record.path, record.clip)) {
        append.replace(*at, record, view, frames, summary.floats);
        report.redescribed.push_back(clips[i].name());
      } else {
        append.add(record, view, frames, summary.floats);
        report.described.push_back(clips[i].name());
      }
    });
  }
  append.commit();
  report.clips = append.size();
  return report;
}

std::string stored_clip_name(const io::Motion_store& store, std::size_t i) {
  const io::Store_record record = store.record(i);
  return record.clip.empty() ? record.path : record.path + "#" + record.clip;
}

}  // namespace deformseg::frontend
