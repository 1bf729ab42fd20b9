// The pieces every sub-command of the deformseg tool shares: reading the input, writing JSON,
// reporting progress.
#pragma once

#include <deformseg/default_mesh.h>
#include <deformseg/io/read_animation.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

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

void add_info_command(CLI::App& app);
void add_synth_command(CLI::App& app);
void add_strain_command(CLI::App& app);

}  // namespace deformseg::tool
