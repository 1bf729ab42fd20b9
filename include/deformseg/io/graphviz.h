/// @file io/graphviz.h
/// @brief Reading a user's labelled graph from a Graphviz DOT or GraphML file:
/// `io::read_labelled_graph`, into `io::Labelled_graph`.
///
/// Programs that include this header link `libboost_graph` (the deformseg target does).
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graphml.hpp>
#include <boost/graph/graphviz.hpp>
#include <boost/property_map/dynamic_property_map.hpp>
#include <boost/property_map/property_map.hpp>
#include <cctype>
#include <cstddef>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io {

/// @brief A simple undirected graph whose vertices carry a string label (the node kind): a
/// `deformseg::ged::LabelledGraph`, what read_labelled_graph returns.
using Labelled_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, std::string>;

/// @brief The formats read_labelled_graph reads.
enum class Graph_format {
  dot,     ///< Graphviz DOT (`.dot`, `.gv`)
  graphml  ///< GraphML (`.graphml`)
};

}  // namespace deformseg::io

// Not deformseg::io::internal: a namespace of that name would hide deformseg::internal from every
// io header included after this one.
namespace deformseg::io::internal {

using io::Graph_format;
using io::Labelled_graph;

struct Read_vertex {
  std::string id;  // the DOT node name; GraphML ids are not reported by Boost
  std::string label;
  bool labelled = false;
};
using Read_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, Read_vertex>;

// A writable property map for the "label" attribute that also records which vertices had one.
class Label_recorder {
public:
  using key_type = std::size_t;
  using value_type = std::string;
  using reference = std::string;
  using category = boost::read_write_property_map_tag;
  explicit Label_recorder(Read_graph& g) : g_(&g) {}
  friend std::string get(const Label_recorder& map, std::size_t v) { return (*map.g_)[v].label; }
  friend void put(const Label_recorder& map, std::size_t v, const std::string& label) {
    (*map.g_)[v].label = label;
    (*map.g_)[v].labelled = true;
  }

private:
  Read_graph* g_;
};

inline std::string node_name(const Read_graph& g, std::size_t v) {
  if (!g[v].id.empty()) return "node '" + g[v].id + "'";
  return "node " + std::to_string(v) + " (in file order, from 0)";
}

// Whether a DOT text declares a strict graph (its first word, any case, after comments).
inline bool is_strict(const std::string& text) {
  std::size_t at = 0;
  while (at < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[at]))) {
      ++at;
    } else if (text.compare(at, 2, "//") == 0 || text[at] == '#') {
      at = text.find('\n', at);
    } else if (text.compare(at, 2, "/*") == 0) {
      at = text.find("*/", at);
      if (at != std::string::npos) at += 2;
    } else {
      break;
    }
  }
  if (at >= text.size()) return false;
  std::string word = text.substr(at, 6);
  std::transform(word.begin(), word.end(), word.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return word == "strict" && (at + 6 >= text.size() || !std::isalnum(static_cast<unsigned char>(text[at + 6])));
}

// Reads the graph; returns whether a DOT graph is strict (an edge given twice is one edge).
inline bool parse(std::istream& in, Graph_format format, Read_graph& g) {
  boost::dynamic_properties properties(boost::ignore_other_properties);
  properties.property("label", Label_recorder(g));
  bool strict = false;
  try {
    if (format == Graph_format::dot) {
      const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      strict = is_strict(text);
      properties.property("node_id", boost::get(&Read_vertex::id, g));
      if (!boost::read_graphviz(text, g, properties)) throw invalid_input("not a Graphviz DOT graph");
    } else {
      boost::read_graphml(in, g, properties);
    }
  } catch (const boost::directed_graph_error&) {
    throw invalid_input("a directed graph; GED compares undirected graphs (write 'graph', not 'digraph', "
                        "or edgedefault=\"undirected\")");
  } catch (const boost::bad_any_cast&) {
    throw invalid_input("the GraphML key 'label' must have attr.type=\"string\"");
  } catch (const invalid_input&) {
    throw;
  } catch (const std::exception& e) {
    throw invalid_input(std::string("cannot parse the graph: ") + e.what());
  }
  return strict;
}

// Every node labelled, no self loop, no parallel edge (merged in a strict graph); then the graph
// without the bookkeeping.
inline Labelled_graph checked(const Read_graph& g, bool strict) {
  const std::size_t n = boost::num_vertices(g);
  Labelled_graph result(n);
  for (std::size_t v = 0; v < n; ++v) {
    if (!g[v].labelled) throw invalid_input(node_name(g, v) + " has no 'label' attribute");
    result[v] = g[v].label;
  }
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (auto [e, end] = boost::edges(g); e != end; ++e) {
    const std::size_t u = boost::source(*e, g), v = boost::target(*e, g);
    if (u == v) throw invalid_input("self loop at " + node_name(g, u) + "; GED compares simple graphs");
    edges.emplace_back(std::min(u, v), std::max(u, v));
  }
  std::sort(edges.begin(), edges.end());
  if (strict) edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const auto twice = std::adjacent_find(edges.begin(), edges.end());
  if (twice != edges.end())
    throw invalid_input("two edges between " + node_name(g, twice->first) + " and " + node_name(g, twice->second) +
                        "; GED compares simple graphs");
  for (auto [u, v] : edges) boost::add_edge(u, v, result);
  return result;
}

inline Graph_format format_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".dot" || extension == ".gv") return Graph_format::dot;
  if (extension == ".graphml") return Graph_format::graphml;
  throw invalid_input("unknown graph format '" + extension + "': expected .dot, .gv or .graphml",
                      {.file = path.string()});
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Reads a labelled graph from a stream in the given format.
///
/// Each node must carry a `label` attribute, a string (in DOT `a [label="arm"]`; in GraphML a
/// `<key attr.name="label" attr.type="string" for="node">`, whose `<default>` counts as a label).
/// Other attributes are ignored. Node numbers: in GraphML node i is the i-th `<node>` element; in
/// DOT, Boost's reader numbers the nodes in the (byte) order of their names, so node i has the
/// i-th name in sorted order.
/// @pre an undirected simple graph: no `digraph` / `edgedefault="directed"`, no self loop, no two
/// edges between the same nodes, except in a DOT `strict graph`, where an edge given twice
/// (either way round) is one edge.
/// @param in the stream.
/// @param format DOT or GraphML.
/// @param name how errors name the input (a file name), may be empty.
/// @throws invalid_input naming `name` and the problem: a parse error, a directed graph, a node
/// without label (by DOT name, or by index for GraphML), a self loop, a parallel edge.
/// @par Complexity O(V + E log E).
inline Labelled_graph read_labelled_graph(std::istream& in, Graph_format format, const std::string& name = "") {
  try {
    internal::Read_graph g;
    const bool strict = internal::parse(in, format, g);
    return internal::checked(g, strict);
  } catch (const invalid_input& e) {
    throw e.located({.file = name});
  }
}

/// @brief Reads a labelled graph from a Graphviz DOT (`.dot`, `.gv`) or GraphML (`.graphml`)
/// file, the format chosen by the extension (any case).
///
/// As read_labelled_graph(std::istream&, Graph_format, const std::string&) for the content.
/// @throws invalid_input naming the file: missing or unreadable, unknown extension, or any
/// problem of the content.
/// @par Complexity O(V + E log E).
inline Labelled_graph read_labelled_graph(const std::filesystem::path& path) {
  const Graph_format format = internal::format_of(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_input("cannot open the graph file", {.file = path.string()});
  return read_labelled_graph(in, format, path.string());
}

}  // namespace deformseg::io
