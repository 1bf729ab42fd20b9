// The pieces every sub-command of the deformseg tool shares: reading the input, writing JSON,
// reporting progress.
#pragma once

#include <deformseg/color.h>
#include <deformseg/default_mesh.h>
#include <deformseg/io/read_animation.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace deformseg::tool {

/// The input of a sub-command that reads an animation, and how to read it.
struct Input_options {
  std::string input;
  std::string topology;
  bool triangulate = false;
  int threads = 0;
};

/// Adds INPUT, --topology, --triangulate and --threads to a sub-command.
void add_input_options(CLI::App& command, Input_options& options);

/// Reads the animation the options name, saying on standard error what it reads.
Surface_mesh_animation read_input(const Input_options& options);

/// Writes `document` to `path` ("-": standard output), indented.
void write_json(const nlohmann::json& document, const std::string& path);

/// A line on standard error, for progress.
void progress(const std::string& line);

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
void add_synth_command(CLI::App& app);
void add_strain_command(CLI::App& app);
void add_temporal_command(CLI::App& app);
void add_spatiotemporal_command(CLI::App& app);
void add_ged_command(CLI::App& app);
void add_ged_matrix_command(CLI::App& app);
void add_similarity_command(CLI::App& app);
void add_matrix_command(CLI::App& app);
void add_evaluate_command(CLI::App& app);

}  // namespace deformseg::tool
