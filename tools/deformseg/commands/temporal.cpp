// deformseg temporal INPUT: intervals of similar poses, from the normalised rest-pose strain.
#include "command.h"

#include <deformseg/io/internal/file_io.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

struct Temporal_command_options {
  Input_options input;
  std::size_t rest_frame = 0;
  std::string reference_mesh;
  std::string method = "optimal";
  std::string metric = "euclidean";
  std::optional<double> threshold;
  bool absolute = false;
  std::optional<std::size_t> segments;
  std::size_t min_length = 1;
  std::string json;
  std::string png;
  std::string matrix;
};

// The threshold (or penalty) the options give, or the policy's default.
temporal::Segmentation_threshold threshold_of(const Temporal_command_options& o,
                                              temporal::Segmentation_threshold fallback) {
  if (!o.threshold) return fallback;
  return {.value = *o.threshold, .relative = !o.absolute};
}

// The segmentation with the policy the options name; also what threshold it used.
temporal::Temporal_segmentation segment(const Temporal_command_options& o, const temporal::Segment_cost& cost,
                              temporal::Segmentation_threshold& used) {
  if (o.method == "binary-split") {
    const temporal::Binary_split policy{.threshold = threshold_of(o, temporal::Binary_split{}.threshold),
                                        .min_length = o.min_length};
    used = policy.threshold;
    return temporal::segment_frames(cost, policy);
  }
  if (o.method == "greedy") {
    const temporal::Thesis_greedy policy{.threshold = threshold_of(o, temporal::Thesis_greedy{}.threshold)};
    used = policy.threshold;
    return temporal::segment_frames(cost, policy);
  }
  if (o.method == "barbic") return temporal::segment_frames(cost, temporal::Barbic_pca{});
  const temporal::Optimal_partition policy{.penalty = threshold_of(o, temporal::Optimal_partition{}.penalty),
                                           .segments = o.segments,
                                           .min_length = o.min_length};
  used = policy.penalty;
  return temporal::segment_frames(cost, policy);
}

void write_matrix(const Eigen::MatrixXf& d, const std::string& path) {
  progress("writing the frame distance matrix to " + path);
  deformseg::io::internal::Streamed_file file(path);
  std::string line;
  for (Eigen::Index i = 0; i < d.rows(); ++i) {
    line.clear();
    for (Eigen::Index j = 0; j < d.cols(); ++j) {
      if (j > 0) line += ',';
      deformseg::io::internal::append_shortest(line, d(i, j));
    }
    line += '\n';
    file.write(line);
  }
  file.close();
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

nlohmann::json document(const Temporal_command_options& o, const temporal::Temporal_segmentation& s,
                        const temporal::Segmentation_threshold& threshold) {
  nlohmann::json segments = nlohmann::json::array();
  for (const auto& segment : s.segments)
    segments.push_back({{"first", segment.first}, {"last", segment.last}, {"cost", segment.cost}});
  nlohmann::json result = {{"input", o.input.input}, {"frames", s.frames}, {"method", o.method},
                           {"metric", o.metric}, {"threshold", nullptr}, {"segments", segments}};
  if (o.method != "barbic" && !o.segments)
    result["threshold"] = {{"value", threshold.value}, {"relative", threshold.relative}};
  return result;
}

void run(const Temporal_command_options& o) {
  if (o.segments && o.method != "optimal") throw invalid_input("--segments asks for --method optimal");
  if (!o.reference_mesh.empty() && o.rest_frame != 0)
    throw invalid_input("--reference-mesh takes the place of the rest frame: it excludes --rest-frame");
  const mesh::Surface_mesh_animation animation = read_input(o.input);
  const std::optional<mesh::Surface_mesh> reference_mesh =
      o.reference_mesh.empty() ? std::nullopt : std::optional(read_reference_mesh(o.reference_mesh));
  progress("computing the strain and the frame distances of " + std::to_string(animation.num_frames()) + " frames");
  const auto field = reference_mesh ? naming_reference_mesh(o.reference_mesh, [&] {
    return strain::compute_strain(animation, *reference_mesh, {.threads = o.input.threads});
  }) : strain::compute_strain(animation, {.rest_frame = o.rest_frame, .threads = o.input.threads});
  const strain::Frame_metric metric = o.metric == "l1" ? strain::Frame_metric::l1
                              : o.metric == "cosine" ? strain::Frame_metric::cosine
                                                     : strain::Frame_metric::euclidean;
  const Eigen::MatrixXf distances = frame_distances(field, {.metric = metric, .threads = o.input.threads});
  temporal::Segmentation_threshold used;
  const temporal::Temporal_segmentation result = segment(o, temporal::Segment_cost(distances), used);
  if (!o.matrix.empty()) write_matrix(distances, o.matrix);
  if (!o.png.empty()) write_figure(distances, result, o.input.input, o.png);
  const nlohmann::json json = document(o, result, used);
  write_outputs(json, o.json, [&] {
    std::cout << result.frames << " frames, " << result.segments.size() << " segments (first last cost):\n";
    for (const auto& segment : result.segments)
      std::cout << segment.first << ' ' << segment.last << ' ' << segment.cost << '\n';
  });
}

}  // namespace

void add_temporal_command(CLI::App& app) {
  auto options = std::make_shared<Temporal_command_options>();
  CLI::App* command =
      app.add_subcommand("temporal", "Temporal segmentation: frame intervals of similar poses, from the "
                                     "normalised rest-pose strain");
  add_input_options(*command, options->input);
  command->add_option("--rest-frame", options->rest_frame, "The rest pose of the strain. Default: 0");
  add_reference_mesh_option(*command, options->reference_mesh);
  command->add_option("--method", options->method,
                      "optimal: least length-weighted cost, with a penalty per segment or --segments "
                      "(default); binary-split; greedy: the thesis' Algorithm 4-1; barbic: PCA change "
                      "detection (Barbic et al. 2004)")
      ->check(CLI::IsMember({"optimal", "binary-split", "greedy", "barbic"}));
  command->add_option("--metric", options->metric, "Frame distance: euclidean (default), l1, cosine")
      ->check(CLI::IsMember({"euclidean", "l1", "cosine"}));
  command->add_option("--threshold", options->threshold,
                      "binary-split and greedy: the largest within-segment dissimilarity (default 0.5 and "
                      "0.2); optimal: the penalty per segment (default 0.03); relative to the mean frame "
                      "distance (optimal: to the one-segment cost) unless --absolute")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--absolute", options->absolute, "--threshold is absolute, in frame distance units");
  command->add_option("--segments", options->segments, "Exactly K segments (--method optimal)")
      ->check(CLI::PositiveNumber);
  command->add_option("--min-length", options->min_length, "Fewest frames of a segment (optimal, binary-split)")
      ->check(CLI::PositiveNumber);
  add_json_option(*command, options->json, "the segments");
  command->add_option("--png", options->png, "Draw the frame distance matrix and the segments into FILE.png")
      ->check(output_file());
  command->add_option("--matrix", options->matrix, "Write the frame distance matrix as CSV to FILE")
      ->check(output_file());
  command->callback([options] { run(*options); });
}

}  // namespace deformseg::tool
