// The pieces every sub-command of the deformseg tool shares: reading the input, writing JSON,
// reporting progress.
#pragma once

#include "figures/figure.h"
#include "parameters.h"

#include <frontend/inputs.h>
#include <frontend/outputs.h>

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
#include <span>
#include <string>
#include <vector>

namespace deformseg::tool {

/// The inputs of a command that reads animations and how to read them: the front end's input
/// options, the same for every command and every input.
using Input_options = frontend::Input_options;

/// Adds a positional argument `name` taking from `fewest` to `most` animations (-1: any number)
/// into `inputs`, with the input options: --clip, --fps, --topology, --triangulate, --weld and
/// --no-weld, --refuse-defects, --threads.
void add_inputs(CLI::App& command, const std::string& name, std::vector<std::string>& inputs, int fewest, int most,
                Input_options& options, const std::string& help);

/// Adds INPUT (one animation) and the input options.
void add_input(CLI::App& command, std::string& input, Input_options& options);

/// Reads the one animation `input` of a command as `options` say, saying on standard error what it reads
/// and, when the repair changed the mesh, what it changed.
frontend::Read_input read_input(const std::string& input, const Input_options& options,
                                bool first_clip_by_default = false);

/// Reads one of a command's inputs, as `read_input`, once the caller has checked that `--clip`
/// applies to them all (`frontend::check_clip_applies`).
frontend::Read_input read_one_of(const std::string& input, const Input_options& options);

/// Reads every input, as `read_input`, `--clip` applying to those that name no clip after '#';
/// with `motions_only`, refuses those of fewer than 2 frames.
std::vector<frontend::Read_input> read_inputs(const std::vector<std::string>& inputs, const Input_options& options,
                                              bool motions_only = true);

/// What the inputs were, for a command's JSON: [{"file", "clip", "fps"}].
nlohmann::json sources(std::span<const frontend::Read_input> inputs, const Input_options& options);

/// The same for one input read frame by frame.
nlohmann::json sources(const frontend::Stream_read& input, const Input_options& options);

/// Says on standard error, as `read_input` does, which clip a streamed input plays and what the
/// repair changed (once the source is open), or, `done`, the warnings its frames gave.
void report_stream(const std::string& input, const frontend::Stream_read& read, const Input_options& options,
                   bool done);

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

/// A similarity as every summary prints it: three decimals ("0.807"); `--json` and CSV files keep
/// every digit.
std::string value_text(double value);

/// A share as a summary prints it, in percent with one decimal ("93.3" for 0.9328); `--json` keeps
/// every digit.
std::string percent_text(double share);

/// A measurement as a summary prints it, to 6 significant digits ("0.872746", "-0.101031", "1.5e-07"),
/// not the 17 a raw double shows; `--json` keeps every digit. Complexity O(1).
std::string figure_text(double value);

/// A point as a summary prints it: "[x, y, z]", each coordinate as `figure_text`.
/// @pre `point` is a JSON array of numbers. Complexity O(its size).
std::string point_text(const nlohmann::json& point);

/// Seconds as a summary prints them, to the millisecond ("1.234").
std::string seconds_text(double seconds);

/// The seconds from `start` to now, on the steady clock.
double seconds_since(std::chrono::steady_clock::time_point start);

/// A similarity matrix's progress (a `Progress`, in `frontend::similarity_matrix`'s steps: one a
/// description, then one a comparison) on standard error, each phase counted on its own:
/// "reading and describing: D of N animations", then, once the comparisons start, "described K of
/// N animations in T s (M left out)", then "matrix: P of Q comparisons" about every 5 %. The
/// frontend's total drops from N + N (N + 1) / 2 to N + K (K + 1) / 2 when some of the N are left
/// out, which is how K is known: the totals of the two phases are each fixed.
struct Matrix_progress {
  std::size_t descriptions = 0;  ///< N, the animations to read and describe (0: described already)
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double describe_seconds = 0;  ///< set when the descriptions are all made
  bool described_reported = false;  ///< whether the "described K of N" line is out
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
void add_describe_command(CLI::App& app);
void add_search_command(CLI::App& app);
void add_knn_graph_command(CLI::App& app);
void add_store_command(CLI::App& app);

/// Reads the one animation `input` of a command frame by frame when it can be read so
/// (`frontend::streams`: a character file's clip, a point cache with its topology, frame files not
/// welded), calling `f(source)` once with its frame source (`frontend::with_input_stream`), and
/// saying on standard error what `read_input` says; returns false, having read nothing, when it
/// cannot be (the command then reads it whole, with `read_input`).
/// The caller checks that `--clip` applies (`frontend::check_clip_applies`) to its inputs.
/// @throws invalid_input as `read_input`.
template <class F>
bool stream_input(const std::string& input, const Input_options& options, bool first_clip_by_default,
                  frontend::Stream_read& read, F&& f) {
  constexpr frontend::Front front = frontend::Front::command_line;
  if (!frontend::streams(input, options, front)) return false;
  progress("reading " + input);
  frontend::with_input_stream(input, options, front, first_clip_by_default, read, [&](auto& source) {
    report_stream(input, read, options, false);
    f(source);
  });
  report_stream(input, read, options, true);
  return true;
}

}  // namespace deformseg::tool
