/// \page ClusteringPolicyConcept The ClusteringPolicy concept
///
/// How items given by their distance matrix are partitioned into clusters (@ref method_similarity;
/// the key-frame graphs by their graph edit distances). The C++20 concepts
/// deformseg::clustering::ClusteringPolicy and deformseg::clustering::WeightedClusteringPolicy
/// check it at compile time.
///
/// A type `P` is a model when it is copyable and, for `const P& p` and a
/// `const Eigen::MatrixXd& distances` (n x n, symmetric, zero diagonal, non-negative, finite):
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`p(distances)` <td>deformseg::clustering::Clustering <td>`labels`: one per item, any values; `medoids`
///     optional
/// </table>
///
/// It is a deformseg::clustering::WeightedClusteringPolicy when, besides, for a
/// `const deformseg::clustering::Grouped_items& groups`:
///
/// <table>
/// <tr><th>expression <th>type <th>meaning
/// <tr><td>`p(groups)` <td>deformseg::clustering::Clustering <td>one label per group, each group counting as
///     `groups.weights[g]` items at distance 0
/// </table>
///
/// deformseg::clustering::cluster checks the matrix (deformseg::clustering::check_distance_matrix),
/// merges the items at distance exactly 0 (deformseg::clustering::group_identical_items) and hands
/// the policy the groups (weighted when it can take them), so that such items always share a label;
/// it checks the number of labels (throwing deformseg::invalid_input when wrong), makes them canonical
/// (0..k-1 in order of first appearance), keeps the policy's medoids when they are one item of each
/// cluster (else computes them), and computes the mean silhouette
/// (deformseg::clustering::silhouette). A policy holds its own options as aggregate members.
///
/// \par Has models
/// <table>
/// <tr><th>policy <th>k <th>options (defaults)
/// <tr><td>deformseg::clustering::K_medoids <td>given, or best silhouette over 2..10 <td>`clusters` (none),
///     `max_clusters` (10), `seed` (0), `max_iterations` (100)
/// <tr><td>deformseg::clustering::Agglomerative <td>given, by height, or best silhouette over 2..10 <td>`linkage`
///     (average), `clusters` (none), `height` (none), `max_clusters` (10)
/// <tr><td>deformseg::clustering::K_means <td>given, or best silhouette over 2..10 <td>`clusters` (none),
///     `max_clusters` (10), `prototypes` (all items), `seed` (0), `max_iterations` (100), `restarts` (3)
/// </table>
///
/// All three are weighted models, deterministic for their options and seed and whatever the number
/// of threads. `examples/own_clustering_policy.cpp` adds a policy of its own:
/// @include own_clustering_policy.cpp
///
/// \par A type that is not a model
/// is rejected at compile time: `cluster(distances, p)` with such a `p` fails with the message
/// "required for the satisfaction of 'ClusteringPolicy<Policy>'" and the requirement it misses
/// (`test/compile_fail/cluster_not_a_policy.cpp`).
