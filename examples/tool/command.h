// The pieces every sub-command of the deformseg tool shares: reading the input, writing JSON,
// reporting progress.
#pragma once

#include <deformseg/color.h>
#include <deformseg/default_mesh.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/read_animation.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
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
  std::string clip;         // glTF: a clip's name or index; empty: the first
  double fps = 30;          // glTF: frames per second of the sampling
  bool weld = false;        // --weld: weld a frame sequence's or a point cache's vertices
  bool no_weld = false;     // --no-weld: keep a glTF file's vertices as they are
  bool refuse_defects = false;  // --refuse-defects: fail on degenerate or non-manifold triangles
};

/// What reading the input found besides the animation.
struct Input_report {
  io::Repair_report repair;
  std::optional<io::Gltf_read_report> gltf;  // for a glTF input
};

/// Adds INPUT, --topology, --triangulate, --threads, --clip, --fps, --weld, --no-weld and
/// --refuse-defects to a sub-command.
void add_input_options(CLI::App& command, Input_options& options);

/// Reads the animation the options name, saying on standard error what it reads and, when the
/// repair changed the mesh, what it changed; what it found goes to `report` when not null.
Surface_mesh_animation read_input(const Input_options& options, Input_report* report = nullptr);

/// The repair report as JSON: every count, by name.
nlohmann::json to_json(const io::Repair_report& report);

/// The repair report in words, "welded 1438 vertices, dropped 3 degenerate triangles", or
/// "nothing" when it changed nothing.
std::string describe(const io::Repair_report& report);

/// Writes `document` to `path` ("-": standard output), indented.
void write_json(const nlohmann::json& document, const std::string& path);

/// A line on standard error, for progress.
void progress(const std::string& line);

/// The check of a FILE option (`--json`, `--png`, `--csv`, ...), run as the command line is parsed,
/// before any input is read: the file's folder exists. "-" (standard output) passes.
CLI::Validator output_file();

/// An RGB image, row after row from the top, 3 bytes a pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
  Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 3, 255) {}
  void set(int x, int y, Rgb color) {
    const std::size_t at = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    pixels[at] = color.r, pixels[at + 1] = color.g, pixels[at + 2] = color.b;
  }
};

/// Writes `image` as a PNG file.
void write_png(const Image& image, const std::string& path);

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

}  // namespace deformseg::tool
