// part_links: which separate parts of a mesh the segmentation takes as neighbours. With no
// argument, a "character" of three closed tetrahedra sharing no vertex: a body, a plate lying on
// it (1 mm away) and a lamp far above; the body and the lamp turn together, the plate stays.
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/part_links.h>

#include <Eigen/Geometry>

#include <array>
#include <cstdio>
#include <vector>

int main() {
  using namespace deformseg;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  const auto add_tetrahedron = [&](double x, double y, double z) {
    const auto v = std::uint32_t(points.size());
    for (const auto& p : {std::array{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}})
      points.push_back({x + p[0], y + p[1], z + p[2]});
    for (const auto& t : {std::array{0u, 2u, 1u}, {0u, 1u, 3u}, {0u, 3u, 2u}, {1u, 2u, 3u}})
      triangles.push_back({v + t[0], v + t[1], v + t[2]});
  };
  add_tetrahedron(0, 0, 0);           // the body: triangles 0-3
  add_tetrahedron(0.334, 0.334, 0.334);  // the plate, on the body's slanted face: 4-7
  add_tetrahedron(0, 4, 0);           // the lamp: 8-11

  // Frame 0 as built, frame 1 with the body and the lamp turned about the vertical axis.
  std::vector<double> positions;
  for (const auto& p : points) positions.insert(positions.end(), p.begin(), p.end());
  const Eigen::AngleAxisd turn(0.3, Eigen::Vector3d::UnitY());
  for (std::size_t v = 0; v < points.size(); ++v) {
    Eigen::Vector3d p(points[v][0], points[v][1], points[v][2]);
    if (v < 4 || v >= 8) p = turn * p;
    positions.insert(positions.end(), {p.x(), p.y(), p.z()});
  }
  const mesh::Surface_mesh_animation animation(mesh::make_face_graph<mesh::Surface_mesh>(points, triangles),
                                               positions);

  for (const auto& [f, g] : spatiotemporal::part_links(animation))
    std::printf("triangles %u and %u are neighbours\n", f, g);
  const auto print_graph = [&](const char* title, const spatiotemporal::Spatiotemporal_options& options) {
    const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(animation, options);
    std::printf("%s: %zu key frame, nodes", title, graph.size());
    for (std::size_t v = 0; v < boost::num_vertices(graph[0].graph); ++v)
      std::printf(" %s (area %.2f)", spatiotemporal::node_label(graph[0].graph[v]).c_str(), graph[0].graph[v].area);
    std::printf("\n");
  };
  print_graph("shared edges only (the thesis)", {.parts = {.contact_distance = 0, .rigid_tolerance = 0}});
  print_graph("parts that touch", {.parts = {.contact_distance = 0.01, .rigid_tolerance = 0}});
  print_graph("and parts that move as one", {});
  return 0;
}
