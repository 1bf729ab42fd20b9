/// @file motion_similarity.h
/// @brief The similarity of two animations (`motion_similarity`) and of every pair of a set
/// (`similarity_matrix`), by a similarity policy.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/similarity/evolving_graph_similarity.h>
#include <deformseg/similarity/similarity.h>
#include <deformseg/similarity/strain_distribution_similarity.h>

#include <Eigen/Core>

#include <cstddef>
#include <ranges>
#include <vector>

namespace deformseg {

/// @brief The default similarity policy of `motion_similarity`, `similarity_matrix` and the
/// `deformseg` tool: `Strain_distribution_similarity`, which passes the tests of both kinds
/// (the same motion on other shapes is more alike than other motions on the same shape) where
/// the thesis' `Evolving_graph_similarity` fails some (see the manual).
using Default_similarity = Strain_distribution_similarity<>;

/// @brief The similarity of animations `a` and `b`: `policy.compare(policy.describe(a),
/// policy.describe(b))`.
/// @tparam Mesh a `DeformingMesh` (both animations of one type; they need not share a mesh).
/// @tparam Policy a `SimilarityPolicy` (default `Default_similarity`).
/// @return the value in [0, 1], the raw score, the frame-to-frame alignment and what was compared.
/// @throws invalid_input as the policy does (an animation with no frame, ...).
/// @par Complexity the policy's: twice `describe`, once `compare`.
template <DeformingMesh Mesh, class Policy = Default_similarity>
  requires SimilarityPolicy<Policy, Mesh>
Similarity motion_similarity(const Mesh& a, const Mesh& b, const Policy& policy = {}) {
  return policy.compare(policy.describe(a), policy.describe(b));
}

/// @brief The similarity of every pair of `animations`: each animation described once
/// (`policy.describe`, its evolving graph or histograms), then each pair i < j compared, pairs in
/// parallel (OpenMP); the matrix is symmetric (entry (j, i) is entry (i, j)) with the diagonal
/// the comparison of each animation with itself, so 1 for the library's policies, and entry (i, j)
/// equals `motion_similarity(animations[i], animations[j], policy).value`.
/// @tparam Animations a random-access range of a `DeformingMesh` type.
/// @return the N x N matrix of similarity values.
/// @throws invalid_input as the policy does (the first failing pair's exception).
/// @par Complexity N describes and N (N + 1) / 2 compares; the result does not depend on the
/// number of threads.
template <std::ranges::random_access_range Animations, class Policy = Default_similarity>
  requires DeformingMesh<std::ranges::range_value_t<Animations>> &&
           SimilarityPolicy<Policy, std::ranges::range_value_t<Animations>>
Eigen::MatrixXd similarity_matrix(const Animations& animations, const Policy& policy = {}) {
  const std::size_t n = std::size_t(std::ranges::size(animations));
  std::vector<typename Policy::Description> descriptions;
  descriptions.reserve(n);
  for (const auto& animation : animations) descriptions.push_back(policy.describe(animation));
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) pairs.emplace_back(i, j);
  const auto size = Eigen::Index(n);
  Eigen::MatrixXd values(size, size);
  internal::parallel_for_each_index(pairs.size(), [&](std::size_t p) {
    const auto [i, j] = pairs[p];
    const double v = policy.compare(descriptions[i], descriptions[j]).value;
    values(Eigen::Index(i), Eigen::Index(j)) = values(Eigen::Index(j), Eigen::Index(i)) = v;
  });
  return values;
}

}  // namespace deformseg
