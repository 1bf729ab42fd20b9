// Tests of deforming_mesh.h: the DeformingMesh concept, Deforming_mesh, make_face_graph.
#include "mesh_types.h"
#include "tetrahedron.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <CGAL/Polyhedron_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

using namespace deformseg;

namespace {

using test::Polyhedron;

using deformseg::test::tetra_points;
using deformseg::test::tetra_triangles;

// Frame t moves every vertex by (t, 2t, 3t).
std::vector<double> translated_frames(std::size_t frames) {
  std::vector<double> xyz;
  for (std::size_t t = 0; t < frames; ++t)
    for (const auto& p : tetra_points)
      for (int k = 0; k < 3; ++k) xyz.push_back(p[k] + double(t) * (k + 1));
  return xyz;
}

// A type with every member but the frame point map: not a DeformingMesh.
struct Without_point_map {
  using Face_graph = mesh::Surface_mesh;
  const mesh::Surface_mesh& face_graph() const;
  std::size_t num_frames() const;
};

}  // namespace

static_assert(mesh::FaceGraph<mesh::Surface_mesh>);
static_assert(mesh::FaceGraph<Polyhedron>);
static_assert(mesh::DeformingMesh<mesh::Deforming_mesh<mesh::Surface_mesh>>);
static_assert(mesh::DeformingMesh<mesh::Deforming_mesh<Polyhedron, float>>);
static_assert(!mesh::DeformingMesh<Without_point_map>);
static_assert(!mesh::DeformingMesh<mesh::Surface_mesh>);

TEMPLATE_TEST_CASE("Deforming_mesh: frames in, the same positions out", "[deforming_mesh]",
                   mesh::Surface_mesh, Polyhedron) {
  mesh::Deforming_mesh<TestType> animation(mesh::make_face_graph<TestType>(tetra_points, tetra_triangles),
                                     translated_frames(3));
  REQUIRE(animation.num_frames() == 3);
  REQUIRE(animation.num_vertices() == 4);
  REQUIRE(animation.num_faces() == 4);

  // The index table follows the triangles given, up to the rotation of each cycle.
  for (std::size_t j = 0; j < 4; ++j) {
    auto tri = animation.triangles()[j];
    auto expected = tetra_triangles[j];
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    CHECK(std::vector<int>(tri.begin(), tri.end()) ==
          std::vector<int>(expected.begin(), expected.end()));
  }

  const auto positions = animation.frame_positions(2);
  const auto points = animation.frame_point_map(2);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto p = get(points, animation.vertex_descriptors()[i]);
    for (int k = 0; k < 3; ++k) {
      CHECK(p[k] == tetra_points[i][k] + 2.0 * (k + 1));
      CHECK(positions[3 * i + k] == p[k]);
      CHECK(animation.frame_matrix(2)(k, Eigen::Index(i)) == p[k]);
    }
  }
}

TEST_CASE("Deforming_mesh takes a Coordinate_buffer's storage and copies a std::vector's", "[deforming_mesh]") {
  const auto graph = mesh::make_face_graph<mesh::Surface_mesh>(tetra_points, tetra_triangles);
  const std::vector<double> xyz = translated_frames(3);
  mesh::Coordinate_buffer<double> buffer(xyz.size());  // sized, not written: every number written below
  std::copy(xyz.begin(), xyz.end(), buffer.begin());
  const double* storage = buffer.data();

  const mesh::Surface_mesh_animation taken(graph, std::move(buffer));
  const mesh::Surface_mesh_animation copied(graph, xyz);
  CHECK(taken.all_positions().data() == storage);
  CHECK(copied.all_positions().data() != xyz.data());
  CHECK(std::equal(taken.all_positions().begin(), taken.all_positions().end(), xyz.begin(), xyz.end()));
  CHECK(std::equal(copied.all_positions().begin(), copied.all_positions().end(), xyz.begin(), xyz.end()));

  mesh::Coordinate_buffer<double> short_buffer(xyz.begin(), xyz.begin() + 13);
  CHECK_THROWS_WITH(mesh::Surface_mesh_animation(graph, std::move(short_buffer)),
                    "expected a multiple of 3 x 4 coordinates, got 13");
  mesh::Coordinate_buffer<double> with_nan(xyz.begin(), xyz.end());
  with_nan[12 + 3 * 2] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(mesh::Surface_mesh_animation(graph, std::move(with_nan)),
                    "frame 1: vertex 2 has a non-finite coordinate");
}

TEST_CASE("Deforming_mesh: frames added one by one, or from a point map", "[deforming_mesh]") {
  const auto graph = mesh::make_face_graph<mesh::Surface_mesh>(tetra_points, tetra_triangles);
  mesh::Deforming_mesh<mesh::Surface_mesh, float> animation(graph);
  CHECK(animation.num_frames() == 0);
  animation.add_frame_from(get(CGAL::vertex_point, graph));
  const auto xyz = translated_frames(2);
  animation.add_frame(std::span<const double>(xyz).subspan(12, 12));
  REQUIRE(animation.num_frames() == 2);
  CHECK(animation.frame_positions(0)[3 * 3 + 2] == 1.0f);
  CHECK(animation.frame_positions(1)[3 * 3 + 2] == 4.0f);

  // A copy shares the connectivity but not the positions.
  auto copy = animation;
  copy.add_frame(std::span<const double>(xyz).subspan(0, 12));
  CHECK(copy.num_frames() == 3);
  CHECK(animation.num_frames() == 2);
  CHECK(&copy.face_graph() == &animation.face_graph());
}

// The face graphs of the tests: OpenMesh's TriMesh of Vec3d too, when the build found OpenMesh.
using Face_graphs = std::tuple<mesh::Surface_mesh, Polyhedron
#if DEFORMSEG_TEST_OPENMESH
                               ,
                               test::Open_mesh
#endif
                               >;

// CGAL's point map for OpenMesh would round the points to float: make_face_graph sets them itself.
TEMPLATE_LIST_TEST_CASE("make_face_graph keeps every point to the last bit", "[deforming_mesh]", Face_graphs) {
  // Coordinates that float does not hold.
  std::vector<std::array<double, 3>> points = tetra_points;
  for (auto& p : points)
    for (double& x : p) x = x / 3 + 0.1;
  const TestType graph = mesh::make_face_graph<TestType>(points, tetra_triangles);
  mesh::Deforming_mesh<TestType> animation(graph);
  animation.add_frame_from(get(CGAL::vertex_point, animation.face_graph()));
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(animation.frame_positions(0)[3 * i + std::size_t(k)] == points[i][k]);
}

TEST_CASE("make_deforming_mesh copies any model, Polyhedron_3 handles included",
          "[deforming_mesh]") {
  mesh::Deforming_mesh<Polyhedron> original(mesh::make_face_graph<Polyhedron>(tetra_points, tetra_triangles),
                                      translated_frames(2));
  const auto copy = mesh::make_deforming_mesh<float>(original);
  REQUIRE(copy.num_frames() == 2);
  for (std::size_t i = 0; i < 3 * 4 * 2; ++i)
    CHECK(copy.all_positions()[i] == float(original.all_positions()[i]));
  CHECK(&copy.face_graph() != &original.face_graph());
}

TEST_CASE("Deforming_mesh rejects bad input with a clear message", "[deforming_mesh][errors]") {
  const auto graph = mesh::make_face_graph<mesh::Surface_mesh>(tetra_points, tetra_triangles);

  SECTION("a coordinate count that is not a multiple of 3 V") {
    CHECK_THROWS_WITH(mesh::Surface_mesh_animation(graph, std::vector<double>(13, 0.0)),
                      "expected a multiple of 3 x 4 coordinates, got 13");
  }
  SECTION("a NaN coordinate names its frame and vertex") {
    auto xyz = translated_frames(3);
    xyz[2 * 12 + 3 * 1 + 2] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(mesh::Surface_mesh_animation(graph, xyz),
                      "frame 2: vertex 1 has a non-finite coordinate");
  }
  SECTION("an infinite coordinate in an added frame") {
    mesh::Surface_mesh_animation animation(graph, translated_frames(1));
    std::vector<double> xyz(12, 0.0);
    xyz[0] = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(animation.add_frame(std::span<const double>(xyz)),
                      "frame 1: vertex 0 has a non-finite coordinate");
  }
  SECTION("a frame with another vertex count") {
    mesh::Surface_mesh_animation animation(graph);
    std::vector<double> xyz(9, 0.0);
    CHECK_THROWS_WITH(animation.add_frame(std::span<const double>(xyz)),
                      "frame 0: frame has 3 vertices, the mesh 4");
  }
  SECTION("a frame out of range") {
    mesh::Surface_mesh_animation animation(graph, translated_frames(2));
    CHECK_THROWS_WITH(animation.frame_positions(2), "frame 2 asked of an animation of 2 frames");
  }
  SECTION("a quad face") {
    mesh::Surface_mesh quad;
    std::vector<mesh::Surface_mesh::Vertex_index> v;
    for (int i = 0; i < 4; ++i) v.push_back(quad.add_vertex(mesh::Kernel::Point_3(i % 2, i / 2, 0)));
    quad.add_face(v[0], v[1], v[3], v[2]);
    CHECK_THROWS_WITH(mesh::Surface_mesh_animation(quad), "face 0 has 4 vertices; deformseg needs triangles");
  }
  SECTION("a Surface_mesh with removed vertices") {
    mesh::Surface_mesh mesh = graph;
    mesh.remove_vertex(*mesh.vertices().begin());
    CHECK_THROWS_WITH(mesh::Surface_mesh_animation(mesh), Catch::Contains("collect_garbage()"));
  }
}

TEST_CASE("make_face_graph names the triangle that cannot be added", "[deforming_mesh][errors]") {
  SECTION("index out of range") {
    const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 1, 4}};
    CHECK_THROWS_WITH(mesh::make_face_graph<mesh::Surface_mesh>(tetra_points, triangles),
                      "triangle 1 has vertex index 4 out of range [0, 4)");
  }
  SECTION("a non-manifold edge") {
    const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 1, 3}};
    CHECK_THROWS_WITH(mesh::make_face_graph<mesh::Surface_mesh>(tetra_points, triangles),
                      Catch::StartsWith("triangle 1 cannot be added"));
  }
  SECTION("a degenerate triangle repeating a vertex") {
    const std::vector<std::array<int, 3>> triangles{{0, 0, 2}};
    CHECK_THROWS_WITH(mesh::make_face_graph<Polyhedron>(tetra_points, triangles),
                      Catch::StartsWith("triangle 0 cannot be added"));
  }
}

namespace {

TEST_CASE("check_frames_per_second: the one check of a frame rate, its message the same everywhere",
          "[deforming_mesh][errors]") {
  CHECK_NOTHROW(mesh::check_frames_per_second(24));
  for (const double fps : {0.0, -30.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    CHECK_THROWS_WITH(mesh::check_frames_per_second(fps),
                      Catch::StartsWith("fps must be positive and finite (the frame rate, in frames per second), not"));
    CHECK_THROWS_WITH(mesh::check_frames_per_second(fps, "motion_signatures"),
                      Catch::StartsWith("motion_signatures: fps"));
  }
  CHECK_THROWS_WITH(mesh::check_frames_per_second(0, {}, {.file = "walk.obj"}),
                    Catch::StartsWith("walk.obj: fps must"));
  mesh::Deforming_mesh<mesh::Surface_mesh> animation(
      mesh::make_face_graph<mesh::Surface_mesh>(tetra_points, tetra_triangles));
  CHECK_THROWS_WITH(animation.set_frames_per_second(-1), "fps must be positive and finite (the frame rate, in frames "
                                                         "per second), not -1.000000");
}

}  // namespace
