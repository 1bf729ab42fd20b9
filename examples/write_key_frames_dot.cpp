// Writes the evolving graph of a tube bending at two joints in turn as Graphviz DOT files (one per
// key frame), and every frame as a PLY mesh coloured by segment.
#include <deformseg/io/frame_sequence.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/segment_colors.h>
#include <deformseg/spatiotemporal/segment_graph_dot.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  mesh::Bending_tube spec;
  spec.joints = {{.position = 0.3}, {.position = 0.7}};
  spec.schedule = {
      {5, {0.0, 0.0}}, {10, {right, 0.0}, mesh::Easing::linear}, {10, {right, right}, mesh::Easing::linear}};
  const auto animation = mesh::make_bending_tube(spec).animation;
  // [dot]
  const spatiotemporal::Spatiotemporal_segmentation segmentation =
      spatiotemporal::spatiotemporal_segmentation(animation, {.threshold = 0.01});
  const spatiotemporal::Frame_segments frames(segmentation, animation.triangles(), mesh::face_areas(animation, 0));
  const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(frames);

  for (const auto& file : spatiotemporal::write_key_frames_dot(graph, "two_joints_dot")) std::cout << file.string() << '\n';
  // [dot]
  std::cout << "key frame 1 as DOT:\n";
  spatiotemporal::write_segment_graph_dot(std::cout, graph[1].graph);

  // Segment 0 has the same colour in every frame; rigid triangles are grey.
  // [colors]
  const auto files =
      io::write_sequence(animation, "two_joints_segments",
                         {.face_colors = [&](std::size_t t) { return spatiotemporal::segment_face_colors(frames, t); }});
  // [colors]
  std::cout << files.size() << " coloured meshes in two_joints_segments/\n";
  return 0;
}
