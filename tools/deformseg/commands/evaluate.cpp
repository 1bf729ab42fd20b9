// deformseg evaluate LABELS.csv: reads and describes every labelled clip, computes the similarity
// matrix and says how well it retrieves the same motion on other bodies (evaluate_retrieval).
#include "command.h"
#include "policy_options.h"

#include <frontend/clip_cache.h>
#include <frontend/store_search.h>

#include <deformseg/color/strain_colors.h>
#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <string>
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

// The labelled clips compared (without those skipped), and those skipped.
struct Compared_clips {
  std::vector<evaluation::Labelled_clip> clips;
  std::vector<std::string> skipped;  // "FILE clip NAME: MESSAGE"
};

// The rows of the labels that name one file on one body, in their order.
struct File_rows {
  std::filesystem::path file, body;
  std::vector<std::size_t> rows;
};

// The rows by file and body, in the order of their first rows.
std::vector<File_rows> rows_by_file(const std::vector<evaluation::Labelled_clip>& rows, const Evaluate_options& o) {
  std::vector<File_rows> files;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto same = [&](const File_rows& f) { return f.file == rows[i].file && f.body == rows[i].body_file; };
    auto at = std::ranges::find_if(files, same);
    if (at == files.end()) at = files.insert(files.end(), {rows[i].file, rows[i].body_file, {}});
    at->rows.push_back(i);
  }
  for (const File_rows& f : files)
    if (!io::is_character_file(f.file) && f.rows.size() > 1)
      throw invalid_input("lists " + std::to_string(f.rows.size()) + " clips of " + f.file.string() +
                              ", which is not a character file (glTF, FBX, Collada, BVH) and holds one animation",
                          {.file = o.labels});
  return files;
}

// The labelled clips in the order they are compared (a file's rows together, the files in the
// order of their first rows), read one at a time from any thread: a character file is parsed and
// repaired by the first of its clips to be read and freed after the last (`frontend::Clip_cache`),
// so that few are held at once; a row without a clip takes --clip's.
class Clip_reader {
public:
  Clip_reader(std::vector<evaluation::Labelled_clip> rows, const Evaluate_options& o)
      : Clip_reader(std::move(rows), rows_by_file(rows, o), o) {}  // binds, not moves: the grouping reads rows

  std::size_t size() const { return order_.size(); }
  const evaluation::Labelled_clip& clip(std::size_t k) const { return rows_[order_[k].row]; }
  // "FILE clip 'NAME'", with " on BODY" for a row's body_file, as a skipped clip is named.
  std::string name(std::size_t k) const {
    const std::filesystem::path& body = clip(k).body_file;
    return clip(k).file.string() + " clip '" + clip(k).item.clip + "'" + (body.empty() ? "" : " on " + body.string());
  }

  // The animation of clip k, as `frontend::read_input` reads it.
  // @throws invalid_input as the reader (the file's, for every clip of a file that cannot be opened).
  mesh::Surface_mesh_animation read(std::size_t k) {
    File& file = *files_[order_[k].file];
    announce(file);
    const std::string path = file.of.file.string();
    if (!io::is_character_file(file.of.file)) {
      Input_options frames = o_.read;
      frames.clip.clear();  // --clip is for the glTF rows
      return frontend::read_input(path, frames, frontend::Front::command_line).animation;
    }
    const frontend::Character_on_body character{path, file.of.body.string()};
    const frontend::Clip_cache::Release release(cache_, character);
    const std::shared_ptr<const io::Gltf_file> gltf = cache_.acquire(character);
    const std::string clip = rows_[order_[k].row].item.clip.empty() ? o_.read.clip : rows_[order_[k].row].item.clip;
    io::require_clip_choice(*gltf, clip);  // an empty clip names a file's only one
    return gltf->read(cache_.connectivity(character)->repaired(),
                      {.clip = clip, .fps = o_.read.fps, .threads = o_.read.threads});
  }

private:
  // `grouped`: the rows by file and body (`rows_by_file`), grouped once for the cache and the order.
  Clip_reader(std::vector<evaluation::Labelled_clip>&& rows, std::vector<File_rows> grouped, const Evaluate_options& o)
      : rows_(std::move(rows)), o_(o), cache_(characters_of(grouped), o.read) {
    for (File_rows& of : grouped) {
      for (const std::size_t row : of.rows) order_.push_back({files_.size(), row});
      files_.push_back(std::make_unique<File>(std::move(of)));
    }
  }

  struct File {
    explicit File(File_rows rows) : of(std::move(rows)) {}
    File_rows of;
    std::once_flag announced;
  };
  struct Clip_at {
    std::size_t file, row;
  };

  // The character files of the rows, a row each, on its body_file, named as `read` names them: by
  // the first row of each file and body.
  static std::vector<frontend::Character_on_body> characters_of(const std::vector<File_rows>& grouped) {
    std::vector<frontend::Character_on_body> files;
    for (const File_rows& of : grouped)
      files.insert(files.end(), of.rows.size(), frontend::Character_on_body{of.file.string(), of.body.string()});
    return files;
  }

  // Says, once per file, that its clips are being read.
  void announce(File& file) {
    std::call_once(file.announced, [&] {
      const std::lock_guard say(say_mutex_);
      progress("reading " + std::to_string(file.of.rows.size()) + " clip(s) of " + file.of.file.string());
    });
  }

  const std::vector<evaluation::Labelled_clip> rows_;
  const Evaluate_options& o_;
  frontend::Clip_cache cache_;
  std::vector<std::unique_ptr<File>> files_;
  std::vector<Clip_at> order_;
  std::mutex say_mutex_;
};

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

// A clip as the labels name it: its file's name, #CLIP for a clip of a character file, " on BODY" for a
// row's body_file.
std::string clip_name(const evaluation::Labelled_clip& clip) {
  const std::string file = clip.file.filename().string();
  const std::string name = clip.item.clip.empty() ? file : file + "#" + clip.item.clip;
  return clip.body_file.empty() ? name : name + " on " + clip.body_file.filename().string();
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

// The matrix of the labelled clips, each read and described at once. A clip that cannot be read
// or described (a pose of one frame, say) stops the command, named (those that cannot be read
// first); with --skip-unreadable it is left out.
Eigen::MatrixXd matrix_of_clips(Compared_clips& compared, const Evaluate_options& o, Matrix_progress& report) {
  Clip_reader reader(evaluation::read_motion_labels(o.labels), o);
  report = Matrix_progress{.descriptions = reader.size()};
  const frontend::Read_matrix matrix = frontend::similarity_matrix(
      {reader.size(), [&](std::size_t k) { return reader.read(k); }}, o.policy, std::ref(report), o.read.threads);
  for (const bool reading : {true, false})
    for (const frontend::Left_out& lost : matrix.left_out) {
      if (lost.reading != reading) continue;
      const evaluation::Labelled_clip& clip = reader.clip(lost.index);
      const std::string clip_text = clip.item.clip.empty() ? "" : " clip '" + clip.item.clip + "'";
      const std::string what = reading ? reader.name(lost.index) + ": " + lost.error.what()
                                       : clip.file.string() + clip_text + ": " + lost.error.what();
      const Input_location row{.file = o.labels, .line = clip.line};  // the labels file's row names it too
      if (!o.skip_unreadable) {
        if (reading) throw invalid_input(lost.error.what(), row);
        throw invalid_input(what + " (--skip-unreadable leaves it out)", row);
      }
      progress(std::string("skipped ") + invalid_input(what, row).what());
      compared.skipped.push_back(what);
    }
  for (const std::size_t k : matrix.kept) compared.clips.push_back(reader.clip(k));
  return matrix.similarity;
}

// The matrix of the labelled clips as the store holds them, the rows as `compared.clips`.
Eigen::MatrixXd matrix_of_store(Compared_clips& compared, const Evaluate_options& o, Matrix_progress& report) {
  const frontend::Store_search library(o.store);
  library.check_policy(o.policy, frontend::Front::command_line);
  // The rows grouped by file and body, in the order of first appearance, as Clip_reader orders them.
  const std::vector<evaluation::Labelled_clip> rows = evaluation::read_motion_labels(o.labels);
  const std::vector<std::size_t> at = library.labelled(o.labels, o.read, frontend::Front::command_line);
  std::vector<std::size_t> selected;
  for (const File_rows& of : rows_by_file(rows, o))
    for (const std::size_t i : of.rows) {
      compared.clips.push_back(rows[i]);
      selected.push_back(at[i]);
    }
  progress("comparing " + std::to_string(selected.size()) + " clips of " + o.store + " pair by pair");
  report = Matrix_progress{.descriptions = 0};
  return library.matrix(std::move(selected), std::ref(report), o.read.threads);
}

void run_evaluate(const Evaluate_options& o) {
  frontend::check(o.policy, frontend::Front::command_line);
  frontend::check(o.read, frontend::Front::command_line);
  Compared_clips read;
  Matrix_progress report;
  const Eigen::MatrixXd m = o.store.empty() ? matrix_of_clips(read, o, report) : matrix_of_store(read, o, report);
  const double matrix_seconds = seconds_since(report.start);
  if (read.clips.empty())
    throw invalid_input("nothing evaluated: every row was unreadable (" + std::to_string(read.skipped.size()) + ")",
                        {.file = o.labels});
  std::vector<evaluation::Labelled_item> items;
  for (const auto& clip : read.clips) items.push_back(clip.item);
  const evaluation::Retrieval_scores scores = evaluation::evaluate_retrieval(m, items);
  const std::vector<std::size_t> order = order_by_label(read.clips);
  if (!o.png.empty()) write_grouped_heat_map(m, read.clips, order, o, o.png);
  progress("times: reading and describing " + fixed(report.describe_seconds, 1) + " s, comparing " +
           fixed(matrix_seconds - report.describe_seconds, 1) + " s");
  nlohmann::json document;
  if (!o.json.empty()) {  // the whole matrix, only when asked for
    nlohmann::json inputs = nlohmann::json::array(), rows = nlohmann::json::array();
    for (const auto& clip : read.clips)
      inputs.push_back({{"file", clip.file.string()}, {"clip", clip.item.clip}, {"motion", clip.item.motion},
                        {"body", clip.item.body}, {"body_file", clip.body_file.string()}, {"rig", clip.item.rig}});
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
                 {{"reading_and_describing", report.describe_seconds},
                  {"comparing", matrix_seconds - report.describe_seconds}}}};
  }
  write_outputs(document, o.json, [&] {
    print_scores(scores, items.size());
    if (o.per_query) print_per_query(scores, read.clips);
  });
  if (scores.queries == 0)
    throw invalid_input("nothing evaluated: no clip has a candidate of another body to rank", {.file = o.labels});
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
                      "each on its row's body_file, without reading or describing them; a clip missing or changed "
                      "since (its file or its body file) is an error");
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
