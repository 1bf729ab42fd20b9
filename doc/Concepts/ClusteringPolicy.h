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
/// | expression | type | meaning |
/// |---|---|---|
/// | `p(distances)` | deformseg::clustering::Clustering | `labels`: one per item, any values; `medoids` optional |
///
/// It is a deformseg::clustering::WeightedClusteringPolicy when, besides, for a
/// `const deformseg::clustering::Grouped_items& groups`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `p(groups)` | deformseg::clustering::Clustering | one label per group, each group counting as `groups.weights[g]` items at distance 0 |
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
/// | policy | k | options (defaults) |
/// |---|---|---|
/// | deformseg::clustering::K_medoids | given, or best silhouette over 2..10 | `clusters` (none), `max_clusters` (10), `seed` (0), `max_iterations` (100) |
/// | deformseg::clustering::Agglomerative | given, by height, or best silhouette over 2..10 | `linkage` (average), `clusters` (none), `height` (none), `max_clusters` (10) |
/// | deformseg::clustering::K_means | given, or best silhouette over 2..10 | `clusters` (none), `max_clusters` (10), `prototypes` (all items), `seed` (0), `max_iterations` (100), `restarts` (3) |
///
/// All three are weighted models, deterministic for their options and seed and whatever the number
/// of threads. `examples/own_clustering_policy.cpp` adds a policy of its own:
/// @include own_clustering_policy.cpp
///
/// \par A type that is not a model
/// is rejected at compile time: `cluster(distances, p)` with such a `p` fails with the message
/// "required for the satisfaction of 'ClusteringPolicy<Policy>'" and the requirement it misses
/// (`test/compile_fail/cluster_not_a_policy.cpp`).
