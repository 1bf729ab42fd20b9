/// @file spatiotemporal/segment_graph_dot.h
/// @brief Writes segment graphs in Graphviz DOT: one graph (`write_segment_graph_dot`) or each
/// key frame's graph of an evolving graph in a folder (`write_key_frames_dot`), the nodes
/// labelled as `deformseg ged` reads them and coloured as the meshes coloured by segment.
#pragma once

#include <deformseg/color/color.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/io/files.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/segment_colors.h>

#include <boost/graph/graphviz.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace deformseg::spatiotemporal::internal {

// A node's DOT attributes: its label (R, or D and the segment id), what it is, its area share in
// percent beside it (xlabel), and its colour. A rigid node has no segment attribute, as it has
// `null` in the tool's JSON. Every value is quoted: the shortest text of an area may have an
// exponent (5.79e-05), which DOT's numerals do not allow.
inline std::string dot_node_attributes(const Segment_node& n) {
  const bool rigid = n.kind == Segment_kind::rigid;
  const color::Rgb c = segment_color(n.segment);
  char fill[8];
  std::snprintf(fill, sizeof fill, "#%02x%02x%02x", unsigned(c.r), unsigned(c.g), unsigned(c.b));
  const std::string segment = rigid ? "" : "segment=\"" + std::to_string(n.segment) + "\", ";
  return "[label=\"" + node_label(n) + "\", kind=\"" + (rigid ? "rigid" : "deformed") + "\", " + segment +
         "triangles=\"" + std::to_string(n.triangles) + "\", area=\"" + deformseg::internal::shortest_text(n.area) +
         "\", xlabel=\"" + std::to_string(std::lround(100 * n.area)) + "%\", style=filled, fillcolor=\"" + fill +
         "\"]";
}

}  // namespace deformseg::spatiotemporal::internal

namespace deformseg::spatiotemporal {

/// @brief Writes a segment graph in Graphviz DOT: an undirected `graph`, node ids 0..n-1 in the
/// graph's order, each with `label` ("R", or "D" and the segment id, the node kind as the
/// `deformseg ged` command reads it), `kind` ("rigid" or "deformed"), `segment` (the
/// spatio-temporal segment's id; none on a rigid node), `triangles`, `area` (the node's share of
/// the surface area), `xlabel` (that share in percent, drawn beside the node), and a fill colour
/// (`segment_color`, as the meshes of `segment_face_colors` have it). The graph asks its
/// layout not to overlap the nodes (`overlap=false`), which `neato` and `fdp` honour, and draws
/// nodes as circles in a legible font.
/// @param out the stream.
/// @param graph the graph.
/// @par Complexity O(n + e).
inline void write_segment_graph_dot(std::ostream& out, const Segment_graph& graph) {
  boost::write_graphviz(
      out, graph, [&graph](std::ostream& o, std::size_t v) { o << internal::dot_node_attributes(graph[v]); },
      boost::default_writer(), [](std::ostream& o) {
        o << "graph [overlap=false, splines=true, forcelabels=true];\n"
             "node [shape=circle, fontname=\"Helvetica\", fontsize=14];\n";
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
  io::create_folder(folder);
  const std::size_t digits = std::max<std::size_t>(4, std::to_string(graph.size()).size());
  std::vector<std::filesystem::path> files;
  for (std::size_t k = 0; k < graph.size(); ++k) {
    std::string number = std::to_string(k);
    number.insert(0, digits - number.size(), '0');
    std::ostringstream text;
    text << "// key frame " << k << ": frames " << graph[k].first_frame << "-" << graph[k].last_frame << "\n";
    write_segment_graph_dot(text, graph[k].graph);
    files.push_back(folder / ("key_frame_" + number + ".dot"));
    io::write_file(files.back(), text.str());
  }
  return files;
}

}  // namespace deformseg::spatiotemporal
