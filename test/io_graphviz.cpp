// The readers of graphs and labels first: no io header after them may lose deformseg::internal.
#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/graphviz.h>
#include <deformseg/io/read_animation.h>

#include <deformseg/ged/exact_ged.h>

#include "test_support.h"

#include <catch2/catch.hpp>

#include <sstream>

namespace {

using deformseg::io::Graph_format;
using deformseg::io::Labelled_graph;
using deformseg::io::read_labelled_graph;
using deformseg::test::write_file;

const std::string graphml_head =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<graphml xmlns=\"http://graphml.graphdrawing.org/xmlns\">\n"
    "  <key id=\"k\" for=\"node\" attr.name=\"label\" attr.type=\"string\"/>\n"
    "  <key id=\"w\" for=\"edge\" attr.name=\"weight\" attr.type=\"double\"/>\n";

Labelled_graph from_dot(const std::string& text) {
  std::istringstream in(text);
  return read_labelled_graph(in, Graph_format::dot, "test.dot");
}

std::vector<std::string> labels_of(const Labelled_graph& g) {
  std::vector<std::string> labels;
  for (std::size_t v = 0; v < boost::num_vertices(g); ++v) labels.push_back(g[v]);
  return labels;
}

}  // namespace

TEST_CASE("read_labelled_graph: DOT and GraphML files give the same graph", "[io][graph]") {
  STATIC_REQUIRE(deformseg::ged::LabelledGraph<Labelled_graph>);
  const auto dot = write_file("graphs/arm.dot",
                              "graph arm {\n  torso [label=\"torso\", color=red];\n  upper [label=limb];\n"
                              "  lower [label=limb]\n  torso -- upper -- lower [weight=2];\n}\n");
  const auto graphml = write_file(
      "graphs/arm.GraphML",
      graphml_head + "  <graph edgedefault=\"undirected\">\n"
                     "    <node id=\"torso\"><data key=\"k\">torso</data></node>\n"
                     "    <node id=\"upper\"><data key=\"k\">limb</data></node>\n"
                     "    <node id=\"lower\"><data key=\"k\">limb</data></node>\n"
                     "    <edge source=\"torso\" target=\"upper\"><data key=\"w\">1.5</data></edge>\n"
                     "    <edge source=\"lower\" target=\"upper\"/>\n  </graph>\n</graphml>\n");
  for (const auto& path : {dot, graphml}) {
    INFO(path);
    const Labelled_graph g = read_labelled_graph(path);
    CHECK(boost::num_edges(g) == 2);
    if (path == dot) {  // DOT nodes by name: lower, torso, upper
      CHECK(labels_of(g) == std::vector<std::string>{"limb", "torso", "limb"});
      CHECK(boost::edge(1, 2, g).second);
      CHECK(boost::edge(2, 0, g).second);
    } else {  // GraphML nodes in file order
      CHECK(labels_of(g) == std::vector<std::string>{"torso", "limb", "limb"});
      CHECK(boost::edge(0, 1, g).second);
      CHECK(boost::edge(1, 2, g).second);
    }
  }
  CHECK(deformseg::ged::Exact_ged{}(read_labelled_graph(dot), read_labelled_graph(graphml)).distance == 0);
}

TEST_CASE("read_labelled_graph: node order, empty labels, GraphML defaults, strict graphs", "[io][graph]") {
  const Labelled_graph g = from_dot("/* arms */ STRICT graph { b -- a; a -- b; a [label=x]; b [label=\"\"] }");
  CHECK(labels_of(g) == std::vector<std::string>{"x", ""});
  CHECK(boost::num_edges(g) == 1);
  CHECK(boost::num_vertices(from_dot("graph {}")) == 0);
  std::istringstream graphml(
      "<graphml><key id=\"k\" for=\"node\" attr.name=\"label\" attr.type=\"string\"><default>part</default></key>"
      "<graph edgedefault=\"undirected\"><node id=\"a\"/><node id=\"b\"><data key=\"k\">hand</data></node>"
      "<edge source=\"a\" target=\"b\"/></graph></graphml>");
  CHECK(labels_of(read_labelled_graph(graphml, Graph_format::graphml)) == std::vector<std::string>{"part", "hand"});
}

TEST_CASE("read_labelled_graph: errors name the file and the problem", "[io][graph]") {
  using Catch::Contains;
  CHECK_THROWS_WITH(read_labelled_graph("no-such-graph.dot"), Contains("no-such-graph.dot") && Contains("cannot open"));
  CHECK_THROWS_WITH(read_labelled_graph(write_file("graphs/g.txt", "graph {}")),
                    Contains("unknown graph format '.txt'"));
  CHECK_THROWS_WITH(from_dot("graph { a [label=x]; b; a -- b }"), Contains("test.dot: node 'b' has no 'label'"));
  CHECK_THROWS_WITH(from_dot("digraph { a [label=x]; b [label=y]; a -> b }"), Contains("test.dot: a directed graph"));
  CHECK_THROWS_WITH(from_dot("graph { a [label=x]; a -- }"), Contains("test.dot: cannot parse the graph"));
  CHECK_THROWS_WITH(from_dot("graph { a [label=x]; a -- a }"), Contains("self loop at node 'a'"));
  CHECK_THROWS_WITH(from_dot("graph { a [label=x]; b [label=x]; a -- b; b -- a }"),
                    Contains("two edges between node 'a' and node 'b'"));
  const auto unlabelled = write_file("graphs/unlabelled.graphml",
                                     graphml_head +
                                         "<graph edgedefault=\"undirected\"><node id=\"p\"><data key=\"k\">x</data>"
                                         "</node><node id=\"q\"/></graph></graphml>");
  CHECK_THROWS_WITH(read_labelled_graph(unlabelled),
                    Contains("unlabelled.graphml: node 1 (in file order, from 0) has no 'label'"));
  const auto directed = write_file("graphs/directed.graphml",
                                   graphml_head +
                                       "<graph edgedefault=\"directed\"><node id=\"p\"><data key=\"k\">x</data>"
                                       "</node><edge source=\"p\" target=\"q\"/></graph></graphml>");
  CHECK_THROWS_WITH(read_labelled_graph(directed), Contains("directed.graphml: a directed graph"));
  const auto broken = write_file("graphs/broken.graphml", graphml_head + "<graph edgedefault=\"undirected\">");
  CHECK_THROWS_WITH(read_labelled_graph(broken), Contains("broken.graphml: cannot parse"));
  std::istringstream numeric(
      "<graphml><key id=\"k\" for=\"node\" attr.name=\"label\" attr.type=\"int\"/>"
      "<graph edgedefault=\"undirected\"><node id=\"a\"><data key=\"k\">3</data></node></graph></graphml>");
  CHECK_THROWS_WITH(read_labelled_graph(numeric, Graph_format::graphml), Contains("attr.type=\"string\""));
}
