// The segments of single frames: a frame's graph, the node of each triangle, and that node
// written into a Surface_mesh face property map; the triangles' areas weigh the nodes.
#include <deformseg/mesh/face_areas.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/spatiotemporal/frame_segments.h>
#include <deformseg/spatiotemporal/segment_colors.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{10, {0.0}}, {10, {std::numbers::pi / 2}, mesh::Easing::linear}, {10, {}}};
  const auto animation = mesh::make_bending_tube(spec).animation;
  const spatiotemporal::Spatiotemporal_segmentation segmentation =
      spatiotemporal::spatiotemporal_segmentation(animation, {.threshold = 0.01});

  // Area shares from the rest frame's triangle areas.
  // [frame_graphs]
  const std::vector<double> areas = mesh::face_areas(animation, 0);
  const spatiotemporal::Frame_segments frames(segmentation, animation.triangles(), areas);
  // [frame_graphs]
  for (std::size_t t : {5, 15}) {
    const spatiotemporal::Segment_graph g = frames.graph(t);
    std::cout << "frame " << t << ": " << boost::num_vertices(g) << " node(s), " << boost::num_edges(g) << " edge(s)\n";
  }

  // The node of each face of frame 15 in a property map of the Surface_mesh.
  mesh::Surface_mesh mesh = animation.face_graph();
  auto node_of = mesh.add_property_map<mesh::Surface_mesh::Face_index, std::uint32_t>("f:segment_node", 0).first;
  spatiotemporal::put_face_segments(frames, 15, mesh, node_of);
  std::size_t on_node_0 = 0;
  for (auto f : mesh.faces()) on_node_0 += node_of[f] == 0;
  std::cout << "frame 15: " << on_node_0 << " triangles on node 0 (the deformed band)\n";
  std::cout << "the band's colour: " << int(spatiotemporal::segment_color(0).r) << ' ' << int(spatiotemporal::segment_color(0).g) << ' '
            << int(spatiotemporal::segment_color(0).b) << '\n';
  return 0;
}
