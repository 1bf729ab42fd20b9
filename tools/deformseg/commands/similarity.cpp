// deformseg similarity A B and deformseg matrix INPUT...: how alike two animations move, with
// their frame-to-frame alignment, and the similarity matrix of a set of animations.
#include "command.h"
#include "policy_options.h"

#include <frontend/similarity.h>
#include <frontend/store_search.h>

#include <deformseg/color/strain_colors.h>
#include <deformseg/similarity/motion_similarity.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

// ---- deformseg similarity A B ----------------------------------------------------------------

struct Similarity_command_options {
  std::vector<std::string> inputs;  // A and B
  Input_options read;
  Policy_options policy;
  frontend::Comparison_request significance;
  std::string json;
  std::string png;
};

// The frame grid of A (rows) and B (columns), about 400 pixels on its longer side, grey lines at
// the frame ticks, the aligned pairs in red, the value in the title.
void write_alignment_figure(const similarity::Similarity& s, const Similarity_command_options& o, std::size_t frames_a,
                            std::size_t frames_b, const std::string& path) {
  progress("writing the alignment path to " + path);
  const int cell = cell_size(frames_a, frames_b, 400, 1, 40);
  Axis rows = frame_axis("frame of A: " + short_name(o.inputs[0]), frames_a, cell);
  Axis columns = frame_axis("frame of B: " + short_name(o.inputs[1]), frames_b, cell);
  for (Axis* axis : {&rows, &columns})
    for (std::size_t k = 1; k < axis->labels.size(); ++k)
      axis->separators.push_back(std::size_t(axis->labels[k].first));
  Matrix_figure figure(
      frames_a, frames_b, cell,
      "similarity " + value_text(s.value) + " (" + o.policy.policy + ", " + frontend::alignment_name(o.policy) + ")",
      rows, columns, std::nullopt);
  for (std::size_t i = 0; i < frames_a; ++i)
    for (std::size_t j = 0; j < frames_b; ++j) figure.fill_cell(i, j, {245, 245, 245});
  figure.draw_separators(rows, columns, {205, 205, 205});
  for (const auto& [i, j] : s.alignment) figure.fill_cell(i, j, {220, 30, 30});
  figure.write(path);
}

void report_similarity(const Similarity_command_options& o, const frontend::Compared& compared,
                       const nlohmann::json& sources, std::size_t frames_a, std::size_t frames_b) {
  if (compared.z_score)
    progress("z-score against " + std::to_string(compared.shuffled_copies) + " frame-shuffled copies of B");
  const similarity::Similarity& s = compared.similarity;
  if (!o.png.empty()) write_alignment_figure(s, o, frames_a, frames_b, o.png);
  nlohmann::json document = {{"a", o.inputs[0]}, {"b", o.inputs[1]}, {"sources", sources}};
  document.update(frontend::similarity_record(compared, o.policy));
  write_outputs(document, o.json, [&] {
    std::cout << "similarity  " << value_text(s.value) << "\nscore       " << s.score << "\naligned     " << s.alignment.size()
              << " frame pairs\ncompared    " << s.compared << '\n';
    if (compared.z_score)
      std::cout << "z-score     " << *compared.z_score << " (against " << compared.shuffled_copies
                << " frame-shuffled copies of B)\n";
    if (compared.explanation) {
      std::cout << "where the signatures differ, along the " << compared.explanation->pairs << " aligned rows:\n";
      for (const std::string& line : frontend::explanation_lines(*compared.explanation, o.policy.bands.value_or(1), 6))
        std::cout << "  " << line << '\n';
    }
  });
}

// Character files' clips, point caches and frame sequences are described frame by frame where the
// policy allows it (a long take then needs memory for its signatures, not its frames); the others
// are read whole.
void run_similarity(const Similarity_command_options& o) {
  frontend::check(o.policy, frontend::Front::command_line);
  frontend::check(o.significance, o.policy, frontend::Front::command_line);
  frontend::check(o.read, frontend::Front::command_line);
  frontend::check_clip_applies(o.inputs, o.read, frontend::Front::command_line);
  std::array<frontend::Streamed_input, 2> streamed{};
  if (const auto compared = frontend::compare_streamed({o.inputs[0], o.inputs[1]}, o.read, o.policy, o.significance,
                                                        frontend::Front::command_line, streamed)) {
    nlohmann::json records = nlohmann::json::array();
    for (std::size_t k = 0; k < 2; ++k) {
      const frontend::Streamed_input& input = streamed[k];
      if (input.clip)
        progress(o.inputs[k] + ": clip \"" + *input.clip + "\", " + std::to_string(input.frames) + " frames at " +
                 nlohmann::json(o.read.fps).dump() + " fps");
      if (input.repair.changed()) progress(o.inputs[k] + ": repaired: " + frontend::describe(input.repair));
      if (const std::string warning = input.outliers.warning(frontend::Front::command_line); !warning.empty())
        progress("warning: " + o.inputs[k] + ": " + warning);
      records.push_back(frontend::input_record(
          frontend::input_name(o.inputs[k], o.read, frontend::Front::command_line).file, o.read.fps));
      if (input.clip) records.back()["clip"] = *input.clip;
    }
    progress("compared " + std::to_string(streamed[0].frames) + " and " + std::to_string(streamed[1].frames) +
             " frames, each described frame by frame");
    return report_similarity(o, *compared, records, streamed[0].frames, streamed[1].frames);
  }
  const std::vector<frontend::Read_input> inputs = read_inputs(o.inputs, o.read);
  const mesh::Surface_mesh_animation &a = inputs[0].animation, &b = inputs[1].animation;
  progress("comparing " + std::to_string(a.num_frames()) + " and " + std::to_string(b.num_frames()) + " frames");
  report_similarity(o, frontend::compare(a, b, o.policy, o.significance, o.read.threads), sources(inputs, o.read),
                    a.num_frames(), b.num_frames());
}

// ---- deformseg matrix INPUT... ---------------------------------------------------------------

struct Matrix_command_options {
  std::vector<std::string> inputs;
  std::string store;
  Input_options read;
  Policy_options policy;
  std::string csv;
  std::string json;
  std::string png;
};

// Cells coloured by viridis from the smallest value (dark) to 1 (yellow), the animations' names
// along the top and the left.
void write_heat_map(const Eigen::MatrixXd& m, const Matrix_command_options& o, const std::vector<std::string>& inputs,
                    const std::string& path) {
  progress("writing the heat map to " + path);
  const auto n = std::size_t(m.rows());
  const int cell = cell_size(n, n, 480, 4, 40);
  const double low = std::min(m.minCoeff(), 1.0 - 1e-12);
  std::vector<std::string> names;
  for (const std::string& input : inputs) names.push_back(short_name(input));
  Matrix_figure figure(n, n, cell, "similarity (" + o.policy.policy + ", " + frontend::alignment_name(o.policy) + ")",
                       named_axis("", names), named_axis("", names),
                       Color_bar{"similarity", low, 1.0, [](double f) { return color::strain_color(f); }});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      figure.fill_cell(i, j, color::strain_color((m(Eigen::Index(i), Eigen::Index(j)) - low) / (1.0 - low)));
  figure.write(path);
}

// The matrix of the inputs read and described now, or of the store's clips as described.
Eigen::MatrixXd matrix_of(const Matrix_command_options& o, std::vector<std::string>& names, nlohmann::json& records) {
  if (o.store.empty()) {
    std::vector<mesh::Surface_mesh_animation> animations;
    for (frontend::Read_input& input : read_inputs(o.inputs, o.read)) {
      records.push_back(frontend::input_record(input, o.read.fps));
      animations.push_back(std::move(input.animation));
    }
    names = o.inputs;
    progress("comparing " + std::to_string(animations.size()) + " animations pair by pair");
    Matrix_progress report{.descriptions = animations.size()};
    return frontend::similarity_matrix(animations, o.policy, std::ref(report), o.read.threads);
  }
  const frontend::Store_search library(o.store);
  library.check_policy(o.policy, frontend::Front::command_line);
  for (std::size_t i = 0; i < library.size(); ++i) {
    const store::Store_record record = library.store().record(i);
    names.push_back(library.name(i));
    const nlohmann::json clip = record.clip.empty() ? nlohmann::json() : nlohmann::json(record.clip);
    records.push_back({{"file", record.path}, {"clip", clip}, {"body", record.body}, {"fps", record.fps}});
  }
  progress("comparing the " + std::to_string(library.size()) + " clips of " + o.store + " pair by pair");
  Matrix_progress report{.descriptions = 0};
  return library.matrix(std::ref(report), o.read.threads);
}

void run_matrix(const Matrix_command_options& o) {
  frontend::check(o.policy, frontend::Front::command_line);
  if (o.store.empty() && o.inputs.size() < 2)
    throw invalid_input("matrix needs two or more animations, or --store S");
  if (!o.store.empty() && !o.inputs.empty())
    throw invalid_input("matrix takes animations or --store S, not both");
  std::vector<std::string> names;
  nlohmann::json records = nlohmann::json::array();
  const Eigen::MatrixXd m = matrix_of(o, names, records);
  if (!o.csv.empty()) {
    if (o.csv != "-") progress("writing the matrix to " + o.csv);
    frontend::write_matrix_csv(m, o.csv, names);
  }
  if (!o.png.empty()) write_heat_map(m, o, names, o.png);
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    rows.push_back(nlohmann::json::array());
    for (Eigen::Index j = 0; j < m.cols(); ++j) rows.back().push_back(m(i, j));
  }
  const nlohmann::json document = {{"inputs", names}, {"sources", records}, {"policy", o.policy.policy},
                                   {"alignment_policy", frontend::alignment_name(o.policy)}, {"similarity", rows}};
  write_outputs(document, o.json, [&] {
    for (std::size_t i = 0; i < names.size(); ++i) {
      std::cout << i << "  " << names[i] << "\n  ";
      for (Eigen::Index j = 0; j < m.cols(); ++j) std::cout << ' ' << m(Eigen::Index(i), j);
      std::cout << '\n';
    }
  }, o.csv == "-");
}

}  // namespace

void add_similarity_command(CLI::App& app) {
  auto o = std::make_shared<Similarity_command_options>();
  CLI::App* command = app.add_subcommand("similarity", "How alike two animations move: a value in [0, 1], the "
                                                       "score and the frame-to-frame alignment");
  add_inputs(*command, "inputs", o->inputs, 2, 2, o->read, "The two animations, A and B");
  add_policy_options(*command, o->policy);
  add_parameters(*command, frontend::comparison_parameters, o->significance);
  add_json_option(*command, o->json, "the result");
  command->add_option("--png", o->png, "Draw the alignment path over the frame grid (A down, B across) into FILE.png")
      ->check(output_file());
  command->callback([o] { run_similarity(*o); });
}

void add_matrix_command(CLI::App& app) {
  auto o = std::make_shared<Matrix_command_options>();
  CLI::App* command = app.add_subcommand("matrix", "The similarity of every pair of a set of animations");
  add_inputs(*command, "inputs", o->inputs, 2, -1, o->read, "Two or more animations (or none, with --store)");
  command->get_option("inputs")->required(false);
  add_policy_options(*command, o->policy);
  command->add_option("--store", o->store,
                      "The clips of a motion store (deformseg describe), as described, in place of animations");
  command->add_option("--csv", o->csv,
                      "Write the matrix as CSV, with the inputs as row and column names, to FILE ('-': standard "
                      "output, in place of the summary)")
      ->check(output_file());
  add_json_option(*command, o->json, "the matrix");
  command->add_option("--png", o->png,
                      "Draw a heat map (viridis, from the smallest value to 1), the inputs named, into FILE.png")
      ->check(output_file());
  command->callback([o] { run_matrix(*o); });
}

}  // namespace deformseg::tool
