// How much each lower bound of search/motion_bounds.h would prune in a top-k search over the
// shared characters (motions.csv). Not a Google Benchmark:
//
//   build/test/bench/motion_bounds_pruning [--every S] [-k K] [--chunks C] [--threads T]
//
// Every S-th clip of the labels (default 1: all 362) is described by the default policy, its
// signatures rounded to floats and summarised (C chunks, default 4; T threads compute the values,
// default 2). Every clip is a query against all the
// others (compare(query, candidate)); the k-th best value of its row (default k = 10) is the v_k of
// the pruning rule. For each bound alone, and for the cascades, the share of (query, candidate)
// pairs it prunes (`!may_beat(bound, v_k)`), beside the share any exact bound could prune (the
// candidates whose value is below v_k), the mean bound and the time per call. It also checks that
// no bound exceeds D (and says so: a bench asserts nothing, but a violation would be printed).
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include "../motion_bounds_reference.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace deformseg;
namespace fs = std::filesystem;
using signatures::Motion_signature_view;

namespace {

struct Options {
  std::size_t every = 1, k = 10, chunks = 4;
  int threads = 2;
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string name = argv[i];
    const unsigned long value = std::stoul(argv[i + 1]);
    if (name == "--every") options.every = std::max(1ul, value);
    else if (name == "-k") options.k = std::max(1ul, value);
    else if (name == "--chunks") options.chunks = std::max(1ul, value);
    else if (name == "--threads") options.threads = int(std::max(1ul, value));
    else throw std::invalid_argument("unknown option " + name);
  }
  return options;
}

std::vector<Eigen::MatrixXf> described_clips(const fs::path& dir, std::size_t every) {
  std::ifstream labels(dir / "motions.csv");
  if (!labels) throw std::runtime_error("no " + (dir / "motions.csv").string());
  std::string line;
  std::getline(labels, line);
  const similarity::Motion_signature_similarity<> policy;
  std::vector<Eigen::MatrixXf> clips;
  for (std::size_t index = 0; std::getline(labels, line); ++index) {
    if (index % every != 0) continue;
    std::stringstream fields(line);
    std::string file, clip;
    std::getline(fields, file, ',');
    std::getline(fields, clip, ',');
    if (file.empty()) continue;
    const auto animation = io::read_animation((dir / file).string(), {.clip = clip});
    clips.push_back(policy.describe(animation).signatures.cast<float>());
  }
  return clips;
}

Motion_signature_view view_of(const Eigen::MatrixXf& m) {
  return {m.data(), std::size_t(m.rows()), std::size_t(m.cols())};
}

// The rows bound with each query row's own bound (row_bounds: the row against the candidate's
// chunk boxes) instead of its chunk's: what the exact pass's row bounds give before its first row.
double per_row_bound(const Motion_signature_view& a, const search::Motion_summary_view& b, double unit) {
  std::vector<double> r(a.rows);
  search::row_bounds(a, b, unit, r);
  const std::size_t n = a.rows, m = b.rows();
  const double d00 = r[0], d_last = r[n - 1];  // no exact corners here: the row bounds alone
  if (n == 1) return r[0];
  double sum = d00 + d_last, rho = *std::min_element(r.begin(), r.end());
  for (std::size_t i = 1; i + 1 < n; ++i) sum += r[i];
  const auto mean_at = [&](std::size_t length) { return (sum + double(length - n) * rho) / double(length); };
  return std::min(mean_at(std::max(n, m)), mean_at(n + m - 1));
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  const char* data = std::getenv("DEFORMSEG_DATA_DIR");
  const fs::path dir = fs::path(data && *data ? data : DEFORMSEG_DATA_DIR) / "characters";
  const auto clips = described_clips(dir, options.every);
  const std::size_t count = clips.size();
  if (count <= options.k) throw std::runtime_error("fewer clips than k + 1");
  const double unit = signatures::frame_dissimilarity_unit(std::size_t(clips[0].cols()),
                                                           similarity::Motion_signature_similarity<>{}.scale);
  std::vector<search::Motion_summary> summaries;
  std::size_t rows = 0;
  for (const auto& c : clips)
    summaries.push_back(search::summarize(view_of(c), options.chunks)), rows += std::size_t(c.rows());
  std::printf("%zu clips, %.1f rows on average, width %lld, k = %zu, %zu chunks\n", count,
              double(rows) / double(count), static_cast<long long>(clips[0].cols()), options.k, options.chunks);

  // Every (query, candidate) value by brute force.
  std::vector<double> dissimilarity(count * count);
  internal::parallel_for(count, options.threads, [&](std::size_t q) {
    for (std::size_t c = 0; c < count; ++c)
      dissimilarity[q * count + c] =
          test::dtw_mean(test::reference_dissimilarities(view_of(clips[q]), view_of(clips[c]), unit));
  });

  using Bound = std::function<double(std::size_t, std::size_t)>;
  const auto summary = [&](std::size_t i) { return summaries[i].view(); };
  const std::vector<std::pair<std::string, Bound>> bounds{
      {"lb_box", [&](std::size_t q, std::size_t c) { return search::lb_box(summary(q), summary(c), unit); }},
      {"lb_mean", [&](std::size_t q, std::size_t c) { return search::lb_mean(summary(q), summary(c), unit); }},
      {"lb_rows_columns",
       [&](std::size_t q, std::size_t c) { return search::lb_rows_columns(summary(q), summary(c), unit); }},
      {"max(box, rows_columns)",
       [&](std::size_t q, std::size_t c) {
         return std::max(search::lb_box(summary(q), summary(c), unit),
                         search::lb_rows_columns(summary(q), summary(c), unit));
       }},
      {"max(box, mean, rows_columns)",
       [&](std::size_t q, std::size_t c) {
         return std::max({search::lb_box(summary(q), summary(c), unit),
                          search::lb_mean(summary(q), summary(c), unit),
                          search::lb_rows_columns(summary(q), summary(c), unit)});
       }},
      {"per-row (row_bounds)",
       [&](std::size_t q, std::size_t c) { return per_row_bound(view_of(clips[q]), summary(c), unit); }},
  };

  // Per query, v_k: the k-th best value among the other clips.
  std::vector<double> kth(count);
  std::size_t prunable = 0, pairs = 0;
  for (std::size_t q = 0; q < count; ++q) {
    std::vector<double> values;
    for (std::size_t c = 0; c < count; ++c)
      if (c != q) values.push_back(1 - dissimilarity[q * count + c]);
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(options.k - 1), values.end(), std::greater<>());
    kth[q] = values[options.k - 1];
    for (const double v : values) prunable += v < kth[q], ++pairs;
  }
  std::printf("pairs %zu; below v_k (what an exact bound could prune at most): %.1f %%\n", pairs,
              100.0 * double(prunable) / double(pairs));
  std::printf("%-30s %9s %11s %11s %10s\n", "bound", "pruned", "mean bound", "mean D", "ns/call");
  std::vector<std::vector<char>> pruned_by(bounds.size(), std::vector<char>(count * count, 0));
  for (std::size_t b = 0; b < bounds.size(); ++b) {
    std::size_t pruned = 0, violations = 0;
    double sum_bound = 0, sum_d = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t q = 0; q < count; ++q)
      for (std::size_t c = 0; c < count; ++c) {
        if (c == q) continue;
        const double bound = bounds[b].second(q, c), d = dissimilarity[q * count + c];
        violations += bound > d * (1 + 0x1p-40) + 0x1p-50;
        sum_bound += bound, sum_d += d;
        const bool prune = !search::may_beat(bound, kth[q]);
        pruned += prune;
        pruned_by[b][q * count + c] = prune;
      }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-30s %8.1f%% %11.4f %11.4f %10.0f%s\n", bounds[b].first.c_str(),
                100.0 * double(pruned) / double(pairs), sum_bound / double(pairs), sum_d / double(pairs),
                1e9 * seconds / double(pairs), violations ? "  BOUND ABOVE D" : "");
  }
  // What each bound adds over lb_box: pairs it prunes that lb_box does not.
  for (std::size_t b = 1; b < bounds.size(); ++b) {
    std::size_t beyond = 0;
    for (std::size_t p = 0; p < count * count; ++p) beyond += pruned_by[b][p] && !pruned_by[0][p];
    std::printf("%-30s prunes %.2f %% of the pairs that lb_box does not\n", bounds[b].first.c_str(),
                100.0 * double(beyond) / double(pairs));
  }
  std::size_t mean_beyond = 0;
  for (std::size_t p = 0; p < count * count; ++p) mean_beyond += pruned_by[1][p] && !pruned_by[3][p];
  std::printf("lb_mean prunes %.2f %% of the pairs that max(box, rows_columns) does not\n",
              100.0 * double(mean_beyond) / double(pairs));
  return 0;
}
