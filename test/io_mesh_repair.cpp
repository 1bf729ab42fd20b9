// Tests of io/mesh_repair.h: repair_triangles and make_repaired_animation on soups made here
// (degenerate, duplicate, non-manifold, misoriented triangles; welding), checked against brute
// force on random soups; the repair through read_frame_sequence and read_animation.
#include "test_support.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/outlying_vertices.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/strain/strain.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

using deformseg::invalid_input;
using deformseg::mesh::make_face_graph;
using deformseg::mesh::Surface_mesh;
using deformseg::io::Defect_policy;
using deformseg::io::make_repaired_animation;
using deformseg::io::Repair_options;
using deformseg::io::Repair_report;
using deformseg::io::repair_triangles;
using deformseg::io::internal::Oriented_soup;
using deformseg::io::internal::Soup_triangle;
using deformseg::io::internal::drop_triangles;
using deformseg::io::internal::misoriented_triangles;
using deformseg::io::internal::weld_vertices;
using Catch::Matchers::Message;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;
namespace fs = std::filesystem;

namespace {

// A soup: one frame of points, and triangles.
struct Soup {
  std::vector<double> points;  // 3 V
  Triangles triangles;

  std::uint32_t add(double x, double y, double z) {
    points.insert(points.end(), {x, y, z});
    return static_cast<std::uint32_t>(points.size() / 3 - 1);
  }
  std::size_t num_vertices() const { return points.size() / 3; }
};

// A cone: an apex above a ring of `n` vertices around (cx, 0, cz), apex at height `h`, its `n`
// triangles a closed fan around the apex, all counter-clockwise seen from outside.
void add_cone(Soup& soup, std::uint32_t apex, double cx, double cz, double h, int n) {
  std::vector<std::uint32_t> ring;
  for (int i = 0; i < n; ++i)
    ring.push_back(soup.add(cx + std::cos(2 * M_PI * i / n), h, cz + std::sin(2 * M_PI * i / n)));
  for (int i = 0; i < n; ++i) soup.triangles.push_back({apex, ring[(i + 1) % n], ring[i]});
}

// The hand-made soup of the brief, in three parts that share no vertex:
// - triangles 0-1: a square (0 1 2 3), then triangle 2 repeats vertex 1 (0 1 1);
// - triangles 3-5: three triangles on the edge (4, 5), fins towards 6, 7, 8;
// - triangles 6-13: two cones of 4 triangles each touching at their apex, vertex 9.
Soup defective_soup() {
  Soup soup;
  for (const auto& p : {std::array{0., 0., 0.}, {1., 0., 0.}, {1., 1., 0.}, {0., 1., 0.}}) soup.add(p[0], p[1], p[2]);
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 1}};
  for (const auto& p : {std::array{3., 0., 0.}, {3., 0., 1.}, {4., 0., 0.}, {3., 1., 0.}, {2., 0., 0.}})
    soup.add(p[0], p[1], p[2]);
  soup.triangles.insert(soup.triangles.end(), {{4, 5, 6}, {5, 4, 7}, {4, 5, 8}});
  const std::uint32_t apex = soup.add(6, 0, 0);
  add_cone(soup, apex, 6, 0, 1, 4);
  add_cone(soup, apex, 6, 0, -1, 4);
  return soup;
}

// The repair of a one-frame soup.
deformseg::io::Repaired_triangles repaired(const Soup& soup, const Repair_options& options = {}) {
  return repair_triangles(std::span<const double>(soup.points), soup.num_vertices(), std::span(soup.triangles),
                          options);
}

// An unwelded cube: each face its own 4 vertices (24 in all), two triangles per face, outward.
Soup unwelded_cube() {
  Soup soup;
  // Each face as its 4 corners (bits x, y, z of the corner index) counter-clockwise from outside.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& face : faces) {
    std::array<std::uint32_t, 4> v{};
    for (int k = 0; k < 4; ++k) v[k] = soup.add(face[k] & 1, (face[k] >> 1) & 1, (face[k] >> 2) & 1);
    soup.triangles.push_back({v[0], v[1], v[2]});
    soup.triangles.push_back({v[0], v[2], v[3]});
  }
  return soup;
}

// Frame 0 then a second frame: every point scaled by 2 and moved by (1, 2, 3).
std::vector<double> two_frames(const std::vector<double>& first) {
  std::vector<double> positions = first;
  for (std::size_t i = 0; i < first.size(); ++i) positions.push_back(2 * first[i] + double(1 + i % 3));
  return positions;
}

// Triangles equal up to rotation and reversal.
bool same_triangle(std::array<std::uint32_t, 3> a, std::array<std::uint32_t, 3> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

}  // namespace

TEST_CASE("repair_triangles: a clean mesh is kept as it is", "[io][repair]") {
  const Soup cube = unwelded_cube();
  const auto result = repaired(cube);
  CHECK(result.triangles == cube.triangles);
  CHECK(result.source_vertex.size() == 24);
  for (std::uint32_t i = 0; i < 24; ++i) CHECK(result.source_vertex[i] == i);
  CHECK(result.source_triangle == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
  CHECK_FALSE(result.report.changed());
  CHECK(result.report.vertices == 24);
  CHECK(result.report.triangles == 12);
}

TEST_CASE("repair_triangles: a repeated vertex, a non-manifold edge and vertex, with their counts", "[io][repair]") {
  const Soup soup = defective_soup();
  const auto result = repaired(soup);
  const Repair_report& r = result.report;
  CHECK(r.input_vertices == 18);
  CHECK(r.input_triangles == 14);
  CHECK(r.welded_vertices == 0);
  CHECK(r.degenerate_triangles == 1);
  CHECK(r.duplicate_triangles == 0);
  CHECK(r.non_manifold_edges == 1);
  CHECK(r.non_manifold_vertices == 1);
  // The edge's ends split into 3 fans each (2 copies each), the apex into 2 (1 copy).
  CHECK(r.duplicated_vertices == 5);
  CHECK(r.reoriented_triangles == 0);  // the fins meet only at their non-manifold edge
  CHECK(r.unrepairable_triangles == 0);
  CHECK(r.vertices == 23);
  CHECK(r.triangles == 13);
  CHECK(r.changed());
  // The counts by name, for the report's writers, each its member's value.
  const auto counts = r.counts();
  CHECK(counts[3] == std::pair<std::string_view, std::size_t>("degenerate_triangles", 1));
  CHECK(counts[7] == std::pair<std::string_view, std::size_t>("duplicated_vertices", 5));
  CHECK(counts[13] == std::pair<std::string_view, std::size_t>("triangles", 13));
  CHECK(result.source_triangle == std::vector<std::uint32_t>{0, 1, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13});
  // Without welding, the vertices keep their indices and the copies follow.
  for (std::uint32_t i = 0; i < 18; ++i) CHECK(result.source_vertex[i] == i);
  std::multiset<std::uint32_t> copied(result.source_vertex.begin() + 18, result.source_vertex.end());
  CHECK(copied == std::multiset<std::uint32_t>{4, 4, 5, 5, 9});
  CHECK_NOTHROW(make_face_graph<Surface_mesh>(std::vector<std::array<double, 3>>(23), result.triangles));

  Repair_report report;
  const auto animation =
      make_repaired_animation(std::span<const double>(soup.points), 18, std::span(soup.triangles), {}, &report);
  CHECK(animation.num_vertices() == 23);
  CHECK(animation.num_faces() == 13);
  CHECK(report.duplicated_vertices == 5);
  // A copy is where its source is.
  for (std::size_t i = 18; i < 23; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      CHECK(animation.frame_positions(0)[3 * i + k] == soup.points[3 * result.source_vertex[i] + k]);
}

TEST_CASE("repair_triangles: refuse names the first defect", "[io][repair][errors]") {
  Soup soup = defective_soup();
  const Repair_options refuse{.defects = Defect_policy::refuse};
  CHECK_THROWS_MATCHES(repaired(soup, refuse), invalid_input, Message("triangle 2 repeats vertex 1"));
  soup.triangles.erase(soup.triangles.begin() + 2);  // now triangles 2-4 are the fins of edge (4, 5)
  CHECK_THROWS_MATCHES(repaired(soup, refuse), invalid_input,
                       Message("edge (4, 5) is shared by 3 triangles (2, 3, 4)"));
  soup.triangles.erase(soup.triangles.begin() + 4);
  CHECK_THROWS_MATCHES(repaired(soup, refuse), invalid_input, Message("vertex 9 joins 2 separate fans of triangles"));

  SECTION("duplicates, whatever the order of their vertices") {
    soup.triangles.push_back({2, 0, 1});
    soup.triangles.push_back({3, 2, 0});
    CHECK_THROWS_MATCHES(repaired(soup, refuse), invalid_input, Message("triangles 0 and 12 have the same vertices"));
    const auto result = repaired(soup);
    CHECK(result.report.duplicate_triangles == 2);
  }
  SECTION("inconsistent orientation") {
    soup.triangles[1] = {0, 3, 2};  // runs from 2 to 0, as triangle 0 does
    CHECK_THROWS_MATCHES(repaired(soup, refuse), invalid_input,
                         Message("triangles 0 and 1 are inconsistently oriented: both go from vertex 2 to vertex 0 on "
                                 "their shared edge"));
    const auto result = repaired(soup);
    CHECK(result.report.reoriented_triangles == 1);
    CHECK(result.triangles[1] == std::array<std::uint32_t, 3>{2, 3, 0});
  }
  SECTION("welding is not a defect") {
    const Soup cube = unwelded_cube();
    const auto result = repaired(cube, {.weld = true, .defects = Defect_policy::refuse});
    CHECK(result.report.welded_vertices == 16);
  }
  SECTION("a triangle that repeats a vertex once welded") {
    Soup strip;
    for (const double x : {0., 1., 1.}) strip.add(x, 0, 0);
    strip.add(0, 1, 0);
    strip.triangles = {{0, 1, 3}, {1, 2, 3}};
    CHECK_THROWS_MATCHES(repaired(strip, {.weld = true, .defects = Defect_policy::refuse}), invalid_input,
                         Message("triangle 1 repeats vertex 1 once its vertices are welded"));
    CHECK(repaired(strip, {.weld = true}).report.degenerate_triangles == 1);
  }
}

TEST_CASE("repair_triangles: checks its input", "[io][repair][errors]") {
  const Soup cube = unwelded_cube();
  const std::span<const double> points(cube.points);
  CHECK_THROWS_MATCHES(repair_triangles(points.first(70), 24, std::span(cube.triangles)), invalid_input,
                       Message("expected a multiple of 3 x 24 coordinates, got 70"));
  Triangles bad = cube.triangles;
  bad[3][1] = 24;
  CHECK_THROWS_MATCHES(repair_triangles(points, 24, std::span(bad)), invalid_input,
                       Message("triangle 3 has vertex index 24 out of range [0, 24)"));
  CHECK_THROWS_MATCHES(repair_triangles(points, 24, std::span(cube.triangles), {.weld = true, .weld_tolerance = -1}),
                       invalid_input, Message("weld_tolerance must be finite and at least 0, not -1"));
  std::vector<double> nan = two_frames(cube.points);
  nan[72 + 3 * 5 + 1] = std::nan("");
  CHECK_THROWS_MATCHES(repair_triangles(std::span<const double>(nan), 24, std::span(cube.triangles), {.weld = true}),
                       invalid_input, Message("frame 1: vertex 5 has a non-finite coordinate"));
}

TEST_CASE("repair_triangles: welding an unwelded cube in a 2-frame animation", "[io][repair][weld]") {
  const Soup cube = unwelded_cube();
  std::vector<double> positions = two_frames(cube.points);
  const Repair_options weld{.weld = true};

  Repair_report report;
  const auto closed = make_repaired_animation(std::span<const double>(positions), 24, std::span(cube.triangles), weld,
                                              &report);
  CHECK(report.welded_vertices == 16);
  CHECK(report.vertices == 8);
  CHECK(report.triangles == 12);
  CHECK_FALSE(report.duplicated_vertices + report.reoriented_triangles + report.degenerate_triangles);
  CHECK(closed.num_vertices() == 8);
  CHECK(CGAL::is_closed(closed.face_graph()));
  // Output vertices in the order of their smallest input vertex: face 0 gives corners 0 2 3 1.
  const auto result = repair_triangles(std::span<const double>(positions), 24, std::span(cube.triangles), weld);
  CHECK(std::vector<std::uint32_t>(result.source_vertex.begin(), result.source_vertex.begin() + 4) ==
        std::vector<std::uint32_t>{0, 1, 2, 3});
  CHECK(result.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});

  SECTION("vertices that coincide in frame 0 only are not welded") {
    positions[72 + 0] += 0.5;  // input vertex 0 (corner 0 of face 0) leaves the others in frame 1
    const auto slit = repair_triangles(std::span<const double>(positions), 24, std::span(cube.triangles), weld);
    CHECK(slit.report.welded_vertices == 15);
    CHECK(slit.report.vertices == 9);
    CHECK(std::count(slit.source_vertex.begin(), slit.source_vertex.end(), 0u) == 1);
    CHECK_FALSE(CGAL::is_closed(
        make_repaired_animation(std::span<const double>(positions), 24, std::span(cube.triangles), weld).face_graph()));
  }
  SECTION("within the tolerance, not beyond") {
    // The box of both frames goes from (0, 0, 0) to (3, 4, 5): its diagonal is sqrt(50).
    const double step = 1e-3 * std::sqrt(50.0);
    positions[1] += 0.9 * step;
    positions[72 + 1] += 0.9 * step;
    CHECK(repair_triangles(std::span<const double>(positions), 24, std::span(cube.triangles),
                           {.weld = true, .weld_tolerance = 1e-3})
              .report.welded_vertices == 16);
    positions[72 + 1] += 0.2 * step;
    CHECK(repair_triangles(std::span<const double>(positions), 24, std::span(cube.triangles),
                           {.weld = true, .weld_tolerance = 1e-3})
              .report.welded_vertices == 15);
  }
  SECTION("float positions") {
    const std::vector<float> floats(positions.begin(), positions.end());
    CHECK(repair_triangles(std::span<const float>(floats), 24, std::span(cube.triangles), weld).report.vertices == 8);
  }
}

namespace {

// A random small soup: `frames` frames of vertices on a coarse lattice (so that many coincide in
// frame 0), some of them moving apart in later frames, and random triangles over few vertices
// (so that edges and vertices are often non-manifold, triangles degenerate or repeated).
struct Random_animation {
  std::size_t vertices = 0;
  std::vector<double> positions;
  Triangles triangles;
};

Random_animation random_animation(std::mt19937& rng) {
  Random_animation a;
  a.vertices = std::uniform_int_distribution<std::size_t>(3, 14)(rng);
  const std::size_t frames = std::uniform_int_distribution<std::size_t>(1, 3)(rng);
  std::uniform_int_distribution<int> lattice(0, 2);
  std::vector<double> first;
  for (std::size_t i = 0; i < 3 * a.vertices; ++i) first.push_back(lattice(rng));
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t i = 0; i < first.size(); ++i)
      a.positions.push_back(first[i] + (t > 0 && i % 7 == 0 && lattice(rng) == 0 ? 0.25 * double(t) : 0.0));
  const std::size_t count = std::uniform_int_distribution<std::size_t>(0, 16)(rng);
  std::uniform_int_distribution<std::uint32_t> vertex(0, static_cast<std::uint32_t>(a.vertices - 1));
  for (std::size_t j = 0; j < count; ++j) a.triangles.push_back({vertex(rng), vertex(rng), vertex(rng)});
  return a;
}

// The groups of vertices that coincide in every frame (within `distance`), by brute force:
// O(V^2 T) pairs, then their connected components, each numbered by its smallest vertex.
std::vector<std::uint32_t> brute_force_welding(const Random_animation& a, double distance) {
  const std::size_t n = a.vertices;
  std::vector<std::uint32_t> group(n);
  for (std::uint32_t i = 0; i < n; ++i) group[i] = i;
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; j < n; ++j) {
        bool coincide = true;
        for (std::size_t x = 0; x < a.positions.size(); x += 3 * n)
          for (std::size_t k = 0; k < 3; ++k)
            coincide = coincide && std::abs(a.positions[x + 3 * i + k] - a.positions[x + 3 * j + k]) <= distance;
        if (coincide && group[j] > group[i]) {
          group[j] = group[i];
          merged = true;
        }
      }
  }
  return group;  // the smallest vertex of each one's component
}

double diagonal(const std::vector<double>& xyz) {
  std::array<double, 3> low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    low[i % 3] = std::min(low[i % 3], xyz[i]);
    high[i % 3] = std::max(high[i % 3], xyz[i]);
  }
  return std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
}

}  // namespace

TEST_CASE("repair_triangles: random soups against brute force", "[io][repair][weld]") {
  std::mt19937 rng(20261201);
  std::size_t changed = 0, welded = 0, copied = 0, unrepairable = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Random_animation a = random_animation(rng);
    const bool weld = trial % 2 == 0;
    const Repair_options options{.weld = weld, .weld_tolerance = 0.1};
    const auto result =
        repair_triangles(std::span<const double>(a.positions), a.vertices, std::span(a.triangles), options);
    INFO("trial " << trial);
    const std::size_t out = result.source_vertex.size();
    REQUIRE(result.report.vertices == out);
    REQUIRE(result.report.triangles == result.triangles.size());

    // A halfedge mesh accepts it, of both graph types.
    std::vector<std::array<double, 3>> points(out);
    CHECK_NOTHROW(make_face_graph<Surface_mesh>(points, result.triangles));
    CHECK_NOTHROW(make_face_graph<CGAL::Polyhedron_3<CGAL::Simple_cartesian<double>>>(points, result.triangles));

    // The welding is brute force's, numbered in the order of the smallest vertex of each group.
    const std::vector<std::uint32_t> group =
        weld ? brute_force_welding(a, 0.1 * diagonal(a.positions)) : brute_force_welding(a, -1);
    std::vector<std::uint32_t> representatives;
    for (std::uint32_t v = 0; v < a.vertices; ++v)
      if (group[v] == v) representatives.push_back(v);
    REQUIRE(out >= representatives.size());
    CHECK(std::vector<std::uint32_t>(result.source_vertex.begin(),
                                     result.source_vertex.begin() + representatives.size()) == representatives);
    CHECK(result.report.welded_vertices == a.vertices - representatives.size());

    // Every output triangle is its input triangle over the same (welded) source vertices.
    REQUIRE(result.source_triangle.size() == result.triangles.size());
    for (std::size_t j = 0; j < result.triangles.size(); ++j) {
      std::array<std::uint32_t, 3> sources{}, input = a.triangles[result.source_triangle[j]];
      for (std::size_t k = 0; k < 3; ++k) {
        sources[k] = result.source_vertex[result.triangles[j][k]];
        input[k] = group[input[k]];
      }
      CHECK(same_triangle(sources, input));
      if (j > 0) CHECK(result.source_triangle[j] > result.source_triangle[j - 1]);
    }
    // Every input triangle is kept, or dropped and counted.
    CHECK(a.triangles.size() == result.triangles.size() + result.report.degenerate_triangles +
                                    result.report.duplicate_triangles + result.report.unrepairable_triangles);

    // Every output vertex moves as its source.
    const auto animation =
        make_repaired_animation(std::span<const double>(a.positions), a.vertices, std::span(a.triangles), options);
    REQUIRE(animation.num_vertices() == out);
    for (std::size_t t = 0; t < animation.num_frames(); ++t)
      for (std::size_t i = 0; i < out; ++i)
        for (std::size_t k = 0; k < 3; ++k)
          CHECK(animation.frame_positions(t)[3 * i + k] ==
                a.positions[(t * a.vertices + result.source_vertex[i]) * 3 + k]);

    changed += result.report.changed();
    welded += result.report.welded_vertices > 0;
    copied += result.report.duplicated_vertices > 0;
    unrepairable += result.report.unrepairable_triangles > 0;
  }
  // The trials did meet what they are meant to test.
  CHECK(changed > 1000);
  CHECK(welded > 300);
  CHECK(copied > 300);
  CHECK(unrepairable == 0);  // CGAL's pass alone makes every one a manifold
}

TEST_CASE("weld_vertices: many vertices on one trajectory are one vertex / 0 and -0 alike", "[io][repair][weld]") {
  // 60,000 vertices in 2 frames, all at the origin but vertex 1 (-0 for 0) and vertex 2, which
  // leaves it in frame 1 by more than the tolerance, and vertex 3 by less. Compared pair by pair,
  // the one group would take 1.8e9 comparisons (what a glTF accessor of zeros once cost).
  const std::size_t n = 60000;
  std::vector<double> positions(2 * 3 * n, 0.0);
  positions[3 * 1] = -0.0;
  positions[3 * n + 3 * 2] = 1.0;   // x only: the diagonal is 1, the welding distance 1e-3
  positions[3 * n + 3 * 3] = 5e-4;  // within it of the origin, not of vertex 2
  const std::vector<std::uint32_t> welded =
      weld_vertices(std::span<const double>(positions), n, 1e-3);
  REQUIRE(welded.size() == n);
  CHECK(welded[0] == 0);
  CHECK(welded[1] == 0);
  CHECK(welded[2] == 1);
  CHECK(welded[3] == 0);
  CHECK(std::count(welded.begin(), welded.end(), 0u) == std::ptrdiff_t(n - 1));
}

TEST_CASE("repair_triangles: parts that cannot be oriented, a Moebius strip and the projective plane", "[io][repair]") {
  // A strip of 2 x 6 quads whose ends are glued with a half turn, its middle row of vertices
  // inside the strip.
  Soup strip;
  const int n = 6;
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 3; ++r) {
      const double angle = 2 * M_PI * i / n;
      const double width = (r - 1) * 0.3;
      const double twist = angle / 2;
      strip.add((1 + width * std::cos(twist)) * std::cos(angle), (1 + width * std::cos(twist)) * std::sin(angle),
                width * std::sin(twist));
    }
  const auto at = [&](int i, int r) { return static_cast<std::uint32_t>(i == n ? 3 * 0 + (2 - r) : 3 * i + r); };
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 2; ++r) {
      strip.triangles.push_back({at(i, r), at(i + 1, r), at(i + 1, r + 1)});
      strip.triangles.push_back({at(i, r), at(i + 1, r + 1), at(i, r + 1)});
    }
  const auto result = repaired(strip);
  std::vector<std::array<double, 3>> points(result.source_vertex.size());
  CHECK_NOTHROW(make_face_graph<Surface_mesh>(points, result.triangles));
  // CGAL cuts it along a seam of 4 copied vertices, every triangle kept.
  CHECK(result.report.non_manifold_vertices == 4);
  CHECK(result.report.duplicated_vertices == 4);
  CHECK(result.report.reoriented_triangles == 5);
  CHECK(result.report.unrepairable_triangles == 0);
  CHECK(result.report.triangles == 24);
  CHECK_THROWS_WITH(repaired(strip, {.defects = Defect_policy::refuse}),
                    Catch::Contains("are inconsistently oriented"));

  // The projective plane of 6 vertices and 10 triangles, closed: every vertex is inside.
  Soup plane;
  plane.points.assign(18, 0.0);
  plane.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 1, 5},
                     {1, 2, 4}, {1, 3, 4}, {1, 3, 5}, {2, 3, 5}, {2, 4, 5}};
  const auto cut = repaired(plane);
  CHECK_NOTHROW(make_face_graph<Surface_mesh>(std::vector<std::array<double, 3>>(cut.source_vertex.size()),
                                                          cut.triangles));
  CHECK(cut.report.duplicated_vertices == 4);
  CHECK(cut.report.triangles == 10);
}

TEST_CASE("repair_triangles: the check that skips CGAL's pass on an oriented manifold", "[io][repair]") {
  using deformseg::io::internal::is_oriented_manifold;
  using Soup_triangles = std::vector<Soup_triangle>;
  Soup cube = unwelded_cube();
  const auto welded = repaired(Soup{two_frames(cube.points), cube.triangles}, {.weld = true});
  CHECK(is_oriented_manifold(Soup_triangles(welded.triangles.begin(), welded.triangles.end()), 8));
  CHECK(is_oriented_manifold(Soup_triangles(cube.triangles.begin(), cube.triangles.end()), 24));
  Soup cones;
  add_cone(cones, cones.add(0, 0, 0), 0, 1, 1, 4);
  CHECK(is_oriented_manifold(Soup_triangles(cones.triangles.begin(), cones.triangles.end()), 5));
  add_cone(cones, 0, 0, -1, 1, 4);
  CHECK_FALSE(is_oriented_manifold(Soup_triangles(cones.triangles.begin(), cones.triangles.end()), 9));
  // Two open fans that touch at vertex 0, which a halfedge mesh would take: not a manifold.
  CHECK_FALSE(is_oriented_manifold(Soup_triangles{{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 6}}, 7));
  CHECK(is_oriented_manifold(Soup_triangles{{0, 1, 2}, {0, 2, 3}}, 4));
  CHECK_FALSE(is_oriented_manifold(Soup_triangles{{0, 1, 2}, {0, 3, 2}}, 4));
}

TEST_CASE("repair_triangles: the guard after CGAL finds triangles along an edge in the same direction",
          "[io][repair]") {
  const std::vector<Soup_triangle> triangles = {{0, 1, 2}, {0, 1, 3}, {1, 0, 4}, {4, 0, 1}};
  CHECK(misoriented_triangles(triangles) == std::vector<bool>{false, true, false, true});
  Oriented_soup soup;
  soup.triangles = triangles;
  soup.source_triangle = {0, 1, 2, 3};
  soup.reversed = {false, true, false, false};
  drop_triangles(soup, {false, true, false, true});
  CHECK(soup.triangles == std::vector<Soup_triangle>{{0, 1, 2}, {1, 0, 4}});
  CHECK(soup.source_triangle == std::vector<std::uint32_t>{0, 2});
  CHECK(soup.reversed == std::vector<bool>{false, false});
  CHECK(soup.unrepairable_triangles == 2);
}

TEST_CASE("repair_triangles: vertices of no triangle are kept and do not change the strain", "[io][repair][strain]") {
  // A square of two triangles stretched along x by 1.5 in frame 1, plus a vertex of no triangle
  // (flying off) and a degenerate triangle between the square's first two triangles.
  Soup soup;
  for (const auto& p : {std::array{0., 0., 0.}, {1., 0., 0.}, {1., 1., 0.}, {0., 1., 0.}, {5., 5., 5.}})
    soup.add(p[0], p[1], p[2]);
  const Triangles clean{{0, 1, 2}, {0, 2, 3}};
  soup.triangles = {{0, 1, 2}, {2, 2, 4}, {0, 2, 3}};
  std::vector<double> positions = soup.points;
  for (std::size_t i = 0; i < soup.points.size(); ++i) positions.push_back(soup.points[i] * (i % 3 == 0 ? 1.5 : 1.0));
  positions[15 + 12] = 40;  // vertex 4 flies off in frame 1

  Repair_report report;
  const auto animation = make_repaired_animation(std::span<const double>(positions), 5, std::span(soup.triangles), {},
                                                 &report);
  CHECK(report.degenerate_triangles == 1);
  CHECK(animation.num_vertices() == 5);
  CHECK(animation.num_faces() == 2);

  std::vector<double> square;
  for (std::size_t t = 0; t < 2; ++t)
    square.insert(square.end(), positions.begin() + 15 * t, positions.begin() + 15 * t + 12);
  const auto reference =
      make_repaired_animation(std::span<const double>(square), 4, std::span<const std::array<std::uint32_t, 3>>(clean));
  const auto strain = deformseg::strain::compute_strain(animation);
  const auto expected = deformseg::strain::compute_strain(reference);
  REQUIRE(strain.num_faces() == 2);
  for (std::size_t f = 0; f < 2; ++f)
    for (std::size_t t = 0; t < 2; ++t) CHECK(strain(f, t) == expected(f, t));
  CHECK(strain(0, 1) > 0.1);
}

namespace {

// Writes `frames` OBJ frames of the cube, welded or not, into a fresh folder.
fs::path obj_sequence(const std::string& name, const Soup& soup, int frames, const std::string& extra_faces = "") {
  const fs::path folder = deformseg::test::fresh_dir("io_mesh_repair/" + name);
  for (int t = 0; t < frames; ++t) {
    std::ofstream out(folder / ("frame_" + std::to_string(t) + ".obj"));
    for (std::size_t v = 0; v < soup.num_vertices(); ++v)
      out << "v " << soup.points[3 * v] * (1 + t) << " " << soup.points[3 * v + 1] << " " << soup.points[3 * v + 2] + t
          << "\n";
    for (const auto& tri : soup.triangles) out << "f " << tri[0] + 1 << " " << tri[1] + 1 << " " << tri[2] + 1 << "\n";
    out << extra_faces;
  }
  return folder;
}

}  // namespace

TEST_CASE("read_frame_sequence and read_animation repair, weld on request, and report",
          "[io][repair][frame_sequence]") {
  // The unwelded cube, plus triangle 12 that repeats vertex 4 (as the
  // RobotExpressive robot's triangle 16 does).
  const Soup cube = unwelded_cube();
  const fs::path folder = obj_sequence("cube", cube, 3, "f 1 5 5\n");
  using deformseg::io::read_animation;
  using deformseg::io::read_frame_sequence;

  Repair_report report;
  const auto animation = read_frame_sequence(folder.string(), {}, &report);
  CHECK(report.degenerate_triangles == 1);
  CHECK(report.welded_vertices == 0);
  CHECK(report.vertices == 24);
  CHECK(animation.num_vertices() == 24);
  CHECK(animation.num_faces() == 12);
  CHECK(animation.num_frames() == 3);
  CHECK(animation.frame_positions(2)[3 * 23 + 2] == cube.points[3 * 23 + 2] + 2);

  const auto welded = read_animation(folder.string(), {.repair = Repair_options{.weld = true}}, &report);
  CHECK(report.welded_vertices == 16);
  CHECK(report.degenerate_triangles == 1);
  CHECK(welded.num_vertices() == 8);
  CHECK(CGAL::is_closed(welded.face_graph()));
  // Output vertex 2 is input vertex 2, corner (1, 1, 0), at (2, 1, 1) in frame 1.
  CHECK(welded.frame_positions(1)[3 * 2] == 2);
  CHECK(welded.frame_positions(1)[3 * 2 + 2] == 1);

  const fs::path first = folder / "frame_0.obj";
  CHECK_THROWS_MATCHES(read_frame_sequence(folder.string(), {.repair = {.defects = Defect_policy::refuse}}),
                       invalid_input, Message(first.string() + ": frame 0: triangle 12 repeats vertex 4"));
  CHECK_THROWS_MATCHES(read_animation(folder.string(), {.repair = Repair_options{.defects = Defect_policy::refuse}}),
                       invalid_input, Message(first.string() + ": frame 0: triangle 12 repeats vertex 4"));

  SECTION("a point cache with a topology") {
    const fs::path cache = folder.parent_path() / "cube.pc2";
    deformseg::io::write_pc2(animation, cache);
    const auto read =
        read_animation(cache.string(), {.topology = first, .repair = Repair_options{.weld = true}}, &report);
    CHECK(report.welded_vertices == 16);
    CHECK(report.degenerate_triangles == 1);
    CHECK(read.num_vertices() == 8);
    CHECK(read.num_frames() == 3);
    CHECK_THROWS_MATCHES(
        read_animation(cache.string(), {.topology = first, .repair = Repair_options{.defects = Defect_policy::refuse}}),
        invalid_input, Message(first.string() + ": triangle 12 repeats vertex 4"));
  }
}

TEST_CASE("Outlier_check: a corrupt coordinate is found, root motion and large parts are not", "[io][repair]") {
  // A 10 x 10 grid of unit squares: its median radius is about 3.7 (the median distance of its
  // 121 vertices from its middle, (5, 5, 0)).
  std::vector<double> grid_frame;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) grid_frame.insert(grid_frame.end(), {double(i), double(j), 0.0});
  const deformseg::io::Outlier_check check{std::span<const double>(grid_frame)};
  CHECK(check.scale() > 3);
  CHECK(check.scale() < 4.5);
  const auto moved = [&](double dx, std::size_t vertex, double x) {
    std::vector<double> frame = grid_frame;
    for (std::size_t v = 0; v < frame.size() / 3; ++v) frame[3 * v] += dx;
    frame[3 * vertex] = x + dx;
    return frame;
  };
  // Root motion a million times the mesh's size, and a vertex 10^4 radii away (a long prop, a ground).
  CHECK(!check(std::span<const double>(moved(1e7, 0, 0)), 1));
  CHECK(!check(std::span<const double>(moved(0, 60, 3.7e4)), 2));
  // A vertex at 1e20, and one 10^6 radii away, whatever the frame's place.
  for (const double dx : {0.0, -1e7}) {
    const auto outlier = check(std::span<const double>(moved(dx, 60, 1e20)), 3);
    REQUIRE(outlier);
    CHECK(outlier->frame == 3);
    CHECK(outlier->vertex == 60);
    CHECK(outlier->distance > 0.99e20);
    CHECK_THAT(outlier->text(), Catch::Matchers::StartsWith("frame 3 vertex 60 lies 1e+20 from the frame's middle"));
    const auto far = check(std::span<const double>(moved(dx, 7, 5e6)), 4);
    REQUIRE(far);
    CHECK(far->vertex == 7);
  }
  // The farthest of several; a first frame with an outlier of its own still has the grid's scale.
  std::vector<double> two = moved(0, 3, 1e9);
  two[3 * 90] = -1e12;
  CHECK(check(std::span<const double>(two), 5)->vertex == 90);
  const deformseg::io::Outlier_check corrupt_first{std::span<const double>(two)};
  CHECK(corrupt_first.scale() < 4.5);
  CHECK(corrupt_first(std::span<const double>(two), 0)->vertex == 90);
  // Single-precision coordinates, as the readers of caches keep them.
  std::vector<float> single(grid_frame.begin(), grid_frame.end());
  single[3 * 5 + 2] = 1e30f;
  CHECK(deformseg::io::Outlier_check(std::span<const float>(single))(std::span<const float>(single), 0)->vertex == 5);
  // A mesh with no spread (all its vertices at one point) has no scale to judge by.
  const std::vector<double> point(30, 1.0);
  CHECK(!deformseg::io::Outlier_check(std::span<const double>(point))(std::span<const double>(moved(0, 2, 1e20)), 0));
}
