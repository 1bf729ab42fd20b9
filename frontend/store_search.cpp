#include "store_search.h"

#include "store.h"

namespace deformseg::frontend {

Store_search::Store_search(const std::string& folder, io::Verify verify)
    : clips_(io::Motion_store::open(folder, verify)),
      policy_(store_policy(stored_policy_choice(clips_.store()), Front::command_line)) {}

std::string Store_search::name(std::size_t i) const { return stored_clip_name(store(), i); }

similarity::Motion_signature_description Store_search::describe(const mesh::Surface_mesh_animation& query) const {
  return policy_.describe(query);
}

similarity::Nearest_motions Store_search::nearest(const mesh::Surface_mesh_animation& query,
                                                  const similarity::Nearest_motions_options& options) const {
  if (size() == 0) throw invalid_input("the store holds no clip", {.file = store().folder().string()});
  const similarity::Motion_signature_description description = describe(query);
  return similarity::nearest_motions(similarity::view(description), clips_, options, policy_);
}

similarity::Nearest_motions Store_search::nearest_to_clip(std::size_t i,
                                                          const similarity::Nearest_motions_options& options) const {
  if (i >= size())
    throw invalid_input("no clip " + std::to_string(i) + ": the store holds " + std::to_string(size()) + " clips",
                        {.file = store().folder().string()});
  return similarity::nearest_others(clips_, i, options, policy_);
}

std::vector<similarity::Clip_match> Store_search::find(const mesh::Surface_mesh_animation& query,
                                                      const similarity::Find_in_collection_options& options) const {
  if (size() == 0) throw invalid_input("the store holds no clip", {.file = store().folder().string()});
  return similarity::find_motion_in_collection(describe(query), clips_, options, policy_);
}

std::vector<similarity::Nearest_motions> Store_search::knn_graph(
    const similarity::Nearest_motions_options& options) const {
  return similarity::knn_graph(clips_, options, policy_);
}

Eigen::MatrixXd Store_search::matrix(const Progress& progress) const {
  return similarity::similarity_matrix(clips_, policy_, progress);
}

}  // namespace deformseg::frontend
