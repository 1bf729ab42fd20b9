// Reading a user's labelled graph (Graphviz DOT or GraphML, nodes with a `label` attribute).
#include <deformseg/ged/exact_ged.h>
#include <deformseg/io/graphviz.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

int main() {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "deformseg_read_labelled_graph.dot";
  std::ofstream(path) << "graph arm {\n  shoulder [label=joint]; elbow [label=joint]; hand [label=end];\n"
                         "  shoulder -- elbow -- hand;\n}\n";
  // [read]
  const deformseg::io::Labelled_graph arm = deformseg::io::read_labelled_graph(path);
  // [read]
  std::filesystem::remove(path);
  std::cout << boost::num_vertices(arm) << " nodes, " << boost::num_edges(arm) << " edges; labels";
  for (std::size_t v = 0; v < boost::num_vertices(arm); ++v) std::cout << ' ' << arm[v];
  std::cout << '\n';
  try {  // a node without a label is an error that names the file and the node
    std::istringstream bad("graph { a [label=x]; b; a -- b }");
    deformseg::io::read_labelled_graph(bad, deformseg::io::Graph_format::dot, "bad.dot");
    return 1;
  } catch (const deformseg::invalid_input& e) {
    std::cout << "error: " << e.what() << '\n';
  }
  return boost::num_edges(arm) == 2 ? 0 : 1;
}
