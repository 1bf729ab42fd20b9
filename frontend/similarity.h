// The motion similarity as a command and a Python function ask for it: a policy and its
// alignment by name (the one table of the policies, their rules and defaults, which makes the
// library's policy types), and the z-score against frame-shuffled copies.
#pragma once

#include "inputs.h"
#include "parameters.h"
#include "registry.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/similarity/any_policy.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/threads.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

namespace deformseg::frontend {

/// A similarity policy as a user chooses it: by name, with the options a user may set (the tool's
/// --policy, --alignment, --threshold, --up, --bands and --sides; Python's keywords of the same names); every other
/// parameter is the policy's default. An aggregate, for designated initializers.
struct Policy_choice {
  std::string policy{similarity_policies[0].name};  ///< one of `similarity_policies`; default: the first
  std::string alignment{};            ///< one of `similarity_alignments`; empty: the policy's own
  std::optional<double> threshold{};  ///< a graph policy's deformed threshold; none: the policy's own
  std::string up{};                   ///< one of `up_directions`; empty: +y
  std::optional<std::size_t> bands{};  ///< the motion signatures' height bands; none: 1
  std::string sides{};                 ///< one of `side_directions`; empty: the whole width
};

/// The up direction a name of `up_directions` gives (+y for an empty name), none for "none".
/// @pre `name` is empty or one of `up_directions`.
std::optional<Eigen::Vector3d> up_direction(std::string_view name);

/// The direction across the body a name of `side_directions` gives; none for an empty name.
/// @pre `name` is empty or one of `side_directions`.
std::optional<Eigen::Vector3d> side_direction(std::string_view name);

/// The policy choice's table.
inline constexpr std::tuple policy_parameters{
    choice_parameter("policy", &Policy_choice::policy, "The similarity policy", policy_choices),
    optional_choice_parameter("alignment", &Policy_choice::alignment,
                              "The alignment of the frames. Default: dtw for motion-signature and graph-characters, "
                              "smith-waterman for the others",
                              alignment_choices),
    numeric_parameter("threshold", &Policy_choice::threshold,
                      "graph, graph-characters: the deformed threshold of the segmentation. Default: 0.5 for graph, "
                      "0.3 for graph-characters",
                      shares),
    optional_choice_parameter("up", &Policy_choice::up,
                              "motion-signature: the animations' up axis, whose rises and falls the signatures "
                              "tell apart. Default: +y",
                              up_direction_choices),
    numeric_parameter("bands", &Policy_choice::bands,
                      "motion-signature: the surface cut into this many bands of equal height in the first pose, "
                      "each compared with the band at its height, so that a big head does not outweigh the legs "
                      "(3 or 4 for a library of many studios or body plans: chapter 7 of the manual). Default: 1",
                      positive_counts(double(signatures::max_bands))),
    optional_choice_parameter("sides", &Policy_choice::sides,
                              "motion-signature: keep the two sides of the body apart, cut at its centre along "
                              "this axis across it, so that a motion and its mirror image (a left and a right "
                              "kick) differ. Default: none, the two alike",
                              side_direction_choices),
};

/// The entry of `similarity_policies` that `choice` names.
/// @pre `check(choice, front)` passed; else `std::logic_error`.
const Policy_entry& policy_entry(const Policy_choice& choice);

/// The name of the alignment of `choice`: its own, or its policy's.
/// @pre as `policy_entry`.
std::string alignment_name(const Policy_choice& choice);

/// The library's policy that `choice` names, aligning by its alignment, with its threshold (or the
/// policy's) and up direction, its own loops (describing, and a graph policy's edit distances and
/// clustering) on `threads` threads (0: all; a loop inside another parallel loop, as a similarity
/// matrix's pairs, runs on one); every other parameter at the library's default.
/// @pre as `policy_entry`; `threads` in [0, max_threads], else the policy refuses it when used.
similarity::Any_policy make_policy(const Policy_choice& choice, int threads = 0);

/// What a comparison reports besides its value: the z-score against frame-shuffled copies of the
/// second animation, and on request where the motion signatures differ.
struct Comparison_request {
  std::optional<std::size_t> significance{};  ///< copies; none: 20, or 0 for the graph policies
  unsigned seed = 1;
  bool explain = false;  ///< the motion signatures' channels along the alignment (`Compared::explanation`)
};

/// The comparison request's table.
inline constexpr std::tuple comparison_parameters{
    numeric_parameter("significance", &Comparison_request::significance,
                      "The z-score of the value against this many copies of the second animation with frames "
                      "shuffled (0: none, 1 refused). Default: 20, none for the graph policies",
                      counts(10000)),
    numeric_parameter("seed", &Comparison_request::seed, "The seed of the shuffles. Default: 1",
                      counts(4294967295.0)),
    Parameter<Comparison_request, bool>{
        "explain", &Comparison_request::explain,
        "motion-signature: say which time scales, height bands and halves of the surface made the two alike or "
        "different, each channel's share of the difference along the alignment"},
};

/// Checks a policy choice's names and combinations before any input is read: the one check of the
/// names (the tool's options and Python's keywords give its words); the threshold's range is the
/// table's, refused where the value comes in.
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Policy_choice& choice, Front front);

/// Checks a comparison request, for `choice`, before any input is read.
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Comparison_request& request, const Policy_choice& choice, Front front);

/// A similarity, its significance and, on request, where the motion signatures differ.
struct Compared {
  similarity::Similarity similarity;
  std::optional<double> z_score;
  std::size_t shuffled_copies = 0;
  std::optional<similarity::Motion_signature_explanation> explanation{};  ///< with `Comparison_request::explain`
};

/// How alike `a` and `b` move under `choice` and, for a policy whose frames can be shuffled,
/// the z-score of the value against shuffled copies of `b` as `significance` asks: each described
/// and the copies scored on `threads` threads (0: all; the result does not depend on it).
Compared compare(const mesh::Surface_mesh_animation& a, const mesh::Surface_mesh_animation& b,
                 const Policy_choice& choice, const Comparison_request& request, int threads = 0);

/// Animations as the similarity matrices of the front end take them: by address, so that a caller's
/// animations need not be gathered into one container (Python's list, the tool's clips).
using Animation_addresses = std::span<const mesh::Surface_mesh_animation* const>;

/// `similarity::similarity_matrix` of every pair of `animations` under `choice`: the policies'
/// matrices compiled once, here, for the tool and the Python module.
/// @pre `check(choice, front)` passed, no address is null; `threads` as the library's (0: all).
/// @throws as `similarity::similarity_matrix` (`animation_not_described`, `cancelled`, ...).
/// @par Complexity N descriptions and N (N + 1) / 2 comparisons of the policy.
Eigen::MatrixXd similarity_matrix(Animation_addresses animations, const Policy_choice& choice,
                                  const Progress& progress = {}, int threads = 0);

/// The all-pairs `similarity_matrix` of animations held in one container.
Eigen::MatrixXd similarity_matrix(std::span<const mesh::Surface_mesh_animation> animations,
                                  const Policy_choice& choice, const Progress& progress = {}, int threads = 0);

/// `similarity::similarity_matrix` of `queries` (rows) against `database` (columns) under `choice`.
/// @pre as the all-pairs `similarity_matrix`.
/// @par Complexity Q + D descriptions and Q D comparisons of the policy.
Eigen::MatrixXd similarity_matrix(Animation_addresses queries, Animation_addresses database,
                                  const Policy_choice& choice, const Progress& progress = {}, int threads = 0);

/// The animations of a similarity matrix read one at a time (`similarity_matrix` of a source), so
/// that they need not all be held at once.
struct Animation_source {
  std::size_t count = 0;  ///< N, the animations
  /// The animation of index i (below `count`): called once for each, from any thread; the
  /// `invalid_input` it throws says why that animation cannot be read.
  std::function<mesh::Surface_mesh_animation(std::size_t)> read;
};

/// An animation that a `Read_matrix` leaves out, and why.
struct Left_out {
  std::size_t index;    ///< its index in the source
  bool reading;         ///< whether reading it failed (else describing it)
  invalid_input error;  ///< the reader's or the policy's error
};

/// A similarity matrix of the animations of a source that could be read and described.
struct Read_matrix {
  Eigen::MatrixXd similarity;       ///< K x K, of the animations kept, in the source's order
  std::vector<std::size_t> kept;    ///< their K indices in the source, increasing
  std::vector<Left_out> left_out;   ///< the others, by index
};

/// `similarity::similarity_matrix` under `choice` of the animations `source` reads: each read and
/// described at once on `threads` threads, then freed (memory for the descriptions and an
/// animation a thread, not for every animation), then the pairs of those described compared; an
/// animation that cannot be read or described is left out, with its error. The matrix of the
/// animations kept equals `similarity_matrix` of them, whatever the threads.
/// @pre `check(choice, front)` passed; `source.read` is set unless `source.count` is 0.
/// @param progress as the library's: N + K (K + 1) / 2 steps, one a description (total
/// N + N (N + 1) / 2 while they are made) then one a pair.
/// @throws invalid_input for a thread count outside [0, max_threads], before any work.
/// @throws cancelled as `similarity::similarity_matrix`.
/// @par Complexity N reads and descriptions, K (K + 1) / 2 comparisons of the policy.
Read_matrix similarity_matrix(const Animation_source& source, const Policy_choice& choice,
                              const Progress& progress = {}, int threads = 0);

/// What reading an input frame by frame found.
struct Streamed_input {
  std::size_t frames = 0;  ///< its frames
  Outliers outliers{};     ///< its outlying vertices (`check_outliers`)
  /// A character file's clip, its name as in the file (as `io::Gltf_read_report::clip`).
  std::optional<std::string> clip{};
  io::Repair_report repair{};  ///< what a character file's repair changed
};

/// `compare` of the animations that `inputs` name, each read frame by frame: the motion-signature
/// policy describes a stream holding the frames its longest lag spans, not the whole animation
/// (a clip of a character file, its connectivity welded and repaired from what the file fixes; a
/// point cache with its topology; a frame sequence, not welded, since welding it compares every
/// frame), with the same result as `compare` of the animations read whole. `streamed` gets their
/// frame counts, outlying vertices (refused with `options.refuse_defects`), clips and repairs.
/// The shuffled copies are scored on `options.threads` threads.
/// @return nullopt, having described nothing, when an input must be read whole: another policy, a
/// welded point cache or frame sequence, a point cache without topology, an animation of fewer
/// than 2 frames.
/// @throws invalid_input naming the file or the frame that cannot be read.
std::optional<Compared> compare_streamed(const std::array<std::string, 2>& inputs, const Input_options& options,
                                         const Policy_choice& choice,
                                         const Comparison_request& request, Front front,
                                         std::array<Streamed_input, 2>& streamed);

/// A similarity as a report: {"policy", "alignment_policy", "similarity", "score", "labels_a",
/// "labels_b", "alignment": [[i, j], ...], "compared", "z_score" (or null), "shuffled_copies",
/// "explanation" (`explanation_record`, or null)}.
nlohmann::json similarity_record(const Compared& compared, const Policy_choice& choice);

/// An explanation as a report: {"pairs", "channels": [{"kind": "speed" or "vertical_rate", "lag",
/// "band", "side" (-1, 0 or 1), "half": "lower" or "upper", "share", "mean_difference"}, ...]}.
nlohmann::json explanation_record(const similarity::Motion_signature_explanation& explanation);

/// The `most` channels of the largest shares, in words, one a line: "41.2%  speeds at lag 0.533 s,
/// the faster half of the surface: A 1.84x as fast as B" (or "... of height band 2 of 3, counted
/// from the ground" when there are several bands, and ", its negative side" with sides).
std::vector<std::string> explanation_lines(const similarity::Motion_signature_explanation& explanation,
                                           std::size_t bands, std::size_t most);

}  // namespace deformseg::frontend
