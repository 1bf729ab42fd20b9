/// @file search/similarity_tile.h
/// @brief `similarity_tile`: a tile of the all-pairs similarity matrix of a `MotionCollection`'s clips
/// under the default policy, each pair aligned once, the unit of work a cluster hands out; and the
/// whole matrix of a collection (`similarity_matrix`), its one tile.
#pragma once

#include <deformseg/internal/parallel_for.h>
#include <deformseg/search/internal/aligned_value.h>
#include <deformseg/search/motion_collection.h>
#include <deformseg/search/pruning_report.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace deformseg::search {

/// @brief A tile of the similarity matrix of `collection`'s clips under `policy` (default the
/// default policy): entry (a, b) is entry (rows.begin + a, columns.begin + b) of
/// `similarity_matrix(collection)`, bit for bit; entry (i, j) is `policy.compare(clip min(i, j),
/// clip max(i, j)).value`.
///
/// A tile is the unit of work a cluster hands out: the tiles of a partition of the rows and of the
/// columns make up the matrix, and since it is symmetric the tiles on and above the diagonal
/// suffice. A pair whose two entries are in the tile is aligned once.
/// @param collection a `MotionCollection` described with `policy`'s options.
/// @param rows, columns the tile's clips. @pre both end at most at `collection.size()` (checked).
/// @param policy the scale and alignment of the values (default: the default policy's); no window.
/// @param progress one step a pair aligned (see `Progress`); default none.
/// @param threads the threads (default 0: all the hardware's threads (`thread_count`)); the values do not depend on it.
/// @throws invalid_input when `rows` or `columns` are not blocks of the collection, or when `policy`
/// has a window; cancelled as `similarity_matrix`.
/// @par Complexity one value pass (`alignment::Dtw::mean_cost`, O(n m W)) per pair of the tile,
/// counted once when both its entries are in it; O(max rows) memory per thread beyond the tile.
/// @par Example
/// @include knn_tiles.cpp
template <MotionCollection C>
Eigen::MatrixXd similarity_tile(const C& collection, Clip_range rows, Clip_range columns,
                                const similarity::Motion_signature_similarity<>& policy = {},
                                const Progress& progress = {}, int threads = 0) {
  internal::check_range(collection, rows, "similarity_tile", "rows");
  internal::check_range(collection, columns, "similarity_tile", "columns");
  Eigen::MatrixXd values(Eigen::Index(rows.size()), Eigen::Index(columns.size()));
  if (values.size() == 0) return values;
  const double unit = internal::search_unit(policy, collection.view(rows.begin).width, "similarity_tile");
  // Entry (i, j) is aligned unless it is the mirror, below the diagonal, of an entry of the tile.
  const auto mirrored = [&](std::size_t i, std::size_t j) { return j < i && rows.contains(j) && columns.contains(i); };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = rows.begin; i < rows.end; ++i)
    for (std::size_t j = columns.begin; j < columns.end; ++j)
      if (!mirrored(i, j)) pairs.emplace_back(i, j);
  const auto at = [&](std::size_t i, std::size_t j) -> double& {
    return values(Eigen::Index(i - rows.begin), Eigen::Index(j - columns.begin));
  };
  deformseg::internal::parallel_for_reporting(pairs.size(), threads, progress, 0, pairs.size(), [&](std::size_t p) {
    const auto [i, j] = pairs[p];
    Pruning_report unused;
    at(i, j) = *internal::aligned_value(collection.view(std::min(i, j)), collection.view(std::max(i, j)), unit, {},
                                        {}, unused);
  });
  for (std::size_t i = rows.begin; i < rows.end; ++i)
    for (std::size_t j = columns.begin; j < columns.end; ++j)
      if (mirrored(i, j)) at(i, j) = at(j, i);
  return values;
}

/// @brief The similarity of every pair of `collection`'s clips under `policy` (default the default
/// policy): entry (i, j) and (j, i), i <= j, is `policy.compare(clip i, clip j).value`, bit for
/// bit the matrix `similarity_matrix` gives for the animations the clips were described from; the
/// one tile `similarity_tile(collection, all_clips(collection), all_clips(collection))`.
/// @param collection a `MotionCollection` described with `policy`'s options.
/// @param policy the scale and alignment of the values (default: the default policy's); no window.
/// @param progress one step a pair i <= j (see `Progress`); default none.
/// @param threads the threads (default 0: all the hardware's threads, `thread_count`); the values
/// do not depend on it.
/// @throws invalid_input when `policy` has a window or `threads` is out of range; cancelled as
/// `similarity_matrix`.
/// @par Complexity N (N + 1) / 2 value passes (`alignment::Dtw::mean_cost`), O(n m W) each, on
/// `threads` threads; O(max rows) memory per thread beyond the N x N result.
template <MotionCollection C>
Eigen::MatrixXd similarity_matrix(const C& collection, const similarity::Motion_signature_similarity<>& policy = {},
                                  const Progress& progress = {}, int threads = 0) {
  return similarity_tile(collection, all_clips(collection), all_clips(collection), policy, progress, threads);
}

}  // namespace deformseg::search
