/// @file spatiotemporal/compact_segment_graph.h
/// @brief `compact_segment_graph`: a segment graph with its detached rigid nodes (rigid pieces that
/// touch no other segment) merged into one, as real characters need before graph edit distances.
///
/// A game character is many separate meshes (body, head, eyes, hands, weapons, a cape on bones):
/// each piece that does not deform is a rigid node with no edge, and such pieces make most of a
/// character's frame graph (@ref section_compact_graphs). They say nothing about the motion beyond
/// their count and area, yet they make every edit distance cubic in their number.
#pragma once

#include <deformseg/spatiotemporal/frame_segments.h>

#include <boost/graph/adjacency_list.hpp>

#include <cstddef>
#include <vector>

namespace deformseg::spatiotemporal {

/// @brief `graph` with every rigid node of degree 0 merged into one rigid node, placed after the
/// other nodes, whose triangles and area are their sums; the other nodes and all edges are kept in
/// their order. A graph with at most one detached rigid node is returned unchanged.
/// @par Complexity O(V + E).
inline Segment_graph compact_segment_graph(const Segment_graph& graph) {
  const std::size_t n = boost::num_vertices(graph);
  std::vector<bool> detached(n, false);
  std::size_t count = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (graph[v].kind == Segment_kind::rigid && boost::out_degree(v, graph) == 0) detached[v] = true, ++count;
  if (count <= 1) return graph;

  Segment_graph out;
  std::vector<std::size_t> index(n);
  Segment_node merged{.kind = Segment_kind::rigid};
  for (std::size_t v = 0; v < n; ++v) {
    if (detached[v]) {
      merged.triangles += graph[v].triangles;
      merged.area += graph[v].area;
    } else {
      index[v] = boost::add_vertex(graph[v], out);
    }
  }
  boost::add_vertex(merged, out);
  for (auto [e, end] = boost::edges(graph); e != end; ++e)
    boost::add_edge(index[boost::source(*e, graph)], index[boost::target(*e, graph)], out);
  return out;
}

}  // namespace deformseg::spatiotemporal
