// deformseg::compiled, the signatures and similarity modules: the motion signatures of the default
// animation, and motion_similarity, similarity_matrix (all pairs, queries x database) and
// described_similarity_matrix with the default policy (Default_similarity). The headers declare
// these instantiations `extern template` (ends of signatures/motion_signatures.h and
// similarity/motion_similarity.h).
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/similarity/motion_similarity.h>

#include <vector>

namespace deformseg::signatures {
template Eigen::MatrixXd motion_signatures_at<double>(std::span<const double>, std::span<const double>,
                                                      const Motion_signature_options&, double,
                                                      std::span<const double>);
template Eigen::MatrixXd motion_signatures<double>(std::span<const double>, std::span<const double>,
                                                   const Motion_signature_options&, double);
template Eigen::MatrixXd motion_signatures<mesh::Surface_mesh_animation>(const mesh::Surface_mesh_animation&,
                                                                        const Motion_signature_options&);
}  // namespace deformseg::signatures

namespace deformseg::similarity {
template Similarity motion_similarity<mesh::Surface_mesh_animation, Default_similarity>(
    const mesh::Surface_mesh_animation&, const mesh::Surface_mesh_animation&, const Default_similarity&);
template Eigen::MatrixXd similarity_matrix<std::vector<mesh::Surface_mesh_animation>, Default_similarity>(
    const std::vector<mesh::Surface_mesh_animation>&, const Default_similarity&, const Progress&, int);
template Eigen::MatrixXd similarity_matrix<std::vector<mesh::Surface_mesh_animation>,
                                           std::vector<mesh::Surface_mesh_animation>, Default_similarity>(
    const std::vector<mesh::Surface_mesh_animation>&, const std::vector<mesh::Surface_mesh_animation>&,
    const Default_similarity&, const Progress&, int);
template Eigen::MatrixXd described_similarity_matrix<Default_similarity>(
    std::span<const Motion_signature_description>, const Default_similarity&, const Progress&, int);
}  // namespace deformseg::similarity
