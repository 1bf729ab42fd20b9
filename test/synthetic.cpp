// Tests of synthetic.h: the bending tube and its ground truth.
#include "test_support.h"

#include <deformseg/mesh/synthetic.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>

using namespace deformseg;

namespace {

using deformseg::test::right_angle;

Eigen::Vector3d vertex(const mesh::Deforming_mesh<mesh::Surface_mesh>& a, std::size_t t, std::size_t i) {
  return a.frame_matrix(t).col(Eigen::Index(i));
}

double edge_length(const mesh::Deforming_mesh<mesh::Surface_mesh>& a, std::size_t t, std::size_t f, int k) {
  const auto& tri = a.triangles()[f];
  return (vertex(a, t, tri[k]) - vertex(a, t, tri[(k + 1) % 3])).norm();
}

// Signed volume enclosed by the frame's triangles (divergence theorem): positive when they are
// oriented outwards.
double enclosed_volume(const mesh::Deforming_mesh<mesh::Surface_mesh>& a, std::size_t t) {
  double six_volume = 0;
  for (const auto& tri : a.triangles())
    six_volume += vertex(a, t, tri[0]).dot(vertex(a, t, tri[1]).cross(vertex(a, t, tri[2])));
  return six_volume / 6;
}

// Rest, bend by 90 degrees, hold, unbend: 10 frames each.
mesh::Bending_tube bend_once() {
  mesh::Bending_tube spec;
  spec.schedule = {{10, {0.0}}, {10, {right_angle}}, {10, {}}, {10, {0.0}}};
  return spec;
}

}  // namespace

TEST_CASE("bending tube: sizes, schedule and closed outward surface", "[synthetic]") {
  const auto tube = mesh::make_bending_tube(bend_once());
  const auto& a = tube.animation;
  CHECK(a.num_frames() == 41);
  CHECK(a.num_vertices() == 49 * 16 + 2);
  CHECK(a.num_faces() == 2 * 48 * 16 + 2 * 16);
  CHECK(CGAL::is_closed(a.face_graph()));
  CHECK(enclosed_volume(a, 0) > 0);
  CHECK(enclosed_volume(a, 25) > 0);

  using Frames = std::array<std::size_t, 2>;
  CHECK(tube.phase_frames == std::vector<Frames>{{1, 10}, {11, 20}, {21, 30}, {31, 40}});
  CHECK(tube.joint_angles[10][0] == 0.0);
  CHECK(tube.joint_angles[20][0] == right_angle);
  CHECK(tube.joint_angles[25][0] == right_angle);
  CHECK(tube.joint_angles[40][0] == 0.0);
  CHECK(tube.joint_angles[15][0] > 0.0);
  CHECK(tube.joint_angles[15][0] < right_angle);
}

TEST_CASE("bending tube: the top turns about the joint by the scheduled angle", "[synthetic]") {
  const auto tube = mesh::make_bending_tube(bend_once());
  const std::size_t top = tube.animation.num_vertices() - 1;  // the top cap's centre
  CHECK((vertex(tube.animation, 0, top) - Eigen::Vector3d(0, 0, 1)).norm() < 1e-15);
  CHECK((vertex(tube.animation, 25, top) - Eigen::Vector3d(0.5, 0, 0.5)).norm() < 1e-15);
  CHECK((vertex(tube.animation, 40, top) - Eigen::Vector3d(0, 0, 1)).norm() < 1e-15);
}

TEST_CASE("bending tube: only the triangles of a blend zone change shape", "[synthetic]") {
  mesh::Bending_tube spec = bend_once();
  spec.joints = {{.position = 0.31, .blend_width = 0.1}, {.position = 0.7, .blend_width = 0.2}};
  spec.schedule = {{5, {right_angle, 0.0}}, {5, {0.0, -right_angle}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& a = tube.animation;

  std::array<std::size_t, 3> count{};  // rigid, joint 0, joint 1
  for (std::size_t f = 0; f < a.num_faces(); ++f) {
    ++count[std::size_t(tube.face_joint[f] + 1)];
    double largest_change = 0;
    for (std::size_t t = 0; t < a.num_frames(); ++t)
      for (int k = 0; k < 3; ++k)
        largest_change = std::max(largest_change, std::abs(edge_length(a, t, f, k) - edge_length(a, 0, f, k)));
    if (tube.face_joint[f] < 0)
      CHECK(largest_change < 1e-14);
    else if (std::abs(a.frame_matrix(0).col(a.triangles()[f][0]).z() -
                      spec.joints[std::size_t(tube.face_joint[f])].position) < 0.03)
      CHECK(largest_change > 1e-3);  // well inside the zone, the bend shows
  }
  // 48 rings over the length: zone 0 spans rings 12.48..17.28, so the 6 segments from ring 12
  // to ring 18 touch it; zone 1 spans rings 28.8..38.4, touched by the 11 from 28 to 39.
  CHECK(count[1] == 2 * 16 * 6);
  CHECK(count[2] == 2 * 16 * 11);
  CHECK(count[0] == a.num_faces() - count[1] - count[2]);
}

TEST_CASE("bending tube: placement is a similarity of every frame", "[synthetic]") {
  mesh::Bending_tube spec = bend_once();
  const auto plain = mesh::make_bending_tube(spec);
  spec.placement = {.scale = 3.5,
                    .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized())),
                    .translation = Eigen::Vector3d(10, -20, 30)};
  const auto placed = mesh::make_bending_tube(spec);
  const Eigen::Matrix3d rotation = spec.placement.rotation.toRotationMatrix();
  for (std::size_t t : {0, 17, 40})
    for (std::size_t i = 0; i < plain.animation.num_vertices(); i += 37) {
      const Eigen::Vector3d expected = rotation * (3.5 * vertex(plain.animation, t, i)) + spec.placement.translation;
      CHECK((vertex(placed.animation, t, i) - expected).norm() < 1e-12);
    }
  CHECK(placed.face_joint == plain.face_joint);
}

TEST_CASE("bending tube: other shapes, same schedule and ground truth layout", "[synthetic]") {
  mesh::Bending_tube spec = bend_once();
  spec.shape = {.radius = 0.25, .length = 2.0, .sectors = 7, .rings = 20, .caps = false};
  const auto tube = mesh::make_bending_tube<CGAL::Polyhedron_3<mesh::Kernel>>(spec);
  CHECK(tube.animation.num_frames() == 41);
  CHECK(tube.animation.num_vertices() == 21 * 7);
  CHECK(tube.animation.num_faces() == 2 * 20 * 7);
  CHECK(!CGAL::is_closed(tube.animation.face_graph()));
  // The zone 0.425..0.575 of 20 rings covers rings 8.5..11.5: three rings of triangles touch it.
  CHECK(std::count(tube.face_joint.begin(), tube.face_joint.end(), 0) == 2 * 7 * 4);
}

TEST_CASE("bending tube: a zone narrower than a ring still marks the triangles it splits",
          "[synthetic]") {
  mesh::Bending_tube spec = bend_once();
  spec.shape.rings = 4;
  spec.joints = {{.position = 0.6, .blend_width = 0.01}};
  const auto tube = mesh::make_bending_tube(spec);
  // The zone lies strictly between rings 2 and 3 (heights 0.5 and 0.75): no vertex is inside it,
  // yet the triangles between those rings have vertices on both bones.
  CHECK(std::count(tube.face_joint.begin(), tube.face_joint.end(), 0) == 2 * 16);
}

TEST_CASE("bending tube: rings on the edges of a zone follow one bone exactly", "[synthetic]") {
  mesh::Bending_tube spec = bend_once();
  spec.shape.rings = 40;
  // Zones 0.25..0.35 and 0.65..0.75: edges on rings 10, 14, 26 and 30, however the subtraction
  // rounds. Each zone deforms the 4 segments between its edge rings, and those edge rings stay
  // rigid with their bone.
  spec.joints = {{.position = 0.3, .blend_width = 0.1}, {.position = 0.7, .blend_width = 0.1}};
  spec.schedule = {{4, {right_angle, right_angle}}};
  const auto tube = mesh::make_bending_tube(spec);
  CHECK(std::count(tube.face_joint.begin(), tube.face_joint.end(), 0) == 2 * 16 * 4);
  CHECK(std::count(tube.face_joint.begin(), tube.face_joint.end(), 1) == 2 * 16 * 4);
}

TEST_CASE("bending tube: invalid specifications are rejected", "[synthetic][errors]") {
  mesh::Bending_tube spec = bend_once();
  SECTION("overlapping joints") {
    spec.joints = {{.position = 0.4, .blend_width = 0.2}, {.position = 0.5, .blend_width = 0.2}};
    spec.schedule = {};
    CHECK_THROWS_WITH(mesh::make_bending_tube(spec), Catch::StartsWith("joint 1: blend zones"));
  }
  SECTION("a phase with the wrong number of angles") {
    spec.schedule = {{3, {0.1, 0.2}}};
    CHECK_THROWS_WITH(mesh::make_bending_tube(spec), Catch::StartsWith("phase 0: needs"));
  }
  SECTION("a phase of no frame") {
    spec.schedule = {{3, {0.1}}, {0, {}}};
    CHECK_THROWS_AS(mesh::make_bending_tube(spec), invalid_input);
  }
  SECTION("a flat tube") {
    spec.shape.radius = 0;
    CHECK_THROWS_AS(mesh::make_bending_tube(spec), invalid_input);
  }
  SECTION("a zero scale") {
    spec.placement.scale = 0;
    CHECK_THROWS_WITH(mesh::make_bending_tube(spec), "placement scale must be > 0");
  }
  SECTION("frames that would not fit in memory, refused before any is made") {
    spec.shape.sectors = 10'000;
    spec.shape.rings = 10'000;
    CHECK_THROWS_WITH(mesh::make_bending_tube(spec),
                      Catch::Contains("a tube of 100010002 vertices over") && Catch::Contains("fewer sectors"));
  }
}
