// Tests of frame_segments.h and evolving_graph.h: each frame's graph against a brute force on
// random label volumes, the key frames of bending tubes written out by hand, invariance, real data.
#include "test_support.h"
#include "mesh_types.h"

#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/graphviz.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/segment_graph_dot.h>

#include <boost/graph/adjacency_list.hpp>
#include <Eigen/Geometry>

#include <random>
#include <set>
#include <sstream>
#include <vector>

using namespace deformseg;

namespace {

using test::grid;
using test::Triangles;

bool share_edge(const Triangles& triangles, std::size_t f, std::size_t g) {
  int shared = 0;
  for (auto v : triangles[f]) shared += std::count(triangles[g].begin(), triangles[g].end(), v) ? 1 : 0;
  return f != g && shared == 2;
}

// A graph as text: its nodes in order (R, or D and the segment id), then its edges.
std::string shape(const spatiotemporal::Segment_graph& g) {
  std::ostringstream text;
  for (std::size_t v = 0; v < boost::num_vertices(g); ++v)
    text << (v ? " " : "") << spatiotemporal::node_label(g[v]);
  std::set<std::pair<std::size_t, std::size_t>> edges;
  for (auto e : boost::make_iterator_range(boost::edges(g)))
    edges.emplace(std::min(boost::source(e, g), boost::target(e, g)),
                  std::max(boost::source(e, g), boost::target(e, g)));
  text << " |";
  for (auto [u, v] : edges) text << ' ' << u << '-' << v;
  return text.str();
}

// The key frames as "first-last: shape".
std::vector<std::string> key_frames(const spatiotemporal::Evolving_graph& graph) {
  std::vector<std::string> out;
  for (const spatiotemporal::Key_frame& k : graph)
    out.push_back(std::to_string(k.first_frame) + "-" + std::to_string(k.last_frame) + ": " + shape(k.graph));
  return out;
}

using deformseg::test::right_angle;
constexpr auto linear = mesh::Easing::linear;
// A low threshold: linear blend skinning strains the bend's neutral axis about ten times less
// than its outside, and the deformed band closes into a ring only when those cells count too.
const spatiotemporal::Spatiotemporal_options tube_options{.threshold = 0.01};

mesh::Bending_tube two_joints() {
  mesh::Bending_tube spec;
  spec.joints = {{.position = 0.3}, {.position = 0.7}};
  return spec;
}

}  // namespace

TEST_CASE("frame segments: each frame's graph equals a brute force on random label volumes", "[evolving_graph]") {
  std::mt19937 random(11);
  for (int trial = 0; trial < 30; ++trial) {
    const Triangles triangles = grid(3 + std::uint32_t(trial % 4));
    const std::size_t faces = triangles.size(), frames = 1 + std::size_t(trial % 4);
    std::bernoulli_distribution coin(0.25 + 0.1 * double(trial % 4));
      std::vector<std::uint8_t> deformed(faces * frames);
    for (auto& d : deformed) d = coin(random);
    strain::Strain_field<float>::Storage values(deformed.size());
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = deformed[i] ? 1.0f : 0.0f;
    const strain::Strain_field<float> field(faces, frames, std::move(values), {}, std::nullopt, 0);
    const auto s = spatiotemporal::spatiotemporal_segmentation(field, triangles,
                                                               {.min_triangles = 1, .min_frames = 1, .max_island = 0});
    std::vector<double> areas(faces);
    for (std::size_t f = 0; f < faces; ++f) areas[f] = 1.0 + double(f % 3);
    const spatiotemporal::Frame_segments segments(s, triangles, areas);
    for (std::size_t t = 0; t < frames; ++t) {
      const spatiotemporal::Segment_graph g = segments.graph(t);
      const std::vector<std::uint32_t> node = segments.face_nodes(t);
      // Same node if and only if the same deformed segment, or both rigid and joined by a path
      // of rigid triangles (found here by repeated relaxation, the slow way).
      std::vector<std::size_t> region(faces);
      std::iota(region.begin(), region.end(), std::size_t{0});
      for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t f = 0; f < faces; ++f)
          for (std::size_t h = 0; h < faces; ++h)
            if (s.label(f, t) == -1 && s.label(h, t) == -1 && share_edge(triangles, f, h) && region[h] < region[f])
              region[f] = region[h], changed = true;
      }
      double total_area = 0, node_area_sum = 0;
      std::size_t node_triangles = 0;
      for (std::size_t v = 0; v < boost::num_vertices(g); ++v)
        node_area_sum += g[v].area, node_triangles += g[v].triangles;
      for (double a : areas) total_area += a;
      CHECK(node_triangles == faces);
      CHECK(node_area_sum == Approx(1.0));
      std::vector<double> area_of(boost::num_vertices(g), 0.0);
      for (std::size_t f = 0; f < faces; ++f) {
        area_of[node[f]] += areas[f] / total_area;
        const spatiotemporal::Segment_node& n = g[node[f]];
        CHECK(n.segment == s.label(f, t));
        CHECK((n.kind == spatiotemporal::Segment_kind::rigid) == (s.label(f, t) == -1));
        for (std::size_t h = 0; h < faces; ++h) {
          const bool same = s.label(f, t) == -1 ? s.label(h, t) == -1 && region[f] == region[h]
                                                : s.label(h, t) == s.label(f, t);
          CHECK((node[f] == node[h]) == same);
          if (share_edge(triangles, f, h) && node[f] != node[h]) CHECK(boost::edge(node[f], node[h], g).second);
        }
      }
      for (std::size_t v = 0; v < boost::num_vertices(g); ++v) CHECK(g[v].area == Approx(area_of[v]));
      // Every edge joins two nodes with triangles that share a mesh edge.
      for (auto e : boost::make_iterator_range(boost::edges(g))) {
        bool touching = false;
        for (std::size_t f = 0; f < faces && !touching; ++f)
          for (std::size_t h = 0; h < faces && !touching; ++h)
            touching = node[f] == boost::source(e, g) && node[h] == boost::target(e, g) && share_edge(triangles, f, h);
        CHECK(touching);
      }
      // Canonical order: deformed nodes by segment id, then rigid ones.
      for (std::size_t v = 1; v < boost::num_vertices(g); ++v) {
        const bool both_deformed = g[v - 1].kind == spatiotemporal::Segment_kind::deformed &&
                                   g[v].kind == spatiotemporal::Segment_kind::deformed;
        CHECK(!(g[v - 1].kind == spatiotemporal::Segment_kind::rigid &&
                g[v].kind == spatiotemporal::Segment_kind::deformed));
        if (both_deformed) CHECK(g[v - 1].segment < g[v].segment);
      }
    }
  }
}

TEST_CASE("frame segments: a band across a grid cuts its rigid part in two", "[evolving_graph]") {
  // A 4 x 4 grid; the squares of row 1 deformed (segment 0), so rows 0 and 2-3 are two rigid
  // regions touching it. Rigid nodes come after it, by first triangle.
  const Triangles triangles = grid(4);
  std::vector<std::int32_t> labels(32, -1);
  for (std::size_t f = 8; f < 16; ++f) labels[f] = 0;
  const spatiotemporal::Spatiotemporal_segmentation s(32, 1, labels);
  const spatiotemporal::Frame_segments segments(s, triangles);
  const spatiotemporal::Segment_graph g = segments.graph(0);
  CHECK(shape(g) == "D0 R R | 0-1 0-2");
  CHECK(g[0].triangles == 8);
  CHECK(g[1].triangles == 8);   // row 0
  CHECK(g[2].triangles == 16);  // rows 2 and 3
  CHECK(g[2].area == Approx(0.5));
  const auto node = segments.face_nodes(0);
  CHECK(node[0] == 1);
  CHECK(node[31] == 2);
  CHECK(node[9] == 0);
  CHECK_THROWS_WITH(segments.graph(1), Catch::Contains("frame 1"));
  CHECK_THROWS_WITH(spatiotemporal::Frame_segments(s, grid(3)), Catch::Contains("18 triangles"));
  CHECK_THROWS_WITH(spatiotemporal::Frame_segments(s, triangles, std::vector<double>(32, 0.0)),
                    Catch::Contains("sum to 0"));
  CHECK_THROWS_WITH(spatiotemporal::Frame_segments(s, triangles, std::vector<double>(3, 1.0)),
                    Catch::Contains("3 face areas"));
}

TEST_CASE("evolving graph: a tube bending once gives R, then R - D - R, then R", "[evolving_graph]") {
  mesh::Bending_tube spec;
  spec.schedule = {{10, {0.0}}, {10, {right_angle}, linear}, {10, {}}};
  const auto tube = mesh::make_bending_tube(spec);
  const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(tube.animation, tube_options);
  // Previous-pose strain: deformed exactly while the joint moves (frames 11-20).
  CHECK(key_frames(graph) == std::vector<std::string>{"0-10: R |", "11-20: D0 R R | 0-1 0-2", "21-30: R |"});
  CHECK(graph.num_frames() == 31);
  CHECK(graph.num_segments() == 1);
  CHECK(graph.key_frame_of(0) == 0);
  CHECK(graph.key_frame_of(11) == 1);
  CHECK(graph.key_frame_of(30) == 2);
  CHECK_THROWS_WITH(graph.key_frame_of(31), Catch::Contains("frame 31"));
  // The band lies in the blend zone, 15 % of the length, 13.6 % of the area with the caps (17.4 %
  // with the rings on its edges); the two rigid ends hold the rest, alike.
  const spatiotemporal::Segment_graph& bent = graph[1].graph;
  CHECK(bent[0].area > 0.136 / 2);
  CHECK(bent[0].area < 0.174);
  CHECK(bent[0].area + bent[1].area + bent[2].area == Approx(1.0));
  CHECK(bent[1].area == Approx(bent[2].area).epsilon(0.05));
  CHECK(graph[0].graph[0].triangles == tube.animation.num_faces());
  // Rest-pose strain measures the pose: the tube stays deformed while it is bent, hold included.
  const spatiotemporal::Evolving_graph rest = spatiotemporal::evolving_graph(
      tube.animation, {.reference = strain::Strain_reference::rest_pose, .threshold = 0.01});
  REQUIRE(rest.size() >= 2);
  CHECK(shape(rest[0].graph) == "R |");
  CHECK(shape(rest[rest.size() - 1].graph) == "D0 R R | 0-1 0-2");
  CHECK(rest[rest.size() - 1].last_frame == 30);
}

TEMPLATE_LIST_TEST_CASE("evolving graph: every mesh type gives the default model's graph, to the last bit",
                        "[evolving_graph][mesh_types]", test::Mesh_types) {
  mesh::Bending_tube spec = two_joints();
  spec.shape = {.sectors = 8, .rings = 30};
  spec.schedule = {{3, {0.0, 0.0}}, {6, {right_angle, 0.0}, linear}, {3, {}}, {6, {right_angle, right_angle}, linear}};
  const auto tube = mesh::make_bending_tube(spec);
  const TestType on(tube.animation);
  for (const auto& options : {tube_options, spatiotemporal::Spatiotemporal_options{.threshold = 0.01, .parts = {0, 0}}}) {
    const spatiotemporal::Evolving_graph expected = spatiotemporal::evolving_graph(tube.animation, options);
    const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(on.model(), options);
    REQUIRE(expected.size() > 1);
    CHECK(key_frames(graph) == key_frames(expected));
    CHECK(graph.num_segments() == expected.num_segments());
    REQUIRE(graph.size() == expected.size());
    for (std::size_t k = 0; k < graph.size(); ++k)
      for (std::size_t v = 0; v < boost::num_vertices(graph[k].graph); ++v)
        CHECK(graph[k].graph[v] == expected[k].graph[v]);  // kind, segment, triangles, area (==)
  }
}

TEST_CASE("evolving graph: two joints bending one after the other, and overlapping", "[evolving_graph]") {
  mesh::Bending_tube spec = two_joints();
  spec.schedule = {{5, {0.0, 0.0}}, {10, {right_angle, 0.0}, linear}, {5, {}},
                   {10, {right_angle, right_angle}, linear}, {5, {}}};
  CHECK(key_frames(spatiotemporal::evolving_graph(mesh::make_bending_tube(spec).animation, tube_options)) ==
        std::vector<std::string>{"0-5: R |", "6-15: D0 R R | 0-1 0-2", "16-20: R |", "21-30: D1 R R | 0-1 0-2",
                                 "31-35: R |"});
  // The upper joint starts while the lower one is half way: for six frames both bend, and the
  // middle of the tube is a rigid region between the two bands (it touches segments 0 and 1).
  spec.schedule = {{5, {0.0, 0.0}}, {6, {right_angle / 2, 0.0}, linear}, {6, {right_angle, right_angle / 2}, linear},
                   {6, {right_angle, right_angle}, linear}, {5, {}}};
  CHECK(key_frames(spatiotemporal::evolving_graph(mesh::make_bending_tube(spec).animation, tube_options)) ==
        std::vector<std::string>{"0-5: R |", "6-11: D0 R R | 0-1 0-2", "12-17: D0 D1 R R R | 0-2 0-3 1-3 1-4",
                                 "18-23: D1 R R | 0-1 0-2", "24-28: R |"});
}

TEST_CASE("evolving graph: a moved, turned and scaled tube gives the same evolving graph", "[evolving_graph]") {
  mesh::Bending_tube spec = two_joints();
  spec.schedule = {{4, {0.0, 0.0}}, {8, {right_angle, 0.0}}, {8, {right_angle, -right_angle}, linear},
                   {4, {0.0, 0.0}}};
  const spatiotemporal::Evolving_graph a =
      spatiotemporal::evolving_graph(mesh::make_bending_tube(spec).animation, tube_options);
  spec.placement = {.scale = 0.02,
                    .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, -2, 3).normalized())),
                    .translation = Eigen::Vector3d(-7, 300, 12)};
  const spatiotemporal::Evolving_graph b =
      spatiotemporal::evolving_graph(mesh::make_bending_tube(spec).animation, tube_options);
  REQUIRE(key_frames(a) == key_frames(b));
  CHECK(a.size() > 3);
  for (std::size_t k = 0; k < a.size(); ++k)
    for (std::size_t v = 0; v < boost::num_vertices(a[k].graph); ++v) {
      CHECK(a[k].graph[v].triangles == b[k].graph[v].triangles);
      CHECK(a[k].graph[v].area == Approx(b[k].graph[v].area).margin(1e-9));
    }
}

TEST_CASE("evolving graph: key frames must cover the frames in order", "[evolving_graph]") {
  std::vector<spatiotemporal::Key_frame> gap;
  gap.push_back({0, 3, spatiotemporal::Segment_graph(1)});
  gap.push_back({5, 6, spatiotemporal::Segment_graph(1)});
  CHECK_THROWS_WITH(spatiotemporal::Evolving_graph(7, 0, gap),
                    Catch::Contains("frames 5-6") && Catch::Contains("frame 4"));
  CHECK_THROWS_WITH(spatiotemporal::Evolving_graph(
                        9, 0, {{0, 8, spatiotemporal::Segment_graph(1)}, {9, 9, spatiotemporal::Segment_graph(1)}}),
                    Catch::Contains("cover 10 of 9"));
  CHECK(spatiotemporal::Evolving_graph(0, 0, {}).empty());
}

TEST_CASE("evolving graph: the horse gallop and the samba, deterministic", "[evolving_graph][data]") {
  for (const char* name : {"horse-gallop", "samba"}) {
    const auto folder = test::unpacked(std::string(name) + "/" + name + ".tar.xz") / name;
    const auto animation = io::read_frame_sequence(folder.string());
    const spatiotemporal::Evolving_graph a = spatiotemporal::evolving_graph(animation);
    const spatiotemporal::Evolving_graph b = spatiotemporal::evolving_graph(animation);
    std::size_t largest = 0, nodes = 0;
    for (const spatiotemporal::Key_frame& k : a) {
      largest = std::max(largest, boost::num_vertices(k.graph));
      nodes += boost::num_vertices(k.graph);
    }
    INFO(name << ": " << a.size() << " key frames of " << a.num_frames() << " frames, " << a.num_segments()
              << " segments, " << double(nodes) / double(a.size()) << " nodes per key frame, at most " << largest);
    CHECK(key_frames(a) == key_frames(b));
    CHECK(a.num_frames() == animation.num_frames());
    CHECK(a.size() > 5);
    CHECK(a.size() < a.num_frames());
    CHECK(largest < 100);
    WARN(name << ": " << a.size() << " key frames of " << a.num_frames() << " frames, " << a.num_segments()
              << " segments, " << double(nodes) / double(a.size()) << " nodes per key frame, at most " << largest);
  }
}

TEST_CASE("evolving graph: Graphviz draws every key frame of the horse", "[evolving_graph][data]") {
  // Areas as small as 5.8e-05 are written in exponent form, which DOT's numerals do not allow
  // unquoted: every attribute is quoted, and `dot` accepts every file.
  REQUIRE(std::system("dot -V > /dev/null 2>&1") == 0);  // Graphviz, which scripts/install-deps installs
  const auto folder = test::unpacked("horse-gallop/horse-gallop.tar.xz") / "horse-gallop";
  const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(io::read_frame_sequence(folder.string()));
  const auto dir = test::fresh_dir("horse_key_frames_dot");
  const auto files = spatiotemporal::write_key_frames_dot(graph, dir);
  REQUIRE(files.size() == graph.size());
  std::size_t with_exponent = 0;
  for (const auto& file : files) {
    const std::string text = test::file_text(file);
    with_exponent += text.find("e-0") != std::string::npos;
    INFO(file.string());
    CHECK(std::system(("dot -Tsvg -o /dev/null '" + file.string() + "' 2>&1").c_str()) == 0);
  }
  CHECK(with_exponent > 0);  // the case that failed is among them
}

TEST_CASE("evolving graph: a rigid node has no segment attribute in DOT, as it has null in JSON",
          "[evolving_graph]") {
  spatiotemporal::Segment_graph graph;
  boost::add_vertex(
      spatiotemporal::Segment_node{.kind = spatiotemporal::Segment_kind::rigid, .triangles = 30, .area = 0.75}, graph);
  boost::add_vertex(
      spatiotemporal::Segment_node{
          .kind = spatiotemporal::Segment_kind::deformed, .segment = 4, .triangles = 10, .area = 0.25},
      graph);
  boost::add_edge(0, 1, graph);
  std::ostringstream text;
  spatiotemporal::write_segment_graph_dot(text, graph);
  const std::string dot = text.str();
  INFO(dot);
  CHECK(dot.find("0[label=\"R\", kind=\"rigid\", triangles=\"30\", area=\"0.75\"") != std::string::npos);
  CHECK(dot.find("1[label=\"D4\", kind=\"deformed\", segment=\"4\", triangles=\"10\", area=\"0.25\"") !=
        std::string::npos);
  CHECK(dot.find("segment=\"-1\"") == std::string::npos);
  CHECK(dot.find("xlabel=\"75%\"") != std::string::npos);  // the area share beside each node
  CHECK(dot.find("xlabel=\"25%\"") != std::string::npos);
  CHECK(dot.find("graph [overlap=false") != std::string::npos);  // a layout that keeps nodes apart
  std::istringstream in(dot);
  const io::Labelled_graph read = io::read_labelled_graph(in, io::Graph_format::dot, "graph.dot");
  CHECK(boost::num_vertices(read) == 2);
  CHECK(read[1] == "D4");
}
