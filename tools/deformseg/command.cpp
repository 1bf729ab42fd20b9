#include "command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace deformseg::tool {

namespace {

const char* const input_help =
    "a character file (glTF .glb, .gltf; FBX .fbx; Collada .dae; BVH motion capture .bvh, on a body made from its "
    "skeleton unless --body gives one; a clip as FILE.glb#CLIP or by --clip), a folder of frames (.obj, .off, .ply; "
    "natural order), a quoted glob pattern, or a point cache (.pc2, .mdd) with --topology";

}  // namespace

void add_inputs(CLI::App& command, const std::string& name, std::vector<std::string>& inputs, int fewest, int most,
                Input_options& options, const std::string& help) {
  command.add_option(name, inputs, help + ", each " + input_help)->required()->expected(fewest, most);
  add_parameters(command, frontend::input_parameters, options);
}

void add_input(CLI::App& command, std::string& input, Input_options& options) {
  command.add_option("input", input, std::string("The animation: ") + input_help)->required();
  add_parameters(command, frontend::input_parameters, options);
}

namespace {

// What an input read whole (frontend::Read_input) or frame by frame (frontend::Stream_read) says
// once open: the clip it plays and what the repair changed.
template <class Read>
void report_opened(const Read& read, const Input_options& options) {
  if (read.gltf)
    progress("clip \"" + read.gltf->clip + "\", " + std::to_string(read.gltf->frames) + " frames at " +
             nlohmann::json(options.fps).dump() + " fps");
  if (read.repair.changed()) progress("repaired: " + frontend::describe(read.repair));
}

// The warnings its frames gave: outlying vertices, a body that the clip moves in part.
template <class Read>
void report_warnings(const std::string& input, const Read& read, const Input_options& options) {
  if (const std::string warning = read.outliers.warning(frontend::Front::command_line); !warning.empty())
    progress("warning: " + input + ": " + warning);
  if (const std::string warning = frontend::body_fit_warning(read, options); !warning.empty())
    progress("warning: " + input + ": " + warning);
}

frontend::Read_input read_one(const std::string& input, const Input_options& options, bool first_clip_by_default) {
  progress("reading " + input);
  frontend::Read_input read = frontend::read_input(input, options, frontend::Front::command_line,
                                                   first_clip_by_default);
  report_opened(read, options);
  report_warnings(input, read, options);
  return read;
}

}  // namespace

void report_stream(const std::string& input, const frontend::Stream_read& read, const Input_options& options,
                   bool done) {
  if (done)
    report_warnings(input, read, options);
  else
    report_opened(read, options);
}

frontend::Read_input read_input(const std::string& input, const Input_options& options, bool first_clip_by_default) {
  frontend::check_clip_applies({input}, options, frontend::Front::command_line);
  return read_one(input, options, first_clip_by_default);
}

frontend::Read_input read_one_of(const std::string& input, const Input_options& options) {
  return read_one(input, options, false);
}

std::vector<frontend::Read_input> read_inputs(const std::vector<std::string>& inputs, const Input_options& options,
                                              bool motions_only) {
  frontend::check_clip_applies(inputs, options, frontend::Front::command_line);
  std::vector<frontend::Read_input> read;
  for (const std::string& input : inputs) {
    read.push_back(read_one(input, options, false));
    if (motions_only) frontend::require_motion(read.back().animation, input);
  }
  return read;
}

nlohmann::json sources(std::span<const frontend::Read_input> inputs, const Input_options& options) {
  nlohmann::json records = nlohmann::json::array();
  for (const frontend::Read_input& input : inputs) records.push_back(frontend::input_record(input, options.fps));
  return records;
}

nlohmann::json sources(const frontend::Stream_read& input, const Input_options& options) {
  nlohmann::json record = frontend::input_record(input.name.file, options.fps);
  if (input.gltf) record["clip"] = input.gltf->clip;
  return nlohmann::json::array({record});
}

void write_outputs(const nlohmann::json& document, const std::string& json_path,
                   const std::function<void()>& print_summary, bool standard_output_taken) {
  if (!json_path.empty()) frontend::write_json(document, json_path);
  if (json_path != "-" && !standard_output_taken) print_summary();
}

void add_json_option(CLI::App& command, std::string& path, const std::string& what) {
  command.add_option("--json", path, "Write " + what + " as JSON to FILE ('-': standard output, in place of the "
                                     "summary)")
      ->check(output_file());
}

void print_written(const nlohmann::json& summary) {
  const auto& files = summary["files"];
  std::cout << "frames     " << summary["frames"] << "\nvertices   " << summary["vertices"] << "\ntriangles  "
            << summary["triangles"] << "\nfiles      " << files.size();
  if (!files.empty()) std::cout << ": " << files.front().get<std::string>();
  if (files.size() > 1) std::cout << " ... " << files.back().get<std::string>();
  std::cout << '\n';
}

std::vector<std::size_t> evenly_spaced_frames(std::size_t frames, std::size_t count) {
  count = std::min(count, frames);
  std::vector<std::size_t> chosen;
  for (std::size_t k = 0; k < count; ++k)
    chosen.push_back(count == 1 ? 0 : std::size_t(std::llround(double(k) * double(frames - 1) / double(count - 1))));
  return chosen;
}

CLI::Validator output_file() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        if (path == "-") return {};
        const std::filesystem::path folder = std::filesystem::path(path).parent_path();
        std::error_code error;
        if (!folder.empty() && !std::filesystem::is_directory(folder, error))
          return "cannot write " + path + ": the folder " + folder.string() + " does not exist";
        if (std::filesystem::is_directory(path, error)) return "cannot write " + path + ": it is a folder";
        return {};
      },
      "FILE");
}

CLI::Validator output_folder() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code error;
        // The nearest part of the path that exists must be a folder: the rest is created.
        for (std::filesystem::path part = path; !part.empty(); part = part.parent_path()) {
          if (!std::filesystem::exists(part, error)) {
            if (part == part.parent_path()) break;
            continue;
          }
          if (std::filesystem::is_directory(part, error)) return {};
          return part == std::filesystem::path(path) ? "cannot write into " + path + ": it is a file, not a folder"
                                                     : "cannot create the folder " + path + ": " + part.string() +
                                                           " is a file, not a folder";
        }
        return {};
      },
      "DIR");
}

void progress(const std::string& line) { std::cerr << "deformseg: " << line << '\n'; }

std::string value_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

std::string percent_text(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", 100 * share);
  return text;
}

std::string figure_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string point_text(const nlohmann::json& point) {
  std::string text = "[";
  for (const nlohmann::json& coordinate : point)
    text += (text.size() > 1 ? ", " : "") + figure_text(coordinate.get<double>());
  return text + "]";
}

std::string seconds_text(double seconds) { return value_text(seconds); }

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

namespace {

// The K of a matrix of K animations, from its K (K + 1) / 2 comparisons (each pair and each
// animation with itself). Complexity O(sqrt(comparisons)).
std::size_t animations_compared(std::size_t comparisons) {
  std::size_t k = 0;
  while ((k + 1) * (k + 2) / 2 <= comparisons) ++k;
  return k;
}

std::string elapsed_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

}  // namespace

bool Matrix_progress::operator()(std::size_t done, std::size_t total) {
  const double seconds = seconds_since(start);
  if (done < descriptions) {  // reading and describing; the frontend reports about every 5 %
    progress("reading and describing: " + std::to_string(done) + " of " + std::to_string(descriptions) +
             " animations, " + elapsed_text(seconds));
    return true;
  }
  if (describe_seconds == 0 && descriptions > 0) describe_seconds = seconds;
  // The last description's report still has the first total; the comparisons' reports have the
  // total of the animations kept, so the line waits for the first of them.
  const std::size_t comparisons = total - descriptions, compared = done - descriptions;
  if (descriptions > 0 && !described_reported && (compared > 0 || comparisons == 0)) {
    described_reported = true;
    const std::size_t kept = animations_compared(comparisons), left_out = descriptions - kept;
    progress("described " + (left_out ? std::to_string(kept) + " of " : "") + std::to_string(descriptions) +
             " animations in " + elapsed_text(describe_seconds) +
             (left_out ? " (" + std::to_string(left_out) + " left out)" : ""));
  }
  if (compared > 0 && (compared >= next_report || compared == comparisons)) {
    progress("matrix: " + std::to_string(compared) + " of " + std::to_string(comparisons) + " comparisons, " +
             elapsed_text(seconds));
    next_report = compared + std::max<std::size_t>(1, comparisons / 20);
  }
  return true;
}

}  // namespace deformseg::tool
