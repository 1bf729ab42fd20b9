// compact_segment_graph: a key-frame graph of a character made of separate meshes, its detached
// rigid pieces merged into one node before graph edit distances. With no argument, a graph of a
// deformed segment between two rigid regions, plus four rigid pieces touching nothing.
#include <deformseg/spatiotemporal/compact_segment_graph.h>

#include <cstdio>

int main() {
  using namespace deformseg;
  spatiotemporal::Segment_graph g;
  const auto upper =
      boost::add_vertex(spatiotemporal::Segment_node{spatiotemporal::Segment_kind::rigid, -1, 300, 0.30}, g);
  const auto knee =
      boost::add_vertex(spatiotemporal::Segment_node{spatiotemporal::Segment_kind::deformed, 0, 40, 0.04}, g);
  const auto lower =
      boost::add_vertex(spatiotemporal::Segment_node{spatiotemporal::Segment_kind::rigid, -1, 200, 0.20}, g);
  boost::add_edge(upper, knee, g);
  boost::add_edge(knee, lower, g);
  for (double area : {0.25, 0.1, 0.06, 0.05})  // a head, a sword, two eyes: separate meshes
    boost::add_vertex(
        spatiotemporal::Segment_node{spatiotemporal::Segment_kind::rigid, -1, std::size_t(area * 1000), area}, g);

  const spatiotemporal::Segment_graph compact = spatiotemporal::compact_segment_graph(g);
  std::printf("before: %zu nodes, %zu edges; after: %zu nodes, %zu edges\n", boost::num_vertices(g),
              boost::num_edges(g), boost::num_vertices(compact), boost::num_edges(compact));
  for (std::size_t v = 0; v < boost::num_vertices(compact); ++v)
    std::printf("  %s: %zu triangles, area %.2f\n", spatiotemporal::node_label(compact[v]).c_str(),
                compact[v].triangles, compact[v].area);
  return 0;
}
