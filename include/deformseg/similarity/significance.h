/// @file similarity/significance.h
/// @brief `similarity_significance`: how far a similarity value stands above those of copies of
/// the second animation with its frames shuffled, as a z-score; and `reordered_frames`, the
/// customisation point that shuffles a policy's description.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/internal/random.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <concepts>
#include <span>
#include <vector>

namespace deformseg::similarity {

/// @brief The frames (rows) of a per-frame description in the order `order` gives: row t of the
/// result is row `order[t]` of `frames`. The overload for the descriptions that are matrices with
/// a row per frame (`Motion_signature_similarity`, `Strain_distribution_similarity`); a policy
/// with another description provides its own overload in its namespace (found by
/// argument-dependent lookup), as `Self_similarity_matching` does.
/// @pre every entry of `order` is below `frames.rows()` (not checked).
template <class Scalar, int Options>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Options> reordered_frames(
    const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Options>& frames, std::span<const std::size_t> order) {
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Options> out(Eigen::Index(order.size()), frames.cols());
  for (std::size_t t = 0; t < order.size(); ++t) out.row(Eigen::Index(t)) = frames.row(Eigen::Index(order[t]));
  return out;
}

/// @brief The number of frames of a per-frame description: its rows.
template <class Scalar, int Options>
std::size_t frame_count(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Options>& frames) {
  return std::size_t(frames.rows());
}

/// @brief A description whose frames can be shuffled: `frame_count(d)` and
/// `reordered_frames(d, order)` exist for it (the library's per-frame descriptions: motion
/// signatures, strain histograms, self-similarity). `similarity_significance` takes these; a
/// front end asks this concept, looked up here, rather than calling the two functions itself.
/// @par Example
/// @include reorderable_description.cpp
template <class Description>
concept ReorderableDescription = requires(const Description& d, std::span<const std::size_t> order) {
  { frame_count(d) } -> std::convertible_to<std::size_t>;
  { reordered_frames(d, order) } -> std::convertible_to<Description>;
};

/// @brief A policy that scores many reorderings of one description against another faster than
/// one `compare` each: `p.reordering_comparison(a, b)` returns a function object `c` such that
/// `c(order)` is `p.compare(a, reordered_frames(b, order)).value` bit for bit, its shared work
/// (such as the frame dissimilarities, which a reordering only permutes) done once.
/// `similarity_significance` uses it when the policy offers it (`Motion_signature_similarity`
/// does); otherwise it compares each shuffled copy.
template <class Policy, class Description>
concept ReorderingComparison = requires(const Policy& p, const Description& d, std::span<const std::size_t> order) {
  { p.reordering_comparison(d, d)(order) } -> std::convertible_to<double>;
};

/// @brief The significance of `policy.compare(a, b).value`: its z-score against `copies` copies of
/// `b` whose frames are shuffled by `random`, `(value - mean) / standard deviation` of theirs.
///
/// A shuffled copy keeps every frame and loses their order, so the z-score says how much of the
/// value comes from the frames coming in the same order, beyond alike frames alone: a high value
/// with a low z-score means alike poses or rhythms in another order. Deterministic for a given
/// generator state (the caller passes it, so runs repeat exactly), and the same with every
/// standard library: the shuffles are deformseg's own (Fisher-Yates on draws of the generator's
/// bits), not `std::shuffle`, whose algorithm each library chooses. The shuffles are drawn in
/// order from `random`, each from the one before (up to 64 at a time), and only then scored,
/// on `threads` threads, so the z-score and the generator's state after the call do not depend
/// on the number of threads.
/// @tparam Policy a `SimilarityPolicy` whose `Description` is a `ReorderableDescription`; its
/// `compare` (or its `reordering_comparison`'s calls) may run on several threads at once.
/// @tparam Random a generator of 32 or 64 uniform bits: `std::mt19937` or `std::mt19937_64`.
/// @param policy the policy that compares `a` with `b` and with each shuffled copy of `b`.
/// @param a, b the descriptions; `b`'s frames are shuffled.
/// @param copies how many shuffled copies, at least 2.
/// @param random the generator of the shuffles, advanced by them.
/// @param threads the threads that score the copies: 0 (default) for the environment's count or
/// all the hardware's (`thread_count`), else 1 to `max_threads`. The result does not depend on it.
/// @return the z-score; 0 when the copies all score the same (no spread).
/// @throws invalid_input when `copies < 2` or `threads` is out of range (before any draw), or as
/// `compare`; `cancelled` when an `Interruption_scope` of the calling thread stops the copies.
/// @par Complexity `copies + 1` compares; with a policy that models `ReorderingComparison`, one
/// compare, one `reordering_comparison` and `copies` of its calls (for `Motion_signature_similarity`,
/// the frame dissimilarities once and `copies` alignments' scores and lengths, no path: the values
/// are the same). Memory: up to 64 orders of `frame_count(b)` indices, and what the copies scored
/// at once take.
template <class Policy, ReorderableDescription Description, deformseg::internal::Bits_generator Random>
double similarity_significance(const Policy& policy, const Description& a, const Description& b, std::size_t copies,
                               Random& random, int threads = 0) {
  if (copies < 2) throw invalid_input("similarity_significance: fewer than 2 shuffled copies");
  threads = thread_count(threads, "similarity_significance");
  const double value = policy.compare(a, b).value;
  const std::size_t frames = frame_count(b);
  std::vector<std::size_t> order(frames);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::vector<double> shuffled(copies);
  // A batch of orders drawn one after the other, then scored in parallel: the draws stay in the
  // order of the copies, and the memory bounded however many copies are asked for.
  constexpr std::size_t batch = 64;
  std::vector<std::size_t> orders(std::min(copies, batch) * frames);
  const auto score_copies = [&](const auto& value_of) {
    for (std::size_t first = 0; first < copies; first += batch) {
      const std::size_t count = std::min(batch, copies - first);
      for (std::size_t c = 0; c < count; ++c) {
        deformseg::internal::shuffle(order.begin(), order.end(), random);
        std::copy(order.begin(), order.end(), orders.begin() + std::ptrdiff_t(c * frames));
      }
      deformseg::internal::parallel_for(count, threads, [&](std::size_t c) {
        shuffled[first + c] = value_of(std::span<const std::size_t>(orders.data() + c * frames, frames));
      });
    }
  };
  if constexpr (ReorderingComparison<Policy, Description>)
    score_copies(policy.reordering_comparison(a, b));
  else
    score_copies([&](std::span<const std::size_t> o) { return policy.compare(a, reordered_frames(b, o)).value; });
  const double mean = std::accumulate(shuffled.begin(), shuffled.end(), 0.0) / double(copies);
  double square = 0;
  for (double v : shuffled) square += (v - mean) * (v - mean);
  const double deviation = std::sqrt(square / double(copies - 1));
  return deviation > 0 ? (value - mean) / deviation : 0.0;
}

}  // namespace deformseg::similarity
