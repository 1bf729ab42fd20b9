/// @file similarity/policy_choice.h
/// @brief `with_policy_choice`: a similarity policy and its alignment chosen by name, as the user of
/// a program gives them (the `deformseg` tool's `--policy`, `--alignment`, `--threshold` and
/// `--up`; the Python module's keywords of the same names).
#pragma once

#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/exceptions.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/strain_distribution_similarity.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace deformseg::similarity {

/// @brief The names of the similarity policies: `Motion_signature_similarity` (the default),
/// `Strain_distribution_similarity`, `Evolving_graph_similarity` (the thesis'),
/// `Self_similarity_matching` and `character_graph_similarity` (the graphs tuned on game characters).
inline constexpr std::array<std::string_view, 5> policy_names{"motion-signature", "histogram", "graph",
                                                              "self-similarity", "graph-characters"};
/// @brief The names of the alignments: `alignment::Smith_waterman`, `alignment::Dtw`,
/// `alignment::Subsequence_dtw`.
inline constexpr std::array<std::string_view, 3> alignment_names{"smith-waterman", "dtw", "subsequence-dtw"};
/// @brief The names of the up directions of the motion signatures; "none" for speeds alone.
inline constexpr std::array<std::string_view, 7> up_names{"+x", "-x", "+y", "-y", "+z", "-z", "none"};

/// @brief A similarity policy chosen by name, with the options a user may set; an aggregate for
/// designated initializers. Every other parameter is the policy's default.
struct Policy_choice {
  /// @brief One of `policy_names`. Default "motion-signature", `Default_similarity`.
  std::string policy = "motion-signature";
  /// @brief One of `alignment_names`, or empty (the default) for the policy's own: DTW for the
  /// motion signatures and the character graphs, Smith–Waterman for the others.
  std::string alignment{};
  /// @brief A graph policy's deformed threshold, in [0, 1]; none (the default): its own, 0.5 for
  /// "graph" and 0.3 for "graph-characters".
  std::optional<double> threshold{};
  /// @brief The motion signatures' up direction, one of `up_names`; empty (the default): +y.
  std::string up{};
};

/// @brief The alignment `choice` names, or the policy's own when it names none.
/// @par Complexity O(1).
inline std::string alignment_name(const Policy_choice& choice) {
  if (!choice.alignment.empty()) return choice.alignment;
  return choice.policy == "motion-signature" || choice.policy == "graph-characters" ? "dtw" : "smith-waterman";
}

/// @brief Whether `policy` names one of the evolving-graph policies ("graph", "graph-characters"),
/// whose frames are key-frame labels.
/// @par Complexity O(1).
inline bool is_graph_policy(std::string_view policy) { return policy == "graph" || policy == "graph-characters"; }

/// @brief The up direction an `up_names` entry names (+y when empty), `std::nullopt` for "none".
/// @throws invalid_input for a name not in `up_names`.
/// @par Complexity O(1).
/// @par Example
/// @include check_policy_choice.cpp
inline std::optional<Eigen::Vector3d> up_direction(const std::string& up) {
  if (up.empty()) return Eigen::Vector3d::UnitY();
  if (std::ranges::find(up_names, up) == up_names.end())
    throw invalid_input("unknown up direction '" + up + "': expected +x, -x, +y, -y, +z, -z or none");
  if (up == "none") return std::nullopt;
  return (up[0] == '-' ? -1.0 : 1.0) * Eigen::Vector3d::Unit(up[1] - 'x');
}

/// @brief Checks a choice before any input is read.
/// @throws invalid_input naming the option: an unknown policy, alignment or up direction, a
/// threshold with another policy than a graph one or outside [0, 1], an up direction with
/// another policy than the motion signatures.
/// @par Complexity O(1).
/// @par Example
/// @include check_policy_choice.cpp
inline void check_policy_choice(const Policy_choice& choice) {
  const auto listed = [](const auto& names) {
    std::string list;
    for (const std::string_view name : names) list += (list.empty() ? "" : ", ") + std::string(name);
    return list;
  };
  if (std::ranges::find(policy_names, choice.policy) == policy_names.end())
    throw invalid_input("unknown policy '" + choice.policy + "': expected " + listed(policy_names));
  const std::string alignment = alignment_name(choice);
  if (std::ranges::find(alignment_names, alignment) == alignment_names.end())
    throw invalid_input("unknown alignment '" + alignment + "': expected " + listed(alignment_names));
  if (choice.threshold && !is_graph_policy(choice.policy))
    throw invalid_input("threshold applies to the graph policies only, not to the " + choice.policy + " policy");
  if (choice.threshold && !(*choice.threshold >= 0 && *choice.threshold <= 1))
    throw invalid_input("threshold must be in [0, 1], not " + std::to_string(*choice.threshold));
  if (!choice.up.empty() && choice.policy != "motion-signature")
    throw invalid_input("up applies to the motion-signature policy only, not to the " + choice.policy + " policy");
  up_direction(choice.up);
}

/// @brief Calls `run(policy)` with the similarity policy `choice` names, its alignment and
/// options set, and returns what `run` returns (the same type for every policy).
///
/// @code
/// const Similarity s = with_policy_choice({.policy = "histogram", .alignment = "dtw"},
///                                         [&](const auto& policy) { return motion_similarity(a, b, policy); });
/// @endcode
/// @throws invalid_input as `check_policy_choice`, before `run` is called.
/// @par Complexity that of `run`; the choice costs O(1).
template <class Run>
auto with_policy_choice(const Policy_choice& choice, const Run& run) {
  check_policy_choice(choice);
  const auto with_alignment = [&](auto aligner) {
    using Aligner = decltype(aligner);
    if (is_graph_policy(choice.policy)) {
      auto policy = character_graph_similarity<Aligner>();
      if (choice.policy == "graph") policy.segmentation = thesis_segmentation();
      policy.segmentation.threshold = choice.threshold.value_or(policy.segmentation.threshold);
      return run(policy);
    }
    if (choice.policy == "self-similarity") return run(Self_similarity_matching<Aligner>{});
    if (choice.policy == "histogram") return run(Strain_distribution_similarity<Aligner>{});
    Motion_signature_similarity<Aligner> policy;
    policy.signatures.up = up_direction(choice.up);
    return run(policy);
  };
  const std::string alignment = alignment_name(choice);
  if (alignment == "dtw") return with_alignment(alignment::Dtw{});
  if (alignment == "subsequence-dtw") return with_alignment(alignment::Subsequence_dtw{});
  return with_alignment(alignment::Smith_waterman{});
}

}  // namespace deformseg::similarity
