/// @file spatiotemporal/frame_segments.h
/// @brief The spatial segments of each frame of a spatio-temporal segmentation, as a
/// Boost.Graph adjacency list (@ref method_spatiotemporal): `Frame_segments`, `Segment_graph`,
/// `Segment_node`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/spatiotemporal/body_layout.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace deformseg::spatiotemporal {

/// @brief What a node of a segment graph is: a rigid region or the slice of a deformed
/// spatio-temporal segment.
enum class Segment_kind : std::uint8_t {
  rigid,    ///< an edge-connected region of rigid triangles of one frame
  deformed  ///< the triangles of one deformed spatio-temporal segment in one frame
};

/// @brief The bundled vertex property of a `Segment_graph`: one spatial segment of a frame.
struct Segment_node {
  Segment_kind kind = Segment_kind::rigid;  ///< rigid region or deformed segment
  /// @brief The spatio-temporal segment id of a deformed node;
  /// `Spatiotemporal_segmentation::rigid` (-1) for a rigid one.
  std::int32_t segment = Spatiotemporal_segmentation::rigid;
  /// @brief Its triangles (in a key frame: their mean count over its frames, rounded).
  std::size_t triangles = 0;
  /// @brief Its share of the mesh's area, in [0, 1] (in a key frame: the mean over its frames).
  double area = 0;
  /// @brief True when every member is equal.
  friend bool operator==(const Segment_node&, const Segment_node&) = default;
};

/// @brief A node's short name: "R" for a rigid node, "D" and the segment id for a deformed one
/// ("D3"), as figures, DOT files and the tool show it.
inline std::string node_label(const Segment_node& node) {
  if (node.kind == Segment_kind::rigid) return "R";
  std::string label = "D";
  label += std::to_string(node.segment);
  return label;
}

/// @brief The spatial segments of a frame: a node per segment (`Segment_node`), an edge between
/// two segments whose triangles are neighbours (`Body_layout`). Vertices are numbered 0..n-1 (`vecS`) in the
/// canonical order of `Frame_segments`.
using Segment_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, Segment_node>;

namespace internal {

// A frame's segment graph in canonical order, before it becomes a Segment_graph: what
// `same_shape` compares and what key frames average.
struct Frame_graph {
  std::vector<std::pair<Segment_kind, std::int32_t>> nodes;      // kind and segment id
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;    // u < v, sorted
  std::vector<std::size_t> triangles;                            // per node
  std::vector<double> area;                                      // per node, share of the mesh

  bool same_shape(const Frame_graph& other) const { return nodes == other.nodes && edges == other.edges; }
};

struct Frame_segments_access;


}  // namespace internal

/// @brief The spatial segments of every frame of a spatio-temporal segmentation, frame by frame:
/// each frame's `Segment_graph` and the node of each triangle.
///
/// The nodes of frame t are the slices of the deformed spatio-temporal segments alive in it
/// (one node per segment, even if its slice is in several pieces: the pieces join in other
/// frames) and the connected regions of its rigid triangles; an edge joins two nodes whose
/// triangles are neighbours in the layout (share a mesh edge, or are linked between parts). Rigid
/// regions have no identity of their own across frames, so a rigid node is known by the deformed
/// segments it touches: nodes come in a canonical order, deformed nodes first by segment id, then
/// rigid nodes by the sorted ids of the segments they touch, ties by their smallest triangle
/// index. Two frames with the same nodes (kinds and segment ids, rigid nodes by what they touch)
/// and the same edges then have the same graph up to the attributes, node for node.
///
/// Keeps a reference to the segmentation, its layout, and nothing per frame: each call computes
/// its frame.
class Frame_segments {
public:
  /// @brief Prepares the frames of a segmentation over the thesis' adjacency: as the other
  /// constructor with `Body_layout(triangles, face_areas)`.
  /// @param segmentation the spatio-temporal segmentation.
  /// @param triangles the face-vertex index table of its triangles (for a `Deforming_mesh`, its
  /// `triangles()`), which gives their adjacency.
  /// @param face_areas the area of each triangle, for the nodes' area shares (typically in the
  /// rest frame; any scale); empty (default): every triangle weighs the same.
  /// @pre as the other constructor, and as `Body_layout`'s.
  /// @par Complexity O(F log F) for the triangles' adjacency.
  Frame_segments(const Spatiotemporal_segmentation& segmentation,
                 std::span<const std::array<std::uint32_t, 3>> triangles, std::span<const double> face_areas = {})
      : Frame_segments(segmentation, Body_layout(triangles, face_areas)) {}

  /// @brief Prepares the frames of a segmentation over `layout`: nodes are joined, and rigid
  /// regions grown, across its neighbours (shared edges and links between parts), and weighed by
  /// its area shares.
  /// @pre `segmentation` outlives this object; `layout.num_faces() == segmentation.num_faces()`,
  /// else throws `invalid_input`.
  /// @par Complexity O(1) besides moving the layout.
  Frame_segments(const Spatiotemporal_segmentation& segmentation, Body_layout layout)
      : segmentation_(&segmentation), layout_(std::move(layout)) {
    if (layout_.num_faces() != segmentation.num_faces())
      throw invalid_input("Frame_segments: " + std::to_string(layout_.num_faces()) + " triangles for a segmentation of " +
                          std::to_string(segmentation.num_faces()));
  }

  /// @brief Deleted: the object would refer to a temporary segmentation.
  Frame_segments(Spatiotemporal_segmentation&&, std::span<const std::array<std::uint32_t, 3>>,
                 std::span<const double> = {}) = delete;
  /// @brief Deleted: the object would refer to a temporary segmentation.
  Frame_segments(Spatiotemporal_segmentation&&, Body_layout) = delete;

  /// @brief The number of frames.
  std::size_t num_frames() const noexcept { return segmentation_->num_frames(); }
  /// @brief The segmentation the frames come from.
  const Spatiotemporal_segmentation& segmentation() const noexcept { return *segmentation_; }
  /// @brief The layout its nodes are found over.
  const Body_layout& layout() const noexcept { return layout_; }

  /// @brief The segment graph of frame `t`, nodes in canonical order.
  /// @throws invalid_input when `t >= num_frames()`.
  /// @par Complexity O(F + E) for F triangles and E pairs of neighbours, plus sorting the nodes.
  Segment_graph graph(std::size_t t) const { return to_graph(frame_graph(t)); }

  /// @brief The node of each triangle in frame `t`'s graph (an index into `graph(t)`'s vertices),
  /// in face index order.
  /// @throws invalid_input when `t >= num_frames()`.
  /// @par Complexity as `graph`.
  std::vector<std::uint32_t> face_nodes(std::size_t t) const {
    std::vector<std::uint32_t> nodes;
    frame_graph(t, &nodes);
    return nodes;
  }

private:
  friend struct internal::Frame_segments_access;
  static constexpr std::int32_t rigid = Spatiotemporal_segmentation::rigid;

  // Frame t's graph before it becomes a Segment_graph; with face_nodes, the node of each
  // triangle. For evolving_graph, which compares and averages frames.
  internal::Frame_graph frame_graph(std::size_t t, std::vector<std::uint32_t>* face_nodes = nullptr) const {
    const auto labels = segmentation_->frame_labels(t);
    std::vector<std::uint32_t> raw(labels.size());
    const Raw_nodes nodes = raw_nodes(labels, raw);
    const auto edges = raw_edges(raw);
    const std::vector<std::uint32_t> order = canonical_order(nodes, edges);
    std::vector<std::uint32_t> rank(order.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) rank[order[i]] = i;
    internal::Frame_graph graph;
    for (std::uint32_t r : order) {
      graph.nodes.emplace_back(nodes.segment[r] == rigid ? Segment_kind::rigid : Segment_kind::deformed,
                               nodes.segment[r]);
      graph.triangles.push_back(nodes.triangles[r]);
      graph.area.push_back(nodes.area[r]);
    }
    for (auto [u, v] : edges) graph.edges.emplace_back(std::min(rank[u], rank[v]), std::max(rank[u], rank[v]));
    std::sort(graph.edges.begin(), graph.edges.end());
    if (face_nodes) {
      for (auto& n : raw) n = rank[n];
      *face_nodes = std::move(raw);
    }
    return graph;
  }

  // A Segment_graph of a frame graph, with its attributes.
  static Segment_graph to_graph(const internal::Frame_graph& frame) {
    Segment_graph graph(frame.nodes.size());
    for (std::size_t v = 0; v < frame.nodes.size(); ++v)
      graph[v] = {frame.nodes[v].first, frame.nodes[v].second, frame.triangles[v], frame.area[v]};
    for (auto [u, v] : frame.edges) boost::add_edge(u, v, graph);
    return graph;
  }


  // Nodes in order of their first triangle: a deformed segment or a rigid region each.
  struct Raw_nodes {
    std::vector<std::int32_t> segment;      // segment id, or rigid
    std::vector<std::uint32_t> first_face;  // smallest triangle index
    std::vector<std::size_t> triangles;
    std::vector<double> area;
  };

  // The node of each triangle (deformed: one per segment; rigid: a breadth-first search over
  // rigid neighbours), with each node's size and area.
  Raw_nodes raw_nodes(std::span<const std::int32_t> labels, std::vector<std::uint32_t>& node_of) const {
    constexpr std::uint32_t unset = ~0u;
    std::fill(node_of.begin(), node_of.end(), unset);
    Raw_nodes nodes;
    std::vector<std::uint32_t> node_of_segment(segmentation_->num_segments(), unset);
    std::vector<std::uint32_t> queue;
    const auto add_node = [&](std::int32_t segment, std::uint32_t face) {
      nodes.segment.push_back(segment), nodes.first_face.push_back(face);
      nodes.triangles.push_back(0), nodes.area.push_back(0);
      return std::uint32_t(nodes.segment.size() - 1);
    };
    for (std::uint32_t f = 0; f < labels.size(); ++f) {
      if (node_of[f] != unset) continue;
      if (labels[f] != rigid) {
        std::uint32_t& n = node_of_segment[std::size_t(labels[f])];
        if (n == unset) n = add_node(labels[f], f);
        node_of[f] = n;
        continue;
      }
      const std::uint32_t n = add_node(rigid, f);
      queue.assign(1, f);
      node_of[f] = n;
      for (std::size_t q = 0; q < queue.size(); ++q)
        for (std::uint32_t g : layout_.neighbours(queue[q]))
          if (labels[g] == rigid && node_of[g] == unset) node_of[g] = n, queue.push_back(g);
    }
    for (std::size_t f = 0; f < labels.size(); ++f) {
      ++nodes.triangles[node_of[f]];
      nodes.area[node_of[f]] += layout_.area_shares()[f];
    }
    return nodes;
  }

  // The pairs of nodes whose triangles are neighbours, each once.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> raw_edges(const std::vector<std::uint32_t>& node_of) const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::uint32_t f = 0; f < node_of.size(); ++f)
      for (std::uint32_t g : layout_.neighbours(f))
        if (g > f && node_of[f] != node_of[g])
          edges.emplace_back(std::min(node_of[f], node_of[g]), std::max(node_of[f], node_of[g]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
  }

  // Deformed nodes by segment id, then rigid nodes by the sorted segment ids they touch, ties
  // by first triangle.
  static std::vector<std::uint32_t> canonical_order(const Raw_nodes& nodes,
                                                    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
    std::vector<std::vector<std::int32_t>> touches(nodes.segment.size());
    for (auto [u, v] : edges) {
      if (nodes.segment[v] != rigid) touches[u].push_back(nodes.segment[v]);
      if (nodes.segment[u] != rigid) touches[v].push_back(nodes.segment[u]);
    }
    for (auto& t : touches) std::sort(t.begin(), t.end());
    std::vector<std::uint32_t> order(nodes.segment.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      const bool rigid_a = nodes.segment[a] == rigid, rigid_b = nodes.segment[b] == rigid;
      if (rigid_a != rigid_b) return rigid_b;
      if (!rigid_a) return nodes.segment[a] < nodes.segment[b];
      return std::tie(touches[a], nodes.first_face[a]) < std::tie(touches[b], nodes.first_face[b]);
    });
    return order;
  }

  const Spatiotemporal_segmentation* segmentation_;
  Body_layout layout_;
};

namespace internal {

// What evolving_graph needs of Frame_segments beyond its public interface.
struct Frame_segments_access {
  static Frame_graph frame_graph(const Frame_segments& s, std::size_t t) { return s.frame_graph(t); }
  static Segment_graph to_graph(const Frame_graph& frame) { return Frame_segments::to_graph(frame); }
};

}  // namespace internal

}  // namespace deformseg::spatiotemporal
