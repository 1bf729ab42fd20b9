// What the tests of other mesh models check against the default model: the same similarity, to
// the last bit, under every built-in policy.
#pragma once

#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/strain_distribution_similarity.h>

#include <catch2/catch.hpp>

namespace deformseg::test {

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
