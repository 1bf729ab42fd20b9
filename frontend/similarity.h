// The motion similarity as a command and a Python function ask for it: a policy and its
// alignment by name, and the z-score against frame-shuffled copies.
#pragma once

#include "inputs.h"
#include "parameters.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/policy_choice.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <tuple>

namespace deformseg::frontend {

/// The similarity policies, in the order of `similarity::policy_names`.
inline constexpr std::array similarity_policies{
    Choice{"motion-signature", "per-frame distributions of how fast, and how fast up or down, the surface moves at "
                               "several time scales, no correspondence needed (default)"},
    Choice{"histogram", "per-frame histograms of the strain, no correspondence needed; its values crowd near 1 "
                        "(chapter 7 of the manual gives figures): read the z-score or a rank, not the value"},
    Choice{"graph", "the thesis' method: evolving graphs, graph edit distances, clustering and label alignment "
                    "(Smith-Waterman); for bodies that deform alike, as the thesis' animals"},
    Choice{"self-similarity", "each animation's own frame x frame distances after rigid alignment"},
    Choice{"graph-characters", "the evolving graphs with settings tuned on game characters (a fixed strain scale, "
                               "threshold 0.3, parts linked, segments of 6 frames, DTW); not the thesis' method"},
};

/// The alignments, in the order of `similarity::alignment_names`; none given: the policy's own
/// (dtw for motion-signature and graph-characters, smith-waterman for the others).
inline constexpr std::array alignments{
    Choice{"smith-waterman", "local: the best matching parts"},
    Choice{"dtw", "global: both whole"},
    Choice{"subsequence-dtw", "open begin and end"},
};

/// The up directions of the motion signatures, in the order of `similarity::up_names`; none
/// given: +y (glTF's up).
inline constexpr std::array up_directions{
    Choice{"+x", "x up"},     Choice{"-x", "x down"}, Choice{"+y", "y up (default, glTF's)"}, Choice{"-y", "y down"},
    Choice{"+z", "z up"},     Choice{"-z", "z down"}, Choice{"none", "speeds alone, blind to direction"},
};

/// The policy choice's table.
inline constexpr std::tuple policy_parameters{
    choice_parameter("policy", &similarity::Policy_choice::policy, "The similarity policy", similarity_policies),
    choice_parameter("alignment", &similarity::Policy_choice::alignment,
                     "The alignment of the frames. Default: dtw for motion-signature and graph-characters, "
                     "smith-waterman for the others",
                     alignments),
    numeric_parameter("threshold", &similarity::Policy_choice::threshold,
                      "graph, graph-characters: the deformed threshold of the segmentation. Default: 0.5 for graph, "
                      "0.3 for graph-characters",
                      shares),
    choice_parameter("up", &similarity::Policy_choice::up,
                     "motion-signature: the animations' up axis, whose rises and falls the signatures tell apart. "
                     "Default: +y",
                     up_directions),
};

/// The significance of a similarity: its z-score against frame-shuffled copies of the second.
struct Significance_request {
  std::optional<std::size_t> significance{};  ///< copies; none: 20, or 0 for the graph policies
  unsigned seed = 1;
};

/// The significance request's table.
inline constexpr std::tuple significance_parameters{
    numeric_parameter("significance", &Significance_request::significance,
                      "The z-score of the value against this many copies of the second animation with frames "
                      "shuffled (0: none, 1 refused). Default: 20, none for the graph policies",
                      counts(10000)),
    numeric_parameter("seed", &Significance_request::seed, "The seed of the shuffles. Default: 1",
                      counts(4294967295.0)),
};

/// Checks a policy choice's names and combinations before any input is read; the threshold's range
/// is the table's, refused where the value comes in.
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const similarity::Policy_choice& choice, Front front);

/// Checks a significance request, for `choice`, before any input is read.
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Significance_request& request, const similarity::Policy_choice& choice, Front front);

/// A similarity and its significance.
struct Compared {
  similarity::Similarity similarity;
  std::optional<double> z_score;
  std::size_t shuffled_copies = 0;
};

/// How alike `a` and `b` move under `choice` and, for a policy whose frames can be shuffled,
/// the z-score of the value against shuffled copies of `b` as `significance` asks.
Compared compare(const mesh::Surface_mesh_animation& a, const mesh::Surface_mesh_animation& b,
                 const similarity::Policy_choice& choice, const Significance_request& significance);

/// What reading an input frame by frame found.
struct Streamed_input {
  std::size_t frames = 0;  ///< its frames
  Outliers outliers{};     ///< its outlying vertices (`check_outliers`)
};

/// `compare` of the animations that `inputs` name, each read frame by frame: the motion-signature
/// policy describes a stream holding the frames its longest lag spans, not the whole animation
/// (a point cache with its topology, a frame sequence; neither welded, since welding compares every
/// frame), with the same result as `compare` of the animations read whole. `streamed` gets their
/// frame counts and outlying vertices (refused with `options.refuse_defects`).
/// @return nullopt, having described nothing, when an input must be read whole: another policy, a
/// glTF file, a welded input, a point cache without topology, an animation of fewer than 2 frames.
/// @throws invalid_input naming the file or the frame that cannot be read.
std::optional<Compared> compare_streamed(const std::array<std::string, 2>& inputs, const Input_options& options,
                                         const similarity::Policy_choice& choice,
                                         const Significance_request& significance, Front front,
                                         std::array<Streamed_input, 2>& streamed);

/// A similarity as a report: {"policy", "alignment_policy", "similarity", "score", "labels_a",
/// "labels_b", "alignment": [[i, j], ...], "compared", "z_score" (or null), "shuffled_copies"}.
nlohmann::json similarity_record(const Compared& compared, const similarity::Policy_choice& choice);

}  // namespace deformseg::frontend
