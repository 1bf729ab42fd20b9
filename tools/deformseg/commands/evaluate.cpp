// deformseg evaluate LABELS.csv: reads every labelled clip, computes the similarity matrix and
// says how well it retrieves the same motion on other bodies (evaluate_retrieval).
#include "command.h"
#include "policy_options.h"

#include <frontend/store_search.h>

#include <deformseg/color/strain_colors.h>
#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/similarity/motion_similarity.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <tuple>
#include <vector>

namespace deformseg::tool {
namespace {

struct Evaluate_options {
  std::string labels;
  std::string store;
  Policy_options policy;
  Input_options read;
  bool skip_unreadable = false;
  std::string json;
  std::string png;
  bool per_query = false;
};

std::string fixed(double value, int decimals = 3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The animations read, and the labelled clips they are (without those skipped).
struct Read_clips {
  std::vector<mesh::Surface_mesh_animation> animations;
  std::vector<evaluation::Labelled_clip> clips;
  std::vector<std::string> skipped;  // "FILE clip NAME: MESSAGE"
};

// Reads the clips of `rows` that come from `file` on one body (rows[i] for i in `of_file`, their
// `body_file`, else --body), parsing it once; a row without a clip takes --clip's. The clips are
// read on --threads threads, one a thread (a file of one clip reads its frames on them), and kept
// or skipped in their order.
void read_file_clips(const std::filesystem::path& file, const std::vector<std::size_t>& of_file,
                     const std::vector<evaluation::Labelled_clip>& rows, const Evaluate_options& o, Read_clips& out) {
  const auto skip_or_throw = [&](const std::vector<std::size_t>& lost, const invalid_input& e) {
    if (!o.skip_unreadable) throw e;
    for (const std::size_t i : lost)
      out.skipped.push_back(file.string() + " clip '" + rows[i].item.clip + "': " + e.what());
  };
  if (!io::is_character_file(file)) {
    try {
      Input_options frames = o.read;
      frames.clip.clear();  // --clip is for the glTF rows
      out.animations.push_back(frontend::read_input(file.string(), frames, frontend::Front::command_line).animation);
      out.clips.push_back(rows[of_file.front()]);
    } catch (const invalid_input& e) {
      skip_or_throw(of_file, e);
    }
    return;
  }
  std::optional<io::Gltf_file> gltf;
  try {
    Input_options read = o.read;  // the rows of one file and one body
    if (const auto& body = rows[of_file.front()].body_file; !body.empty()) read.body = body.string();
    gltf.emplace(frontend::character_file(file.string(), read));
  } catch (const invalid_input& e) {
    return skip_or_throw(of_file, e);
  }
  std::vector<std::optional<mesh::Surface_mesh_animation>> read(of_file.size());
  std::vector<std::optional<invalid_input>> failed(of_file.size());
  deformseg::internal::parallel_for(of_file.size(), o.read.threads, [&](std::size_t k) {
    const std::size_t i = of_file[k];
    try {
      const std::string clip = rows[i].item.clip.empty() ? o.read.clip : rows[i].item.clip;
      io::require_clip_choice(*gltf, clip);  // an empty clip names a file's only one
      read[k] = gltf->read({.clip = clip, .fps = o.read.fps,
                            .repair = frontend::repair_options(file.string(), o.read),
                            .threads = o.read.threads});
    } catch (const invalid_input& e) {
      failed[k] = e;
    }
  });
  for (std::size_t k = 0; k < of_file.size(); ++k) {
    if (failed[k]) {
      skip_or_throw({of_file[k]}, *failed[k]);
      continue;
    }
    out.animations.push_back(std::move(*read[k]));
    out.clips.push_back(rows[of_file[k]]);
  }
}

Read_clips read_clips(const std::vector<evaluation::Labelled_clip>& rows, const Evaluate_options& o) {
  using File_on_body = std::pair<std::filesystem::path, std::filesystem::path>;
  std::vector<File_on_body> files;  // in the order of first appearance
  for (const auto& row : rows)
    if (std::ranges::find(files, File_on_body{row.file, row.body_file}) == files.end())
      files.emplace_back(row.file, row.body_file);
  Read_clips out;
  for (const auto& [file, body] : files) {
    std::vector<std::size_t> of_file;
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (rows[i].file == file && rows[i].body_file == body) of_file.push_back(i);
    if (!io::is_character_file(file) && of_file.size() > 1)
      throw invalid_input("lists " + std::to_string(of_file.size()) + " clips of " + file.string() +
                          ", which is not a character file (glTF, FBX, Collada) and holds one animation", {.file = o.labels});
    progress("reading " + std::to_string(of_file.size()) + " clip(s) of " + file.string());
    read_file_clips(file, of_file, rows, o, out);
  }
  for (const auto& line : out.skipped) progress("skipped " + line);
  return out;
}

// The items' order in the figure: by motion (distractors last), then body, then clip.
std::vector<std::size_t> order_by_label(const std::vector<evaluation::Labelled_clip>& clips) {
  std::vector<std::size_t> order(clips.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  const auto key = [&](std::size_t i) {
    const evaluation::Labelled_item& item = clips[i].item;
    return std::tuple(item.motion == evaluation::distractor_label, item.motion, item.body, item.clip);
  };
  std::ranges::stable_sort(order, [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  return order;
}

// The matrix with rows and columns in `order`, each value coloured (viridis) by its rank among
// all entries, from the smallest (dark) to the largest (yellow); the motions named along both
// sides, a white line between two of them.
void write_grouped_heat_map(const Eigen::MatrixXd& m, const std::vector<evaluation::Labelled_clip>& clips,
                            const std::vector<std::size_t>& order, const Evaluate_options& o,
                            const std::string& path) {
  progress("writing the matrix, grouped by motion, to " + path);
  const std::size_t n = order.size();
  const int cell = cell_size(n, n, 720, 1, 40);
  std::vector<std::string> motion_of_cell;
  for (std::size_t k : order) motion_of_cell.push_back(clips[k].item.motion);
  const Axis motions = grouped_axis("", motion_of_cell);
  // By rank, not by value: the values of real clips crowd near 1 and one outlier would flatten
  // a linear scale.
  std::vector<double> sorted(m.data(), m.data() + m.size());
  std::ranges::sort(sorted);
  const auto rank = [&](double v) {
    return sorted.size() < 2 ? 1.0
                             : double(std::ranges::lower_bound(sorted, v) - sorted.begin()) / double(sorted.size() - 1);
  };
  const auto value_at_rank = [&](double fraction) {
    return sorted.empty() ? 0.0 : sorted[std::size_t(std::lround(fraction * double(sorted.size() - 1)))];
  };
  Matrix_figure figure(n, n, cell, "similarity of " + std::to_string(n) + " clips by motion (" + o.policy.policy + ")",
                       motions, motions,
                       Color_bar{"similarity (coloured by rank)", 0, 1, [](double f) { return color::strain_color(f); },
                                 value_at_rank});
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c)
      figure.fill_cell(r, c, color::strain_color(rank(m(Eigen::Index(order[r]), Eigen::Index(order[c])))));
  figure.draw_separators(motions, motions);
  figure.write(path);
}

template <class T>
nlohmann::json optional_json(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::string optional_text(const std::optional<double>& value) { return value ? fixed(*value) : "none"; }

nlohmann::json scores_json(const evaluation::Retrieval_scores& s) {
  nlohmann::json per_motion = nlohmann::json::array();
  for (const auto& m : s.per_motion)
    per_motion.push_back({{"motion", m.motion}, {"queries", m.queries}, {"correct", m.correct},
                          {"nn_accuracy", m.nn_accuracy}});
  nlohmann::json per_query = nlohmann::json::array();
  for (const auto& q : s.per_query)
    per_query.push_back({{"query", q.query}, {"nearest", q.nearest}, {"nearest_similarity", q.nearest_similarity},
                         {"first_relevant_rank", optional_json(q.first_relevant_rank)},
                         {"average_precision", optional_json(q.average_precision)}});
  return {{"queries", s.queries}, {"queries_without_relevant", s.queries_without_relevant},
          {"queries_without_candidate", s.queries_without_candidate}, {"nn_accuracy", optional_json(s.nn_accuracy)},
          {"mean_average_precision", optional_json(s.mean_average_precision)},
          {"roc_auc", optional_json(s.roc_auc)}, {"median_same", optional_json(s.median_same)},
          {"median_different", optional_json(s.median_different)}, {"same_pairs", s.same_pairs},
          {"different_pairs", s.different_pairs}, {"labels", s.labels}, {"confusion", s.confusion},
          {"per_motion", per_motion}, {"per_query", per_query}};
}

// A clip as the labels name it: its file's name, and #CLIP for a clip of a glTF file.
std::string clip_name(const evaluation::Labelled_clip& clip) {
  const std::string file = clip.file.filename().string();
  return clip.item.clip.empty() ? file : file + "#" + clip.item.clip;
}

// One line per query: what it found nearest, and at which rank the first clip of its motion came.
void print_per_query(const evaluation::Retrieval_scores& s, const std::vector<evaluation::Labelled_clip>& clips) {
  std::cout << "per query (query: nearest candidate, its value; rank of the first of the query's motion)\n";
  for (const auto& q : s.per_query) {
    const evaluation::Labelled_clip& query = clips[q.query];
    const evaluation::Labelled_clip& nearest = clips[q.nearest];
    std::cout << "  " << clip_name(query) << " (" << query.item.motion << "): " << clip_name(nearest) << " ("
              << nearest.item.motion << ") " << fixed(q.nearest_similarity) << "; "
              << (q.first_relevant_rank ? "first " + query.item.motion + " at " + std::to_string(*q.first_relevant_rank)
                                        : "no " + query.item.motion + " among the candidates")
              << '\n';
  }
}

void print_confusion(const evaluation::Retrieval_scores& s) {
  std::size_t width = 6;
  for (const auto& label : s.labels) width = std::max(width, label.size() + 1);
  std::cout << "confusion (rows: query motion, columns: nearest neighbour's motion)\n" << std::string(width, ' ');
  for (const auto& label : s.labels)  // right-aligned over the counts, cut to 5 letters
    std::cout << ' ' << std::string(5 - std::min<std::size_t>(5, label.size()), ' ') << label.substr(0, 5);
  std::cout << '\n';
  for (std::size_t r = 0; r < s.labels.size(); ++r) {
    if (s.labels[r] == evaluation::distractor_label) continue;  // never queried
    std::cout << s.labels[r] << std::string(width - s.labels[r].size(), ' ');
    for (const std::size_t count : s.confusion[r]) {
      const std::string text = count ? std::to_string(count) : ".";
      std::cout << ' ' << std::string(5 - std::min<std::size_t>(5, text.size()), ' ') << text;
    }
    std::cout << '\n';
  }
}

void print_scores(const evaluation::Retrieval_scores& s, std::size_t items) {
  std::cout << "items                " << items << "\nqueries              " << s.queries
            << "\nwithout relevant     " << s.queries_without_relevant << "\nNN accuracy          "
            << optional_text(s.nn_accuracy) << "\nmAP                  " << optional_text(s.mean_average_precision)
            << "\nROC-AUC              " << optional_text(s.roc_auc) << "\nmedian same          "
            << optional_text(s.median_same) << " (" << s.same_pairs << " pairs)\nmedian different     "
            << optional_text(s.median_different) << " (" << s.different_pairs << " pairs)\nper motion\n";
  for (const auto& m : s.per_motion)
    std::cout << "  " << m.motion << std::string(14 - std::min<std::size_t>(13, m.motion.size()), ' ') << m.correct
              << " / " << m.queries << "  " << fixed(m.nn_accuracy) << '\n';
  print_confusion(s);
}

// The matrix of the clips read. A clip the policy cannot describe (a pose of one frame, say) stops
// the command, named; with --skip-unreadable it is left out and the matrix made again without it.
Eigen::MatrixXd matrix_of_clips(Read_clips& read, const Evaluate_options& o, Matrix_progress& report) {
  while (true) {
    try {
      report = Matrix_progress{.descriptions = read.animations.size()};
      return frontend::similarity_matrix(read.animations, o.policy, std::ref(report), o.read.threads);
    } catch (const similarity::animation_not_described& e) {
      const auto at = std::ptrdiff_t(e.index());
      const evaluation::Labelled_clip& clip = read.clips[e.index()];
      const std::string clip_text = clip.item.clip.empty() ? "" : " clip '" + clip.item.clip + "'";
      const std::string what = clip.file.string() + clip_text + ": " + e.reason();
      if (!o.skip_unreadable) throw invalid_input(what + " (--skip-unreadable leaves it out)");
      progress("skipped " + what);
      read.skipped.push_back(what);
      read.animations.erase(read.animations.begin() + at);
      read.clips.erase(read.clips.begin() + at);
    }
  }
}

// The matrix of the labelled clips as the store holds them, the rows as `read.clips`.
Eigen::MatrixXd matrix_of_store(Read_clips& read, const Evaluate_options& o, Matrix_progress& report) {
  const frontend::Store_search library(o.store);
  library.check_policy(o.policy, frontend::Front::command_line);
  // The rows grouped by file, in the order of first appearance, as read_clips reads them.
  const std::vector<evaluation::Labelled_clip> rows = evaluation::read_motion_labels(o.labels);
  const std::vector<std::size_t> at = library.labelled(o.labels, o.read, frontend::Front::command_line);
  std::vector<std::size_t> selected;
  std::vector<bool> taken(rows.size(), false);
  for (std::size_t first = 0; first < rows.size(); ++first) {
    if (taken[first]) continue;
    for (std::size_t i = first; i < rows.size(); ++i)
      if (rows[i].file == rows[first].file) {
        taken[i] = true;
        read.clips.push_back(rows[i]);
        selected.push_back(at[i]);
      }
  }
  progress("comparing " + std::to_string(selected.size()) + " clips of " + o.store + " pair by pair");
  report = Matrix_progress{.descriptions = 0};
  return library.matrix(std::move(selected), std::ref(report), o.read.threads);
}

void run_evaluate(const Evaluate_options& o) {
  frontend::check(o.policy, frontend::Front::command_line);
  frontend::check(o.read, frontend::Front::command_line);
  const auto start = std::chrono::steady_clock::now();
  Read_clips read;
  if (o.store.empty()) {
    read = read_clips(evaluation::read_motion_labels(o.labels), o);
    progress("read " + std::to_string(read.animations.size()) + " clips in " + fixed(seconds_since(start), 1) + " s");
  }
  const double read_seconds = seconds_since(start);
  Matrix_progress report;
  const Eigen::MatrixXd m = o.store.empty() ? matrix_of_clips(read, o, report) : matrix_of_store(read, o, report);
  const double matrix_seconds = seconds_since(report.start);
  std::vector<evaluation::Labelled_item> items;
  for (const auto& clip : read.clips) items.push_back(clip.item);
  const evaluation::Retrieval_scores scores = evaluation::evaluate_retrieval(m, items);
  const std::vector<std::size_t> order = order_by_label(read.clips);
  if (!o.png.empty()) write_grouped_heat_map(m, read.clips, order, o, o.png);
  progress("times: reading " + fixed(read_seconds, 1) + " s, describing " + fixed(report.describe_seconds, 1) +
           " s, comparing " + fixed(matrix_seconds - report.describe_seconds, 1) + " s");
  nlohmann::json document;
  if (!o.json.empty()) {  // the whole matrix, only when asked for
    nlohmann::json inputs = nlohmann::json::array(), rows = nlohmann::json::array();
    for (const auto& clip : read.clips)
      inputs.push_back({{"file", clip.file.string()}, {"clip", clip.item.clip}, {"motion", clip.item.motion},
                        {"body", clip.item.body}, {"rig", clip.item.rig}});
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      rows.push_back(nlohmann::json::array());
      for (Eigen::Index j = 0; j < m.cols(); ++j) rows.back().push_back(m(i, j));
    }
    document = {{"labels", o.labels},
                {"policy", o.policy.policy},
                {"alignment_policy", frontend::alignment_name(o.policy)},
                {"fps", o.read.fps},
                {"inputs", inputs},
                {"skipped", read.skipped},
                {"scores", scores_json(scores)},
                {"figure_order", order},
                {"similarity", rows},
                {"seconds",
                 {{"reading", read_seconds},
                  {"describing", report.describe_seconds},
                  {"comparing", matrix_seconds - report.describe_seconds}}}};
  }
  write_outputs(document, o.json, [&] {
    print_scores(scores, items.size());
    if (o.per_query) print_per_query(scores, read.clips);
  });
}

}  // namespace

void add_evaluate_command(CLI::App& app) {
  auto o = std::make_shared<Evaluate_options>();
  CLI::App* command = app.add_subcommand(
      "evaluate", "How well motion similarity retrieves the same motion on other bodies: NN accuracy, mAP, "
                  "ROC-AUC, medians and the confusion table of a labelled set of clips");
  command->add_option("labels", o->labels,
                      "CSV file with the header file,clip,motion[,rig][,body][,body_file] (files relative to its "
                      "folder; body_file: the body a row's clip plays on; motion '-': a distractor; fields may be in "
                      "double quotes)")
      ->required();
  add_policy_options(*command, o->policy);
  add_parameters(*command, frontend::input_parameters, o->read);
  command->add_option("--store", o->store,
                      "Compare the labelled clips as a motion store holds them (deformseg describe LABELS --store S), "
                      "without reading or describing them; a clip missing or changed since is an error");
  command->add_flag("--skip-unreadable", o->skip_unreadable,
                    "Leave out, with a line on standard error, the clips that cannot be read or described (a "
                    "pose of one frame), instead of stopping");
  command->add_flag("--per-query", o->per_query,
                    "Also print, for each query, its nearest candidate and the rank of the first candidate of its "
                    "motion (the JSON always has them)");
  add_json_option(*command, o->json, "the labels, scores (per query among them), matrix and times");
  command->add_option("--png", o->png,
                      "Draw the matrix with rows and columns grouped by motion (distractors last, white lines "
                      "between groups), each cell coloured by the rank of its value, into FILE.png")
      ->check(output_file());
  command->callback([o] { run_evaluate(*o); });
}

}  // namespace deformseg::tool
