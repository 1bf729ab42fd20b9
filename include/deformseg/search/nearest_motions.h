/// @file search/nearest_motions.h
/// @brief `nearest_motions`: the k clips of a `MotionCollection` most similar to a query under the
/// default policy, exactly as `similarity_matrix` ranks them, most of the collection ruled out by
/// lower bounds before any alignment; `nearest_others`, a clip's k nearest others in its own
/// collection; `knn_graph`, every clip's (or a block's) k nearest others; `merge_nearest`, the
/// searches of blocks of candidates made one. The all-pairs matrix of a collection is
/// `similarity_tile.h`'s.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/search/internal/aligned_value.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/search/motion_collection.h>
#include <deformseg/search/pruning_report.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <atomic>
#include <iterator>
#include <cstddef>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace deformseg::search {

/// @brief One clip found by `nearest_motions`: its index in the collection and its similarity
/// value with the query.
struct Neighbour {
  std::size_t index = 0;  ///< the clip's index in the collection
  double value = 0;       ///< `compare(query, clip).value` (oriented as `similarity_matrix`)
  /// @brief Equal index and bit-identical value.
  bool operator==(const Neighbour&) const = default;
};

/// @brief The result of `nearest_motions` for one query.
struct Nearest_motions {
  /// @brief The `min(k, candidates)` most similar clips, by value descending and, between equal
  /// values, by index ascending: the query's row of `similarity_matrix`, stably sorted, cut at k.
  std::vector<Neighbour> neighbours;
  /// @brief How the candidates were decided.
  Pruning_report pruning;
};

/// @brief How `nearest_motions` and `knn_graph` search.
struct Nearest_motions_options {
  /// @brief How many clips to find per query. Default 10.
  std::size_t k = 10;
  /// @brief The threads (0: all the hardware's threads, `thread_count`); the result and the counts
  /// do not depend on it.
  int threads = 0;
  /// @brief Called on the calling thread after each batch of queries (see `Progress`), one step a
  /// query; default none.
  Progress progress{};
  /// @brief The clips searched (default all): a search among a block of the collection, whose
  /// results over disjoint blocks `merge_nearest` makes the search of their union.
  std::optional<Clip_range> candidates{};
};

namespace internal {

// Whether neighbour x ranks before y: greater value, then smaller index.
inline bool ranks_before(const Neighbour& x, const Neighbour& y) {
  return x.value != y.value ? x.value > y.value : x.index < y.index;
}

// The k best neighbours found so far, best first.
class Top_neighbours {
public:
  explicit Top_neighbours(std::size_t k) : k_(k) { best_.reserve(k + 1); }
  std::size_t size() const { return best_.size(); }
  bool full() const { return best_.size() >= k_; }
  // The value a candidate must reach to enter (ties enter by index, so a tie is never ruled out).
  double threshold() const { return full() && k_ > 0 ? best_.back().value : -std::numeric_limits<double>::infinity(); }
  void offer(Neighbour n) {
    if (k_ == 0 || (full() && !ranks_before(n, best_.back()))) return;
    best_.insert(std::upper_bound(best_.begin(), best_.end(), n, ranks_before), n);
    if (best_.size() > k_) best_.pop_back();
  }
  std::vector<Neighbour> take() { return std::move(best_); }

private:
  std::size_t k_;
  std::vector<Neighbour> best_;
};

// What one thread of a search reuses from candidate to candidate, so that trying one allocates
// nothing once the vectors have grown to the longest clip.
struct Search_scratch {
  std::vector<double> gaps;       // lb_rows_columns' chunk gaps, then row_bounds' per-row sums
  std::vector<double> row_bound;  // the alignment's per-row bounds
};

// The candidates taken together between two looks at the k-th best value: fixed, so that what is
// pruned (and the counts) does not depend on the number of threads.
inline constexpr std::size_t search_batch = 32;

// One query's search: the summary bound of every candidate, then the candidates in increasing
// order of it, a batch at a time, each ruled out by its rows' bound, abandoned, or aligned.
template <MotionCollection C>
class Query_search {
public:
  // `self`: the query's index when it is a clip of `collection` (left out, and each pair
  // oriented as similarity_matrix does: the lower index first); `among`: the candidates.
  Query_search(const C& collection, signatures::Motion_signature_view query, std::optional<std::size_t> self,
               Clip_range among, double unit, std::size_t k, int threads)
      : collection_(collection), query_(query), summary_(summarize(query)), summary_view_(summary_.view()),
        self_(self), among_(among), unit_(unit), k_(k), threads_(threads),
        scratch_(std::size_t(deformseg::thread_count(threads, "nearest_motions"))) {}

  Nearest_motions run() {
    const std::vector<std::size_t> order = by_summary_bound();
    Nearest_motions result;
    result.pruning.candidates = order.size();
    Top_neighbours top(k_);
    if (k_ == 0) {
      result.pruning.pruned_by_summary = order.size();
      return result;
    }
    // First the k likeliest, aligned whole, so that the k-th value prunes from the start.
    const std::vector<std::size_t> seeds = likeliest(order);
    run_batch(seeds, -std::numeric_limits<double>::infinity(), top, result.pruning);
    std::vector<std::size_t> rest;
    rest.reserve(order.size() - seeds.size());
    std::set_difference(order.begin(), order.end(), seeds.begin(), seeds.end(), std::back_inserter(rest),
                        [&](std::size_t x, std::size_t y) { return in_order(x, y); });
    std::size_t next = 0;
    while (next < rest.size()) {
      const double threshold = top.threshold();
      std::size_t end = next;
      while (end < rest.size() && end - next < search_batch && !rules_out(bound(rest[end]), threshold)) ++end;
      if (end == next) break;  // this candidate's bound rules it out, and every later one's is larger
      run_batch(std::span(rest).subspan(next, end - next), threshold, top, result.pruning);
      next = end;
    }
    result.pruning.pruned_by_summary = rest.size() - next;
    result.neighbours = top.take();
    return result;
  }

private:
  // Candidate c's summary bound and guess (bounds_ and guesses_ hold the candidates' from among_.begin).
  double bound(std::size_t c) const { return bounds_[c - among_.begin]; }
  double guess(std::size_t c) const { return guesses_[c - among_.begin]; }

  // The order of the search: by summary bound, then by index.
  bool in_order(std::size_t x, std::size_t y) const { return bound(x) != bound(y) ? bound(x) < bound(y) : x < y; }

  // The candidates, sorted by their summary bound, then by index; and each one's guess.
  std::vector<std::size_t> by_summary_bound() {
    const std::size_t n = among_.size();
    bounds_.assign(n, 0.0);
    guesses_.assign(n, 0.0);
    const Motion_summary_view query = summary_view_;
    // Clip i's summary view is made here once per search: a collection held in memory makes it
    // unchecked (its summaries were made by summarize), a store checks its row count, which a store
    // opened without its checksums is not otherwise known to hold.
    deformseg::internal::parallel_for(
        n, threads_,
        [&](std::size_t i) {
          const Motion_summary_view clip = collection_.summary(among_.begin + i);
          bounds_[i] = lb_mean(query, clip, unit_);
          guesses_[i] = internal::squared_distance(query.mean(), clip.mean());
        },
        deformseg::internal::Loop_grain{.chunk = 256, .min_parallel = 2048});
    std::vector<std::size_t> order;
    order.reserve(n);
    for (std::size_t c = among_.begin; c < among_.end; ++c)
      if (c != self_) order.push_back(c);
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return in_order(x, y); });
    return order;
  }

  // The k candidates whose mean signatures are nearest the query's (ties by index), in search order:
  // a guess, not a bound, at the k nearest.
  std::vector<std::size_t> likeliest(const std::vector<std::size_t>& order) const {
    std::vector<std::size_t> seeds = order;
    const auto by_guess = [&](std::size_t x, std::size_t y) {
      return guess(x) != guess(y) ? guess(x) < guess(y) : x < y;
    };
    const std::size_t count = std::min(k_, seeds.size());
    std::nth_element(seeds.begin(), seeds.begin() + std::ptrdiff_t(count), seeds.end(), by_guess);
    seeds.resize(count);
    std::sort(seeds.begin(), seeds.end(), [&](std::size_t x, std::size_t y) { return in_order(x, y); });
    return seeds;
  }

  static bool rules_out(double lower_bound, double threshold) { return !may_beat(lower_bound, threshold); }

  void run_batch(std::span<const std::size_t> batch, double threshold, Top_neighbours& top, Pruning_report& report) {
    values_.assign(batch.size(), std::nullopt);
    counts_.assign(batch.size(), Pruning_report{});
    // Each worker takes a scratch of its own (a loop has at most scratch_.size() workers).
    std::atomic<std::size_t> next_scratch{0};
    deformseg::internal::parallel_for_with_locals(
        batch.size(), threads_, 1, [&] { return &scratch_[next_scratch++]; },
        [&](Search_scratch* scratch, std::size_t b) {
          values_[b] = value_of(batch[b], threshold, *scratch, counts_[b]);
        });
    for (std::size_t b = 0; b < batch.size(); ++b) {
      report += counts_[b];
      if (values_[b]) top.offer({batch[b], *values_[b]});
    }
  }

  // Candidate c's value, or std::nullopt when it is proven below `threshold` (counted in `report`).
  std::optional<double> value_of(std::size_t c, double threshold, Search_scratch& scratch,
                                 Pruning_report& report) const {
    const signatures::Motion_signature_view clip = collection_.view(c);
    const bool query_first = !self_ || *self_ < c;
    const signatures::Motion_signature_view a = query_first ? query_ : clip, b = query_first ? clip : query_;
    if (threshold == -std::numeric_limits<double>::infinity()) return aligned_value(a, b, unit_, {}, {}, report);
    const Motion_summary_view clip_summary = collection_.summary(c);
    const std::size_t chunks = summary_view_.chunks() + clip_summary.chunks();
    if (scratch.gaps.size() < std::max(chunks, a.rows)) scratch.gaps.resize(std::max(chunks, a.rows));
    if (rules_out(lb_rows_columns(summary_view_, clip_summary, unit_, scratch.gaps), threshold)) {
      ++report.pruned_by_rows;
      return std::nullopt;
    }
    if (scratch.row_bound.size() < a.rows) scratch.row_bound.resize(a.rows);
    const std::span<double> row_bound = std::span(scratch.row_bound).first(a.rows);
    row_bounds(a, query_first ? clip_summary : summary_view_, unit_, row_bound, scratch.gaps);
    // Bounds of the reference dissimilarity made bounds of the kernel's, which may be a little lower.
    for (double& r : row_bound) r = std::max(0.0, safe_lower_bound(r));
    return aligned_value(a, b, unit_, threshold, row_bound, report);
  }

  const C& collection_;
  signatures::Motion_signature_view query_;
  Motion_summary summary_;
  Motion_summary_view summary_view_;  // of summary_, checked once
  std::optional<std::size_t> self_;
  Clip_range among_;
  double unit_;
  std::size_t k_;
  int threads_;
  std::vector<double> bounds_, guesses_;  // of the candidates among_, from among_.begin
  std::vector<Search_scratch> scratch_;  // one per worker of a batch
  std::vector<std::optional<double>> values_;  // a batch's values
  std::vector<Pruning_report> counts_;         // a batch's counts
};

// The candidates `options` names, checked, naming `who`.
template <MotionCollection C>
Clip_range candidates_of(const C& collection, const Nearest_motions_options& options, const char* who) {
  const Clip_range among = options.candidates.value_or(all_clips(collection));
  check_range(collection, among, who, "candidates");
  return among;
}

// Clip i's search among the others of `among`: the one code path of `nearest_others` and of
// every row of `knn_graph`.
template <MotionCollection C>
Nearest_motions search_others(const C& collection, std::size_t i, Clip_range among, double unit, std::size_t k,
                              int threads) {
  return Query_search<C>(collection, collection.view(i), i, among, unit, k, threads).run();
}

}  // namespace internal

/// @brief The `options.k` clips of `collection` most similar to `query` under `policy` (the
/// default policy, `Motion_signature_similarity<>`), each with its value
/// `policy.compare(query, clip).value`, bit for bit, ranked by value descending and then by index:
/// exactly the query's row of `similarity_matrix(queries, database)`, stably sorted.
///
/// Exact, and fast because most clips are never aligned: every clip's summary gives a lower
/// bound of its dissimilarity (`lb_mean`). First the k clips whose mean signatures are nearest
/// the query's are aligned whole, a guess at the nearest that makes the k-th best value high from
/// the start; then the others are tried in increasing order of their bound, and the search stops
/// at the first whose bound proves it cannot reach the k-th value (nor can any after it). A clip
/// tried is first bounded by its rows (`lb_rows_columns`), then aligned by the value pass of
/// `alignment::Dtw::mean_cost`, which abandons once it is proven below the k-th value. Ties with
/// the k-th value are never ruled out, so ties rank as in the matrix. Clips are tried 32 at a time
/// between two looks at the k-th value, whatever the number of threads, so the result and
/// `Nearest_motions::pruning` are the same on any number.
/// @param query the query's signatures: `view(policy.describe(animation))`, or a clip of a
/// collection (then it is found too, at value 1: see `nearest_others` to leave it out).
/// @param collection a `MotionCollection` described with `policy`'s options.
/// @param options k (default 10), threads.
/// @param policy the scale and alignment of the values (default: the default policy's); its
/// alignment must have no window.
/// @throws invalid_input when the query has no row or another width than the collection's, or
/// when `policy` has a window.
/// @throws cancelled as `similarity_matrix`.
/// @par Complexity O(N W) for the bounds of N clips of width W and O(N log N) to order them,
/// then, for each clip not ruled out, O(K^2 W) for its rows' bound and O(n m W) at most for its
/// alignment (n, m rows); how many are ruled out depends on the data (the manual's chapter 7
/// gives figures). O(N) memory beyond the collection.
template <MotionCollection C>
Nearest_motions nearest_motions(signatures::Motion_signature_view query, const C& collection,
                                const Nearest_motions_options& options = {},
                                const similarity::Motion_signature_similarity<>& policy = {}) {
  internal::check_query(collection, query, "nearest_motions");
  const double unit = internal::search_unit(policy, query.width, "nearest_motions");
  const Clip_range among = internal::candidates_of(collection, options, "nearest_motions");
  return internal::Query_search<C>(collection, query, std::nullopt, among, unit, options.k, options.threads).run();
}

/// @brief The `options.k` clips of `collection` most similar to its own clip `i`, clip i left out:
/// row i of `similarity_matrix(collection)` less its diagonal, ranked as `nearest_motions` ranks
/// (value descending, then index ascending), cut at k; each value is the matrix's entry, bit for bit,
/// so each pair is oriented as the matrix orients it (`compare(clip min(i, j), clip max(i, j))`).
///
/// The search of `nearest_motions` with clip i as the query, but clip i is no candidate: it is
/// neither searched nor counted in `Nearest_motions::pruning` (`candidates` is `size() - 1`). Row
/// i of `knn_graph` is this search, the same code path: the same neighbours, values and counts.
/// @param collection a `MotionCollection` described with `policy`'s options.
/// @param i the clip whose neighbours are wanted. @pre `i < collection.size()` (checked).
/// @param options k (default 10; fewer neighbours when the collection holds at most k others),
/// threads (default 0: all the hardware's threads (`thread_count`); the result and the counts do not depend on it); its
/// progress is not called (one query).
/// @param policy the scale and alignment of the values (default: the default policy's); no window.
/// @throws invalid_input when `i` is not a clip of `collection`, or when `policy` has a window.
/// @throws cancelled as `similarity_matrix`.
/// @par Complexity as `nearest_motions` over the N - 1 other clips: O(N W) for their summary
/// bounds, O(N log N) to order them, and the alignments the bounds do not rule out.
/// @par Example
/// @include nearest_others.cpp
template <MotionCollection C>
Nearest_motions nearest_others(const C& collection, std::size_t i, const Nearest_motions_options& options = {},
                               const similarity::Motion_signature_similarity<>& policy = {}) {
  if (i >= collection.size())
    throw invalid_input("nearest_others: no clip " + std::to_string(i) + ": the collection holds " +
                        std::to_string(collection.size()));
  const double unit = internal::search_unit(policy, collection.view(i).width, "nearest_others");
  const Clip_range among = internal::candidates_of(collection, options, "nearest_others");
  return internal::search_others(collection, i, among, unit, options.k, options.threads);
}

/// @brief The `options.k` nearest other clips (itself left out) of each clip of `rows`: row i of
/// the k-nearest-neighbour graph for i in `rows`, exactly `nearest_others(collection, i, options,
/// policy)`, each pair's value that of `similarity_matrix` over the collection's clips (entry (i, j)
/// for i < j is `compare(clip i, clip j)`, and so is entry (j, i)).
///
/// A block of rows is the unit of work a cluster hands out: the graph of the whole collection is
/// the concatenation of the graphs of consecutive blocks, whatever their sizes. With
/// `options.candidates`, each row is searched among those clips only; `merge_nearest` of the rows
/// found among disjoint blocks of candidates gives the rows found among their union.
/// @param collection a `MotionCollection` described with `policy`'s options.
/// @param rows the clips whose neighbours are wanted. @pre `rows.end <= collection.size()` (checked).
/// @param options k (default 10), threads (the rows are searched in parallel, each as
/// `nearest_others` searches on one thread; the result and the counts do not depend on it),
/// progress (one step a row), candidates (default all).
/// @param policy the scale and alignment of the values (default: the default policy's); no window.
/// @throws invalid_input when `rows` or the candidates are not blocks of the collection, or when
/// `policy` has a window.
/// @throws cancelled as `similarity_matrix`.
/// @par Complexity `rows.size()` searches as `nearest_motions` over the candidates.
/// @par Example
/// @include knn_tiles.cpp
template <MotionCollection C>
std::vector<Nearest_motions> knn_graph(const C& collection, Clip_range rows,
                                       const Nearest_motions_options& options = {},
                                       const similarity::Motion_signature_similarity<>& policy = {}) {
  internal::check_range(collection, rows, "knn_graph", "rows");
  const Clip_range among = internal::candidates_of(collection, options, "knn_graph");
  std::vector<Nearest_motions> graph(rows.size());
  if (rows.size() == 0) return graph;
  const double unit = internal::search_unit(policy, collection.view(rows.begin).width, "knn_graph");
  deformseg::internal::parallel_for_reporting(
      rows.size(), options.threads, options.progress, 0, rows.size(), [&](std::size_t r) {
        graph[r] = internal::search_others(collection, rows.begin + r, among, unit, options.k, 1);
      });
  return graph;
}

/// @brief Every clip's `options.k` nearest other clips of `collection` (itself left out): the
/// k-nearest-neighbour graph, one `Nearest_motions` per clip, `knn_graph(collection,
/// all_clips(collection), options, policy)`; row i is exactly `nearest_others(collection, i,
/// options, policy)`.
/// @par Complexity N searches as `nearest_motions`: O(N^2 W) for the summary bounds, and the
/// alignments the bounds do not rule out.
template <MotionCollection C>
std::vector<Nearest_motions> knn_graph(const C& collection, const Nearest_motions_options& options = {},
                                       const similarity::Motion_signature_similarity<>& policy = {}) {
  return knn_graph(collection, all_clips(collection), options, policy);
}

/// @brief One query's neighbours found among disjoint blocks of candidates (`parts`, in any order),
/// made the neighbours found among their union: the `k` best of all, by value descending and then
/// by index ascending (the ranking of every search), and the counts summed.
///
/// The neighbours equal, value for value, those of one search among the union (the k best of a
/// union are among the k best of its parts); the counts are those of the separate searches, which
/// prune less than one search does.
/// @param parts the results of one query's searches (`nearest_motions`, `nearest_others` or a row of
/// `knn_graph`) with the same k or more, among disjoint candidates. @pre no clip in two parts.
/// @param k the neighbours kept.
/// @par Complexity O(P log P) for the P neighbours of the parts.
inline Nearest_motions merge_nearest(std::span<const Nearest_motions> parts, std::size_t k) {
  Nearest_motions merged;
  for (const Nearest_motions& part : parts) {
    merged.neighbours.insert(merged.neighbours.end(), part.neighbours.begin(), part.neighbours.end());
    merged.pruning += part.pruning;
  }
  std::sort(merged.neighbours.begin(), merged.neighbours.end(), internal::ranks_before);
  if (merged.neighbours.size() > k) merged.neighbours.resize(k);
  return merged;
}

}  // namespace deformseg::search
