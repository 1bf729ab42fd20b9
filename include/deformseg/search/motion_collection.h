/// @file search/motion_collection.h
/// @brief The `MotionCollection` concept, what the nearest-motion search reads (each clip's
/// signatures and summary, by index), `Motion_collection`, its model over descriptions held in
/// memory (`store::Motion_store` models it over a store on disk), and `Clip_range`, a block of
/// consecutive clips, the unit of the tiles a cluster computes.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <concepts>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::search {

/// @brief A numbered set of described clips, as the search reads it: `c.size()` clips, clip i's
/// signatures as `c.view(i)` (a `Motion_signature_view`, every clip of the same width) and its
/// summary as `c.summary(i)` (a `Motion_summary_view` of `summarize(c.view(i))`, made once when
/// the clip was added). Views stay valid while the collection lives and is not changed.
/// See @ref MotionCollectionConcept.
template <class C>
concept MotionCollection = requires(const C& c, std::size_t i) {
  { c.size() } -> std::convertible_to<std::size_t>;
  { c.view(i) } -> std::same_as<signatures::Motion_signature_view>;
  { c.summary(i) } -> std::convertible_to<Motion_summary_view>;
};

/// @brief A `MotionCollection` of descriptions held in memory: the descriptions of
/// `Motion_signature_similarity` (its default options, or any of one width), each summarised
/// once as it is added.
/// @par Example
/// @include nearest_motions.cpp
class Motion_collection {
public:
  /// @brief An empty collection.
  Motion_collection() = default;

  /// @brief The collection of `descriptions`, in their order.
  /// @throws invalid_input as `add`.
  /// @par Complexity O(R W) per description of R rows and W values per row.
  explicit Motion_collection(std::vector<similarity::Motion_signature_description> descriptions) {
    descriptions_.reserve(descriptions.size());
    for (auto& d : descriptions) add(std::move(d));
  }

  /// @brief Adds `description` as clip `size()`.
  /// @throws invalid_input when it has no row, or not the width of the clips already in.
  /// @par Complexity O(R W).
  void add(similarity::Motion_signature_description description) {
    const std::size_t rows = std::size_t(description.signatures.rows()),
                      width = std::size_t(description.signatures.cols());
    if (rows == 0 || width == 0)
      throw invalid_input("Motion_collection: clip " + std::to_string(size()) + " has no signature");
    if (!descriptions_.empty() && width != std::size_t(descriptions_.front().signatures.cols()))
      throw invalid_input("Motion_collection: clip " + std::to_string(size()) + " has signatures of " +
                          std::to_string(width) + " values, the collection's have " +
                          std::to_string(descriptions_.front().signatures.cols()));
    descriptions_.push_back(std::move(description));
    summaries_.push_back(summarize(similarity::view(descriptions_.back())));
  }

  /// @brief The number of clips.
  std::size_t size() const { return descriptions_.size(); }
  /// @brief Clip `i`'s signatures. @pre `i < size()` (not checked).
  signatures::Motion_signature_view view(std::size_t i) const { return similarity::view(descriptions_[i]); }
  /// @brief Clip `i`'s summary, not checked again: `summarize` made it. @pre `i < size()` (not checked).
  Motion_summary_view summary(std::size_t i) const {
    const Motion_summary& s = summaries_[i];
    return Motion_summary_view::unchecked(s.floats, s.width, s.chunks);
  }
  /// @brief Clip `i`'s description. @pre `i < size()` (not checked).
  const similarity::Motion_signature_description& description(std::size_t i) const { return descriptions_[i]; }

private:
  std::vector<similarity::Motion_signature_description> descriptions_;
  std::vector<Motion_summary> summaries_;
};

static_assert(MotionCollection<Motion_collection>);

/// @brief Clips `begin` to `end - 1` of a collection: a block of rows or columns of a tile of the
/// similarity matrix (`similarity_tile`), or the candidates of a search
/// (`Nearest_motions_options::candidates`).
struct Clip_range {
  std::size_t begin = 0;  ///< the first clip
  std::size_t end = 0;    ///< one past the last clip; `begin <= end`
  /// @brief The number of clips, `end - begin`.
  std::size_t size() const { return end - begin; }
  /// @brief Whether clip `i` is in the block.
  bool contains(std::size_t i) const { return begin <= i && i < end; }
  /// @brief Equal bounds.
  bool operator==(const Clip_range&) const = default;
};

/// @brief Every clip of `collection`: `{0, collection.size()}`.
template <MotionCollection C>
Clip_range all_clips(const C& collection) {
  return {0, collection.size()};
}

namespace internal {

// Refuses, naming `who` and `what` (rows, columns, candidates), a block that is not one of the
// collection's.
template <MotionCollection C>
void check_range(const C& collection, Clip_range range, const char* who, const char* what) {
  if (range.begin > range.end || range.end > collection.size())
    throw invalid_input(std::string(who) + ": the " + what + " [" + std::to_string(range.begin) + ", " +
                        std::to_string(range.end) + ") are not clips of the collection, which holds " +
                        std::to_string(collection.size()));
}

// Refuses, naming `who`, a query of no row or of another width than the collection's clips.
template <MotionCollection C>
void check_query(const C& collection, signatures::Motion_signature_view query, const char* who) {
  if (query.rows == 0) throw invalid_input(std::string(who) + ": the query has no signature");
  if (collection.size() > 0 && query.width != collection.view(0).width)
    throw invalid_input(std::string(who) + ": the query's signatures have " + std::to_string(query.width) +
                        " values, the collection's " + std::to_string(collection.view(0).width));
}

}  // namespace internal

}  // namespace deformseg::search
