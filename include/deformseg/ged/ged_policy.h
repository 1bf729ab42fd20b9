/// @file ged/ged_policy.h
/// @brief The `GedPolicy` concept: what a graph edit distance policy provides (@ref GedConcepts).
#pragma once

#include <deformseg/ged/cost_model.h>
#include <deformseg/ged/ged_result.h>

#include <concepts>

namespace deformseg::ged {

/// @brief A graph edit distance policy: `policy(a, b, costs)` compares two labelled graphs under
/// a cost model and returns a `Ged_result` (@ref GedPolicyConcept).
///
/// Has models: `Exact_ged`, `Bipartite_ged`, `Assignment_lower_bound`.
template <class P, class G, class C>
concept GedPolicy = LabelledGraph<G> && GedCostModel<C, label_t<G>> &&
                    requires(const P& p, const G& a, const G& b, const C& costs) {
                      { p(a, b, costs) } -> std::same_as<Ged_result>;
                    };

}  // namespace deformseg::ged
