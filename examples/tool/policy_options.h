// The similarity policy options that the similarity, matrix and evaluate sub-commands share.
#pragma once

#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>

#include <CLI/CLI.hpp>

#include <string>

namespace deformseg::tool {

struct Policy_options {
  std::string policy = "histogram";
  std::string alignment = "smith-waterman";
  double threshold = Spatiotemporal_options{}.threshold;
};

inline void add_policy_options(CLI::App& command, Policy_options& o) {
  command.add_option("--policy", o.policy,
                     "histogram: per-frame histograms of the strain, no correspondence needed (default); "
                     "graph: the thesis' evolving graphs, GED, clustering and label alignment; "
                     "self-similarity: each animation's own frame x frame distances after rigid alignment")
      ->check(CLI::IsMember({"histogram", "graph", "self-similarity"}));
  command.add_option("--alignment", o.alignment,
                     "smith-waterman (local, default), dtw (global) or subsequence-dtw (open begin and end)")
      ->check(CLI::IsMember({"smith-waterman", "dtw", "subsequence-dtw"}));
  command.add_option("--threshold", o.threshold, "graph: the deformed threshold of the segmentation. Default: 0.5");
}

// Calls `run` with the similarity policy the options name.
template <class Run>
auto with_policy(const Policy_options& o, const Run& run) {
  const auto with_alignment = [&](auto aligner) {
    using Aligner = decltype(aligner);
    if (o.policy == "graph") {
      Evolving_graph_similarity<ged::Bipartite_ged, Segment_costs, clustering::K_medoids, Aligner> policy;
      policy.segmentation.threshold = o.threshold;
      return run(policy);
    }
    if (o.policy == "self-similarity") return run(Self_similarity_matching<Aligner>{});
    return run(Strain_distribution_similarity<Aligner>{});
  };
  if (o.alignment == "dtw") return with_alignment(alignment::Dtw{});
  if (o.alignment == "subsequence-dtw") return with_alignment(alignment::Subsequence_dtw{});
  return with_alignment(alignment::Smith_waterman{});
}

}  // namespace deformseg::tool
