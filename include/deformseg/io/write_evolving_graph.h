/// @file write_evolving_graph.h
/// @brief Writes segment graphs and the key frames of an evolving graph as Graphviz DOT files
/// (`boost::write_graphviz`): `write_segment_graph_dot`, `write_key_frames_dot`.
#pragma once

#include <deformseg/evolving_graph.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/segment_colors.h>

#include <boost/graph/graphviz.hpp>

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace deformseg::internal {

// A node's DOT attributes: its label (R, or D and the segment id), what it is, and its colour. A
// rigid node has no segment attribute, as it has `null` in the tool's JSON. Every value is
// quoted: the shortest text of an area may have an exponent (5.79e-05), which DOT's numerals do
// not allow.
inline std::string dot_node_attributes(const Segment_node& n) {
  const bool rigid = n.kind == Segment_kind::rigid;
  const Rgb c = segment_color(n.segment);
  char color[8];
  std::snprintf(color, sizeof color, "#%02x%02x%02x", unsigned(c.r), unsigned(c.g), unsigned(c.b));
  const std::string segment = rigid ? "" : "segment=\"" + std::to_string(n.segment) + "\", ";
  return "[label=\"" + node_label(n) + "\", kind=\"" + (rigid ? "rigid" : "deformed") + "\", " + segment +
         "triangles=\"" + std::to_string(n.triangles) + "\", area=\"" +
         shortest_text(n.area) + "\", style=filled, fillcolor=\"" + color + "\"]";
}

}  // namespace deformseg::internal

namespace deformseg::io {

/// @brief Writes a segment graph in Graphviz DOT: an undirected `graph`, node ids 0..n-1 in the
/// graph's order, each with `label` ("R", or "D" and the segment id, the node kind as the
/// `deformseg ged` command reads it), `kind` ("rigid" or "deformed"), `segment` (the
/// spatio-temporal segment's id; none on a rigid node), `triangles`, `area` (the node's share of
/// the surface area), and a fill colour (`segment_color`).
/// @param out the stream.
/// @param graph the graph.
/// @par Complexity O(n + e).
inline void write_segment_graph_dot(std::ostream& out, const Segment_graph& graph) {
  boost::write_graphviz(out, graph, [&graph](std::ostream& o, std::size_t v) {
    o << internal::dot_node_attributes(graph[v]);
  });
}

/// @brief Writes each key frame's graph as a DOT file (`write_segment_graph_dot`) into `folder`,
/// named `key_frame_0000.dot` and on (zero-padded to one width), each starting with a comment
/// that gives its frames.
/// @param graph the evolving graph.
/// @param folder the folder, created if needed; files of the same names are replaced.
/// @return the files written, in key frame order.
/// @throws invalid_input naming the folder or file when it cannot be written.
/// @par Complexity O(total size of the graphs).
inline std::vector<std::filesystem::path> write_key_frames_dot(const Evolving_graph& graph,
                                                               const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw invalid_input("cannot create the folder: " + error.message(), {.file = folder.string()});
  const std::size_t digits = std::max<std::size_t>(4, std::to_string(graph.size()).size());
  std::vector<std::filesystem::path> files;
  for (std::size_t k = 0; k < graph.size(); ++k) {
    std::string number = std::to_string(k);
    number.insert(0, digits - number.size(), '0');
    std::ostringstream text;
    text << "// key frame " << k << ": frames " << graph[k].first_frame << "-" << graph[k].last_frame << "\n";
    write_segment_graph_dot(text, graph[k].graph);
    files.push_back(folder / ("key_frame_" + number + ".dot"));
    internal::write_file_bytes(files.back(), text.str());
  }
  return files;
}

}  // namespace deformseg::io
