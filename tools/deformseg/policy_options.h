// The similarity policy options that the similarity, matrix and evaluate sub-commands share: the
// command-line face of deformseg::similarity::Policy_choice.
#pragma once

#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/policy_choice.h>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace deformseg::tool {

using Policy_options = similarity::Policy_choice;

inline void add_policy_options(CLI::App& command, Policy_options& o) {
  const auto names = [](const auto& list) { return std::vector<std::string>(list.begin(), list.end()); };
  command.add_option("--policy", o.policy,
                     "motion-signature: per-frame distributions of how fast, and how fast up or down, the surface "
                     "moves at several time scales, no correspondence needed (default); "
                     "histogram: per-frame histograms of the strain, no correspondence needed; its values crowd "
                     "near 1 (the Knight's Walking_A against a frozen copy of itself 0.997, against its Death_A "
                     "0.996): read the z-score or a rank, not the value; "
                     "graph: the thesis' evolving graphs, GED, clustering and label alignment; "
                     "self-similarity: each animation's own frame x frame distances after rigid alignment")
      ->check(CLI::IsMember(names(similarity::policy_names)));
  command.add_option("--alignment", o.alignment,
                     "smith-waterman (local), dtw (global) or subsequence-dtw (open begin and end). Default: dtw for "
                     "motion-signature, smith-waterman for the others")
      ->check(CLI::IsMember(names(similarity::alignment_names)));
  command
      .add_option("--threshold", o.threshold,
                  "graph: the deformed threshold of the segmentation, in [0, 1]. Default: 0.5")
      ->check(CLI::Range(0.0, 1.0));
  command.add_option("--up", o.up,
                     "motion-signature: the animations' up axis, whose rises and falls the signatures tell apart; "
                     "none: speeds alone, blind to direction. Default: +y (glTF's up)")
      ->check(CLI::IsMember(names(similarity::up_names)));
}

}  // namespace deformseg::tool
