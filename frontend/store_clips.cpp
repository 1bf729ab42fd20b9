#include "store_clips.h"

#include "outputs.h"

#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/gltf.h>

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <system_error>
#include <tuple>
#include <utility>

namespace deformseg::frontend {

namespace fs = std::filesystem;

namespace {

bool is_labels_file(const std::string& input) {
  const std::string ext = fs::path(input).extension().string();
  return ext == ".csv" || ext == ".CSV";
}

// The clips of a glTF file: `clip` when given, else every clip of the file of 2 frames or more at
// `fps` (the others, poses, go to `poses`); a file without clips gives its one animation under "".
// The file's parse is kept in `parses`, when given and within its budget.
void add_gltf_clips(const std::string& file, const std::string& clip, const std::string& body, double fps,
                    std::vector<Clip_source>& out, std::vector<std::string>& poses, Listed_parses* parses) {
  if (!clip.empty()) {
    out.push_back({store_path(file), clip, body});
    return;
  }
  // A file that cannot be parsed is listed as before (gltf_contents says what is wrong).
  const std::shared_ptr<const io::Gltf_file> parsed = parses ? parses->parse(file, store_path(file)) : nullptr;
  const io::Gltf_contents contents = parsed ? parsed->contents(fps) : io::gltf_contents(file, fps);
  if (contents.clips.empty()) out.push_back({store_path(file), "", body});
  for (std::size_t k = 0; k < contents.clips.size(); ++k) {
    const Clip_source source{store_path(file),
                             contents.clips[k].name.empty() ? std::to_string(k) : contents.clips[k].name, body};
    if (contents.clips[k].frames < 2) poses.push_back(source.name());
    else out.push_back(source);
  }
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

// `all` without the clips named again on the same body: a clip is described once.
std::vector<Clip_source> each_once(std::vector<Clip_source> all) {
  std::vector<Clip_source> once;
  std::set<std::tuple<std::string, std::string, std::string>> seen;
  for (Clip_source& clip : all)
    if (seen.insert({clip.file, clip.clip, clip.body}).second) once.push_back(std::move(clip));
  return once;
}

}  // namespace

std::string store_path(const std::string& path) {
  std::error_code error;
  const fs::path canonical = fs::canonical(path, error);
  if (!error) return canonical.string();
  return fs::absolute(path).lexically_normal().string();
}

std::string store_path_if_given(const std::string& path) { return path.empty() ? "" : store_path(path); }

Input_options with_body(const std::string& body, const Input_options& options) {
  if (body.empty()) return options;
  Input_options own = options;
  own.body = body;
  return own;
}

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
      out.push_back({store_path(file), ""});
      continue;
    }
    const std::string body = store_path_if_given(row.body_file.empty() ? options.body : row.body_file.string());
    std::string clip = row.item.clip.empty() ? options.clip : row.item.clip;
    if (clip.empty()) try {  // the file's only clip, as evaluate reads it
        clip = only_clip(row.file, with_body(body, options));
      } catch (const invalid_input& e) {
        if (!unreadable) throw;
        unreadable->push_back(store::escaped_name(file) + ": " + utf8_text(e.what()));
        continue;
      }
    out.push_back({store_path(file), clip, body});
  }
  return out;
}

std::vector<Clip_source> clip_sources(const std::vector<std::string>& inputs, const Input_options& options,
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
      all.push_back({store_path(name.file), ""});
      continue;
    }
    try {
      add_gltf_clips(name.file, name.clip, store_path_if_given(options.body), options.fps, all, poses,
                     options.body.empty() ? parses : nullptr);
    } catch (const invalid_input& e) {
      if (!unreadable) throw;
      unreadable->push_back(store::escaped_name(input) + ": " + utf8_text(e.what()));
    }
  }
  return each_once(std::move(all));
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
