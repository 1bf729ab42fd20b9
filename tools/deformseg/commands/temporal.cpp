// deformseg temporal INPUT: intervals of similar poses, from the normalised rest-pose strain.
#include "command.h"

#include <frontend/temporal.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

struct Temporal_command_options {
  std::string input;
  Input_options read;
  frontend::Temporal_request temporal;
  std::string json;
  std::string png;
  std::string matrix;
};

void write_matrix(const Eigen::MatrixXf& d, const std::string& path) {
  progress("writing the frame distance matrix to " + path);
  frontend::write_matrix_csv(d, path);
}

// The matrix in grey (black: distance 0, white: the largest), about 400 pixels wide, with each
// segment's diagonal block outlined in red, as the thesis draws them; frames along both axes.
void write_figure(const Eigen::MatrixXf& d, const temporal::Temporal_segmentation& s, const std::string& input,
                  const std::string& path) {
  progress("writing the figure to " + path);
  const auto frames = std::size_t(d.rows());
  const int cell = cell_size(frames, frames, 400, 1, 40);
  const double largest = std::max(double(d.maxCoeff()), double(std::numeric_limits<float>::min()));
  const auto grey = [](double fraction) {
    const auto level = std::uint8_t(std::lround(255 * std::clamp(fraction, 0.0, 1.0)));
    return color::Rgb{level, level, level};
  };
  Matrix_figure figure(frames, frames, cell, std::to_string(s.segments.size()) + " segments of " + short_name(input),
                       frame_axis("frame", frames, cell), frame_axis("frame", frames, cell),
                       Color_bar{"frame distance", 0, largest, grey});
  for (std::size_t i = 0; i < frames; ++i)
    for (std::size_t j = 0; j < frames; ++j)
      figure.fill_cell(i, j, grey(d(Eigen::Index(i), Eigen::Index(j)) / largest));
  for (const auto& segment : s.segments)
    figure.outline_diagonal_block(segment.first, segment.last, {230, 30, 30}, std::max(1, cell / 3));
  figure.write(path);
}

void run(const Temporal_command_options& o) {
  frontend::check(o.temporal, frontend::Front::command_line);
  const frontend::Read_input input = read_input(o.input, o.read);
  progress("computing the strain and the frame distances of " + std::to_string(input.animation.num_frames()) +
           " frames");
  const Eigen::MatrixXf distances =
      frontend::frame_distances(input.animation, frontend::distance_request(o.temporal), o.read.threads);
  const frontend::Temporal_result result = frontend::segment(distances, o.temporal);
  if (!o.matrix.empty()) write_matrix(distances, o.matrix);
  if (!o.png.empty()) write_figure(distances, result.segmentation, o.input, o.png);
  nlohmann::json document = frontend::temporal_record(result, o.temporal);
  document["input"] = o.input;
  document["sources"] = sources({&input, 1}, o.read);
  write_outputs(document, o.json, [&] {
    const temporal::Temporal_segmentation& s = result.segmentation;
    std::cout << s.frames << " frames, " << s.segments.size() << " segments (first last cost):\n";
    for (const auto& segment : s.segments)
      std::cout << segment.first << ' ' << segment.last << ' ' << segment.cost << '\n';
  });
}

}  // namespace

void add_temporal_command(CLI::App& app) {
  auto options = std::make_shared<Temporal_command_options>();
  CLI::App* command =
      app.add_subcommand("temporal", "Temporal segmentation: frame intervals of similar poses, from the "
                                     "normalised rest-pose strain");
  add_input(*command, options->input, options->read);
  add_parameters(*command, frontend::temporal_parameters, options->temporal);
  add_json_option(*command, options->json, "the segments");
  command->add_option("--png", options->png, "Draw the frame distance matrix and the segments into FILE.png")
      ->check(output_file());
  command->add_option("--matrix", options->matrix, "Write the frame distance matrix as CSV to FILE")
      ->check(output_file());
  command->callback([options] { run(*options); });
}

}  // namespace deformseg::tool
