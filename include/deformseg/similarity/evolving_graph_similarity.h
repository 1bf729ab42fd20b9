/// @file similarity/evolving_graph_similarity.h
/// @brief `Evolving_graph_similarity`: the thesis' motion similarity (@ref method_similarity): the
/// key-frame graphs of two evolving graphs compared by graph edit distance, clustered into labels,
/// and the two label sequences aligned.
#pragma once

#include <deformseg/alignment/alignment.h>
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/clustering/clustering.h>
#include <deformseg/clustering/k_medoids.h>
#include <deformseg/spatiotemporal/compact_segment_graph.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/ged/bipartite_ged.h>
#include <deformseg/ged/ged_matrix.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/similarity/segment_costs.h>
#include <deformseg/similarity/similarity.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace deformseg::similarity {

/// @brief How `Evolving_graph_similarity` scores a pair of frames from their cluster labels.
enum class Label_dissimilarity {
  mismatch,  ///< 0 for the same cluster, 1 for different ones (the method's match / mismatch)
  medoids,   ///< the edit distance between the two clusters' medoids over the largest such distance
  /// the edit distance between the two frames' own key-frame graphs over the largest between the
  /// two animations: the clusters are left out
  graphs
};

/// @brief The thesis' spatio-temporal segmentation, the default of `Evolving_graph_similarity`:
/// `Spatiotemporal_options` with each animation's own strain scale and threshold 0.5 (their
/// defaults), no part links (`{0, 0}`: shared edges alone join triangles) and segments of 2 frames
/// and more.
/// @par Complexity O(1).
/// @par Example
/// @include graph_policies.cpp
inline spatiotemporal::Spatiotemporal_options thesis_segmentation() {
  return {.min_frames = 2, .parts = {.contact_distance = 0, .rigid_tolerance = 0}};
}

/// @brief The spatio-temporal segmentation tuned on the shared game characters (@ref chapter_07):
/// a fixed strain scale (sigma 0.02), threshold 0.3, separate parts linked where they touch or move
/// as one, segments of 6 frames and more (`Spatiotemporal_options`' defaults besides sigma and
/// threshold). Not the thesis' method.
/// @par Complexity O(1).
/// @par Example
/// @include graph_policies.cpp
inline spatiotemporal::Spatiotemporal_options character_segmentation() { return {.sigma = 0.02, .threshold = 0.3}; }

/// @brief Similarity policy (models `SimilarityPolicy`), the thesis' pipeline: each animation's
/// evolving graph (`evolving_graph` with `segmentation`); the graph edit distances (`ged`, under
/// `costs`) between all key-frame graphs of both animations; their clustering (`clustering`,
/// through `clustering::cluster`, so graphs at distance 0 share a label); each frame labelled with
/// its key frame's cluster (key frames expanded by their durations); the two label sequences
/// aligned (`alignment`, the dissimilarity of two labels as `labels` says); `normalization` turns
/// the score into the similarity.
///
/// Its defaults are the thesis' method (@ref method_similarity): each animation's strain scaled to
/// its own (`Spatiotemporal_options::sigma` unset), cells deformed above 0.5, shared edges alone
/// joining triangles (no part links), segments of 2 frames and more, and the label sequences aligned
/// by Smith–Waterman. Two defaults are choices where the thesis says nothing: the bipartite edit
/// distance (`ged::Bipartite_ged`) instead of the exact one, whose cost is exponential in the
/// graphs' nodes, and costs that price area shares besides kinds (`Segment_costs`).
///
/// What to expect of it: the graphs describe where an animation deforms, not how it moves as a
/// whole. It sees the same motion on shapes that deform alike, as the thesis' animals; on game
/// characters, whose separate meshes and rigid parts barely strain, it sees little
/// (@ref section_graph_policies). `character_graph_similarity` gives the settings tuned on those
/// characters.
/// @tparam Ged a `ged::GedPolicy` for `Segment_graph` (default `ged::Bipartite_ged`: the exact
/// distance is exponential, and key-frame graphs of real data reach a dozen nodes).
/// @tparam Costs a `ged::GedCostModel` for `Segment_node` (default `Segment_costs`).
/// @tparam Clustering a `clustering::ClusteringPolicy` (default `clustering::K_medoids`, k by
/// silhouette).
/// @tparam Alignment an `alignment::AlignmentPolicy` (default `alignment::Smith_waterman`, the thesis'
/// local alignment).
/// @tparam Normalization as for `Strain_distribution_similarity`.
/// @par Complexity `describe`: the evolving graph, O(T F), and the GEDs among its K key frames;
/// `compare`: Ka Kb GEDs, the clustering of Ka + Kb graphs, and the alignment's O(Ta Tb).
template <class Ged = ged::Bipartite_ged, class Costs = Segment_costs, class Clustering = clustering::K_medoids,
          alignment::AlignmentPolicy Alignment = alignment::Smith_waterman,
          class Normalization = Best_score_normalization>
requires ged::GedPolicy<Ged, spatiotemporal::Segment_graph, Costs> && clustering::ClusteringPolicy<Clustering>
struct Evolving_graph_similarity {
  /// @brief The spatio-temporal segmentation. Default: `thesis_segmentation()`.
  spatiotemporal::Spatiotemporal_options segmentation = thesis_segmentation();
  /// @brief Whether each key-frame graph's detached rigid nodes (rigid pieces touching no other
  /// segment: a character's separate meshes) are merged into one before the edit distances
  /// (`compact_segment_graph`). Default true: a character's separate meshes would each be a node,
  /// counted by the edit distances as parts rather than motion, and would make them slower
  /// (@ref section_compact_graphs); a single connected mesh is unchanged.
  bool compact_graphs = true;
  /// @brief The graph edit distance. Default: `ged::Bipartite_ged`.
  Ged ged{};
  /// @brief Its costs. Default: `Segment_costs` (kinds and area shares).
  Costs costs{};
  /// @brief The clustering of the key-frame graphs. Default: `clustering::K_medoids` (k by
  /// silhouette, from 2 to 10).
  Clustering clustering{};
  /// @brief The dissimilarity of two frames' labels. Default: `Label_dissimilarity::mismatch`.
  Label_dissimilarity labels = Label_dissimilarity::mismatch;
  /// @brief The alignment of the label sequences. Default: `Alignment{}`.
  Alignment alignment{};
  /// @brief How the score becomes the similarity. Default: `Best_score_normalization`.
  Normalization normalization{};
  /// @brief The threads of the edit distances (`describe`'s `ged::ged_matrix`, `compare`'s pairs
  /// of A's and B's graphs) and of `clustering::cluster`'s own loops: 0 (default) for all the
  /// hardware's threads (`thread_count`), else 1 to `max_threads`. The segmentation and the
  /// clustering take their own (`segmentation.threads`; `clustering.threads` for the library's
  /// clustering policies). The result does not depend on it.
  int threads = 0;

  /// @brief What is compared of one animation: its evolving graph, its key-frame graphs and their
  /// edit distances among themselves.
  struct Description {
    spatiotemporal::Evolving_graph graph;               ///< the evolving graph
    std::vector<spatiotemporal::Segment_graph>
        graphs;                         ///< its key frames' graphs, in order (compacted with `compact_graphs`)
    Eigen::MatrixXd distances;          ///< their pairwise edit distances (`ged::ged_matrix`)
  };

  /// @brief The evolving graph of `animation` and the edit distances of its key frames.
  /// @tparam Mesh a `DeformingMesh`.
  /// @throws invalid_input for `threads` out of range (before any work); as `evolving_graph`.
  template <mesh::DeformingMesh Mesh>
  Description describe(const Mesh& animation) const {
    const int used = thread_count(threads, "Evolving_graph_similarity");
    Description d{spatiotemporal::evolving_graph(animation, segmentation), {}, {}};
    for (const spatiotemporal::Key_frame& k : d.graph)
      d.graphs.push_back(compact_graphs ? spatiotemporal::compact_segment_graph(k.graph) : k.graph);
    d.distances = ged::ged_matrix(d.graphs, ged, costs, {.threads = used});
    return d;
  }

  /// @brief The similarity of two animations from their descriptions.
  /// @throws invalid_input for `threads` out of range (before any work); as the policies do.
  Similarity compare(const Description& a, const Description& b) const {
    const int used = thread_count(threads, "Evolving_graph_similarity");
    const Eigen::MatrixXd distances = joint_distances(a, b, used);
    const clustering::Clustering clusters = clustering::cluster(distances, clustering, used);
    Similarity result;
    result.labels_a = frame_labels(a.graph, clusters.labels, 0);
    result.labels_b = frame_labels(b.graph, clusters.labels, a.graphs.size());
    const std::size_t n = result.labels_a.size(), m = result.labels_b.size();
    alignment::Alignment aligned;
    if (labels == Label_dissimilarity::mismatch) {
      aligned = alignment.align(n, m, alignment::label_mismatch(result.labels_a, result.labels_b));
    } else if (labels == Label_dissimilarity::graphs) {
      aligned = align_graphs(distances, a, b);
    } else {
      const Eigen::MatrixXd between = medoid_distances(distances, clusters);
      const auto& la = result.labels_a;
      const auto& lb = result.labels_b;
      aligned = alignment.align(n, m, [&](std::size_t i, std::size_t j) { return between(la[i], lb[j]); });
    }
    result.value = normalization(alignment, aligned, n, m);
    result.score = aligned.score;
    result.alignment = std::move(aligned.pairs);
    result.compared = "key-frame graphs of the evolving graphs (" + std::to_string(a.graphs.size()) + " and " +
                      std::to_string(b.graphs.size()) + "), clustered by graph edit distance into " +
                      std::to_string(clusters.clusters) + " labels, frame labels aligned in time";
    return result;
  }

private:
  // The edit distances of all key-frame graphs, A's then B's: the two descriptions' own blocks
  // and the A x B block computed here, pairs in parallel on `used` threads.
  Eigen::MatrixXd joint_distances(const Description& a, const Description& b, int used) const {
    const Eigen::Index na = Eigen::Index(a.graphs.size()), nb = Eigen::Index(b.graphs.size());
    Eigen::MatrixXd d(na + nb, na + nb);
    d.topLeftCorner(na, na) = a.distances;
    d.bottomRightCorner(nb, nb) = b.distances;
    deformseg::internal::parallel_for(std::size_t(na * nb), used, [&](std::size_t p) {
      const Eigen::Index i = Eigen::Index(p) / nb, j = Eigen::Index(p) % nb;
      d(i, na + j) = d(na + j, i) = ged(a.graphs[std::size_t(i)], b.graphs[std::size_t(j)], costs).distance;
    });
    return d;
  }

  // Per frame, the cluster of its key frame's graph (graph `offset + k` of the clustering for
  // key frame k).
  static std::vector<std::size_t> frame_labels(const spatiotemporal::Evolving_graph& graph,
                                               const std::vector<std::size_t>& clusters, std::size_t offset) {
    std::vector<std::size_t> labels;
    labels.reserve(graph.num_frames());
    for (std::size_t k = 0; k < graph.size(); ++k)
      labels.insert(labels.end(), graph[k].num_frames(), clusters[offset + k]);
    return labels;
  }

  // The frames aligned by the edit distances of their key frames' graphs, over the largest of the
  // A x B block.
  alignment::Alignment align_graphs(const Eigen::MatrixXd& distances, const Description& a,
                                    const Description& b) const {
    const Eigen::Index na = Eigen::Index(a.graphs.size()), nb = Eigen::Index(b.graphs.size());
    Eigen::MatrixXd between = distances.block(0, na, na, nb);
    const double largest = between.maxCoeff();
    if (largest > 0) between /= largest;
    const std::vector<std::size_t> key_a = frame_labels(a.graph, iota(a.graphs.size()), 0);
    const std::vector<std::size_t> key_b = frame_labels(b.graph, iota(b.graphs.size()), 0);
    return alignment.align(key_a.size(), key_b.size(), [&](std::size_t i, std::size_t j) {
      return between(Eigen::Index(key_a[i]), Eigen::Index(key_b[j]));
    });
  }

  static std::vector<std::size_t> iota(std::size_t n) {
    std::vector<std::size_t> v(n);
    std::iota(v.begin(), v.end(), std::size_t(0));
    return v;
  }

  // The distances between the clusters' medoids, over the largest (all 0 for a single cluster).
  static Eigen::MatrixXd medoid_distances(const Eigen::MatrixXd& d, const clustering::Clustering& c) {
    const Eigen::Index k = Eigen::Index(c.clusters);
    Eigen::MatrixXd between(k, k);
    for (Eigen::Index u = 0; u < k; ++u)
      for (Eigen::Index v = 0; v < k; ++v)
        between(u, v) = d(Eigen::Index(c.medoids[std::size_t(u)]), Eigen::Index(c.medoids[std::size_t(v)]));
    const double largest = between.maxCoeff();
    if (largest > 0) between /= largest;
    return between;
  }
};

/// @brief The graph policy tuned on the shared game characters, not the thesis' method:
/// `Evolving_graph_similarity` with `character_segmentation()` and the label sequences aligned by
/// `Alignment` (default DTW), both chosen leaving each body out. It ranks those characters' motions
/// better than the thesis' defaults and loses the thesis' own result on the thesis' data
/// (@ref section_graph_policies).
/// @tparam Alignment an `alignment::AlignmentPolicy` (default `alignment::Dtw`).
/// @par Complexity O(1).
/// @par Example
/// @include graph_policies.cpp
template <alignment::AlignmentPolicy Alignment = alignment::Dtw>
Evolving_graph_similarity<ged::Bipartite_ged, Segment_costs, clustering::K_medoids, Alignment>
character_graph_similarity() {
  Evolving_graph_similarity<ged::Bipartite_ged, Segment_costs, clustering::K_medoids, Alignment> policy;
  policy.segmentation = character_segmentation();
  return policy;
}

}  // namespace deformseg::similarity
