// A motion store opened for what the tool's and Python's commands ask of it: searching it for a
// query's nearest clips, finding where a query occurs in its clips, its k-nearest-neighbour graph
// and its matrix, under the policy its clips were described with.
#pragma once

#include "similarity.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/search/find_motion_in_collection.h>
#include <deformseg/search/nearest_motions.h>
#include <deformseg/search/similarity_tile.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/store/stored_motions.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace deformseg::frontend {

/// A store's clips, memory-mapped, with the policy of their description (`stored_policy_choice`).
class Store_search {
 public:
  /// Opens the store in `folder`, checked as `verify` asks.
  /// @throws invalid_input naming the store when it cannot be opened or was described with options
  /// this front end does not write.
  explicit Store_search(const std::string& folder, store::Verify verify = store::Verify::structure);

  std::size_t size() const { return clips_.size(); }
  const store::Stored_motions& clips() const { return clips_; }
  const store::Motion_store& store() const { return clips_.store(); }
  const similarity::Default_similarity& policy() const { return policy_; }
  /// Clip `i` named for reports: "FILE", "FILE#CLIP" or "FILE#CLIP on BODY".
  std::string name(std::size_t i) const;

  /// `query` described as the store's clips were, its rows on `threads` threads (0: all the
  /// hardware's, `thread_count`).
  similarity::Motion_signature_description describe(const mesh::Surface_mesh_animation& query, int threads) const;
  /// The `options.k` clips nearest to `query` (`search::nearest_motions`).
  /// @throws invalid_input naming the store when it holds no clip, or when the candidates are not a
  /// block of its clips.
  search::Nearest_motions nearest(const mesh::Surface_mesh_animation& query,
                                      const search::Nearest_motions_options& options) const;
  /// The `options.k` clips nearest to the query described as `query` (by `describe`).
  /// @throws invalid_input as the other `nearest`, and when `query` has no row or another width
  /// than the store's clips.
  search::Nearest_motions nearest(signatures::Motion_signature_view query,
                                      const search::Nearest_motions_options& options) const;
  /// The `options.k` clips nearest to clip `i` of the store, itself left out
  /// (`search::nearest_others`): row `i` of `knn_graph`, the same neighbours, values and counts.
  /// @throws invalid_input naming the index when the store has no clip `i`.
  search::Nearest_motions nearest_to_clip(std::size_t i, const search::Nearest_motions_options& options) const;
  /// The `options.k` nearest others of each clip of `rows` (default all: the whole graph), among
  /// `options.candidates` (`search::knn_graph`).
  /// @throws invalid_input naming the store when `rows` or the candidates are not blocks of its clips.
  std::vector<search::Nearest_motions> knn_graph(const search::Nearest_motions_options& options,
                                                     std::optional<search::Clip_range> rows = {}) const;
  /// Where `query` occurs in the store (`search::find_motion_in_collection`): the best
  /// `options.count` non-overlapping windows over all its clips, each in its clip's stored frames,
  /// valued on the descriptions as stored (1 minus the mean dissimilarity along the warping path).
  /// @throws invalid_input when the store holds no clip.
  std::vector<search::Clip_match> find(const mesh::Surface_mesh_animation& query,
                                           const search::Find_in_collection_options& options) const;
  /// The similarity of every pair of the store's clips (`similarity::similarity_matrix`), on
  /// `threads` threads (0: all the hardware's, `thread_count`).
  Eigen::MatrixXd matrix(const Progress& progress, int threads) const;
  /// A tile of the matrix: rows `rows`, columns `columns` (`search::similarity_tile`).
  /// @throws invalid_input naming the store when `rows` or `columns` are not blocks of its clips.
  Eigen::MatrixXd tile(search::Clip_range rows, search::Clip_range columns, const Progress& progress = {},
                       int threads = 0) const;
  /// The similarity of every pair of clips `indices` of the store, in that order, on `threads`
  /// threads.
  /// @pre every index is below `size()`.
  Eigen::MatrixXd matrix(std::vector<std::size_t> indices, const Progress& progress, int threads) const;

  /// Refuses policy options that contradict the store's: a policy other than motion signatures
  /// aligned by DTW (`store_policy`), or an `up` (when `asked` gives one) other than the one its
  /// clips were described with.
  /// @throws invalid_input naming the option as `front` spells it (and the store, for `up`).
  void check_policy(const Policy_choice& asked, Front front) const;
  /// The store's index of the clip of each row of the labels CSV `labels`, in the rows' order (a
  /// glTF row without a clip takes `read`'s, or the file's only one; the clip on the row's
  /// `body_file`, else on `read`'s body), each up to date with its
  /// source (`up_to_date`) as read with `read` or, without, with the options it was described with.
  /// @throws invalid_input naming the store, listing the clips it lacks or holds as they were before
  /// their source changed, and saying how to describe them again as `front` does.
  std::vector<std::size_t> labelled(const std::string& labels, const std::optional<Input_options>& read,
                                    Front front) const;

 private:
  // Refuses, naming the store, a block (`what`: rows, columns, candidates) that is not one of its clips.
  void check_range(std::optional<search::Clip_range> range, const char* what) const;

  store::Stored_motions clips_;
  similarity::Default_similarity policy_;
};

}  // namespace deformseg::frontend
