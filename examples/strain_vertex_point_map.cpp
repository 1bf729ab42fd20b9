// Strain against a reference mesh whose points are kept apart from it: the graph's connectivity,
// the reference shape in a vector of one's own, handed over as CGAL's vertex_point_map named
// parameter (as CGAL's Polygon_mesh_processing functions take it). Without it, the graph's own
// points are read.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/strain/strain.h>

#include <CGAL/Named_function_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& animation = tube.animation;

  // The rest shape as one's own points, by vertex index; the graph's points are moved away.
  // [vertex_point_map]
  mesh::Surface_mesh reference = animation.face_graph();
  std::vector<mesh::Kernel::Point_3> rest;
  for (auto v : vertices(reference)) {
    rest.push_back(reference.point(v));
    reference.point(v) = reference.point(v) + mesh::Kernel::Vector_3(0, 0, 2.0 * v.idx());  // not the rest shape
  }
  const auto rest_points = boost::make_iterator_property_map(rest.begin(), get(boost::vertex_index, reference));
  const auto field =
      strain::compute_strain(animation, reference, {}, CGAL::parameters::vertex_point_map(rest_points));
  // [vertex_point_map]

  const auto against_frame_0 = strain::compute_strain(animation, {.normalization = strain::No_normalization{}});
  const auto raw = strain::compute_strain(animation, reference, {.normalization = strain::No_normalization{}},
                                          CGAL::parameters::vertex_point_map(rest_points));
  const auto last = animation.num_frames() - 1;
  const auto a = raw.frame(last), b = against_frame_0.frame(last);
  std::cout << "largest strain of the last frame, against the user's points: "
            << *std::max_element(a.begin(), a.end()) << ", against frame 0: " << *std::max_element(b.begin(), b.end())
            << '\n';
  const auto own = strain::compute_strain(animation, reference, {.normalization = strain::No_normalization{}});
  const auto c = own.frame(last);
  std::cout << "against the graph's own (moved) points: " << *std::max_element(c.begin(), c.end()) << '\n';
  std::cout << "normalised, sigma " << *field.sigma() << '\n';
  return 0;
}
