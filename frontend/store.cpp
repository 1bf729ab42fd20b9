#include "store.h"

#include "outputs.h"

#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/store/store_append.h>

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <span>
#include <system_error>
#include <tuple>
#include <utility>
#include <variant>

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

// glTF files parsed to list their clips (`add_gltf_clips`), kept for their description
// (`Gltf_parses`) so that a file given whole is parsed once (a parse is about a fifteenth of
// describing the clips of an animal of the shared library). Up to `budget` bytes of files; a file
// beyond is parsed again.
struct Listed_parses {
  static constexpr std::uintmax_t budget = std::uintmax_t(256) << 20;
  std::map<std::string, std::shared_ptr<const io::Gltf_file>> files;  // by canonical path
  std::uintmax_t bytes = 0;
};

// The clips of a glTF file: `clip` when given, else every clip of the file of 2 frames or more at
// `fps` (the others, poses, go to `poses`); a file without clips gives its one animation under "".
// The file's parse is kept in `parses`, when given and within its budget.
void add_gltf_clips(const std::string& file, const std::string& clip, const std::string& body, double fps,
                    std::vector<Clip_source>& out, std::vector<std::string>& poses, Listed_parses* parses) {
  if (!clip.empty()) {
    out.push_back({canonical_path(file), clip, body});
    return;
  }
  std::shared_ptr<const io::Gltf_file> parsed;
  std::error_code error;
  const std::uintmax_t size = fs::file_size(file, error);
  if (parses && !error && parses->bytes + size <= Listed_parses::budget) try {
      parsed = std::make_shared<const io::Gltf_file>(file);
    } catch (const invalid_input&) {
      // Listed as before (gltf_contents says what is wrong); its clips fail when described.
    }
  const io::Gltf_contents contents = parsed ? parsed->contents(fps) : io::gltf_contents(file, fps);
  if (parsed) parses->files[canonical_path(file)] = parsed, parses->bytes += size;
  if (contents.clips.empty()) out.push_back({canonical_path(file), "", body});
  for (std::size_t k = 0; k < contents.clips.size(); ++k) {
    const Clip_source source{canonical_path(file),
                             contents.clips[k].name.empty() ? std::to_string(k) : contents.clips[k].name, body};
    if (contents.clips[k].frames < 2) poses.push_back(source.name());
    else out.push_back(source);
  }
}

// A path given or not (a body, a topology), as a store records it: canonical, "" for none.
std::string canonical_if_given(const std::string& path) { return path.empty() ? "" : canonical_path(path); }

// `options` with `body` as its body, when it names one.
Input_options with_body(const std::string& body, const Input_options& options) {
  if (body.empty()) return options;
  Input_options own = options;
  own.body = body;
  return own;
}

// The name of the only clip of a character file ("0" for an unnamed one, "" for none), played on
// `options.body` when it names one.
// @throws invalid_input naming the file when it cannot be parsed or has several clips.
std::string only_clip(const fs::path& file, const Input_options& options) {
  const io::Gltf_file gltf = character_file(file.string(), options);
  io::require_clip_choice(gltf, "");
  const std::vector<std::string> names = gltf.clip_names();
  return names.empty() ? "" : names.front().empty() ? "0" : names.front();
}

}  // namespace

std::vector<Clip_source> labelled_clips(const std::string& labels, const Input_options& options,
                                        std::vector<std::string>* unreadable) {
  std::vector<Clip_source> out;
  std::map<fs::path, std::size_t> rows_of_file;
  const std::vector<evaluation::Labelled_clip> rows = evaluation::read_motion_labels(labels);
  for (const evaluation::Labelled_clip& row : rows) ++rows_of_file[row.file];
  for (const evaluation::Labelled_clip& row : rows) {
    const std::string file = row.file.string();
    if (!io::is_character_file(row.file)) {
      if (rows_of_file[row.file] > 1)
        throw invalid_input("lists " + std::to_string(rows_of_file[row.file]) + " clips of " + file +
                                ", which is not a character file (glTF, FBX, Collada, BVH) and holds one animation",
                            {.file = labels});
      out.push_back({canonical_path(file), ""});
      continue;
    }
    const std::string body = canonical_if_given(row.body_file.empty() ? options.body : row.body_file.string());
    std::string clip = row.item.clip.empty() ? options.clip : row.item.clip;
    if (clip.empty()) try {  // the file's only clip, as evaluate reads it
        clip = only_clip(row.file, with_body(body, options));
      } catch (const invalid_input& e) {
        if (!unreadable) throw;
        unreadable->push_back(store::escaped_name(file) + ": " + utf8_text(e.what()));
        continue;
      }
    out.push_back({canonical_path(file), clip, body});
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
  if (files.size() == 1) return store::hash_file(files.front());
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const fs::path& file : files) hash = (hash ^ store::hash_file(file)) * 0x100000001b3ull;
  return hash == 0 ? 1 : hash;
}

nlohmann::json up_json(const std::optional<Eigen::Vector3d>& up) {
  if (!up) return nullptr;
  return {(*up)[0], (*up)[1], (*up)[2]};
}

// `clip_sources`, the files parsed to list their clips kept in `parses` when given.
std::vector<Clip_source> list_clips(const std::vector<std::string>& inputs, const Input_options& options,
                                    std::vector<std::string>& poses, std::vector<std::string>* unreadable,
                                    Listed_parses* parses) {
  check_clip_applies(inputs, options, Front::command_line);
  std::vector<Clip_source> all;
  for (const std::string& input : inputs) {
    if (is_labels_file(input)) {
      for (Clip_source& clip : labelled_clips(input, options, unreadable)) all.push_back(std::move(clip));
      continue;
    }
    const Input_name name = input_name(input, options, Front::command_line);
    if (!io::is_character_file(name.file)) {
      all.push_back({canonical_path(name.file), ""});
      continue;
    }
    try {
      add_gltf_clips(name.file, name.clip, canonical_if_given(options.body), options.fps, all, poses,
                     options.body.empty() ? parses : nullptr);
    } catch (const invalid_input& e) {
      if (!unreadable) throw;
      unreadable->push_back(store::escaped_name(input) + ": " + utf8_text(e.what()));
    }
  }
  std::vector<Clip_source> once;  // a clip named twice on one body is described once
  std::set<std::tuple<std::string, std::string, std::string>> seen;
  for (Clip_source& clip : all)
    if (seen.insert({clip.file, clip.clip, clip.body}).second) once.push_back(std::move(clip));
  return once;
}

}  // namespace

std::vector<Clip_source> clip_sources(const std::vector<std::string>& inputs, const Input_options& options,
                                      std::vector<std::string>& poses, std::vector<std::string>* unreadable) {
  return list_clips(inputs, options, poses, unreadable, nullptr);
}

similarity::Default_similarity store_policy(const Policy_choice& choice, Front front) {
  check(choice, front);
  const similarity::Any_policy policy = make_policy(choice);
  if (const auto* signatures = std::get_if<similarity::Default_similarity>(&policy)) return *signatures;
  throw invalid_input("a motion store holds the motion signatures aligned by dtw, not " +
                      spelled("policy", choice.policy, front) + " with " +
                      spelled("alignment", alignment_name(choice), front));
}

std::size_t signature_width(const similarity::Default_similarity& policy) {
  const signatures::Motion_signature_options& s = policy.signatures;
  return (s.up ? 2 : 1) * s.lags.size() * s.bands * (s.sides ? 2 : 1) * s.quantiles;
}

std::string store_description(const similarity::Default_similarity& policy) {
  const signatures::Motion_signature_options& s = policy.signatures;
  const std::size_t width = signature_width(policy);
  // The store's policy is the registry's default (store_policy refuses any other).
  const Policy_entry& stored = similarity_policies[0];
  nlohmann::json description = {
      {"policy", stored.name},        {"alignment", stored.alignment}, {"lags", s.lags},
      {"quantiles", s.quantiles},     {"floor", s.floor},           {"up", up_json(s.up)},
      {"vertical_unit", s.vertical_unit}, {"vertical_weight", s.vertical_weight},
      {"signature_rate", policy.signature_rate}, {"scale", policy.scale}, {"width", width}};
  if (s.bands > 1) description["bands"] = s.bands;  // absent: one band, as every store before them
  if (s.sides) description["sides"] = up_json(s.sides);  // absent: the whole width
  return description.dump();
}

Policy_choice stored_policy_choice(const store::Motion_store& store) {
  const std::string manifest = (store.folder() / "store.json").string();
  const nlohmann::json stored = nlohmann::json::parse(store.description(), nullptr, false);
  if (!stored.is_object() || !stored.contains("up"))
    throw invalid_input("the store's description is not one of motion signatures: " + store.description(),
                        {.file = manifest});
  Policy_choice choice;
  for (const Choice& up : up_direction_choices)
    if (up_json(up_direction(up.name)) == stored["up"]) choice.up = up.name;
  if (const auto bands = stored.find("bands"); bands != stored.end() && bands->is_number_unsigned())
    choice.bands = bands->get<std::size_t>();
  for (const Choice& side : side_direction_choices)
    if (stored.contains("sides") && up_json(side_direction(std::string(side.name))) == stored["sides"])
      choice.sides = side.name;
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
  nlohmann::json text = {{"fps", options.fps},
                         {"topology", store::escaped_name(canonical_if_given(options.topology))},
                         {"triangulate", options.triangulate},
                         {"weld", repair_options(file, options).weld},
                         {"refuse_defects", options.refuse_defects}};
  if (!options.body.empty()) text["body"] = store::escaped_name(canonical_path(options.body));  // absent: before bodies
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
  // The file the input is read with, recorded as the topology: a point cache's topology, or a
  // character's body (one or the other applies).
  if (const std::string& companion = options.topology.empty() ? options.body : options.topology; !companion.empty()) {
    const std::string topology_path = canonical_path(companion);
    record.topology_path = store::escaped_name(topology_path);
    const File_stamp topology = stamp(fs::path(topology_path));
    record.topology_size = topology.size;
    record.topology_mtime_ns = topology.mtime_ns;
  }
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

namespace {

// ---- describing clips into a store ---------------------------------------------------------

// A clip described, kept until its turn to be appended.
struct Described_clip {
  std::uint32_t frame_count = 0;
  double fps = 0;
  similarity::Motion_signature_description description;
  search::Motion_summary summary;
  std::string warning;  ///< of outlying vertices (`Outliers::warning`), said when it is appended
};

// The whole animation of `clip` as read_input reads it, its outliers checked; a glTF clip from
// `gltf`, its file parsed once.
Read_input read_whole(const Clip_source& clip, const io::Gltf_file* gltf, const Input_options& options, Front front) {
  if (!gltf) {
    Input_options frames = options;
    frames.clip.clear();
    return read_input(clip.file, frames, front);
  }
  Read_input read{gltf->read({.clip = clip.clip, .fps = options.fps, .repair = repair_options(clip.file, options),
                              .threads = options.threads}),
                  {clip.file, clip.clip}};
  check_outliers(read, options.refuse_defects, front);
  return read;
}

// A description's error, named by its clip (a reader's names its file and frame already).
invalid_input of_clip(const Clip_source& clip, const invalid_input& error) {
  return invalid_input(clip.name() + ": " + error.what());
}

Described_clip summarized(std::size_t frames, double fps, similarity::Motion_signature_description description) {
  search::Motion_summary summary = search::summarize(similarity::view(description), store_summary_chunks);
  return {std::uint32_t(frames), fps, std::move(description), std::move(summary), {}};
}

Described_clip describe_whole(const Clip_source& clip, const io::Gltf_file* gltf, const Input_options& options,
                              const similarity::Default_similarity& policy, Front front) {
  const Read_input read = read_whole(clip, gltf, options, front);
  const mesh::Surface_mesh_animation& animation = read.animation;
  require_motion(animation, clip.name());
  try {
    Described_clip described =
        summarized(animation.num_frames(), mesh::frames_per_second(animation), policy.describe(animation));
    described.warning = read.outliers.warning(front);
    return described;
  } catch (const invalid_input& e) {
    throw of_clip(clip, e);
  }
}

// A frame source that notes when reading fails: the reader's errors name the file and the frame
// already and are passed on as they are, the description's get the clip's name (as read whole).
template <signatures::FrameSource Source>
class Noting_source {
public:
  using Coordinate = typename Source::Coordinate;

  explicit Noting_source(Source& source) : source_(source) {}
  std::size_t num_vertices() const { return source_.num_vertices(); }
  std::size_t num_frames() const { return source_.num_frames(); }
  double frames_per_second() const { return source_.frames_per_second(); }
  std::span<const std::array<std::uint32_t, 3>> triangles() const { return source_.triangles(); }
  void read_frame(std::span<Coordinate> out) {
    noting([&] { source_.read_frame(out); });
  }
  void rewind() {
    noting([&] { source_.rewind(); });
  }
  bool failed() const { return failed_; }

private:
  template <class Read>
  void noting(const Read& read) {
    try {
      read();
    } catch (...) {
      failed_ = true;
      throw;
    }
  }

  Source& source_;
  bool failed_ = false;
};

// `policy.describe_stream(source)`: the same signatures as `describe` of the animation read whole,
// holding the frames the longest lag needs, not the clip's.
template <signatures::FrameSource Source>
Described_clip describe_streamed(Source& source, const Clip_source& clip, const io::Gltf_file* gltf,
                                 const Input_options& options, const similarity::Default_similarity& policy,
                                 Front front) {
  if (source.num_frames() < 2) return describe_whole(clip, gltf, options, policy, front);  // refused as before
  Outliers outliers;
  Outlier_checked_source<Source> checked(source, clip.file, options.refuse_defects, front, outliers);
  Noting_source noting(checked);
  similarity::Motion_signature_description description;
  try {
    description = policy.describe_stream(noting);
  } catch (const invalid_input& e) {
    if (noting.failed()) throw;
    throw of_clip(clip, e);
  }
  Described_clip described = summarized(source.num_frames(), source.frames_per_second(), std::move(description));
  described.warning = outliers.warning(front);
  return described;
}

// Describes `clip` as `read_input` reads it, frame by frame: a glTF clip from `gltf` with
// `connectivity`, the file's (welded, when it is, by what the file fixes: the stream's connectivity
// is read's); a point cache or frame sequence through `io::with_frame_source` with the same
// topology, triangulation, repair and fps, when it `reads_frame_by_frame`.
Described_clip describe_clip(const Clip_source& clip, const io::Gltf_file* gltf,
                             std::shared_ptr<const io::Gltf_connectivity> connectivity, const Input_options& options,
                             const similarity::Default_similarity& policy, Front front) {
  if (gltf) {
    io::Gltf_frame_source source(std::move(connectivity), {.clip = clip.clip, .fps = options.fps});
    return describe_streamed(source, clip, gltf, options, policy, front);
  }
  if (!reads_frame_by_frame(clip.file, options)) return describe_whole(clip, nullptr, options, policy, front);
  return io::with_frame_source(clip.file, animation_read_options(clip.file, options),
                               [&](auto& source) { return describe_streamed(source, clip, nullptr, options, policy, front); });
}

// Each glTF file parsed once for its clips, by the first of them to be described, its connectivity
// repaired once, by the first to stream one, and both freed after the last (clips of other files
// may be described meanwhile, on other threads).
class Gltf_parses {
public:
  // For the clips `order` names, read with `options` (their body, unless a clip names its own);
  // the files that `listed` holds (parsed without a body) taken from it.
  Gltf_parses(const std::vector<Clip_source>& clips, const std::vector<std::size_t>& order,
              const Input_options& options, Listed_parses* listed)
      : options_(options) {
    for (const std::size_t i : order)
      if (io::is_character_file(clips[i].file)) ++files_[key(clips[i])].clips_left;
    if (!listed) return;
    for (auto& [file_and_body, entry] : files_)
      if (file_and_body.second.empty() && options.body.empty())
        if (const auto parsed = listed->files.find(file_and_body.first); parsed != listed->files.end())
          entry.parsed = parsed->second;
    listed->files.clear();  // the files of no clip to describe are freed now
  }

  // The parsed file of `clip` (on its body); a parse that failed throws again for each of its clips.
  std::shared_ptr<const io::Gltf_file> acquire(const Clip_source& clip) {
    File& entry = files_.at(key(clip));
    const std::lock_guard lock(entry.mutex);
    if (entry.error) std::rethrow_exception(entry.error);
    if (!entry.parsed) try {
        entry.parsed = std::make_shared<const io::Gltf_file>(character_file(clip.file, with_body(clip.body, options_)));
      } catch (...) {
        entry.error = std::current_exception();
        throw;
      }
    return entry.parsed;
  }

  // The connectivity of the file of `clip` (acquired), as `read_input` repairs it; a repair that
  // failed throws again for each of its clips.
  std::shared_ptr<const io::Gltf_connectivity> connectivity(const Clip_source& clip) {
    File& entry = files_.at(key(clip));
    const std::lock_guard lock(entry.mutex);
    if (entry.repair_error) std::rethrow_exception(entry.repair_error);
    if (!entry.connectivity) try {
        entry.connectivity =
            std::make_shared<const io::Gltf_connectivity>(*entry.parsed, repair_options(clip.file, options_));
      } catch (...) {
        entry.repair_error = std::current_exception();
        throw;
      }
    return entry.connectivity;
  }

  // One clip of the parse `acquire` gave described: the parse is freed after its last.
  void release(const Clip_source& clip) {
    File& entry = files_.at(key(clip));
    const std::lock_guard lock(entry.mutex);
    if (--entry.clips_left == 0) entry.connectivity.reset(), entry.parsed.reset();
  }

private:
  struct File {
    std::mutex mutex;
    std::shared_ptr<const io::Gltf_file> parsed;
    std::shared_ptr<const io::Gltf_connectivity> connectivity;  // refers to `parsed`
    std::exception_ptr error, repair_error;
    std::size_t clips_left = 0;
  };
  // A file parsed on one body: its name and its body's.
  static std::pair<std::string, std::string> key(const Clip_source& clip) { return {clip.file, clip.body}; }

  std::map<std::pair<std::string, std::string>, File> files_;  // made whole by the constructor, never added to
  const Input_options& options_;
};

// Releases a clip's parse (`Gltf_parses::release`) when it is described or has failed; nothing for
// a clip of another format (no clip).
class Release_parse {
public:
  Release_parse(Gltf_parses& parses, const Clip_source* clip) : parses_(parses), clip_(clip) {}
  Release_parse(const Release_parse&) = delete;
  Release_parse& operator=(const Release_parse&) = delete;
  ~Release_parse() {
    if (clip_) parses_.release(*clip_);
  }

private:
  Gltf_parses& parses_;
  const Clip_source* clip_;
};

// The clips described at once, then appended in order: at least 32, so that few threads wait for
// the batch's last clip; 4 per thread on more than 8. At most `threads` clips are read at once.
std::size_t describe_batch(int threads) { return std::max<std::size_t>(32, 4 * std::size_t(threads)); }

// Appends `described` as clip `clip` of `record` (replacing the clip's old description, if any).
void append_clip(store::Store_append& append, const Clip_source& clip, const store::Store_record& record,
                 const Described_clip& described, Describe_report& report) {
  const signatures::Motion_signature_view view = similarity::view(described.description);
  const std::vector<std::uint32_t> frames(described.description.frames.begin(), described.description.frames.end());
  if (const std::optional<std::size_t> at = append.store().find(record.path, record.clip, record.body)) {
    append.replace(*at, record, view, frames, described.summary.floats);
    report.redescribed.push_back(clip.name());
  } else {
    append.add(record, view, frames, described.summary.floats);
    report.described.push_back(clip.name());
  }
}

// The clips of `clips` to describe, their records in `records`: those the store lacks or holds
// changed, a file's together in the order of the files' first clips (the order they are appended
// in); the others are reported skipped.
std::vector<std::size_t> clips_to_describe(const std::vector<Clip_source>& clips, const Input_options& options,
                                           bool hash, bool skip_unreadable, const store::Motion_store& store,
                                           std::vector<store::Store_record>& records, Describe_report& report) {
  std::map<std::string, std::vector<std::size_t>> of_file;
  std::vector<std::string> files;
  for (std::size_t i = 0; i < clips.size(); ++i) {
    try {
      records[i] = source_record(clips[i], options, hash);
    } catch (const invalid_input& e) {
      if (!skip_unreadable) throw;
      report.unreadable.push_back(clips[i].name() + ": " + utf8_text(e.what()));
      continue;
    }
    const std::optional<std::size_t> at = find_clip(store, clips[i]);
    if (at && unchanged(store.record(*at), records[i], hash)) {
      report.skipped.push_back(clips[i].name());
      continue;
    }
    if (!of_file.count(clips[i].file)) files.push_back(clips[i].file);
    of_file[clips[i].file].push_back(i);
  }
  std::vector<std::size_t> order;
  for (const std::string& file : files) order.insert(order.end(), of_file[file].begin(), of_file[file].end());
  return order;
}

// "45 s", "3 min 20 s", "2 h 5 min": a duration as a progress line gives it.
std::string duration_text(double seconds) {
  const auto whole = std::uint64_t(std::max(0.0, std::round(seconds)));
  if (whole < 60) return std::to_string(whole) + " s";
  if (whole < 3600) return std::to_string(whole / 60) + " min " + std::to_string(whole % 60) + " s";
  return std::to_string(whole / 3600) + " h " + std::to_string(whole / 60 % 60) + " min";
}

// A line per clip described, with the rates so far and the time left at that rate: said under a
// lock by the thread that described the clip, so that a long batch still shows its progress.
class Clip_progress {
public:
  Clip_progress(std::size_t total, const std::function<void(const std::string&)>& say) : total_(total), say_(say) {}

  void described(const Clip_source& clip, std::size_t frames) {
    const std::lock_guard lock(mutex_);
    ++done_, frames_ += frames;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    char rates[64];
    std::snprintf(rates, sizeof rates, "%.1f clips/s, %.0f frames/s", double(done_) / seconds,
                  double(frames_) / seconds);
    say_("described " + std::to_string(done_) + " of " + std::to_string(total_) + ": " + clip.name() + " (" +
         std::to_string(frames) + " frames); " + rates + ", about " +
         duration_text(seconds / double(done_) * double(total_ - done_)) + " left");
  }

private:
  std::mutex mutex_;
  std::size_t total_, done_ = 0, frames_ = 0;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  const std::function<void(const std::string&)>& say_;
};

// Says "describing N clip(s) of FILE" for each file whose first clip is among order[first, end).
void announce_files(const std::vector<Clip_source>& clips, const std::vector<std::size_t>& order, std::size_t first,
                    std::size_t end, const std::function<void(const std::string&)>& say) {
  for (std::size_t k = first; k < end; ++k) {
    const std::string& file = clips[order[k]].file;
    if (k > 0 && clips[order[k - 1]].file == file) continue;
    std::size_t count = 1;
    while (k + count < order.size() && clips[order[k + count]].file == file) ++count;
    say("describing " + std::to_string(count) + " clip(s) of " + file);
  }
}

// `describe_into_store`, taking the files that `listed` holds parsed.
Describe_report describe_clips(const std::string& folder, const std::vector<Clip_source>& clips,
                               const Input_options& options, const similarity::Default_similarity& policy,
                               const Describe_run& run, const std::function<void(const std::string&)>& say,
                               Listed_parses* listed) {
  const auto start_append = [&] {
    return std::make_unique<store::Store_append>(folder, store_description(policy),
                                              search::summary_width(signature_width(policy), store_summary_chunks),
                                              store::motion_summary_layout(store_summary_chunks));
  };
  std::unique_ptr<store::Store_append> append = start_append();
  Describe_report report;
  std::vector<store::Store_record> records(clips.size());
  const std::vector<std::size_t> order =
      clips_to_describe(clips, options, run.hash, run.skip_unreadable, append->store(), records, report);
  Gltf_parses parses(clips, order, options, listed);
  Clip_progress progress(order.size(), say);
  const std::size_t batch = describe_batch(thread_count(options.threads));
  // A batch of one clip leaves the threads to its rows: they take the clips' threads.
  similarity::Default_similarity threaded = policy;
  threaded.signatures.threads = options.threads;
  std::vector<Described_clip> described;
  std::vector<std::optional<invalid_input>> errors;
  // The clips appended since the last commit; every `store_commit_clips` of `order` are committed.
  std::size_t appended = 0;
  const auto commit = [&] {
    report.clips = append->size();
    append->commit();
    append.reset();
    appended = 0;
  };
  for (std::size_t first = 0; first < order.size(); first += batch) {
    const std::size_t count = std::min(batch, order.size() - first);
    announce_files(clips, order, first, first + count, say);
    described.assign(count, {});
    errors.assign(count, std::nullopt);
    // A clip per thread, by the library's one parallel loop (a detail: threads.h has no public
    // loop): a batch of one clip leaves the threads to its rows (loops nested in a loop of several
    // threads run on one). A clip that cannot be read or described is noted, not thrown, so that
    // the clips before it are stored whatever the threads did.
    deformseg::internal::parallel_for(count, options.threads, [&](std::size_t k) {
      const Clip_source& clip = clips[order[first + k]];
      try {
        const std::shared_ptr<const io::Gltf_file> gltf =
            io::is_character_file(clip.file) ? parses.acquire(clip) : nullptr;
        const Release_parse release(parses, gltf ? &clip : nullptr);
        described[k] = describe_clip(clip, gltf.get(), gltf ? parses.connectivity(clip) : nullptr, options, threaded,
                                     run.front);
        progress.described(clip, described[k].frame_count);
      } catch (const invalid_input& e) {
        errors[k] = e;
      }
    });
    for (std::size_t k = 0; k < count; ++k) {
      const Clip_source& clip = clips[order[first + k]];
      if (errors[k]) {
        if (!run.skip_unreadable) {
          if (append && appended > 0) commit();
          throw invalid_input(errors[k]->message() + " (" + spelled("skip_unreadable", run.front) +
                                  " leaves it out; the " +
                                  std::to_string(report.described.size() + report.redescribed.size()) +
                                  " clip(s) described before it are in the store)",
                              errors[k]->where());
        }
        say("left out " + clip.name() + ": " + errors[k]->what());
        report.unreadable.push_back(clip.name() + ": " + utf8_text(errors[k]->what()));
      } else {
        if (!described[k].warning.empty()) say("warning: " + clip.name() + ": " + described[k].warning);
        if (!append) append = start_append();
        store::Store_record& record = records[order[first + k]];
        record.frame_count = described[k].frame_count;
        record.fps = described[k].fps;
        append_clip(*append, clip, record, described[k], report);
        ++appended;
      }
      if ((first + k + 1) % store_commit_clips == 0 && append && appended > 0) commit();
    }
  }
  if (append) commit();
  return report;
}

}  // namespace

Describe_report describe_into_store(const std::string& folder, const std::vector<Clip_source>& clips,
                                    const Input_options& options, const similarity::Default_similarity& policy,
                                    const Describe_run& run, const std::function<void(const std::string&)>& say) {
  return describe_clips(folder, clips, options, policy, run, say, nullptr);
}

Describe_report describe_inputs(const std::string& folder, const std::vector<std::string>& inputs,
                                const Input_options& options, const similarity::Default_similarity& policy,
                                const Describe_run& run, const std::function<void(const std::string&)>& say) {
  std::vector<std::string> poses, unlisted;
  Listed_parses listed;
  const std::vector<Clip_source> clips =
      list_clips(inputs, options, poses, run.skip_unreadable ? &unlisted : nullptr, &listed);
  say(std::to_string(clips.size()) + " clip(s) named by the inputs");
  for (const std::string& pose : poses) say("left out " + pose + ": a pose of 1 frame, no motion");
  for (const std::string& input : unlisted) say("left out " + input);
  Describe_report report = describe_clips(folder, clips, options, policy, run, say, &listed);
  report.unreadable.insert(report.unreadable.begin(), unlisted.begin(), unlisted.end());
  report.poses = std::move(poses);
  return report;
}

Description_plan plan_description(const std::string& folder, const std::vector<Clip_source>& clips,
                                  const Input_options& options, const similarity::Default_similarity& policy,
                                  bool hash) {
  std::error_code error;
  const bool exists = std::filesystem::exists(std::filesystem::path(folder) / "store.json", error);
  const store::Motion_store store = exists ? store::Motion_store::open(folder) : store::Motion_store{};
  if (exists && nlohmann::json::parse(store.description()) != nlohmann::json::parse(store_description(policy)))
    throw invalid_input("the store's clips were described with other options (deformseg store info " + folder +
                            " gives them) than " + store_description(policy),
                        {.file = folder});
  Description_plan plan;
  std::vector<store::Store_record> records(clips.size());
  plan.order = clips_to_describe(clips, options, hash, false, store, records, plan.report);
  plan.report.clips = store.size();
  return plan;
}

Describe_report merge_stores(const std::string& folder, const std::vector<std::string>& parts,
                             const std::function<void(const std::string&)>& say) {
  Describe_report report;
  if (parts.empty()) {
    std::error_code error;
    if (std::filesystem::exists(std::filesystem::path(folder) / "store.json", error))
      report.clips = store::Motion_store::open(folder).size();
    return report;
  }
  const store::Motion_store first = store::Motion_store::open(parts.front());
  store::Store_append append(folder, first.description(), first.summary_width(), first.summary_layout());
  for (const std::string& name : parts) {
    const store::Motion_store part = store::Motion_store::open(name);
    if (part.description() != first.description() || part.summary_layout() != first.summary_layout())
      throw invalid_input("this part's clips were described with other options than " + parts.front() + "'s",
                          {.file = name});
    say("merging " + std::to_string(part.size()) + " clip(s) of " + name);
    for (std::size_t i = 0; i < part.size(); ++i) {
      part.verify_clip(i);  // never carry a corrupted block into the merged store under a new checksum
      const store::Store_record record = part.record(i);
      const std::vector<std::uint32_t> frames(part.frames(i).begin(), part.frames(i).end());
      const std::string clip_name = stored_clip_name(part, i);
      if (const std::optional<std::size_t> at = append.store().find(record.path, record.clip, record.body)) {
        append.replace(*at, record, part.view(i), frames, part.summary(i));
        report.redescribed.push_back(clip_name);
      } else {
        append.add(record, part.view(i), frames, part.summary(i));
        report.described.push_back(clip_name);
      }
    }
  }
  append.commit();
  report.clips = append.size();
  return report;
}

std::string clip_name(const std::string& file, const std::string& clip, const std::string& body) {
  const std::string name = clip.empty() ? file : file + "#" + clip;
  return body.empty() ? name : name + " on " + body;
}

std::string stored_clip_name(const store::Motion_store& store, std::size_t i) {
  const store::Store_record record = store.record(i);
  return clip_name(record.path, record.clip, record.body);
}

std::optional<std::size_t> find_clip(const store::Motion_store& store, const Clip_source& clip) {
  return store.find(store::escaped_name(clip.file), store::escaped_name(clip.clip), store::escaped_name(clip.body));
}

}  // namespace deformseg::frontend
