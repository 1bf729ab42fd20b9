// deformseg similarity A B and deformseg matrix INPUT...: how alike two animations move, with
// their frame-to-frame alignment, and the similarity matrix of a set of animations.
#include "command.h"
#include "policy_options.h"

#include <deformseg/io/internal/file_io.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/color/strain_colors.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <random>

namespace deformseg::tool {
namespace {

// ---- deformseg similarity A B ----------------------------------------------------------------

struct Similarity_command_options {
  Input_options a, b;
  Policy_options policy;
  std::optional<std::size_t> copies;  // none given: 20, or none for the graph policy
  unsigned seed = 1;
  std::string json;
  std::string png;
};

// The similarity of A and B and, for a policy whose frames can be shuffled, the z-score of its
// value against `copies` frame-shuffled copies of B.
struct Similarity_with_significance {
  similarity::Similarity similarity;
  std::optional<double> z_score;
};

template <class Policy>
Similarity_with_significance compare_with_significance(const Policy& policy, const mesh::Surface_mesh_animation& a,
                                                       const mesh::Surface_mesh_animation& b, std::size_t copies,
                                                       unsigned seed) {
  const auto da = policy.describe(a), db = policy.describe(b);
  Similarity_with_significance out{policy.compare(da, db), std::nullopt};
  if constexpr (similarity::ReorderableDescription<std::remove_cvref_t<decltype(db)>>) {
    if (copies >= 2) {
      progress("z-score against " + std::to_string(copies) + " frame-shuffled copies of B");
      std::mt19937 random(seed);
      out.z_score = similarity::similarity_significance(policy, da, db, copies, random);
    }
  }
  return out;
}

// A similarity compares motions: an input of one frame is refused, with the usual cause.
void require_motion(const mesh::Surface_mesh_animation& animation, const std::string& input) {
  if (animation.num_frames() < 2)
    throw invalid_input("an animation of " + std::to_string(animation.num_frames()) +
                            " frame: a motion needs at least 2 (an unquoted glob gives one input per file: quote it)",
                        {.file = input});
}

// The frame grid of A (rows) and B (columns), about 400 pixels on its longer side, grey lines at
// the frame ticks, the aligned pairs in red, the value in the title.
void write_alignment_figure(const similarity::Similarity& s, const Similarity_command_options& o, std::size_t frames_a,
                            std::size_t frames_b, const std::string& path) {
  progress("writing the alignment path to " + path);
  const int cell = cell_size(frames_a, frames_b, 400, 1, 40);
  Axis rows = frame_axis("frame of A: " + short_name(o.a.input), frames_a, cell);
  Axis columns = frame_axis("frame of B: " + short_name(o.b.input), frames_b, cell);
  for (Axis* axis : {&rows, &columns})
    for (std::size_t k = 1; k < axis->labels.size(); ++k)
      axis->separators.push_back(std::size_t(axis->labels[k].first));
  char value[32];
  std::snprintf(value, sizeof value, "%.3f", s.value);
  Matrix_figure figure(
      frames_a, frames_b, cell,
      "similarity " + std::string(value) + " (" + o.policy.policy + ", " + similarity::alignment_name(o.policy) + ")",
      rows, columns, std::nullopt);
  for (std::size_t i = 0; i < frames_a; ++i)
    for (std::size_t j = 0; j < frames_b; ++j) figure.fill_cell(i, j, {245, 245, 245});
  figure.draw_separators(rows, columns, {205, 205, 205});
  for (const auto& [i, j] : s.alignment) figure.fill_cell(i, j, {220, 30, 30});
  figure.write(path);
}

void run_similarity(const Similarity_command_options& o) {
  similarity::check_policy_choice(o.policy);
  if (o.copies == 1) throw invalid_input("--significance needs 0 (none) or at least 2 shuffled copies");
  if (o.copies.value_or(0) >= 2 && o.policy.policy == "graph")
    throw invalid_input("--significance does not apply to the graph policy, whose frames are key-frame labels");
  const std::size_t copies = o.copies.value_or(o.policy.policy == "graph" ? 0 : 20);
  Input_options options_b = o.b;
  options_b.threads = o.a.threads, options_b.fps = o.a.fps;  // given once for both
  const mesh::Surface_mesh_animation a = read_input(o.a), b = read_input(options_b);
  require_motion(a, o.a.input);
  require_motion(b, o.b.input);
  progress("comparing " + std::to_string(a.num_frames()) + " and " + std::to_string(b.num_frames()) + " frames");
  const Similarity_with_significance compared = similarity::with_policy_choice(
      o.policy, [&](const auto& policy) { return compare_with_significance(policy, a, b, copies, o.seed); });
  const similarity::Similarity& s = compared.similarity;
  if (!o.png.empty()) write_alignment_figure(s, o, a.num_frames(), b.num_frames(), o.png);
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& [i, j] : s.alignment) pairs.push_back({i, j});
  const nlohmann::json document = {{"a", o.a.input}, {"b", o.b.input}, {"policy", o.policy.policy},
                                   {"alignment_policy", similarity::alignment_name(o.policy)}, {"similarity", s.value},
                                   {"score", s.score}, {"labels_a", s.labels_a}, {"labels_b", s.labels_b},
                                   {"alignment", pairs}, {"compared", s.compared},
                                   {"z_score", compared.z_score ? nlohmann::json(*compared.z_score) : nlohmann::json()},
                                   {"shuffled_copies", compared.z_score ? copies : 0}};
  write_outputs(document, o.json, [&] {
    std::cout << "similarity  " << s.value << "\nscore       " << s.score << "\naligned     " << s.alignment.size()
              << " frame pairs\ncompared    " << s.compared << '\n';
    if (compared.z_score)
      std::cout << "z-score     " << *compared.z_score << " (against " << copies << " frame-shuffled copies of B)\n";
  });
}

// ---- deformseg matrix INPUT... ---------------------------------------------------------------

struct Matrix_command_options {
  std::vector<std::string> inputs;
  std::string topology;
  int threads = 0;
  double fps = 30;
  Policy_options policy;
  std::string csv;
  std::string json;
  std::string png;
};

// Cells coloured by viridis from the smallest value (dark) to 1 (yellow), the animations' names
// along the top and the left.
void write_heat_map(const Eigen::MatrixXd& m, const Matrix_command_options& o, const std::string& path) {
  progress("writing the heat map to " + path);
  const auto n = std::size_t(m.rows());
  const int cell = cell_size(n, n, 480, 4, 40);
  const double low = std::min(m.minCoeff(), 1.0 - 1e-12);
  std::vector<std::string> names;
  for (const std::string& input : o.inputs) names.push_back(short_name(input));
  Matrix_figure figure(n, n, cell, "similarity (" + o.policy.policy + ", " + similarity::alignment_name(o.policy) + ")",
                       named_axis("", names), named_axis("", names),
                       Color_bar{"similarity", low, 1.0, [](double f) { return color::strain_color(f); }});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      figure.fill_cell(i, j, color::strain_color((m(Eigen::Index(i), Eigen::Index(j)) - low) / (1.0 - low)));
  figure.write(path);
}

void write_csv(const Eigen::MatrixXd& m, const std::vector<std::string>& names, const std::string& path) {
  progress("writing the matrix to " + path);
  std::string text = "animation";
  for (const auto& name : names) text += "," + name;
  text += '\n';
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    text += names[std::size_t(i)];
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      text += ',';
      deformseg::io::internal::append_shortest(text, m(i, j));
    }
    text += '\n';
  }
  deformseg::io::internal::write_file_bytes(path, text);
}

void run_matrix(const Matrix_command_options& o) {
  similarity::check_policy_choice(o.policy);
  std::vector<mesh::Surface_mesh_animation> animations;
  for (const auto& input : o.inputs)
  {
    Input_options read;
    read.input = input, read.topology = o.topology, read.threads = o.threads, read.fps = o.fps;
    animations.push_back(read_input(read));
    require_motion(animations.back(), read.input);
  }
  progress("comparing " + std::to_string(animations.size()) + " animations pair by pair");
  Matrix_progress report{.descriptions = animations.size()};
  const Eigen::MatrixXd m = similarity::with_policy_choice(o.policy, [&](const auto& policy) {
    return similarity::similarity_matrix(animations, policy, std::ref(report));
  });
  if (!o.csv.empty()) write_csv(m, o.inputs, o.csv);
  if (!o.png.empty()) write_heat_map(m, o, o.png);
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    rows.push_back(nlohmann::json::array());
    for (Eigen::Index j = 0; j < m.cols(); ++j) rows.back().push_back(m(i, j));
  }
  const nlohmann::json document = {{"inputs", o.inputs}, {"policy", o.policy.policy},
                                   {"alignment_policy", similarity::alignment_name(o.policy)}, {"similarity", rows}};
  write_outputs(document, o.json, [&] {
    for (std::size_t i = 0; i < o.inputs.size(); ++i) {
      std::cout << i << "  " << o.inputs[i] << "\n  ";
      for (Eigen::Index j = 0; j < m.cols(); ++j) std::cout << ' ' << m(Eigen::Index(i), j);
      std::cout << '\n';
    }
  });
}

}  // namespace

void add_similarity_command(CLI::App& app) {
  auto o = std::make_shared<Similarity_command_options>();
  CLI::App* command = app.add_subcommand("similarity", "How alike two animations move: a value in [0, 1], the "
                                                       "score and the frame-to-frame alignment");
  command
      ->add_option("a", o->a.input,
                   "The first animation (a glTF file, FILE.glb#CLIP, a folder, a quoted glob or a point cache)")
      ->required();
  command->add_option("b", o->b.input, "The second animation")->required();
  command->add_option("--topology-a", o->a.topology, "Connectivity of A, for a point cache");
  command->add_option("--topology-b", o->b.topology, "Connectivity of B, for a point cache");
  command->add_option("--clip-a", o->a.clip, "glTF: the clip of A, by name or index (default: the first)");
  command->add_option("--clip-b", o->b.clip, "glTF: the clip of B, by name or index (default: the first)");
  command->add_option("--fps", o->a.fps,
                      "Frames per second of both inputs: glTF clips are sampled at it, frame files and point caches "
                      "play at it")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--threads", o->a.threads, "Threads for reading (0: all)")->check(thread_counts);
  add_policy_options(*command, o->policy);
  command->add_option("--significance", o->copies,
                      "The z-score of the value against this many copies of B with frames shuffled (0: none). "
                      "Default: 20, none for the graph policy");
  command->add_option("--seed", o->seed, "The seed of the shuffles")->capture_default_str();
  add_json_option(*command, o->json, "the result");
  command->add_option("--png", o->png, "Draw the alignment path over the frame grid (A down, B across) into FILE.png")
      ->check(output_file());
  command->callback([o] {
    o->b.threads = o->a.threads;
    run_similarity(*o);
  });
}

void add_matrix_command(CLI::App& app) {
  auto o = std::make_shared<Matrix_command_options>();
  CLI::App* command = app.add_subcommand("matrix", "The similarity of every pair of a set of animations");
  command
      ->add_option("inputs", o->inputs,
                   "Two or more animations (glTF clips as FILE.glb#CLIP, folders, quoted globs, point caches)")
      ->required()
      ->expected(2, -1);
  command->add_option("--topology", o->topology, "Connectivity for point caches (all inputs share it)");
  command->add_option("--fps", o->fps,
                      "Frames per second of every input: glTF clips are sampled at it, frame files and point caches "
                      "play at it")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--threads", o->threads, "Threads for reading (0: all)")->check(thread_counts);
  add_policy_options(*command, o->policy);
  command->add_option("--csv", o->csv, "Write the matrix as CSV, with the inputs as row and column names, to FILE")
      ->check(output_file());
  add_json_option(*command, o->json, "the matrix");
  command->add_option("--png", o->png,
                      "Draw a heat map (viridis, from the smallest value to 1), the inputs named, into FILE.png")
      ->check(output_file());
  command->callback([o] { run_matrix(*o); });
}

}  // namespace deformseg::tool
