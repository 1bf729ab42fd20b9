// Every public algorithm that takes a mesh, compiled against the archetype of the mesh concepts
// (mesh_archetype.h: only what FaceGraph and DeformingMesh state), gives the default model's result
// to the last bit; and the named parameters of the entry points that read a graph's own points and
// indices (vertex_point_map, vertex_index_map, face_index_map) are honoured.
#include "mesh_archetype.h"
#include "same_as_default_model.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signatures.h>
#include <deformseg/similarity/any_policy.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/spatiotemporal/body_layout.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/part_links.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>
#include <deformseg/strain/strain.h>
#include <deformseg/strain/strain_histograms.h>

#include <CGAL/Named_function_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numbers>
#include <unordered_map>
#include <vector>

using namespace deformseg;
namespace archetype = deformseg::test::archetype;

// The helpers and tests have a namespace of their own: the tests are compiled a batch of files at a
// time, and the other files have helpers of the same names.
namespace concept_archetype_test {

constexpr double right_angle = std::numbers::pi / 2;

// A tube that bends, holds, and unbends: every algorithm finds something in it.
mesh::Surface_mesh_animation bending_tube(double angle = right_angle) {
  mesh::Bending_tube spec;
  spec.shape = {.sectors = 8, .rings = 24};
  spec.schedule = {{4, {}}, {6, {angle}}, {4, {}}, {6, {0.0}}};
  return mesh::make_bending_tube(spec).animation;
}

template <class Value>
bool same_field(const strain::Strain_field<Value>& a, const strain::Strain_field<Value>& b) {
  return std::ranges::equal(a.values(), b.values()) && a.sigma() == b.sigma() &&
         a.degenerate_count() == b.degenerate_count();
}

std::vector<std::int32_t> labels_of(const spatiotemporal::Spatiotemporal_segmentation& s) {
  std::vector<std::int32_t> labels;
  for (std::size_t t = 0; t < s.num_frames(); ++t)
    for (std::int32_t l : s.frame_labels(t)) labels.push_back(l);
  return labels;
}

// The positions of frame t of `a`, as points of the default kernel by vertex index.
std::vector<mesh::Kernel::Point_3> frame_points(const mesh::Surface_mesh_animation& a, std::size_t t) {
  std::vector<mesh::Kernel::Point_3> points;
  const auto xyz = a.frame_positions(t);
  for (std::size_t i = 0; i < a.num_vertices(); ++i) points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  return points;
}

// A user's model on a Surface_mesh whose own points are garbage: its positions are in vectors of
// its own, behind boost::iterator_property_maps by the graph's vertex index.
struct Own_points_animation {
  using Face_graph = mesh::Surface_mesh;
  using Point_map = boost::iterator_property_map<std::vector<mesh::Kernel::Point_3>::const_iterator,
                                                 mesh::Surface_mesh::Property_map<mesh::Surface_mesh::Vertex_index,
                                                                                  std::uint32_t>>;
  explicit Own_points_animation(const mesh::Surface_mesh_animation& a) : graph(a.face_graph()) {
    for (auto v : vertices(graph)) graph.point(v) = mesh::Kernel::Point_3(1e6 * v.idx(), -3, 7);
    index = graph.add_property_map<mesh::Surface_mesh::Vertex_index, std::uint32_t>("v:own_index").first;
    for (auto v : vertices(graph)) index[v] = std::uint32_t(v.idx());
    for (std::size_t t = 0; t < a.num_frames(); ++t) frames.push_back(frame_points(a, t));
  }
  const Face_graph& face_graph() const { return graph; }
  std::size_t num_frames() const { return frames.size(); }
  Point_map frame_point_map(std::size_t t) const { return Point_map(frames.at(t).begin(), index); }

  mesh::Surface_mesh graph;
  mesh::Surface_mesh::Property_map<mesh::Surface_mesh::Vertex_index, std::uint32_t> index;
  std::vector<std::vector<mesh::Kernel::Point_3>> frames;
};

// A writable point map into a vector of the user's, by vertex index.
struct Points_into {
  using key_type = mesh::Surface_mesh::Vertex_index;
  using value_type = mesh::Kernel::Point_3;
  using reference = mesh::Kernel::Point_3&;
  using category = boost::read_write_property_map_tag;
  std::vector<mesh::Kernel::Point_3>* points;
  friend void put(const Points_into& m, key_type v, const value_type& p) { (*m.points)[v.idx()] = p; }
  friend reference get(const Points_into& m, key_type v) { return (*m.points)[v.idx()]; }
};

TEST_CASE("archetype: strain, its overloads and its face property maps", "[archetype][strain]") {
  const auto a = bending_tube();
  const archetype::Model_on on(a);
  const auto& model = on.model();
  CHECK(same_field(strain::compute_strain(model), strain::compute_strain(a)));
  const strain::Strain_options previous{.reference = strain::Strain_reference::previous_pose,
                                        .principal_directions = true};
  const auto field = strain::compute_strain<double>(model, previous);
  CHECK(same_field(field, strain::compute_strain<double>(a, previous)));
  CHECK(same_field(strain::compute_strain(model, {}, strain::Green_lagrange_strain{}, strain::No_normalization{}),
                   strain::compute_strain(a, {}, strain::Green_lagrange_strain{}, strain::No_normalization{})));
  // A reference graph without points of its own: its points come from the vertex_point_map.
  const mesh::Surface_mesh rest = a.face_graph();
  const auto expected = strain::compute_strain(a, rest);
  const auto rest_points = CGAL::parameters::vertex_point_map(model.frame_point_map(0));
  CHECK(same_field(strain::compute_strain(model, model.face_graph(), {}, rest_points), expected));
  CHECK(same_field(strain::compute_strain(a, model.face_graph(), {}, rest_points), expected));
  CHECK(same_field(strain::compute_strain(model, model.face_graph(), {}, strain::Max_principal_strain{},
                                          strain::Gaussian_normalization{}, rest_points),
                   expected));
  // One frame into a face map of the archetype's faces.
  std::unordered_map<archetype::Face, double> values;
  strain::put_strain_frame(field, 7, model.face_graph(), boost::make_assoc_property_map(values));
  std::unordered_map<archetype::Face, Eigen::Vector3d> directions;
  strain::put_principal_directions(field, 7, model.face_graph(), boost::make_assoc_property_map(directions));
  REQUIRE(values.size() == field.num_faces());
  for (auto f : faces(model.face_graph())) {
    CHECK(values.at(f) == field(f.index, 7));
    CHECK(directions.at(f)[1] == field.principal_directions(7)(Eigen::Index(f.index), 1));
  }
  CHECK(strain::strain_histograms(model) == strain::strain_histograms(a));
}

TEST_CASE("archetype: temporal segmentation with each method", "[archetype][temporal]") {
  const auto a = bending_tube();
  const archetype::Model_on on(a);
  test::check_every_method_same(on.model(), a);
}

TEST_CASE("archetype: spatio-temporal segmentation, evolving graph, body layout, part links",
          "[archetype][spatiotemporal]") {
  const auto a = bending_tube();
  const archetype::Model_on on(a);
  const auto& model = on.model();
  const spatiotemporal::Spatiotemporal_options options{.threshold = 0.01};
  CHECK(labels_of(spatiotemporal::spatiotemporal_segmentation(model, options)) ==
        labels_of(spatiotemporal::spatiotemporal_segmentation(a, options)));
  const auto graph = spatiotemporal::evolving_graph(model, options);
  const auto expected = spatiotemporal::evolving_graph(a, options);
  REQUIRE(graph.size() == expected.size());
  CHECK(graph.num_segments() == expected.num_segments());
  for (std::size_t k = 0; k < graph.size(); ++k) {
    REQUIRE(boost::num_vertices(graph[k].graph) == boost::num_vertices(expected[k].graph));
    for (std::size_t v = 0; v < boost::num_vertices(graph[k].graph); ++v)
      CHECK(graph[k].graph[v] == expected[k].graph[v]);
  }
  CHECK(spatiotemporal::part_links(model) == spatiotemporal::part_links(a));
  const auto layout = spatiotemporal::body_layout(model), expected_layout = spatiotemporal::body_layout(a);
  CHECK(layout.num_links() == expected_layout.num_links());
  CHECK(std::ranges::equal(layout.area_shares(), expected_layout.area_shares()));
}

TEST_CASE("archetype: motion signatures, every similarity policy, the matrices, find_motion",
          "[archetype][similarity]") {
  const auto a = bending_tube(), b = bending_tube(right_angle / 2);
  const archetype::Model_on on_a(a), on_b(b);
  CHECK(signatures::motion_signatures(on_a.model()) == signatures::motion_signatures(a));
  test::check_every_policy_same(on_a.model(), on_b.model(), a, b);
  similarity::visit_policy(similarity::Any_policy{similarity::Strain_distribution_similarity<alignment::Dtw>{}},
                           [&](const auto& policy) {
                             test::check_same_similarity(on_a.model(), on_b.model(), a, b, policy);
                           });
  const std::vector<archetype::Animation> models{on_a.model(), on_b.model()};
  const std::vector<mesh::Surface_mesh_animation> defaults{a, b};
  CHECK(similarity::similarity_matrix(models) == similarity::similarity_matrix(defaults));
  CHECK(similarity::similarity_matrix(models, models) == similarity::similarity_matrix(defaults, defaults));
  const auto query = a.frames(4, 13);
  const archetype::Model_on on_query(query);
  const auto found = similarity::find_motion(on_query.model(), on_a.model(), {.count = 1});
  const auto expected = similarity::find_motion(query, a, {.count = 1});
  REQUIRE(found.size() == expected.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    CHECK(found[k].value == expected[k].value);
    CHECK(found[k].alignment == expected[k].alignment);
  }
}

TEST_CASE("point maps of one's own: the algorithms follow the user's map, not the graph's points",
          "[archetype][named_parameters]") {
  const auto a = bending_tube();
  const Own_points_animation own(a);
  REQUIRE(own.graph.point(*vertices(own.graph).begin()) != frame_points(a, 0)[0]);
  CHECK(same_field(strain::compute_strain(own), strain::compute_strain(a)));
  CHECK(signatures::motion_signatures(own) == signatures::motion_signatures(a));
  CHECK(test::same_similarity(similarity::motion_similarity(own, own), similarity::motion_similarity(a, a)));

  // A reference mesh whose own points are garbage, its true points in a vector of the user's.
  const std::vector<mesh::Kernel::Point_3> rest = frame_points(a, 0);
  const auto rest_map = boost::make_iterator_property_map(rest.begin(), get(boost::vertex_index, own.graph));
  const auto expected = strain::compute_strain(a, a.face_graph());
  const auto field = strain::compute_strain(a, own.graph, {}, CGAL::parameters::vertex_point_map(rest_map));
  CHECK(same_field(field, expected));
  CHECK_FALSE(same_field(strain::compute_strain(a, own.graph), expected));  // the graph's own points

  // The user's vertex and face index maps: the identity, given rather than taken from the graph.
  const auto with_indices = strain::compute_strain(
      a, own.graph, {},
      CGAL::parameters::vertex_point_map(rest_map)
          .vertex_index_map(get(boost::vertex_index, own.graph))
          .face_index_map(get(boost::face_index, own.graph)));
  CHECK(same_field(with_indices, expected));

  // A face index map that numbers the faces backwards writes triangle F - 1 - j's strain into face j.
  std::vector<std::uint32_t> backwards(num_faces(own.graph));
  for (auto f : faces(own.graph)) backwards[f.idx()] = std::uint32_t(num_faces(own.graph) - 1 - f.idx());
  const auto reversed = boost::make_iterator_property_map(backwards.begin(), get(boost::face_index, own.graph));
  std::vector<float> values(num_faces(own.graph));
  const auto out = boost::make_iterator_property_map(values.begin(), get(boost::face_index, own.graph));
  strain::put_strain_frame(field, 6, own.graph, out, CGAL::parameters::face_index_map(reversed));
  for (std::size_t j = 0; j < values.size(); ++j) CHECK(values[j] == field(field.num_faces() - 1 - j, 6));

  // make_face_graph writes the points into the user's map.
  std::vector<mesh::Kernel::Point_3> written(rest.size());
  const auto into = CGAL::parameters::vertex_point_map(Points_into{&written});
  const auto built = mesh::make_face_graph<mesh::Surface_mesh>(rest, a.triangles(), into);
  CHECK(written == rest);
  CHECK(num_faces(built) == a.num_faces());
}

}  // namespace concept_archetype_test
