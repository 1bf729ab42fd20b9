// The pieces every sub-command of the deformseg tool shares: reading the input, writing JSON,
// reporting progress.
#pragma once

#include "figures/figure.h"

#include <deformseg/color/color.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/strain/strain.h>
#include <deformseg/threads.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace deformseg::tool {

/// The input of a sub-command that reads an animation, and how to read it.
struct Input_options {
  std::string input;
  std::string topology;
  bool triangulate = false;
  int threads = 0;
  std::string clip;         // glTF: a clip's name or index; empty: the only one (several refused)
  double fps = 30;          // frames per second: glTF's sampling, frame files' and point caches' rate
  bool weld = false;        // --weld: weld a frame sequence's or a point cache's vertices
  bool no_weld = false;     // --no-weld: keep a glTF file's vertices as they are
  bool refuse_defects = false;  // --refuse-defects: fail on degenerate or non-manifold triangles
  bool first_clip_by_default = false;  // info: a glTF file of several clips, none named, gives its first
};

/// The check of every `--threads`: 0 (all) to max_threads, refused when the command line is read,
/// before any work.
inline const CLI::Range thread_counts(0, max_threads);

/// What reading the input found besides the animation.
struct Input_report {
  io::Repair_report repair;
  std::optional<io::Gltf_read_report> gltf;  // for a glTF input
};

/// Adds INPUT, --topology, --triangulate, --threads, --clip, --fps, --weld, --no-weld and
/// --refuse-defects to a sub-command.
void add_input_options(CLI::App& command, Input_options& options);

/// The options with the clip of an input "Fox.glb#Walk" moved to `clip` (Walk) and the input
/// made the file's name (Fox.glb); others as they are.
/// @throws invalid_input when a clip is given by `--clip` and after '#' both.
Input_options with_clip_of_name(Input_options options);

/// Reads the animation the options name, saying on standard error what it reads and, when the
/// repair changed the mesh, what it changed; what it found goes to `report` when not null.
mesh::Surface_mesh_animation read_input(const Input_options& options, Input_report* report = nullptr);

/// Adds `--reference-mesh FILE` to a command that measures strain against a rest pose.
void add_reference_mesh_option(CLI::App& command, std::string& path);

/// The mesh of `--reference-mesh`: a rest pose kept apart from the frames (the cat folder's
/// `cat-reference.obj`), with the connectivity of the animation as read.
mesh::Surface_mesh read_reference_mesh(const std::string& path);

/// The result of `compute()`, a strain against the reference mesh read from `path`, its
/// errors naming that file: a mismatch of connectivity is the user's file's.
template <class ComputeStrain>
auto naming_reference_mesh(const std::string& path, const ComputeStrain& compute) {
  try {
    return compute();
  } catch (const invalid_input& error) {
    throw invalid_input(std::string(error.what()) + " (the reference mesh must have the connectivity of the "
                        "animation as read: `deformseg info` gives its counts)", {.file = path});
  }
}

/// The repair report as JSON: every count, by name.
nlohmann::json to_json(const io::Repair_report& report);

/// The repair report in words, "welded 1438 vertices, dropped 3 degenerate triangles", or
/// "nothing" when it changed nothing.
std::string describe(const io::Repair_report& report);

/// Writes `document` to `path` ("-": standard output), indented.
void write_json(const nlohmann::json& document, const std::string& path);

/// The tool's one rule for what a command prints: its summary in words on standard output, and,
/// with `--json FILE`, the JSON document written to FILE as well; `--json -` puts the JSON on
/// standard output in the summary's place, as does any other output written to '-'
/// (`standard_output_taken`). Files written by --csv, --png, --out, --dot or --mesh-dir do not
/// change it.
void write_outputs(const nlohmann::json& document, const std::string& json_path,
                   const std::function<void()>& print_summary, bool standard_output_taken = false);

/// Adds `--json FILE` to a command: "Write `what` as JSON to FILE", by the rule of write_outputs.
void add_json_option(CLI::App& command, std::string& path, const std::string& what);

/// Prints what convert and synth wrote: frames, vertices, triangles and the files, first and last.
void print_written(const nlohmann::json& summary);

/// `count` frames of `frames` (all of them when there are no more), evenly spaced from the first
/// to the last, rounded to the nearest frame: what strain --png draws and view shows.
std::vector<std::size_t> evenly_spaced_frames(std::size_t frames, std::size_t count);

/// A line on standard error, for progress.
void progress(const std::string& line);

/// A similarity matrix's progress (a `Progress`) on standard error: a line when its
/// `descriptions` are all made, with their time, and one about every 5 % of the steps.
struct Matrix_progress {
  std::size_t descriptions = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double describe_seconds = 0;  // set when the descriptions are all made
  std::size_t next_report = 0;

  bool operator()(std::size_t done, std::size_t total);
};

/// The check of a FILE option (`--json`, `--png`, `--csv`, `--out`, ...), run as the command line is
/// parsed, before any input is read: the file's folder exists and the file is not a folder. "-"
/// (standard output) passes.
CLI::Validator output_file();

/// The check of a DIR option (`--mesh-dir`, `--dot`, view's `--out`, convert's and synth's OUT),
/// run as the command line is parsed, before any input is read: the folder exists, or can be
/// created (the nearest part of its path that exists is a folder, not a file).
CLI::Validator output_folder();

/// What a failed command line most likely meant, given its arguments (without the program's
/// name): "unknown command 'inof': did you mean 'info'?", the same for a sub-command's long
/// options; empty when nothing is near.
std::string typo_hint(const CLI::App& app, const std::vector<std::string>& arguments);

void add_info_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_synth_command(CLI::App& app);
void add_strain_command(CLI::App& app);
void add_temporal_command(CLI::App& app);
void add_spatiotemporal_command(CLI::App& app);
void add_ged_command(CLI::App& app);
void add_ged_matrix_command(CLI::App& app);
void add_similarity_command(CLI::App& app);
void add_matrix_command(CLI::App& app);
void add_evaluate_command(CLI::App& app);
void add_find_command(CLI::App& app);
void add_view_command(CLI::App& app);

}  // namespace deformseg::tool
