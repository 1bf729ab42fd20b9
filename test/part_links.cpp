// Tests of part_links.h and body_layout.h: the geometry against brute force, the links of random
// parts against every vertex-triangle and edge-triangle pair, rigid bodies found and refused, the
// layout in the segmentation, and the thesis' adjacency kept exactly with the links off.
#include "test_support.h"
#include "mesh_types.h"

#include <deformseg/io/read_animation.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/part_links.h>

#include <Eigen/Geometry>

#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace deformseg;

namespace part_links_test {

using Links = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
using Points = std::vector<std::array<double, 3>>;

// A closed tetrahedron at `origin`, scaled by `size`, appended to the points and triangles.
void add_tetrahedron(Points& points, test::Triangles& triangles, const Eigen::Vector3d& origin, double size) {
  const auto v = std::uint32_t(points.size());
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                   Eigen::Vector3d(0, 0, 1)}) {
    const Eigen::Vector3d q = origin + size * p;
    points.push_back({q.x(), q.y(), q.z()});
  }
  for (const auto& t : std::vector<std::array<std::uint32_t, 3>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}})
    triangles.push_back({v + t[0], v + t[1], v + t[2]});
}

// An animation of the points in frame 0 and each frame of `frames` (3 V coordinates each).
mesh::Surface_mesh_animation animation_of(const Points& points, const test::Triangles& triangles,
                                          const std::vector<std::vector<double>>& frames = {}) {
  std::vector<double> positions;
  for (const auto& p : points) positions.insert(positions.end(), p.begin(), p.end());
  for (const auto& frame : frames) positions.insert(positions.end(), frame.begin(), frame.end());
  return {mesh::make_face_graph<mesh::Surface_mesh>(points, triangles), std::move(positions)};
}

Eigen::Vector3d point(const Points& points, std::uint32_t v) { return {points[v][0], points[v][1], points[v][2]}; }

// Every link by brute force: each vertex's first triangle to the nearest triangle of each other
// part within `distance` (ties to the smaller index); each edge longer than 2 `distance`, from its
// smaller vertex to its larger, its first triangle to each triangle of another part it crosses.
Links brute_force_contacts(const Points& points, const test::Triangles& triangles, double distance) {
  const auto parts = spatiotemporal::internal::triangle_parts(triangles, points.size());
  std::set<std::pair<std::uint32_t, std::uint32_t>> links;
  const auto add = [&](std::uint32_t f, std::uint32_t g) { links.emplace(std::min(f, g), std::max(f, g)); };
  const auto corner = [&](std::uint32_t g, int k) { return point(points, triangles[g][std::size_t(k)]); };
  const auto first_with = [&](std::uint32_t a, std::uint32_t b) {
    std::uint32_t f = 0;
    while (std::ranges::count(triangles[f], a) == 0 || std::ranges::count(triangles[f], b) == 0) ++f;
    return f;
  };
  for (std::uint32_t v = 0; v < points.size(); ++v) {
    const std::uint32_t first = first_with(v, v);
    std::map<std::uint32_t, std::pair<double, std::uint32_t>> nearest;  // per part
    for (std::uint32_t g = 0; g < triangles.size(); ++g) {
      const double d = spatiotemporal::internal::squared_distance_to_triangle(point(points, v), corner(g, 0),
                                                                              corner(g, 1), corner(g, 2));
      if (parts[g] == parts[first] || d > distance * distance) continue;
      if (!nearest.count(parts[g]) || std::pair(d, g) < nearest[parts[g]]) nearest[parts[g]] = {d, g};
    }
    for (const auto& [part, found] : nearest) add(first, found.second);
  }
  for (std::uint32_t f = 0; f < triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = std::min(triangles[f][k], triangles[f][(k + 1) % 3]);
      const std::uint32_t b = std::max(triangles[f][k], triangles[f][(k + 1) % 3]);
      if ((point(points, a) - point(points, b)).norm() <= 2 * distance) continue;
      for (std::uint32_t g = 0; g < triangles.size(); ++g)
        if (parts[g] != parts[f] && spatiotemporal::internal::segment_crosses_triangle(
                                        point(points, a), point(points, b), corner(g, 0), corner(g, 1), corner(g, 2)))
          add(first_with(a, b), g);
    }
  return {links.begin(), links.end()};
}

double diagonal(const Points& points) {
  Eigen::Vector3d low = point(points, 0), high = low;
  for (std::uint32_t v = 0; v < points.size(); ++v) low = low.cwiseMin(point(points, v)), high = high.cwiseMax(point(points, v));
  return (high - low).norm();
}

// The positions of `points` with each vertex of `moved` (vertex index ranges) moved by `motion`.
std::vector<double> moved(const Points& points, std::uint32_t first, std::uint32_t last,
                          const Eigen::Isometry3d& motion) {
  std::vector<double> xyz;
  for (std::uint32_t v = 0; v < points.size(); ++v) {
    const Eigen::Vector3d p = v >= first && v < last ? Eigen::Vector3d(motion * point(points, v)) : point(points, v);
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  }
  return xyz;
}

}  // namespace part_links_test

using namespace part_links_test;

TEST_CASE("part geometry: the distance to a triangle and the crossing of a segment, against brute force",
          "[part_links]") {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  const auto any_point = [&] { return Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random)); };
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d a = any_point(), b = any_point(), c = any_point(), p = any_point();
    double nearest = std::numeric_limits<double>::infinity();
    constexpr int steps = 300;
    for (int i = 0; i <= steps; ++i)
      for (int j = 0; i + j <= steps; ++j) {
        const Eigen::Vector3d x = a + (b - a) * (double(i) / steps) + (c - a) * (double(j) / steps);
        nearest = std::min(nearest, (x - p).norm());
      }
    const double exact = std::sqrt(spatiotemporal::internal::squared_distance_to_triangle(p, a, b, c));
    REQUIRE(exact <= nearest + 1e-12);
    REQUIRE(exact >= nearest - 0.02);
    // A segment through a point inside the triangle crosses it; one stopping short of it does not.
    const Eigen::Vector3d inside = (a + b + c) / 3, normal = (b - a).cross(c - a).normalized();
    CHECK(spatiotemporal::internal::segment_crosses_triangle(inside - normal, inside + 0.1 * normal, a, b, c));
    CHECK_FALSE(spatiotemporal::internal::segment_crosses_triangle(inside + 0.01 * normal, inside + normal, a, b, c));
  }
}

TEST_CASE("part_links: the contacts of random parts equal every vertex-triangle and edge-triangle pair",
          "[part_links]") {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> place(0, 3), size(0.3, 1.2);
  std::size_t total = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Points points;
    test::Triangles triangles;
    for (int part = 0; part < 2 + trial % 6; ++part)
      add_tetrahedron(points, triangles, Eigen::Vector3d(place(random), place(random), place(random)), size(random));
    const double distance = 0.05 * double(trial % 4);
    const Links links =
        spatiotemporal::part_links(animation_of(points, triangles), {.contact_distance = distance, .rigid_tolerance = 0});
    const Links expected = brute_force_contacts(points, triangles, distance * diagonal(points));
    if (distance > 0) REQUIRE(links == expected);
    else REQUIRE(links.empty());
    total += links.size();
  }
  CHECK(total > 50);  // the parts touched, often (95 links in all)
}

TEST_CASE("part_links: parts that move as one rigid body are linked, others not", "[part_links]") {
  Points points;
  test::Triangles triangles;
  add_tetrahedron(points, triangles, {0, 0, 0}, 1);  // parts 0, 1 and 2, far apart
  add_tetrahedron(points, triangles, {5, 0, 0}, 1);
  add_tetrahedron(points, triangles, {0, 5, 0}, 1);
  const Eigen::Isometry3d turn(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const Eigen::Isometry3d shift(Eigen::Translation3d(0.5, 0, 0));
  const spatiotemporal::Part_link_options rigid{.contact_distance = 0, .rigid_tolerance = 0.002};
  // Parts 0 and 1 turn together, part 2 stays: 0 and 1 are one body (linked by first triangles).
  std::vector<double> frame = moved(points, 0, 8, turn);
  CHECK(spatiotemporal::part_links(animation_of(points, triangles, {frame}), rigid) == Links{{0, 4}});
  // All three move alike: each linked to the first.
  frame = moved(points, 0, 12, turn);
  CHECK(spatiotemporal::part_links(animation_of(points, triangles, {frame}), rigid) == Links{{0, 4}, {0, 8}});
  // Part 1 only shifted: 0 and 1 no longer move as one; 1 and 2 do not either.
  std::vector<double> other = moved(points, 0, 4, turn);
  const std::vector<double> shifted = moved(points, 4, 8, shift);
  std::copy(shifted.begin() + 12, shifted.begin() + 24, other.begin() + 12);
  CHECK(spatiotemporal::part_links(animation_of(points, triangles, {other}), rigid).empty());
  // Part 1 deforms (a vertex pulled away) while moving with part 0: not rigid, so not linked.
  frame = moved(points, 0, 8, turn);
  frame[3 * 5] += 0.1;
  CHECK(spatiotemporal::part_links(animation_of(points, triangles, {frame}), rigid).empty());
  // Standing still, every part moves as one with every other.
  CHECK(spatiotemporal::part_links(animation_of(points, triangles), rigid) == Links{{0, 4}, {0, 8}});
  CHECK_THROWS_AS(spatiotemporal::part_links(animation_of(points, triangles), {.contact_distance = -1}), invalid_input);
}

TEMPLATE_LIST_TEST_CASE("part_links and body_layout: every mesh type gives the default model's links and layout",
                        "[part_links][mesh_types]", test::Mesh_types) {
  // Part 2 touches part 0; parts 0 and 1 turn as one body while part 2 stays.
  Points points;
  test::Triangles triangles;
  add_tetrahedron(points, triangles, {0, 0, 0}, 1);
  add_tetrahedron(points, triangles, {5, 0, 0}, 1);
  add_tetrahedron(points, triangles, {0.34, 0.34, 0.34}, 1);
  const Eigen::Isometry3d turn(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const auto animation = animation_of(points, triangles, {moved(points, 0, 8, turn)});
  const TestType on(animation);

  const auto expected = spatiotemporal::part_links(animation);
  REQUIRE(expected.size() == 2);  // a contact and a rigid body: both kinds of link are compared
  CHECK(spatiotemporal::part_links(on.model()) == expected);
  const auto layout = spatiotemporal::body_layout(on.model());
  const auto reference = spatiotemporal::body_layout(animation);
  CHECK(layout.num_links() == reference.num_links());
  CHECK(std::ranges::equal(layout.area_shares(), reference.area_shares()));
  REQUIRE(layout.num_faces() == reference.num_faces());
  for (std::size_t f = 0; f < layout.num_faces(); ++f)
    CHECK(std::ranges::equal(layout.neighbours(f), reference.neighbours(f)));
}

TEST_CASE("body layout: touching parts make one rigid node and neighbouring segments", "[part_links]") {
  // Two tetrahedra whose faces touch (the second sits on the first's slanted face, 1e-3 away).
  Points points;
  test::Triangles triangles;
  add_tetrahedron(points, triangles, {0, 0, 0}, 1);
  add_tetrahedron(points, triangles, {0.34, 0.34, 0.34}, 1);
  const auto animation = animation_of(points, triangles, {moved(points, 0, 0, Eigen::Isometry3d::Identity())});
  const spatiotemporal::Spatiotemporal_options thesis{.parts = {0, 0}};
  const auto parts_apart = spatiotemporal::evolving_graph(animation, thesis);
  const auto parts_touching = spatiotemporal::evolving_graph(animation);
  REQUIRE(parts_apart.size() == 1);
  REQUIRE(parts_touching.size() == 1);
  CHECK(boost::num_vertices(parts_apart[0].graph) == 2);  // two rigid regions: no shared edge
  CHECK(boost::num_vertices(parts_touching[0].graph) == 1);
  CHECK(parts_touching[0].graph[0].area == Approx(1.0));

  // A deformed segment on each part: with the contact they are neighbours (or one segment).
  const auto layout = spatiotemporal::body_layout(animation);
  CHECK(layout.num_links() > 0);
  strain::Strain_field<float>::Storage values(2 * triangles.size(), 0.0f);
  values[3] = values[4] = 1.0f;  // face 3 of the first part, face 0 of the second, in both frames
  values[8 + 3] = values[8 + 4] = 1.0f;
  const strain::Strain_field<float> field(triangles.size(), 2, std::move(values), {}, std::nullopt, 0);
  const spatiotemporal::Spatiotemporal_options single{.min_triangles = 1, .min_frames = 1, .max_island = 0};
  const bool faces_linked = std::ranges::count(layout.neighbours(3), 4u) == 1;
  CHECK(faces_linked);
  CHECK(spatiotemporal::spatiotemporal_segmentation(field, layout, single).num_segments() == 1);
  CHECK(spatiotemporal::spatiotemporal_segmentation(field, triangles, single).num_segments() == 2);
}

TEST_CASE("spatio-temporal options: min_area removes exactly the segments whose largest slice is smaller",
          "[part_links]") {
  std::mt19937 random(23);
  for (int trial = 0; trial < 20; ++trial) {
    const test::Triangles triangles = test::grid(6);
    const std::size_t faces = triangles.size(), frames = 3;
    std::bernoulli_distribution coin(0.3);
    std::uniform_real_distribution<double> area(0.1, 2);
    strain::Strain_field<float>::Storage values(faces * frames);
    for (auto& v : values) v = coin(random) ? 1.0f : 0.0f;
    std::vector<double> areas(faces);
    for (auto& a : areas) a = area(random);
    const strain::Strain_field<float> field(faces, frames, std::move(values), {}, std::nullopt, 0);
    const spatiotemporal::Body_layout layout(triangles, areas);
    const spatiotemporal::Spatiotemporal_options all{.min_triangles = 1, .min_frames = 1, .max_island = 0};
    const auto before = spatiotemporal::spatiotemporal_segmentation(field, layout, all);
    std::vector<double> largest(before.num_segments(), 0);
    for (std::size_t t = 0; t < frames; ++t) {
      std::vector<double> slice(before.num_segments(), 0);
      for (std::size_t f = 0; f < faces; ++f)
        if (before.label(f, t) >= 0) slice[std::size_t(before.label(f, t))] += layout.area_shares()[f];
      for (std::size_t k = 0; k < slice.size(); ++k) largest[k] = std::max(largest[k], slice[k]);
    }
    const double min_area = 0.02;
    auto options = all;
    options.min_area = min_area;
    const auto after = spatiotemporal::spatiotemporal_segmentation(field, layout, options);
    std::vector<std::int32_t> kept(before.num_segments(), -1);
    std::int32_t next = 0;
    for (std::size_t k = 0; k < kept.size(); ++k)
      if (largest[k] >= min_area) kept[k] = next++;
    REQUIRE(after.num_segments() == std::size_t(next));
    for (std::size_t t = 0; t < frames; ++t)
      for (std::size_t f = 0; f < faces; ++f)
        REQUIRE(after.label(f, t) == (before.label(f, t) < 0 ? -1 : kept[std::size_t(before.label(f, t))]));
  }
}

TEST_CASE("spatio-temporal options: hysteresis keeps the weak cells joined to a strong one, by flood fill",
          "[part_links]") {
  std::mt19937 random(29);
  std::uniform_real_distribution<float> strain(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const test::Triangles triangles = test::grid(5);
    const std::size_t faces = triangles.size(), frames = 4;
    strain::Strain_field<float>::Storage values(faces * frames);
    for (auto& v : values) v = strain(random);
    const std::vector<float> copy(values.begin(), values.end());
    const strain::Strain_field<float> field(faces, frames, std::move(values), {}, std::nullopt, 0);
    const spatiotemporal::Body_layout layout(triangles);
    const double threshold = 0.9, hysteresis = 0.3, low = threshold * (1 - hysteresis);
    const auto s = spatiotemporal::spatiotemporal_segmentation(
        field, layout,
        {.threshold = threshold, .min_triangles = 1, .min_frames = 1, .max_island = 0, .hysteresis = hysteresis});
    std::vector<std::uint8_t> reached(faces * frames, 0);  // flood from the strong cells over weak ones
    std::vector<std::size_t> queue;
    for (std::size_t c = 0; c < copy.size(); ++c)
      if (copy[c] > threshold) reached[c] = 1, queue.push_back(c);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::size_t t = queue[q] / faces, f = queue[q] % faces;
      std::vector<std::size_t> next;
      for (std::uint32_t g : layout.neighbours(f)) next.push_back(t * faces + g);
      if (t > 0) next.push_back(queue[q] - faces);
      if (t + 1 < frames) next.push_back(queue[q] + faces);
      for (std::size_t c : next)
        if (!reached[c] && copy[c] > low) reached[c] = 1, queue.push_back(c);
    }
    std::size_t deformed = 0;
    for (std::size_t c = 0; c < copy.size(); ++c) {
      REQUIRE((s.label(c % faces, c / faces) >= 0) == bool(reached[c]));
      deformed += reached[c];
    }
    if (trial == 0) CHECK(deformed > 0);
  }
  const strain::Strain_field<float> field(2, 1, strain::Strain_field<float>::Storage(2, 0.0f), {}, std::nullopt, 0);
  const test::Triangles two = {{0, 1, 2}, {2, 1, 3}};
  CHECK_THROWS_AS(spatiotemporal::spatiotemporal_segmentation(field, two, {.hysteresis = 1}), invalid_input);
  CHECK_THROWS_AS(spatiotemporal::spatiotemporal_segmentation(field, two, {.min_area = 2}), invalid_input);
}

TEST_CASE("body layout: with the links off, a character's evolving graph is the thesis' one exactly",
          "[part_links][data]") {
  // The Knight's walk as the thesis' adjacency and segments of 2 frames gave it before the links
  // and the longer default (the tool of issue 29):
  // 27 key frames, 19 segments, 1187 nodes and 136 edges over the key frames.
  const auto animation = io::read_animation((test::data_dir() / "characters" / "Knight.glb").string() + "#Walking_A");
  const auto graph = spatiotemporal::evolving_graph(animation, {.min_frames = 2, .parts = {0, 0}});
  std::size_t nodes = 0, edges = 0;
  for (const auto& k : graph) nodes += boost::num_vertices(k.graph), edges += boost::num_edges(k.graph);
  CHECK(graph.size() == 27);
  CHECK(graph.num_segments() == 19);
  CHECK(nodes == 1187);
  CHECK(edges == 136);
}
