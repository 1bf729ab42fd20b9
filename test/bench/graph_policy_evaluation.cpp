// Retrieval figures of the graph policies (Evolving_graph_similarity) on the shared characters over
// a grid of their parameters, each setting also chosen leaving each body out. Not a Google
// Benchmark:
//
//   build-bench/test/bench/graph_policy_evaluation [--classes walk,run,idle,jump,death]
//       [--threshold 0.3,0.5] [--min-area 0,0.01] [--min-frames 2,4] [--hysteresis 0,0.5]
//       [--contact 0.01] [--rigid 0.002] [--sigma 0,0.05] [--area-weight 1,4]
//       [--labels mismatch,medoids,graphs] [--alignment dtw,smith-waterman] [--describe-only 1]
//       [--area-series 1]
//
// Every list is an axis of the grid (default: the settings of character_graph_similarity, tuned
// on these characters with this program; sigma 0: each clip's own).
// Each clip of motions.csv with one of the classes (default: every labelled clip) is read once at
// 30 fps, welded as the tool reads it. For each setting, the figures of evaluate_retrieval over
// all queries; then, for each body in turn, the setting with the best ROC-AUC (ties: mAP) on the
// other bodies alone, and the figures of the left-out bodies' queries under the setting their
// fold chose. --describe-only times the descriptions of every setting (2 threads) and compares
// nothing. --area-series compares each clip by what its binary labels alone hold, its deformed
// share of the area frame by frame (the segmentation of each setting), by DTW on the absolute
// differences: what any graph of those labels could tell at most of how much a body deforms.
#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/gltf.h>
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/similarity/evolving_graph_similarity.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace deformseg;
namespace fs = std::filesystem;

namespace {

using Policy = decltype(similarity::character_graph_similarity());  // DTW
using Thesis_policy = similarity::Evolving_graph_similarity<>;         // Smith–Waterman
using Animation = mesh::Surface_mesh_animation;

constexpr const char* label_names[] = {"mismatch", "medoids", "graphs"};

struct Setting {
  spatiotemporal::Spatiotemporal_options segmentation;
  double area_weight = 1;
  similarity::Label_dissimilarity labels = similarity::Label_dissimilarity::mismatch;
  bool dtw = true;

  template <class P>
  P policy() const {
    P p;
    p.segmentation = segmentation;
    p.costs.area_weight = area_weight;
    p.labels = labels;
    return p;
  }
  std::string name() const {
    char text[240];
    std::snprintf(text, sizeof text, "threshold %.2f min-area %.3f min-frames %zu hysteresis %.2f contact %.3f "
                  "rigid %.4f sigma %.3f area-weight %.1f labels %s%s", segmentation.threshold, segmentation.min_area,
                  segmentation.min_frames, segmentation.hysteresis, segmentation.parts.contact_distance,
                  segmentation.parts.rigid_tolerance, segmentation.sigma.value_or(0), area_weight,
                  label_names[std::size_t(labels)], dtw ? "" : " smith-waterman");
    return text;
  }
};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
  return parts;
}

std::vector<double> numbers(const std::map<std::string, std::string>& args, const std::string& key, double fallback) {
  const auto found = args.find(key);
  if (found == args.end()) return {fallback};
  std::vector<double> values;
  for (const auto& v : split(found->second)) values.push_back(std::stod(v));
  return values;
}

// The labelled clips of `classes` (all when empty) and their animations.
void read_clips(const fs::path& dir, const std::vector<std::string>& classes,
                std::vector<evaluation::Labelled_item>& items, std::vector<Animation>& animations) {
  std::ifstream in(dir / "motions.csv");
  std::string line;
  std::getline(in, line);
  std::map<std::string, std::vector<evaluation::Labelled_item>> by_file;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string file, clip, motion, rig;
    std::getline(fields, file, ','), std::getline(fields, clip, ','), std::getline(fields, motion, ',');
    std::getline(fields, rig, ',');
    if (file.empty() || motion == "-") continue;
    if (!classes.empty() && std::find(classes.begin(), classes.end(), motion) == classes.end()) continue;
    by_file[file].push_back({.motion = motion, .body = file, .rig = rig, .clip = clip});
  }
  for (auto& [file, members] : by_file) {
    io::Gltf_file gltf((dir / file).string());
    for (auto& item : members) {
      animations.push_back(gltf.read(io::Gltf_read_options{.clip = item.clip, .fps = 30}));
      items.push_back(item);
    }
  }
}

// The value of every two clips under `policy`, and the seconds spent describing.
template <class Policy>
Eigen::MatrixXd values(const std::vector<Animation>& animations, const Policy& policy, double& describe_seconds) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::optional<typename Policy::Description>> described(animations.size());
  deformseg::internal::parallel_for(animations.size(), 1,
                                    [&](std::size_t i) { described[i].emplace(policy.describe(animations[i])); });
  describe_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto n = Eigen::Index(animations.size());
  Eigen::MatrixXd value = Eigen::MatrixXd::Ones(n, n);
  deformseg::internal::parallel_for(std::size_t(n), 1, [&](std::size_t i) {
    for (Eigen::Index j = Eigen::Index(i) + 1; j < n; ++j)
      value(Eigen::Index(i), j) = value(j, Eigen::Index(i)) =
          policy.compare(*described[i], *described[std::size_t(j)]).value;
  });
  return value;
}

// Per frame, the share of the area whose cells are deformed.
std::vector<double> deformed_area(const Animation& animation, const spatiotemporal::Spatiotemporal_options& options) {
  const auto layout = spatiotemporal::body_layout(animation, options.parts);
  const auto field = strain::compute_strain(animation, spatiotemporal::strain_options(options));
  const auto segmentation = spatiotemporal::spatiotemporal_segmentation(field, layout, options);
  std::vector<double> share(segmentation.num_frames(), 0);
  for (std::size_t t = 0; t < share.size(); ++t)
    for (std::size_t f = 0; f < segmentation.num_faces(); ++f)
      if (segmentation.label(f, t) != spatiotemporal::Spatiotemporal_segmentation::rigid)
        share[t] += layout.area_shares()[f];
  return share;
}

// The value of every two clips by their deformed area series: minus the mean absolute difference
// along their DTW path.
Eigen::MatrixXd area_series_values(const std::vector<Animation>& animations,
                                   const spatiotemporal::Spatiotemporal_options& options) {
  std::vector<std::vector<double>> series(animations.size());
  deformseg::internal::parallel_for(animations.size(), 1,
                                    [&](std::size_t i) { series[i] = deformed_area(animations[i], options); });
  const auto n = Eigen::Index(animations.size());
  Eigen::MatrixXd value = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const auto& a = series[std::size_t(i)];
      const auto& b = series[std::size_t(j)];
      const auto path = alignment::Dtw{}.align(a.size(), b.size(), [&](std::size_t x, std::size_t y) {
        return std::abs(a[x] - b[y]);
      });
      value(i, j) = value(j, i) = -path.score / double(path.pairs.size());
    }
  return value;
}

void print(const char* what, const evaluation::Retrieval_scores& s) {
  std::printf("%s: NN %.3f  mAP %.3f  ROC-AUC %.3f  median same %.3f / different %.3f  (%zu queries)\n", what,
              s.nn_accuracy.value_or(0), s.mean_average_precision.value_or(0), s.roc_auc.value_or(0),
              s.median_same.value_or(0), s.median_different.value_or(0), s.queries);
}

// The items and the matrix without body `body`.
evaluation::Retrieval_scores without(const Eigen::MatrixXd& value, const std::vector<evaluation::Labelled_item>& items,
                                     const std::string& body) {
  std::vector<Eigen::Index> kept;
  std::vector<evaluation::Labelled_item> rest;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].body != body) kept.push_back(Eigen::Index(i)), rest.push_back(items[i]);
  return evaluation::evaluate_retrieval(value(kept, kept), rest);
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> args;
  for (int i = 1; i + 1 < argc; i += 2) args[argv[i]] = argv[i + 1];
  const Policy defaults = similarity::character_graph_similarity();
  std::vector<Setting> grid{Setting{defaults.segmentation, defaults.costs.area_weight, defaults.labels}};
  // Each axis multiplies the grid by its values.
  const auto axis = [&](const std::string& key, double fallback, auto set) {
    std::vector<Setting> larger;
    for (const Setting& setting : grid)
      for (double value : numbers(args, key, fallback)) larger.push_back(setting), set(larger.back(), value);
    grid = std::move(larger);
  };
  const auto& o = defaults.segmentation;
  axis("--threshold", o.threshold, [](Setting& s, double v) { s.segmentation.threshold = v; });
  axis("--min-area", o.min_area, [](Setting& s, double v) { s.segmentation.min_area = v; });
  axis("--min-frames", double(o.min_frames), [](Setting& s, double v) { s.segmentation.min_frames = std::size_t(v); });
  axis("--hysteresis", o.hysteresis, [](Setting& s, double v) { s.segmentation.hysteresis = v; });
  axis("--contact", o.parts.contact_distance, [](Setting& s, double v) { s.segmentation.parts.contact_distance = v; });
  axis("--rigid", o.parts.rigid_tolerance, [](Setting& s, double v) { s.segmentation.parts.rigid_tolerance = v; });
  axis("--sigma", o.sigma.value_or(0), [](Setting& s, double v) {
    s.segmentation.sigma = v > 0 ? std::optional(v) : std::nullopt;
  });
  axis("--area-weight", defaults.costs.area_weight, [](Setting& s, double v) { s.area_weight = v; });
  const auto labels = split(args.count("--labels") ? args["--labels"] : "mismatch");
  const auto alignments = split(args.count("--alignment") ? args["--alignment"] : "dtw");
  std::vector<Setting> with_labels;
  for (const Setting& setting : grid)
    for (const auto& name : labels)
      for (const auto& alignment : alignments) {
        with_labels.push_back(setting);
        for (std::size_t l = 0; l < std::size(label_names); ++l)
          if (name == label_names[l]) with_labels.back().labels = similarity::Label_dissimilarity(l);
        with_labels.back().dtw = alignment == "dtw";
      }
  grid = std::move(with_labels);
  const char* env = std::getenv("DEFORMSEG_DATA_DIR");
  const fs::path dir = fs::path(env ? env : DEFORMSEG_DATA_DIR) / "characters";
  std::vector<evaluation::Labelled_item> items;
  std::vector<Animation> animations;
  read_clips(dir, args.count("--classes") ? split(args["--classes"]) : std::vector<std::string>{}, items, animations);
  std::printf("%zu clips, %zu settings\n", items.size(), grid.size());

  if (args.count("--describe-only")) {
    for (const Setting& s : grid) {
      const auto start = std::chrono::steady_clock::now();
      const auto policy = s.policy<Policy>();
      deformseg::internal::parallel_for(animations.size(), 1, [&](std::size_t i) { policy.describe(animations[i]); });
      std::printf("%s: %zu clips described in %.2f s\n", s.name().c_str(), animations.size(),
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return 0;
  }
  std::vector<Eigen::MatrixXd> matrices;
  for (const Setting& s : grid) {
    double describe_seconds = 0;
    const auto start = std::chrono::steady_clock::now();
    if (args.count("--area-series")) matrices.push_back(area_series_values(animations, s.segmentation));
    else if (s.dtw) matrices.push_back(values(animations, s.policy<Policy>(), describe_seconds));
    else matrices.push_back(values(animations, s.policy<Thesis_policy>(), describe_seconds));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s  [describe %.1f s, all %.1f s]\n", s.name().c_str(), describe_seconds, seconds);
    print("  all", evaluation::evaluate_retrieval(matrices.back(), items));
    std::fflush(stdout);
  }

  std::vector<std::string> bodies;
  for (const auto& item : items)
    if (std::find(bodies.begin(), bodies.end(), item.body) == bodies.end()) bodies.push_back(item.body);
  Eigen::MatrixXd left_out(matrices.front().rows(), matrices.front().cols());
  for (const std::string& body : bodies) {
    std::size_t best = 0;
    evaluation::Retrieval_scores best_scores;
    for (std::size_t s = 0; s < grid.size(); ++s) {
      const auto scores = without(matrices[s], items, body);
      const auto key = [](const evaluation::Retrieval_scores& r) {
        return std::pair(r.roc_auc.value_or(0), r.mean_average_precision.value_or(0));
      };
      if (s == 0 || key(scores) > key(best_scores)) best = s, best_scores = scores;
    }
    std::printf("leaving out %s: %s\n", body.c_str(), grid[best].name().c_str());
    for (std::size_t i = 0; i < items.size(); ++i)
      if (items[i].body == body) left_out.row(Eigen::Index(i)) = matrices[best].row(Eigen::Index(i));
  }
  print("each body under the setting chosen without it", evaluation::evaluate_retrieval(left_out, items));
}
