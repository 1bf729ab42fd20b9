/// @file similarity/any_policy.h
/// @brief `Any_policy`: one of the similarity policies, each over one of the alignments, chosen at
/// run time; `visit_policy` calls a function with the policy it holds. A program that lets its user
/// choose (the `deformseg` tool, the Python module) builds one from its own names; the library
/// knows types, not names.
#pragma once

#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/strain_distribution_similarity.h>

#include <utility>
#include <variant>

namespace deformseg::similarity {

/// @brief One of the alignments, chosen at run time: `alignment::Smith_waterman` (local: the best
/// matching parts), `alignment::Dtw` (global: both whole) or `alignment::Subsequence_dtw` (open
/// begin and end). Default-constructed: Smith–Waterman with its defaults.
using Any_alignment = std::variant<alignment::Smith_waterman, alignment::Dtw, alignment::Subsequence_dtw>;

/// @brief `Evolving_graph_similarity` with its default edit distance, costs and clustering, aligning
/// the label sequences by `Alignment`: the thesis' method (its defaults) and the settings tuned on
/// game characters (`character_graph_similarity<Alignment>()`) are both of this type, with other
/// `segmentation`s.
/// @tparam Alignment an `alignment::AlignmentPolicy`.
template <alignment::AlignmentPolicy Alignment>
using Graph_similarity = Evolving_graph_similarity<ged::Bipartite_ged, Segment_costs, clustering::K_medoids, Alignment>;

/// @brief One of the similarity policies, chosen at run time, each over each alternative of
/// `Any_alignment`: `Motion_signature_similarity`, `Strain_distribution_similarity`,
/// `Self_similarity_matching` and `Graph_similarity` (the thesis' evolving graphs, or those tuned on
/// characters), every other template parameter at its default. Default-constructed: the motion
/// signatures aligned by Smith–Waterman; a program sets the one it wants (`policy = Default_similarity{}`).
///
/// `visit_policy` (or `std::visit`) calls a generic function with the policy held, so that the
/// function is compiled once per alternative and the choice costs one indirect call.
using Any_policy = std::variant<
    Motion_signature_similarity<alignment::Smith_waterman>, Motion_signature_similarity<alignment::Dtw>,
    Motion_signature_similarity<alignment::Subsequence_dtw>, Strain_distribution_similarity<alignment::Smith_waterman>,
    Strain_distribution_similarity<alignment::Dtw>, Strain_distribution_similarity<alignment::Subsequence_dtw>,
    Self_similarity_matching<alignment::Smith_waterman>, Self_similarity_matching<alignment::Dtw>,
    Self_similarity_matching<alignment::Subsequence_dtw>, Graph_similarity<alignment::Smith_waterman>,
    Graph_similarity<alignment::Dtw>, Graph_similarity<alignment::Subsequence_dtw>>;

/// @brief Calls `run(policy)` with the policy `any` holds and returns what it returns: `std::visit`.
///
/// @code
/// similarity::Any_policy policy = similarity::Strain_distribution_similarity<alignment::Dtw>{};
/// const Similarity s = similarity::visit_policy(policy, [&](const auto& p) { return motion_similarity(a, b, p); });
/// @endcode
/// @tparam Run callable with each alternative of `Any_policy` (a generic lambda), returning the
/// same type for every one.
/// @pre `any` holds a policy (`!any.valueless_by_exception()`); else `std::bad_variant_access`.
/// @par Complexity that of `run`; the dispatch is O(1).
/// @par Example
/// @include any_policy.cpp
template <class Run>
decltype(auto) visit_policy(const Any_policy& any, Run&& run) {
  return std::visit(std::forward<Run>(run), any);
}

}  // namespace deformseg::similarity
