/// @file evaluation/retrieval_evaluation.h
/// @brief How well a similarity matrix retrieves the same motion on other bodies
/// (`evaluate_retrieval`): nearest-neighbour accuracy, mean average precision, ROC-AUC, medians
/// and the confusion table.
#pragma once

#include <deformseg/exceptions.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::evaluation {

/// @brief The motion label of an item that is compared but never queried (a distractor).
inline constexpr const char* distractor_label = "-";

/// @brief What is known of one animation of a retrieval evaluation.
struct Labelled_item {
  std::string motion{};  ///< its motion class ("walk", ...); `distractor_label` for a distractor
  std::string body{};    ///< the character it animates; candidates of a query are of other bodies
  /// @brief The skeleton it shares with other bodies, whose clips of one name are then the same
  /// data; empty (default) for none.
  std::string rig{};
  std::string clip{};  ///< the clip's name in its file (maybe empty)
};

/// @brief The nearest-neighbour figures of the queries of one motion.
struct Motion_retrieval {
  std::string motion{};      ///< the queries' motion
  std::size_t queries = 0;   ///< queries of that motion that have a candidate
  std::size_t correct = 0;   ///< of them, those whose nearest candidate has the same motion
  double nn_accuracy = 0;    ///< `correct / queries`
};

/// @brief What one query found: its nearest candidate, and how far down its ranking the first
/// candidate of its motion came, to see which clips a policy takes for which.
struct Query_retrieval {
  std::size_t query = 0;          ///< the query's index among the items
  std::size_t nearest = 0;        ///< the index of its nearest candidate (the first ranked)
  double nearest_similarity = 0;  ///< their similarity
  /// @brief The rank of its first relevant candidate, 1 for the nearest; empty when it has none.
  std::optional<std::size_t> first_relevant_rank{};
  /// @brief Its average precision; empty when it has no relevant candidate.
  std::optional<double> average_precision{};
};

/// @brief The figures of `evaluate_retrieval`. Empty optionals where a figure has nothing to
/// average over (no query, no relevant candidate, no pair of a kind).
struct Retrieval_scores {
  /// @brief Queries evaluated: items that are not distractors and have at least one candidate.
  std::size_t queries = 0;
  /// @brief Of them, those without a relevant candidate (left out of `mean_average_precision`).
  std::size_t queries_without_relevant = 0;
  /// @brief Non-distractor items left out for having no candidate at all.
  std::size_t queries_without_candidate = 0;
  /// @brief The fraction of queries whose nearest candidate has the query's motion.
  std::optional<double> nn_accuracy{};
  /// @brief The mean over the queries with a relevant candidate of their average precision.
  std::optional<double> mean_average_precision{};
  /// @brief The probability that a same-motion (query, candidate) pair is more similar than a
  /// different-motion one, ties counting 1/2, over all pairs of all queries.
  std::optional<double> roc_auc{};
  std::optional<double> median_same{};       ///< median similarity of the same-motion pairs
  std::optional<double> median_different{};  ///< median similarity of the different-motion pairs
  std::size_t same_pairs = 0;       ///< number of same-motion (query, candidate) pairs
  std::size_t different_pairs = 0;  ///< number of different-motion (query, candidate) pairs
  /// @brief Every motion of the items (distractor label included), sorted: the rows and columns
  /// of `confusion`.
  std::vector<std::string> labels{};
  /// @brief `confusion[r][c]`: queries of motion `labels[r]` whose nearest candidate has motion
  /// `labels[c]`.
  std::vector<std::vector<std::size_t>> confusion{};
  /// @brief Per query motion (sorted), the nearest-neighbour accuracy.
  std::vector<Motion_retrieval> per_motion{};
  /// @brief Per query (the `queries` of them, in the items' order), what it found.
  std::vector<Query_retrieval> per_query{};
};

namespace internal::retrieval {

inline bool is_candidate(const Labelled_item& query, const Labelled_item& other) {
  if (other.body == query.body) return false;
  // The same clip of a shared rig is the same motion data on another mesh: too easy a match.
  return !(!query.rig.empty() && other.rig == query.rig && other.clip == query.clip);
}

inline std::optional<double> median(std::vector<double> values) {
  if (values.empty()) return std::nullopt;
  std::ranges::sort(values);
  const std::size_t m = values.size() / 2;
  return values.size() % 2 ? values[m] : (values[m - 1] + values[m]) / 2;
}

// Mann-Whitney: the fraction of (same, different) pairs with same > different, ties 1/2, by one
// merge of the two sorted lists.
inline std::optional<double> roc_auc(std::vector<double> same, std::vector<double> different) {
  if (same.empty() || different.empty()) return std::nullopt;
  std::ranges::sort(same);
  std::ranges::sort(different);
  double wins = 0;
  std::size_t below = 0, equal_end = 0;  // different[0, below) < s, different[below, equal_end) == s
  for (const double s : same) {
    while (below < different.size() && different[below] < s) ++below;
    equal_end = std::max(equal_end, below);
    while (equal_end < different.size() && different[equal_end] == s) ++equal_end;
    wins += double(below) + 0.5 * double(equal_end - below);
  }
  return wins / (double(same.size()) * double(different.size()));
}

// The candidates by decreasing similarity, ties by increasing index.
inline std::vector<std::size_t> ranked(const Eigen::MatrixXd& similarity, std::size_t query,
                                       std::vector<std::size_t> candidates) {
  const auto row = Eigen::Index(query);
  std::ranges::stable_sort(candidates, [&](std::size_t a, std::size_t b) {
    return similarity(row, Eigen::Index(a)) > similarity(row, Eigen::Index(b));
  });
  return candidates;
}

// Mean over the relevant candidates of the precision at their rank; nullopt without any.
inline std::optional<double> average_precision(std::span<const std::size_t> ranking,
                                               std::span<const Labelled_item> items, const std::string& motion) {
  double sum = 0;
  std::size_t relevant = 0;
  for (std::size_t rank = 0; rank < ranking.size(); ++rank)
    if (items[ranking[rank]].motion == motion) sum += double(++relevant) / double(rank + 1);
  if (relevant == 0) return std::nullopt;
  return sum / double(relevant);
}

inline void check_input(const Eigen::MatrixXd& similarity, std::span<const Labelled_item> items) {
  if (similarity.rows() != similarity.cols() || std::size_t(similarity.rows()) != items.size())
    throw invalid_input("evaluate_retrieval: the similarity matrix is " + std::to_string(similarity.rows()) + " x " +
                        std::to_string(similarity.cols()) + " for " + std::to_string(items.size()) + " items");
  for (Eigen::Index i = 0; i < similarity.rows(); ++i)
    for (Eigen::Index j = 0; j < similarity.cols(); ++j)
      if (!std::isfinite(similarity(i, j)))
        throw invalid_input("evaluate_retrieval: entry (" + std::to_string(i) + ", " + std::to_string(j) +
                            ") of the similarity matrix is not finite");
}

inline std::size_t label_index(const std::vector<std::string>& labels, const std::string& motion) {
  return std::size_t(std::ranges::lower_bound(labels, motion) - labels.begin());
}

inline std::vector<std::string> sorted_labels(std::span<const Labelled_item> items) {
  std::vector<std::string> labels;
  for (const auto& item : items) labels.push_back(item.motion);
  std::ranges::sort(labels);
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  return labels;
}

inline std::vector<Motion_retrieval> per_motion(const Retrieval_scores& scores) {
  std::vector<Motion_retrieval> result;
  for (std::size_t r = 0; r < scores.labels.size(); ++r) {
    const auto& row = scores.confusion[r];
    const std::size_t queries = std::accumulate(row.begin(), row.end(), std::size_t(0));
    if (queries == 0) continue;
    result.push_back({.motion = scores.labels[r], .queries = queries, .correct = row[r],
                      .nn_accuracy = double(row[r]) / double(queries)});
  }
  return result;
}

}  // namespace internal::retrieval

/// @brief `evaluate_retrieval` with only some items as queries, each against its candidates among
/// all the items: the figures of a group of clips (a pack, a rig) in a whole library, the group's
/// clips as queries, every clip of another body as a candidate. Distractors among `queries` are
/// not queried, as in `evaluate_retrieval`; `labels` and `confusion` list every item's motion.
/// @param similarity the N x N matrix, as `evaluate_retrieval`'s (only the queries' rows are read).
/// @param items the N items, in the order of the matrix's rows and columns.
/// @param queries the indices of the items that may be queries, increasing.
/// @return the figures over those queries (see `Retrieval_scores`).
/// @pre as `evaluate_retrieval`.
/// @throws invalid_input as `evaluate_retrieval`, or for an index of `queries` beyond the items or
/// not above the one before.
/// @par Complexity O(Q N log N) for Q queries: a sort of each query's candidates; then a sort of
/// the pairs.
/// @par Example
/// @include evaluate_retrieval.cpp
inline Retrieval_scores evaluate_retrieval(const Eigen::MatrixXd& similarity, std::span<const Labelled_item> items,
                                           std::span<const std::size_t> queries) {
  namespace r = internal::retrieval;
  r::check_input(similarity, items);
  for (std::size_t k = 0; k < queries.size(); ++k)
    if (queries[k] >= items.size() || (k > 0 && queries[k] <= queries[k - 1]))
      throw invalid_input("evaluate_retrieval: query " + std::to_string(k) + " is item " + std::to_string(queries[k]) +
                          ", not an increasing index below the " + std::to_string(items.size()) + " items");
  Retrieval_scores scores;
  scores.labels = r::sorted_labels(items);
  scores.confusion.assign(scores.labels.size(), std::vector<std::size_t>(scores.labels.size(), 0));
  std::vector<double> same, different;
  double precision_sum = 0, correct = 0;
  for (const std::size_t q : queries) {
    const Labelled_item& query = items[q];
    if (query.motion == distractor_label) continue;
    std::vector<std::size_t> candidates;
    for (std::size_t c = 0; c < items.size(); ++c)
      if (c != q && r::is_candidate(query, items[c])) candidates.push_back(c);
    if (candidates.empty()) {
      ++scores.queries_without_candidate;
      continue;
    }
    ++scores.queries;
    for (const std::size_t c : candidates)
      (items[c].motion == query.motion ? same : different).push_back(similarity(Eigen::Index(q), Eigen::Index(c)));
    const std::vector<std::size_t> ranking = r::ranked(similarity, q, std::move(candidates));
    const std::string& nearest = items[ranking.front()].motion;
    correct += nearest == query.motion;
    ++scores.confusion[r::label_index(scores.labels, query.motion)][r::label_index(scores.labels, nearest)];
    const auto first_relevant =
        std::ranges::find_if(ranking, [&](std::size_t c) { return items[c].motion == query.motion; });
    const std::optional<double> ap = r::average_precision(ranking, items, query.motion);
    if (ap) precision_sum += *ap;
    else ++scores.queries_without_relevant;
    scores.per_query.push_back(
        {.query = q,
         .nearest = ranking.front(),
         .nearest_similarity = similarity(Eigen::Index(q), Eigen::Index(ranking.front())),
         .first_relevant_rank = first_relevant == ranking.end()
                                    ? std::nullopt
                                    : std::optional(std::size_t(first_relevant - ranking.begin()) + 1),
         .average_precision = ap});
  }
  if (scores.queries > 0) scores.nn_accuracy = correct / double(scores.queries);
  if (const std::size_t with_relevant = scores.queries - scores.queries_without_relevant; with_relevant > 0)
    scores.mean_average_precision = precision_sum / double(with_relevant);
  scores.same_pairs = same.size();
  scores.different_pairs = different.size();
  scores.median_same = r::median(same);
  scores.median_different = r::median(different);
  scores.roc_auc = r::roc_auc(std::move(same), std::move(different));
  scores.per_motion = r::per_motion(scores);
  return scores;
}

/// @brief How well `similarity` retrieves, for each labelled animation, the animations of the
/// same motion on other bodies.
///
/// Each item whose motion is not `distractor_label` is a query. Its candidates are every other
/// item of another body, except those with the query's clip name on the query's rig (when the rig
/// is not empty: a clip shared by a rig is the same data). Distractors are candidates, never
/// queries. A candidate is relevant when it has the query's motion. Ranking the candidates by
/// decreasing similarity (ties: the lower index first), the query's nearest neighbour is the first
/// candidate and its average precision the mean, over its relevant candidates, of the fraction of
/// relevant ones among those ranked up to it. ROC-AUC and the medians are over all (query,
/// candidate) pairs of all queries: same-motion pairs against different-motion pairs (a pair of
/// two queries counts once in each direction).
/// @param similarity the N x N matrix, row = query, column = candidate; higher is more alike
/// (need not be symmetric: only row q is read for query q).
/// @param items the N items, in the order of the matrix's rows and columns.
/// @return the figures (see `Retrieval_scores`); per query, its nearest neighbour and the rank of
/// its first relevant candidate in `per_query`.
/// @pre `similarity` is N x N with finite entries, N = `items.size()`.
/// @throws invalid_input naming the shapes or the first non-finite entry otherwise.
/// @par Complexity O(N^2 log N): per query a sort of its candidates; then a sort of the pairs.
inline Retrieval_scores evaluate_retrieval(const Eigen::MatrixXd& similarity, std::span<const Labelled_item> items) {
  std::vector<std::size_t> all(items.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  return evaluate_retrieval(similarity, items, all);
}

}  // namespace deformseg::evaluation
