// The evolving graph of a tube that bends once at constant speed: rigid, then rigid - deformed -
// rigid while it bends, then rigid again; each key frame's graph walked with Boost.Graph.
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/mesh/synthetic.h>

#include <boost/graph/adjacency_list.hpp>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{10, {0.0}}, {10, {std::numbers::pi / 2}, mesh::Easing::linear}, {10, {}}};  // rest, bend, hold
  const auto animation = mesh::make_bending_tube(spec).animation;

  // Previous-pose strain (the default); a low threshold, so that the whole blend zone counts as
  // deformed while the joint moves, its neutral axis too.
  const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(animation, {.threshold = 0.01});
  std::cout << graph.size() << " key frames over " << graph.num_frames() << " frames, " << graph.num_segments()
            << " deformed segment(s)\n";
  for (const spatiotemporal::Key_frame& key : graph) {
    std::cout << "frames " << key.first_frame << "-" << key.last_frame << ":";
    for (auto v : boost::make_iterator_range(boost::vertices(key.graph))) {
      const spatiotemporal::Segment_node& node = key.graph[v];
      std::cout << ' ' << spatiotemporal::node_label(node) << " ("
                << node.triangles << " triangles, " << node.area * 100 << " % of the area)";
    }
    std::cout << ", " << boost::num_edges(key.graph) << " edge(s)\n";
  }
  std::cout << "frame 15 is in key frame " << graph.key_frame_of(15) << '\n';
  return 0;
}
