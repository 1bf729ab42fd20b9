// The similarity policy options that the similarity, matrix and evaluate sub-commands share.
#pragma once

#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/motion_similarity.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace deformseg::tool {

struct Policy_options {
  std::string policy = "motion-signature";
  std::string alignment{};  // empty: the policy's own (DTW for motion-signature, else Smith-Waterman)
  std::optional<double> threshold{};  // the graph policy's only; none given: its default
  std::string up{};                   // the motion signatures' only; empty: their default, +y
};

inline void add_policy_options(CLI::App& command, Policy_options& o) {
  command.add_option("--policy", o.policy,
                     "motion-signature: per-frame distributions of how fast the surface moves at several time "
                     "scales, no correspondence needed (default); "
                     "histogram: per-frame histograms of the strain, no correspondence needed; "
                     "graph: the thesis' evolving graphs, GED, clustering and label alignment; "
                     "self-similarity: each animation's own frame x frame distances after rigid alignment")
      ->check(CLI::IsMember({"motion-signature", "histogram", "graph", "self-similarity"}));
  command.add_option("--alignment", o.alignment,
                     "smith-waterman (local), dtw (global) or subsequence-dtw (open begin and end). Default: dtw for "
                     "motion-signature, smith-waterman for the others")
      ->check(CLI::IsMember({"smith-waterman", "dtw", "subsequence-dtw"}));
  command.add_option("--threshold", o.threshold, "graph: the deformed threshold of the segmentation, in [0, 1]. Default: 0.5")
      ->check(CLI::Range(0.0, 1.0));
  command.add_option("--up", o.up,
                     "motion-signature: the animations' up axis, whose rises and falls the signatures tell apart; "
                     "none: speeds alone, blind to direction. Default: +y (glTF's up)")
      ->check(CLI::IsMember({"+x", "-x", "+y", "-y", "+z", "-z", "none"}));
}

// The up direction an --up value names (+y when none is given), std::nullopt for "none".
inline std::optional<Eigen::Vector3d> up_direction(const std::string& up) {
  if (up == "none") return std::nullopt;
  if (up.empty()) return Eigen::Vector3d::UnitY();
  const double sign = up[0] == '-' ? -1.0 : 1.0;
  return sign * Eigen::Vector3d::Unit(up[1] - 'x');
}

// Refuses, before anything is read, options that the chosen policy does not take.
inline void check_policy_options(const Policy_options& o) {
  if (o.threshold && o.policy != "graph")
    throw invalid_input("--threshold applies to the graph policy only, not to --policy " + o.policy);
  if (!o.up.empty() && o.policy != "motion-signature")
    throw invalid_input("--up applies to the motion-signature policy only, not to --policy " + o.policy);
}

// The alignment the options name, or the policy's own when they name none.
inline std::string alignment_name(const Policy_options& o) {
  if (!o.alignment.empty()) return o.alignment;
  return o.policy == "motion-signature" ? "dtw" : "smith-waterman";
}

// Calls `run` with the similarity policy the options name.
template <class Run>
auto with_policy(const Policy_options& o, const Run& run) {
  const auto with_alignment = [&](auto aligner) {
    using Aligner = decltype(aligner);
    if (o.policy == "graph") {
      Evolving_graph_similarity<ged::Bipartite_ged, Segment_costs, clustering::K_medoids, Aligner> policy;
      policy.segmentation.threshold = o.threshold.value_or(policy.segmentation.threshold);
      return run(policy);
    }
    if (o.policy == "self-similarity") return run(Self_similarity_matching<Aligner>{});
    if (o.policy == "histogram") return run(Strain_distribution_similarity<Aligner>{});
    Motion_signature_similarity<Aligner> policy;
    policy.signatures.up = up_direction(o.up);
    return run(policy);
  };
  const std::string alignment = alignment_name(o);
  if (alignment == "dtw") return with_alignment(alignment::Dtw{});
  if (alignment == "subsequence-dtw") return with_alignment(alignment::Subsequence_dtw{});
  return with_alignment(alignment::Smith_waterman{});
}

}  // namespace deformseg::tool
