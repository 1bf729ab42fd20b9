// The nearest-motion search at three sizes of collection, against the brute force measured in the
// same run. Not a Google Benchmark, since the collections take minutes to make:
//
//   build/test/bench/nearest_motions_sizes [--sizes 1000,10000,100000] [--queries 20] [--k 10]
//       [--threads 2] [--brute 2000] [--knn-graph N] [--cache PATH]
//
// The collections are made from the shared characters' clips (motions.csv), each described once
// by the default policy (--cache keeps those descriptions in a file outside the repository).
// Clip c of a collection is made from a source clip drawn with seed c: a random crop keeping
// 70 to 100 % of it, time-warped by a monotone piecewise-linear map of 4 pieces whose local rates
// are drawn in [0.7, 1.4], resampled by linear interpolation of the rows to 120 to 180 rows, and
// perturbed by Gaussian noise of standard deviation 0.05 per value. The collections of each size
// are prefixes of one sequence, and the queries are made the same way from seeds no clip uses.
// Reported per size: the mean time of a query, candidates per second, the share of candidates
// each stage rules out, and the brute force (every candidate aligned, on --brute candidates,
// scaled to the collection) as the baseline.
#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/io/gltf.h>
#include <deformseg/search/nearest_motions.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/similarity/motion_similarity.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace deformseg;
using similarity::Motion_signature_description;
namespace fs = std::filesystem;

namespace {

struct Settings {
  std::vector<std::size_t> sizes{1000, 10000, 100000};
  std::size_t queries = 20, k = 10, brute = 2000, knn_graph = 0;
  int threads = 2;
  fs::path cache;
};

Settings parse(int argc, char** argv) {
  Settings s;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--sizes") {
      s.sizes.clear();
      std::stringstream list(value);
      for (std::string size; std::getline(list, size, ',');) s.sizes.push_back(std::stoul(size));
    } else if (flag == "--queries") s.queries = std::stoul(value);
    else if (flag == "--k") s.k = std::stoul(value);
    else if (flag == "--threads") s.threads = std::stoi(value);
    else if (flag == "--brute") s.brute = std::stoul(value);
    else if (flag == "--knn-graph") s.knn_graph = std::stoul(value);
    else if (flag == "--cache") s.cache = value;
    else throw std::runtime_error("unknown option " + flag);
  }
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<Motion_signature_description> describe_shared_clips() {
  const fs::path labels = fs::path(DEFORMSEG_DATA_DIR) / "characters" / "motions.csv";
  std::map<std::string, std::vector<std::string>> clips_of_file;
  for (const auto& clip : evaluation::read_motion_labels(labels)) clips_of_file[clip.file.string()].push_back(clip.item.clip);
  const similarity::Default_similarity policy;
  std::vector<Motion_signature_description> described;
  for (const auto& [file, clips] : clips_of_file) {
    io::Gltf_file gltf(file);
    for (const std::string& clip : clips) {
      const io::Sampled_gltf s = gltf.sample(io::Gltf_read_options{.clip = clip, .fps = 30});
      const std::span<const double> first(s.positions.data(), 3 * s.num_vertices);
      const auto weights = signatures::vertex_area_weights(first, std::span(s.triangles), s.num_vertices);
      described.push_back(policy.describe_positions(std::span<const double>(s.positions), weights, 30.0));
    }
  }
  return described;
}

void save(const std::vector<Motion_signature_description>& clips, const fs::path& path) {
  std::ofstream out(path, std::ios::binary);
  for (const auto& c : clips) {
    const Eigen::Index size[2] = {c.signatures.rows(), c.signatures.cols()};
    out.write(reinterpret_cast<const char*>(size), sizeof size);
    out.write(reinterpret_cast<const char*>(c.signatures.data()), std::streamsize(sizeof(float) * size[0] * size[1]));
  }
}

std::vector<Motion_signature_description> load(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<Motion_signature_description> clips;
  Eigen::Index size[2];
  while (in.read(reinterpret_cast<char*>(size), sizeof size)) {
    Motion_signature_description d;
    d.signatures.resize(size[0], size[1]);
    in.read(reinterpret_cast<char*>(d.signatures.data()), std::streamsize(sizeof(float) * size[0] * size[1]));
    for (Eigen::Index r = 0; r < size[0]; ++r) d.frames.push_back(std::size_t(r));
    clips.push_back(std::move(d));
  }
  return clips;
}

// The source clip's rows at fractional row x, linearly interpolated.
Eigen::RowVectorXf row_at(const Eigen::MatrixXf& rows, double x) {
  const auto last = double(rows.rows() - 1);
  x = std::clamp(x, 0.0, last);
  const auto below = Eigen::Index(x);
  const Eigen::Index above = std::min<Eigen::Index>(below + 1, rows.rows() - 1);
  const auto t = float(x - double(below));
  return (1 - t) * rows.row(below) + t * rows.row(above);
}

// Synthetic clip number `seed`, made as the header says.
Motion_signature_description synthetic_clip(const std::vector<Motion_signature_description>& sources,
                                            std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const auto& source = sources[std::uniform_int_distribution<std::size_t>(0, sources.size() - 1)(random)].signatures;
  const double length = double(source.rows() - 1);
  const double kept = std::uniform_real_distribution<double>(0.7, 1.0)(random) * length;
  const double start = std::uniform_real_distribution<double>(0.0, length - kept)(random);
  // Four pieces of the output's time, each at its own rate: knots of the source time.
  std::uniform_real_distribution<double> rate(0.7, 1.4);
  std::vector<double> knots{0.0};
  for (int piece = 0; piece < 4; ++piece) knots.push_back(knots.back() + rate(random));
  const auto rows = Eigen::Index(std::uniform_int_distribution<int>(120, 180)(random));
  std::normal_distribution<float> noise(0.0f, 0.05f);
  Motion_signature_description d;
  d.signatures.resize(rows, source.cols());
  for (Eigen::Index r = 0; r < rows; ++r) {
    const double u = 4.0 * double(r) / double(rows - 1);  // output time in pieces
    const auto piece = std::min<std::size_t>(3, std::size_t(u));
    const double warped = knots[piece] + (u - double(piece)) * (knots[piece + 1] - knots[piece]);
    d.signatures.row(r) = row_at(source, start + kept * warped / knots.back());
    for (Eigen::Index k = 0; k < source.cols(); ++k) d.signatures(r, k) += noise(random);
    d.frames.push_back(std::size_t(r));
  }
  return d;
}

void report_size(const search::Motion_collection& collection, const std::vector<Motion_signature_description>& queries,
                 const Settings& s) {
  search::Pruning_report total;
  const auto start = std::chrono::steady_clock::now();
  for (const auto& q : queries)
    total += search::nearest_motions(similarity::view(q), collection, {.k = s.k, .threads = s.threads}).pruning;
  const double per_query = seconds_since(start) / double(queries.size());
  // The baseline: the first `brute` candidates of the first query, every one aligned whole.
  const std::size_t brute = std::min(s.brute, collection.size());
  const similarity::Default_similarity policy;
  std::vector<double> values(brute);
  const auto brute_start = std::chrono::steady_clock::now();
  deformseg::internal::parallel_for(brute, s.threads, [&](std::size_t c) {
    values[c] = policy.compare(queries.front(), collection.description(c)).value;
  });
  const double brute_per_query = seconds_since(brute_start) * double(collection.size()) / double(brute);
  const double n = double(total.candidates);
  std::printf("%8zu clips: %8.4f s a query (%.3g candidates/s), brute force %8.3f s (x%.1f); ruled out: "
              "summary %.1f %%, rows %.1f %%, abandoned %.1f %% (at %.0f %% of their rows), aligned %.2f %%\n",
              collection.size(), per_query, double(collection.size()) / per_query, brute_per_query,
              brute_per_query / per_query, 100 * double(total.pruned_by_summary) / n,
              100 * double(total.pruned_by_rows) / n, 100 * double(total.abandoned) / n,
              total.rows_abandoned ? 100 * double(total.rows_aligned) / double(total.rows_abandoned) : 0.0,
              100 * double(total.aligned) / n);
}

}  // namespace

int main(int argc, char** argv) try {
  const Settings s = parse(argc, argv);
  auto start = std::chrono::steady_clock::now();
  std::vector<Motion_signature_description> sources;
  if (!s.cache.empty() && fs::exists(s.cache)) sources = load(s.cache);
  if (sources.empty()) {
    sources = describe_shared_clips();
    if (!s.cache.empty()) save(sources, s.cache);
  }
  std::printf("%zu shared clips described or loaded in %.1f s\n", sources.size(), seconds_since(start));
  std::vector<Motion_signature_description> queries;
  for (std::size_t q = 0; q < s.queries; ++q) queries.push_back(synthetic_clip(sources, (std::uint64_t(1) << 40) + q));
  search::Motion_collection collection;
  start = std::chrono::steady_clock::now();
  for (std::size_t size : s.sizes) {
    while (collection.size() < size) collection.add(synthetic_clip(sources, collection.size()));
    std::printf("collection of %zu clips made in %.1f s\n", size, seconds_since(start));
    report_size(collection, queries, s);
  }
  if (s.knn_graph > 0) {
    search::Motion_collection graph_clips;
    for (std::size_t c = 0; c < s.knn_graph; ++c) graph_clips.add(synthetic_clip(sources, c));
    start = std::chrono::steady_clock::now();
    const auto graph = search::knn_graph(graph_clips, {.k = s.k, .threads = s.threads});
    search::Pruning_report total;
    for (const auto& row : graph) total += row.pruning;
    std::printf("knn graph of %zu clips, k = %zu: %.1f s; %.2f %% of the pairs aligned\n", s.knn_graph, s.k,
                seconds_since(start), 100 * double(total.aligned) / double(total.candidates));
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "nearest_motions: " << e.what() << '\n';
  return 1;
}
