// Retrieval figures of Self_similarity_matching on the shared characters (motions.csv): every
// clip with a motion is a query, ranked against every clip of the OTHER files except those of
// the same name on the same rig; NN accuracy, mAP, pooled ROC-AUC and the median values of
// same-motion and different-motion pairs, overall and per query body. Not a Google Benchmark:
//
//   build/test/bench/similarity_evaluation [--window W] [--quantiles K] [--tolerance X]
//       [--normalize shorter|longer] [--profile sorted|temporal] [--leave-out FILE] [--cache PATH]
//       [--baseline default]
//
// --leave-out drops a body from queries and candidates (to choose parameters without it);
// --baseline default evaluates today's Default_similarity instead (no cache); --cache keeps the self-dissimilarity matrices (which the options do not change) in a file
// outside the repository, so that a sweep reads the clips once.
#include <deformseg/io/gltf.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace deformseg;
namespace fs = std::filesystem;

namespace {

struct Clip {
  std::string file, clip, motion, rig;
  Eigen::MatrixXd distances;
};

std::vector<Clip> read_labels(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<Clip> clips;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    Clip c;
    std::getline(fields, c.file, ',');
    std::getline(fields, c.clip, ',');
    std::getline(fields, c.motion, ',');
    std::getline(fields, c.rig, ',');
    if (!c.file.empty()) clips.push_back(std::move(c));
  }
  return clips;
}

void read_distances(std::vector<Clip>& clips, const fs::path& dir) {
  double describe_seconds = 0;
  std::map<std::string, std::vector<Clip*>> by_file;
  for (Clip& c : clips) by_file[c.file].push_back(&c);
  for (auto& [file, members] : by_file) {
    io::Gltf_file gltf((dir / file).string());
    for (Clip* c : members) {
      const io::Sampled_gltf s = gltf.sample(io::Gltf_read_options{.clip = c->clip, .fps = 30});
      const auto described = std::chrono::steady_clock::now();
      const std::span<const double> first(s.positions.data(), 3 * s.num_vertices);
      const auto weights = deformseg::signatures::vertex_area_weights(first, std::span(s.triangles), s.num_vertices);
      c->distances = deformseg::signatures::procrustes_distances(s.positions, weights);
      describe_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - described).count();
    }
    std::cerr << file << ": " << members.size() << " clips\n";
  }
  std::printf("describe (weights and Procrustes distances, sampling not counted): %.2f s, %.1f ms per clip\n",
              describe_seconds, 1e3 * describe_seconds / double(clips.size()));
}

void save(const std::vector<Clip>& clips, const fs::path& path) {
  std::ofstream out(path, std::ios::binary);
  for (const Clip& c : clips) {
    const Eigen::Index n = c.distances.rows();
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(c.distances.data()), std::streamsize(sizeof(double) * n * n));
  }
}

bool load(std::vector<Clip>& clips, const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  for (Clip& c : clips) {
    Eigen::Index n = 0;
    in.read(reinterpret_cast<char*>(&n), sizeof n);
    c.distances.resize(n, n);
    in.read(reinterpret_cast<char*>(c.distances.data()), std::streamsize(sizeof(double) * n * n));
  }
  return bool(in);
}

bool comparable(const Clip& query, const Clip& candidate) {
  return query.file != candidate.file && !(query.rig == candidate.rig && query.clip == candidate.clip);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Mann–Whitney: the chance that a random positive outscores a random negative, ties half.
double roc_auc(std::vector<std::pair<double, bool>> scored) {
  std::sort(scored.begin(), scored.end());
  double rank_sum = 0, positives = 0;
  for (std::size_t i = 0; i < scored.size();) {
    std::size_t j = i;
    while (j < scored.size() && scored[j].first == scored[i].first) ++j;
    const double mid_rank = 0.5 * double(i + 1 + j);
    for (std::size_t k = i; k < j; ++k)
      if (scored[k].second) rank_sum += mid_rank, positives += 1;
    i = j;
  }
  const double negatives = double(scored.size()) - positives;
  return (rank_sum - positives * (positives + 1) / 2) / (positives * negatives);
}

struct Figures {
  double nn = 0, map = 0;
  int queries = 0;
};

// The value of every two clips, by `policy`, from their descriptions.
template <class Policy, class Description>
Eigen::MatrixXd values(const std::vector<Description>& described, const Policy& policy) {
  const std::size_t n = described.size();
  Eigen::MatrixXd value = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  deformseg::internal::parallel_for(n, 0, [&](std::size_t i) {
    for (std::size_t j = i + 1; j < n; ++j)
      value(Eigen::Index(i), Eigen::Index(j)) = value(Eigen::Index(j), Eigen::Index(i)) =
          policy.compare(described[i], described[j]).value;
  });
  return value;
}

// The retrieval figures of `value` (clips x clips), per query body and overall.
void report(const std::vector<Clip>& clips, const Eigen::MatrixXd& value) {
  const std::size_t n = clips.size();

  std::vector<std::pair<double, bool>> pooled;
  std::vector<double> same, different;
  std::map<std::string, Figures> per_body;
  Figures all;
  for (std::size_t q = 0; q < n; ++q) {
    if (clips[q].motion == "-") continue;
    std::vector<std::pair<double, bool>> ranked;  // (-value, relevant), so ascending is best first
    for (std::size_t c = 0; c < n; ++c) {
      if (!comparable(clips[q], clips[c])) continue;
      const bool relevant = clips[c].motion == clips[q].motion;
      const double v = value(Eigen::Index(q), Eigen::Index(c));
      ranked.push_back({-v, relevant});
      pooled.push_back({v, relevant});
      (relevant ? same : different).push_back(v);
    }
    std::stable_sort(ranked.begin(), ranked.end(), [](auto& x, auto& y) { return x.first < y.first; });
    double hits = 0, precision_sum = 0;
    for (std::size_t r = 0; r < ranked.size(); ++r)
      if (ranked[r].second) precision_sum += ++hits / double(r + 1);
    if (hits == 0) continue;  // no relevant candidate: not a query
    Figures& body = per_body[clips[q].file];
    for (Figures* f : {&body, &all}) {
      f->nn += ranked.front().second;
      f->map += precision_sum / hits;
      f->queries += 1;
    }
  }
  for (auto& [body, f] : per_body)
    std::printf("  %-18s queries %3d  NN %.3f  mAP %.3f\n", body.c_str(), f.queries, f.nn / f.queries,
                f.map / f.queries);
  std::printf("ALL queries %d  NN %.3f  mAP %.3f  AUC %.3f  median same %.3f  different %.3f\n", all.queries,
              all.nn / all.queries, all.map / all.queries, roc_auc(pooled), median(same), median(different));
}

// Today's default policy on the same clips, read as meshes (welded); a clip that does not read
// (RobotExpressive until mesh repair lands) is left out of queries and candidates.
int evaluate_default(std::vector<Clip> clips, const fs::path& dir) {
  const similarity::Default_similarity policy;
  std::vector<similarity::Default_similarity::Description> described;
  std::vector<Clip> kept;
  const auto start = std::chrono::steady_clock::now();
  std::map<std::string, std::vector<const Clip*>> by_file;
  for (const Clip& c : clips) by_file[c.file].push_back(&c);
  for (auto& [file, members] : by_file) {
    try {
      io::Gltf_file gltf((dir / file).string());
      for (const Clip* c : members) {
        described.push_back(policy.describe(gltf.read(io::Gltf_read_options{.clip = c->clip, .fps = 30})));
        kept.push_back(*c);
      }
    } catch (const std::exception& e) {
      std::printf("  left out %s: %s\n", file.c_str(), e.what());
    }
  }
  const auto read = std::chrono::steady_clock::now();
  report(kept, values(described, policy));
  const auto done = std::chrono::steady_clock::now();
  std::printf("default policy: read+describe %.1f s, compares %.1f s\n",
              std::chrono::duration<double>(read - start).count(), std::chrono::duration<double>(done - read).count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  similarity::Self_similarity_matching<> policy;
  std::string leave_out, cache;
  bool temporal = false, baseline = false;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--window") policy.options.window = std::stoul(value);
    else if (key == "--quantiles") policy.options.quantiles = std::stoul(value);
    else if (key == "--tolerance") policy.options.tolerance = std::stod(value);
    else if (key == "--profile") temporal = value == "temporal";
    else if (key == "--normalize")
      policy.normalization.length =
          value == "longer" ? similarity::Normalize_by::longer : similarity::Normalize_by::shorter;
    else if (key == "--baseline") baseline = value == "default";
    else if (key == "--leave-out") leave_out = value;
    else if (key == "--cache") cache = value;
    else { std::cerr << "unknown option " << key << "\n"; return 2; }
  }
  const char* env = std::getenv("DEFORMSEG_DATA_DIR");
  const fs::path dir = fs::path(env ? env : DEFORMSEG_DATA_DIR) / "characters";
  std::vector<Clip> clips = read_labels(dir / "motions.csv");
  const auto start = std::chrono::steady_clock::now();
  if (cache.empty() || !load(clips, cache)) {
    read_distances(clips, dir);
    if (!cache.empty()) save(clips, cache);
  }
  const auto read = std::chrono::steady_clock::now();
  std::erase_if(clips, [&](const Clip& c) { return c.file == leave_out; });
  std::vector<similarity::Self_similarity_description> described;
  for (const Clip& c : clips)
    described.push_back({c.distances, temporal ? deformseg::similarity::internal::temporal_profiles(
                                                     c.distances, policy.options.window, policy.options.quantiles)
                                               : deformseg::similarity::internal::row_profiles(
                                                     c.distances, policy.options.window, policy.options.quantiles)});
  const auto profiled = std::chrono::steady_clock::now();
  std::printf("window %zu, quantiles %zu, tolerance %g, left out: %s\n", policy.options.window,
              policy.options.quantiles, policy.options.tolerance, leave_out.empty() ? "none" : leave_out.c_str());
  if (baseline) return evaluate_default(clips, dir);
  const auto compared_start = std::chrono::steady_clock::now();
  const std::size_t n = clips.size();
  report(clips, values(described, policy));
  const auto compared = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("time: read+distances %.1f s, profiles %.2f s, %zu compares %.1f s (%.1f us each)\n",
              seconds(start, read), seconds(read, profiled), n * (n - 1) / 2, seconds(compared_start, compared),
              1e6 * seconds(compared_start, compared) / double(n * (n - 1) / 2));
}
