// The registry: every family a user chooses by name (strain measures, normalisations and
// references, frame metrics, temporal methods, the spatio-temporal segmentation's references,
// similarity policies and alignments, up and side directions, graph edit distance methods). Each
// entry is a name, its help and what the front end makes of it. The tool and the Python module
// take names only through these tables (their parameters' choices, `entry_named` and the makers),
// so that a new method is one entry here and its maker, and no name is compared anywhere else.
#pragma once

#include "parameters.h"

#include <deformseg/ged/bipartite_ged.h>
#include <deformseg/ged/exact_ged.h>
#include <deformseg/ged/lower_bound.h>
#include <deformseg/similarity/any_policy.h>
#include <deformseg/strain/frame_distances.h>
#include <deformseg/strain/strain.h>
#include <deformseg/temporal/segment_cost.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

namespace deformseg::frontend {

/// An entry of a family chosen by name: the name a user gives, its help, and the library's value
/// it stands for.
template <class Value>
struct Named {
  std::string_view name;
  std::string_view help;
  Value value;
};

/// The entry of `family` named `name`.
/// @pre `name` is one of the family's names (a request's check has passed); else std::logic_error.
/// @par Complexity linear in the family's size.
template <class Entry, std::size_t N>
const Entry& entry_named(const std::array<Entry, N>& family, std::string_view name) {
  const auto at = std::ranges::find(family, name, &Entry::name);
  if (at == family.end()) throw std::logic_error("not a checked choice: '" + std::string(name) + "'");
  return *at;
}

/// The name of the entry of `family` whose value is `value`.
/// @pre one entry has that value; else std::logic_error.
template <class Entry, std::size_t N, class Value>
std::string_view name_of(const std::array<Entry, N>& family, const Value& value) {
  const auto at = std::ranges::find(family, value, &Entry::value);
  if (at == family.end()) throw std::logic_error("no entry of the family has the value asked for");
  return at->name;
}

// ---- the strain -------------------------------------------------------------------------------

/// The built-in strain measures; the first is the default.
inline constexpr std::array strain_measures{
    Named<strain::Strain_measure_choice>{"max-principal", "max |l - 1| over the principal stretches l (default)",
                                         strain::Max_principal_strain{}},
    Named<strain::Strain_measure_choice>{
        "green-lagrange", "the Green-Lagrange strain of largest magnitude, max |l^2 - 1| / 2",
        strain::Green_lagrange_strain{}},
    Named<strain::Strain_measure_choice>{"frobenius", "the Frobenius norm of U - I, U the right stretch tensor",
                                         strain::Frobenius_strain{}},
    Named<strain::Strain_measure_choice>{"area-ratio", "the change of area |J - 1|, J = l1 l2: blind to shape",
                                         strain::Area_ratio_strain{}},
};

/// The normalisations of the strain: whether each takes a scale (sigma); the first is the default.
inline constexpr std::array strain_normalizations{
    Named<bool>{"gaussian", "1 - exp(-s^2 / 2 sigma^2), sigma the 95th percentile of the strains unless given "
                            "(default)",
                true},
    Named<bool>{"none", "the raw strains", false},
};

/// What the strain is measured against; the first is the default of the strain (a rest pose: a
/// frame or a reference mesh).
inline constexpr std::array strain_references{
    Named<strain::Strain_reference>{"rest", "one pose: a frame (the rest frame) or the reference mesh (default)",
                                    strain::Strain_reference::rest_pose},
    Named<strain::Strain_reference>{"previous", "the frame before (frame 0's strain is 0)",
                                    strain::Strain_reference::previous_pose},
};

/// What a cell's strain is measured against, for the spatio-temporal segmentation; the first is
/// the default without a reference mesh, the second with one.
inline constexpr std::array segmentation_references{
    Named<strain::Strain_reference>{"previous", "deformed while it moves (default without a reference mesh)",
                                    strain::Strain_reference::previous_pose},
    Named<strain::Strain_reference>{
        "rest", "deformed while away from frame 0, or from the reference mesh (the default with one)",
        strain::Strain_reference::rest_pose},
};

/// The distances between frames' strains; the first is the default.
inline constexpr std::array frame_metrics{
    Named<strain::Frame_metric>{"euclidean", "the Euclidean distance (default)", strain::Frame_metric::euclidean},
    Named<strain::Frame_metric>{"l1", "the sum of absolute differences", strain::Frame_metric::l1},
    Named<strain::Frame_metric>{"cosine", "one minus the cosine of the angle", strain::Frame_metric::cosine},
};

// ---- the temporal segmentation ----------------------------------------------------------------

struct Temporal_request;
struct Temporal_result;

/// A temporal segmentation method: its name, its help, whether it takes a count of segments, and
/// the segmentation it makes of a cost with a request's threshold and lengths.
struct Temporal_method {
  std::string_view name;
  std::string_view help;
  bool counts = false;  ///< whether it takes `Temporal_request::segments`
  Temporal_result (*segment)(const temporal::Segment_cost& cost, const Temporal_request& request) = nullptr;
};

/// The makers of `temporal_methods` (frontend/temporal.cpp): each method with the request's
/// threshold (relative unless absolute), or its own default.
Temporal_result optimal_segments(const temporal::Segment_cost& cost, const Temporal_request& request);
Temporal_result binary_split_segments(const temporal::Segment_cost& cost, const Temporal_request& request);
Temporal_result greedy_segments(const temporal::Segment_cost& cost, const Temporal_request& request);
Temporal_result barbic_segments(const temporal::Segment_cost& cost, const Temporal_request& request);

/// The segmentation methods; the first is the default.
inline constexpr std::array temporal_methods{
    Temporal_method{"optimal",
                    "least length-weighted cost, with a penalty per segment or a count of segments (default)", true,
                    &optimal_segments},
    Temporal_method{"binary-split",
                    "split where the within-segment dissimilarity is largest, while above the threshold", false,
                    &binary_split_segments},
    Temporal_method{"greedy", "the thesis' Algorithm 4-1", false, &greedy_segments},
    Temporal_method{"barbic", "PCA change detection (Barbic et al. 2004)", false, &barbic_segments},
};

// ---- the similarity ---------------------------------------------------------------------------

struct Policy_choice;

/// A similarity policy the front end offers: its name and help, which options apply to it, its
/// defaults, and the library's policy it makes.
struct Policy_entry {
  std::string_view name;
  std::string_view help;
  std::string_view alignment;  ///< the alignment's name when none is given
  /// The deformed threshold when none is given; none: the policy takes no threshold.
  std::optional<double> threshold = std::nullopt;
  bool up = false;          ///< whether the policy takes the signatures' up direction, bands and sides
  bool key_frames = false;  ///< whether its frames are key-frame labels, which no shuffle may test
  /// The policy aligning by `alignment`, with the options of `choice` (its threshold given), every
  /// loop of its own on `threads` threads (0: all).
  similarity::Any_policy (*make)(const similarity::Any_alignment& alignment, const Policy_choice& choice,
                                 int threads) = nullptr;
};

/// The makers of `similarity_policies` (frontend/similarity.cpp).
similarity::Any_policy signature_policy(const similarity::Any_alignment& alignment, const Policy_choice& choice,
                                        int threads);
similarity::Any_policy histogram_policy(const similarity::Any_alignment& alignment, const Policy_choice& choice,
                                        int threads);
similarity::Any_policy thesis_graph_policy(const similarity::Any_alignment& alignment, const Policy_choice& choice,
                                           int threads);
similarity::Any_policy self_similarity_policy(const similarity::Any_alignment& alignment,
                                              const Policy_choice& choice, int threads);
similarity::Any_policy character_graph_policy(const similarity::Any_alignment& alignment,
                                              const Policy_choice& choice, int threads);

/// The similarity policies, whose names the tool's --policy and Python's policy= take; the first is
/// the default, and the one a motion store holds.
inline constexpr std::array similarity_policies{
    Policy_entry{.name = "motion-signature",
                 .help = "per-frame distributions of how fast, and how fast up or down, the surface moves at "
                         "several time scales, no correspondence needed (default)",
                 .alignment = "dtw",
                 .up = true,
                 .make = &signature_policy},
    Policy_entry{.name = "histogram",
                 .help = "per-frame histograms of the strain, no correspondence needed; its values crowd near 1 "
                         "(chapter 7 of the manual gives figures): read the z-score or a rank, not the value",
                 .alignment = "smith-waterman",
                 .make = &histogram_policy},
    Policy_entry{.name = "graph",
                 .help = "the thesis' method: evolving graphs, graph edit distances, clustering and label "
                         "alignment (Smith-Waterman); for bodies that deform alike, as the thesis' animals",
                 .alignment = "smith-waterman",
                 .threshold = 0.5,  // thesis_segmentation()'s
                 .key_frames = true,
                 .make = &thesis_graph_policy},
    Policy_entry{.name = "self-similarity",
                 .help = "each animation's own frame x frame distances after rigid alignment",
                 .alignment = "smith-waterman",
                 .make = &self_similarity_policy},
    Policy_entry{.name = "graph-characters",
                 .help = "the evolving graphs with settings tuned on game characters (a fixed strain scale, "
                         "threshold 0.3, parts linked, segments of 6 frames, DTW); not the thesis' method",
                 .alignment = "dtw",
                 .threshold = 0.3,  // character_segmentation()'s
                 .key_frames = true,
                 .make = &character_graph_policy},
};

/// The alignments, whose names the tool's --alignment and Python's alignment= take; none given: the
/// policy's own (`Policy_entry::alignment`).
inline constexpr std::array similarity_alignments{
    Named<similarity::Any_alignment>{"smith-waterman", "local: the best matching parts", alignment::Smith_waterman{}},
    Named<similarity::Any_alignment>{"dtw", "global: both whole", alignment::Dtw{}},
    Named<similarity::Any_alignment>{"subsequence-dtw", "open begin and end", alignment::Subsequence_dtw{}},
};

/// A direction along an axis: the axis (0 for x, 1 for y, 2 for z) and its sign.
struct Axis_direction {
  int axis = 1;
  double sign = 1;
  friend constexpr bool operator==(const Axis_direction&, const Axis_direction&) = default;
};

/// The up directions of the motion signatures; none given: +y (glTF's up); "none": speeds alone.
inline constexpr std::array up_directions{
    Named<std::optional<Axis_direction>>{"+x", "x up", Axis_direction{0, 1}},
    Named<std::optional<Axis_direction>>{"-x", "x down", Axis_direction{0, -1}},
    Named<std::optional<Axis_direction>>{"+y", "y up (default, glTF's)", Axis_direction{1, 1}},
    Named<std::optional<Axis_direction>>{"-y", "y down", Axis_direction{1, -1}},
    Named<std::optional<Axis_direction>>{"+z", "z up", Axis_direction{2, 1}},
    Named<std::optional<Axis_direction>>{"-z", "z down", Axis_direction{2, -1}},
    Named<std::optional<Axis_direction>>{"none", "speeds alone, blind to direction", std::nullopt},
};

/// The directions across the body that keep its sides apart; none given: the whole width, a motion
/// and its mirror image alike.
inline constexpr std::array side_directions{
    Named<Axis_direction>{"+x", "x across (glTF characters, facing +z)", {0, 1}},
    Named<Axis_direction>{"-x", "x across, the other way", {0, -1}},
    Named<Axis_direction>{"+y", "y across", {1, 1}},
    Named<Axis_direction>{"-y", "y across, the other way", {1, -1}},
    Named<Axis_direction>{"+z", "z across", {2, 1}},
    Named<Axis_direction>{"-z", "z across, the other way", {2, -1}},
};

// ---- graph edit distances ---------------------------------------------------------------------

/// The graph edit distance methods the front end offers, one library policy each.
using Any_ged = std::variant<ged::Exact_ged, ged::Bipartite_ged, ged::Assignment_lower_bound>;

struct Ged_request;

/// A graph edit distance method: its name, its help, and the library's policy it makes of a
/// request (with the request's limits, where they apply).
struct Ged_method {
  std::string_view name;
  std::string_view help;
  Any_ged (*make)(const Ged_request& request) = nullptr;
};

/// The makers of `ged_methods` (frontend/ged.cpp).
Any_ged exact_ged(const Ged_request& request);
Any_ged bipartite_ged(const Ged_request& request);
Any_ged lower_bound_ged(const Ged_request& request);

/// The graph edit distance methods; the first is the default.
inline constexpr std::array ged_methods{
    Ged_method{"exact", "branch and bound, exact unless its expansions or seconds run out (default)", &exact_ged},
    Ged_method{"bipartite", "Riesen & Bunke's assignment approximation, an upper bound", &bipartite_ged},
    Ged_method{"lower", "an assignment lower bound", &lower_bound_ged},
};

// ---- the families' choices, for their parameters ------------------------------------------------

inline constexpr std::array strain_measure_choices = choices_of(strain_measures);
inline constexpr std::array strain_normalization_choices = choices_of(strain_normalizations);
inline constexpr std::array strain_reference_choices = choices_of(strain_references);
inline constexpr std::array segmentation_reference_choices = choices_of(segmentation_references);
inline constexpr std::array frame_metric_choices = choices_of(frame_metrics);
inline constexpr std::array temporal_method_choices = choices_of(temporal_methods);
inline constexpr std::array policy_choices = choices_of(similarity_policies);
inline constexpr std::array alignment_choices = choices_of(similarity_alignments);
inline constexpr std::array up_direction_choices = choices_of(up_directions);
inline constexpr std::array side_direction_choices = choices_of(side_directions);
inline constexpr std::array ged_method_choices = choices_of(ged_methods);

}  // namespace deformseg::frontend
