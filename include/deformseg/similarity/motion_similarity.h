/// @file similarity/motion_similarity.h
/// @brief The similarity of two animations (`motion_similarity`) and of every pair of a set
/// (`similarity_matrix`; `described_similarity_matrix` of descriptions made beforehand), by a
/// similarity policy.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/similarity.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <functional>
#include <optional>
#include <ranges>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::similarity {

/// @brief The default similarity policy of `motion_similarity`, `similarity_matrix` and the
/// `deformseg` tool: `Motion_signature_similarity` (per-frame distributions of how fast the
/// surface moves, aligned by DTW), the policy that does best on the retrieval evaluation of the
/// shared real characters (see the manual's similarity chapter, where every policy's figures stand
/// side by side), and which passes the synthetic and real rankings of the tests.
using Default_similarity = Motion_signature_similarity<>;

/// @brief The similarity of animations `a` and `b`: `policy.compare(policy.describe(a),
/// policy.describe(b))`.
/// @tparam Mesh a `DeformingMesh` (both animations of one type; they need not share a mesh).
/// @tparam Policy a `SimilarityPolicy` (default `Default_similarity`).
/// @return the value in [0, 1], the raw score, the frame-to-frame alignment and what was compared.
/// @throws invalid_input as the policy does (an animation with no frame, ...).
/// @par Complexity the policy's: twice `describe`, once `compare`.
template <mesh::DeformingMesh Mesh, class Policy = Default_similarity>
  requires SimilarityPolicy<Policy, Mesh>
Similarity motion_similarity(const Mesh& a, const Mesh& b, const Policy& policy = {}) {
  return policy.compare(policy.describe(a), policy.describe(b));
}

/// @brief Thrown by `similarity_matrix` when the policy cannot describe one of the animations (a
/// single pose, which has no motion, say): the policy's `invalid_input`, its message after the
/// animation's place, so that a caller can name the animation or leave it out and try again.
class animation_not_described : public invalid_input {
public:
  /// @brief The error of the animation at `index` of the queries (`in_database` false; the only
  /// range of the all-pairs matrix) or of the database, from the policy's `reason`.
  animation_not_described(std::size_t index, bool in_database, const invalid_input& reason)
      : invalid_input(std::string(in_database ? "database animation " : "animation ") + std::to_string(index) + ": " +
                          reason.message(),
                      reason.where()),
        index_(index), in_database_(in_database), reason_(reason.what()) {}

  /// @brief The animation's index in its range.
  std::size_t index() const noexcept { return index_; }
  /// @brief Whether it is of the database of a queries x database matrix.
  bool in_database() const noexcept { return in_database_; }
  /// @brief The policy's message, with its location, without the animation's index.
  const std::string& reason() const noexcept { return reason_; }

private:
  std::size_t index_;
  bool in_database_;
  std::string reason_;
};

namespace internal {

// Each animation of `animations` described once, on `threads` threads, reported as steps from
// `first_step`. An animation the policy refuses is named by an animation_not_described (in the
// database when `database`).
template <class Animations, class Policy>
std::vector<typename Policy::Description> describe_all(const Animations& animations, const Policy& policy,
                                                       std::size_t first_step, std::size_t total_steps,
                                                       const Progress& progress, int threads, bool database = false) {
  const std::size_t n = std::size_t(std::ranges::size(animations));
  // Optional because a Description need not be default-constructible.
  std::vector<std::optional<typename Policy::Description>> made(n);
  deformseg::internal::parallel_for_reporting(n, threads, progress, first_step, total_steps, [&](std::size_t i) {
    try {
      made[i].emplace(policy.describe(std::ranges::begin(animations)[std::ptrdiff_t(i)]));
    } catch (const invalid_input& e) {
      throw animation_not_described(i, database, e);
    }
  });
  std::vector<typename Policy::Description> descriptions;
  descriptions.reserve(n);
  for (auto& d : made) descriptions.push_back(std::move(*d));
  return descriptions;
}

// Entry (i, j) of the all-pairs matrix of `descriptions`, each pair i <= j compared once on
// `threads` threads, reported as steps from `first_step`.
template <class Policy>
Eigen::MatrixXd compare_all_pairs(std::span<const typename Policy::Description> descriptions, const Policy& policy,
                                  std::size_t first_step, std::size_t total_steps, const Progress& progress,
                                  int threads) {
  const std::size_t n = descriptions.size();
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) pairs.emplace_back(i, j);
  const auto size = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd values(size, size);
  deformseg::internal::parallel_for_reporting(pairs.size(), threads, progress, first_step, total_steps,
                                              [&](std::size_t p) {
                                                const auto [i, j] = pairs[p];
                                                const double v = policy.compare(descriptions[i], descriptions[j]).value;
                                                values(Eigen::Index(i), Eigen::Index(j)) = v;
                                                values(Eigen::Index(j), Eigen::Index(i)) = v;
                                              });
  return values;
}

}  // namespace internal

/// @brief The similarity of every pair of animations already described (`policy.describe`), as
/// the all-pairs `similarity_matrix` of the animations gives it: for a caller that describes each
/// animation as soon as it is read, and frees it, so that the animations are never all held.
/// @tparam Policy a similarity policy (`SimilarityPolicy` for the animations described).
/// @param descriptions the N descriptions, each made by `policy.describe` (or a policy with the
/// same description options).
/// @param policy the policy that compares them.
/// @param progress called on the calling thread after each parallel batch of pairs (see
/// `Progress`): N (N + 1) / 2 steps; default none.
/// @param threads the threads, as `similarity_matrix`'s (default 0).
/// @return the symmetric N x N matrix: entry (i, j) and (j, i) are
/// `policy.compare(descriptions[i], descriptions[j]).value` for i <= j.
/// @throws invalid_input when `threads` is negative or above `max_threads`, before any work; as
/// the policy does for the first failing pair.
/// @throws cancelled as `similarity_matrix`.
/// @par Complexity N (N + 1) / 2 compares on `threads` threads; the result does not depend on their
/// number.
/// @par Example
/// @include similarity_matrix.cpp
template <class Policy>
Eigen::MatrixXd described_similarity_matrix(std::span<const typename Policy::Description> descriptions,
                                            const Policy& policy, const Progress& progress = {}, int threads = 0) {
  thread_count(threads, "described_similarity_matrix");
  const std::size_t n = descriptions.size();
  return internal::compare_all_pairs(descriptions, policy, 0, n * (n + 1) / 2, progress, threads);
}

/// @brief The similarity of every pair of `animations`: each animation described once
/// (`policy.describe`, its evolving graph or histograms), then each pair i < j compared,
/// descriptions and pairs in parallel; the matrix is symmetric (entry (j, i) is entry
/// (i, j)) with the diagonal the comparison of each animation with itself, so 1 for the library's
/// policies, and entry (i, j) equals `motion_similarity(animations[i], animations[j], policy).value`.
/// @tparam Animations a random-access range of a `DeformingMesh` type.
/// @param animations the N animations.
/// @param policy the similarity policy (default `Default_similarity{}`).
/// @param progress called on the calling thread as the work advances (see `Progress`): N + N (N +
/// 1) / 2 steps, one a description, one a comparison; called after each parallel batch (about 5 %
/// of the descriptions or of the pairs, at least 16), so once with `done` = N, when the
/// descriptions are all made; default none.
/// @param threads the threads (see threads.h): 0 (the default) for all the hardware's threads
/// unless `DEFORMSEG_NUM_THREADS` or `OMP_NUM_THREADS` says otherwise, else 1 to `max_threads`.
/// @return the N x N matrix of similarity values.
/// @throws animation_not_described (an invalid_input) for the first animation, in index order,
/// that the policy cannot describe, naming it; invalid_input as the policy does for the first
/// failing pair.
/// @throws invalid_input when `threads` is negative or above `max_threads`, before any work.
/// @throws cancelled when `progress` or the calling thread's `Interruption_check` (threads.h)
/// returned false.
/// @par Complexity N describes and N (N + 1) / 2 compares, on `threads` threads; the result does not
/// depend on their number.
template <std::ranges::random_access_range Animations, class Policy = Default_similarity>
  requires mesh::DeformingMesh<std::ranges::range_value_t<Animations>> &&
           SimilarityPolicy<Policy, std::ranges::range_value_t<Animations>>
Eigen::MatrixXd similarity_matrix(const Animations& animations, const Policy& policy = {},
                                  const Progress& progress = {}, int threads = 0) {
  thread_count(threads, "similarity_matrix");
  const std::size_t n = std::size_t(std::ranges::size(animations));
  const std::size_t total = n + n * (n + 1) / 2;
  const auto descriptions = internal::describe_all(animations, policy, 0, total, progress, threads);
  return internal::compare_all_pairs(std::span<const typename Policy::Description>(descriptions), policy, n, total,
                                     progress, threads);
}

/// @brief The similarity of each of `queries` against each animation of `database`: every
/// animation described once, then each (query, database) pair compared, in parallel;
/// entry (q, d) equals `motion_similarity(queries[q], database[d], policy).value`.
/// @tparam Queries a random-access range of a `DeformingMesh` type.
/// @tparam Database a random-access range of the same `DeformingMesh` type.
/// @param queries the Q animations of the rows.
/// @param database the D animations of the columns.
/// @param policy the similarity policy (default `Default_similarity{}`).
/// @param progress called on the calling thread as the work advances (see `Progress`): Q + D + Q D
/// steps, after each parallel batch of the queries' descriptions, the database's and the pairs
/// (as in the all-pairs `similarity_matrix`); default none.
/// @param threads the threads, as the all-pairs `similarity_matrix`'s (default 0).
/// @return the Q x D matrix of similarity values (not symmetric: a policy's `compare` need not be).
/// @throws animation_not_described (an invalid_input) for the first query, or else the first
/// database animation, in index order, that the policy cannot describe, naming it; invalid_input
/// as the policy does for the first failing pair.
/// @throws invalid_input when `threads` is negative or above `max_threads`, before any work.
/// @throws cancelled when `progress` or the calling thread's `Interruption_check` (threads.h)
/// returned false.
/// @par Complexity Q + D describes and Q D compares, on `threads` threads; the result does not
/// depend on their number.
template <std::ranges::random_access_range Queries, std::ranges::random_access_range Database,
          class Policy = Default_similarity>
  requires mesh::DeformingMesh<std::ranges::range_value_t<Queries>> &&
           std::same_as<std::ranges::range_value_t<Queries>, std::ranges::range_value_t<Database>> &&
           SimilarityPolicy<Policy, std::ranges::range_value_t<Queries>>
Eigen::MatrixXd similarity_matrix(const Queries& queries, const Database& database, const Policy& policy = {},
                                  const Progress& progress = {}, int threads = 0) {
  thread_count(threads, "similarity_matrix");
  const std::size_t q = std::size_t(std::ranges::size(queries)), d = std::size_t(std::ranges::size(database));
  const std::size_t total = q + d + q * d;
  const auto rows = internal::describe_all(queries, policy, 0, total, progress, threads);
  const auto columns = internal::describe_all(database, policy, q, total, progress, threads, true);
  Eigen::MatrixXd values(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(d));
  deformseg::internal::parallel_for_reporting(q * d, threads, progress, q + d, total, [&](std::size_t p) {
    values(Eigen::Index(p / d), Eigen::Index(p % d)) = policy.compare(rows[p / d], columns[p % d]).value;
  });
  return values;
}

}  // namespace deformseg::similarity

#if DEFORMSEG_COMPILED
// deformseg::compiled holds these instantiations (src/compiled/similarity.cpp): a program that
// links it compiles against their declarations. Any other type or policy instantiates where it is
// used.
#include <deformseg/mesh/default_mesh.h>

namespace deformseg::similarity {
extern template Similarity motion_similarity<mesh::Surface_mesh_animation, Default_similarity>(
    const mesh::Surface_mesh_animation&, const mesh::Surface_mesh_animation&, const Default_similarity&);
extern template Eigen::MatrixXd similarity_matrix<std::vector<mesh::Surface_mesh_animation>, Default_similarity>(
    const std::vector<mesh::Surface_mesh_animation>&, const Default_similarity&, const Progress&, int);
extern template Eigen::MatrixXd similarity_matrix<std::vector<mesh::Surface_mesh_animation>,
                                                  std::vector<mesh::Surface_mesh_animation>, Default_similarity>(
    const std::vector<mesh::Surface_mesh_animation>&, const std::vector<mesh::Surface_mesh_animation>&,
    const Default_similarity&, const Progress&, int);
extern template Eigen::MatrixXd described_similarity_matrix<Default_similarity>(
    std::span<const Motion_signature_description>, const Default_similarity&, const Progress&, int);
}  // namespace deformseg::similarity
#endif
