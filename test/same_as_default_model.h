// What the tests of other mesh models check against the default model: the same temporal
// segments under every method and the same similarity under every built-in policy, to the last bit.
#pragma once

#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/strain_distribution_similarity.h>
#include <deformseg/temporal/barbic_pca.h>
#include <deformseg/temporal/binary_split.h>
#include <deformseg/temporal/temporal_segmentation.h>
#include <deformseg/temporal/thesis_greedy.h>

#include <catch2/catch.hpp>

#include <algorithm>

namespace deformseg::test {

/// Whether two segmentations are alike to the last bit: the same frames, segments and costs.
inline bool same_segments(const temporal::Temporal_segmentation& a, const temporal::Temporal_segmentation& b) {
  return a.frames == b.frames && std::ranges::equal(a.segments, b.segments, [](const auto& x, const auto& y) {
           return x.first == y.first && x.last == y.last && x.cost == y.cost;
         });
}

/// Checks that each temporal method, with its defaults, segments `model` as it segments `animation`.
template <class Model, class Default>
void check_every_method_same(const Model& model, const Default& animation) {
  CHECK(same_segments(temporal::temporal_segmentation(model), temporal::temporal_segmentation(animation)));
  CHECK(same_segments(temporal::temporal_segmentation(model, temporal::Binary_split{}),
                      temporal::temporal_segmentation(animation, temporal::Binary_split{})));
  CHECK(same_segments(temporal::temporal_segmentation(model, temporal::Thesis_greedy{}),
                      temporal::temporal_segmentation(animation, temporal::Thesis_greedy{})));
  CHECK(same_segments(temporal::temporal_segmentation(model, temporal::Barbic_pca{}),
                      temporal::temporal_segmentation(animation, temporal::Barbic_pca{})));
}

/// Whether two similarities are equal in every field, to the last bit.
inline bool same_similarity(const similarity::Similarity& a, const similarity::Similarity& b) {
  return a.value == b.value && a.score == b.score && a.alignment == b.alignment && a.labels_a == b.labels_a &&
         a.labels_b == b.labels_b && a.compared == b.compared;
}

/// Checks that `policy` compares `model_a` with `model_b` as it compares `a` with `b`.
template <class Model, class Default, class Policy>
void check_same_similarity(const Model& model_a, const Model& model_b, const Default& a, const Default& b,
                           const Policy& policy) {
  CHECK(same_similarity(similarity::motion_similarity(model_a, model_b, policy),
                        similarity::motion_similarity(a, b, policy)));
}

/// Checks `check_same_similarity` under each of the four built-in policies, with its defaults.
template <class Model, class Default>
void check_every_policy_same(const Model& model_a, const Model& model_b, const Default& a, const Default& b) {
  check_same_similarity(model_a, model_b, a, b, similarity::Motion_signature_similarity<>{});
  check_same_similarity(model_a, model_b, a, b, similarity::Strain_distribution_similarity<>{});
  check_same_similarity(model_a, model_b, a, b, similarity::Evolving_graph_similarity<>{});
  check_same_similarity(model_a, model_b, a, b, similarity::Self_similarity_matching<>{});
}

}  // namespace deformseg::test
