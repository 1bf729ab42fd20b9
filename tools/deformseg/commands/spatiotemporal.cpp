// deformseg spatiotemporal INPUT: spatio-temporal segments and the evolving graph of their
// key frames, as JSON, DOT files and meshes coloured by segment.
#include "command.h"

#include <frontend/spatiotemporal.h>

#include <deformseg/io/frame_sequence.h>
#include <deformseg/spatiotemporal/segment_colors.h>
#include <deformseg/spatiotemporal/segment_graph_dot.h>

#include <iostream>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

struct Spatiotemporal_command_options {
  std::string input;
  Input_options read;
  frontend::Spatiotemporal_request segments;
  std::string json;
  std::string dot;
  std::string mesh_dir;
};

void print(const spatiotemporal::Evolving_graph& graph) {
  std::cout << "frames      " << graph.num_frames() << "\nsegments    " << graph.num_segments() << "\nkey frames  "
            << graph.size() << "\nkey frame  frames  nodes (R rigid, D<segment> deformed)  edges\n";
  for (std::size_t k = 0; k < graph.size(); ++k) {
    const spatiotemporal::Segment_graph& g = graph[k].graph;
    std::cout << k << "  " << graph[k].first_frame << "-" << graph[k].last_frame << " ";
    for (std::size_t v = 0; v < boost::num_vertices(g); ++v) std::cout << ' ' << spatiotemporal::node_label(g[v]);
    std::cout << "  " << boost::num_edges(g) << '\n';
  }
}

void run(const Spatiotemporal_command_options& o) {
  frontend::check(o.segments, frontend::Front::command_line);
  const frontend::Read_input input = read_input(o.input, o.read);
  const mesh::Surface_mesh_animation& animation = input.animation;
  progress("segmenting " + std::to_string(animation.num_faces()) + " triangles x " +
           std::to_string(animation.num_frames()) + " frames");
  const frontend::Spatiotemporal_result result =
      frontend::spatiotemporal_segments(animation, o.segments, o.read.threads);
  const spatiotemporal::Evolving_graph& graph = result.graph;
  if (!o.dot.empty()) {
    progress("writing " + std::to_string(graph.size()) + " key frame graphs to " + o.dot);
    spatiotemporal::write_key_frames_dot(graph, o.dot);
  }
  if (!o.mesh_dir.empty()) {
    progress("writing " + std::to_string(animation.num_frames()) + " meshes coloured by segment to " + o.mesh_dir);
    io::write_sequence(animation, o.mesh_dir,
                       {.face_colors = [&](std::size_t t) { return spatiotemporal::segment_face_colors(result.frames, t); }});
  }
  nlohmann::json document = frontend::evolving_graph_record(graph);
  document["input"] = o.input;
  document["sources"] = sources({&input, 1}, o.read);
  write_outputs(document, o.json, [&] { print(graph); });
}

}  // namespace

void add_spatiotemporal_command(CLI::App& app) {
  auto options = std::make_shared<Spatiotemporal_command_options>();
  CLI::App* command = app.add_subcommand(
      "spatiotemporal",
      "Spatio-temporal segments and the evolving graph of their key frames: JSON, DOT, coloured meshes");
  add_input(*command, options->input, options->read);
  add_parameters(*command, frontend::spatiotemporal_parameters, options->segments);
  add_json_option(*command, options->json, "the evolving graph");
  command->add_option("--dot", options->dot,
                      "Write each key frame's graph as a Graphviz DOT file into DIR (created when missing)")
      ->check(output_folder());
  command->add_option("--mesh-dir", options->mesh_dir,
                      "Write every frame as a PLY mesh coloured by segment (rigid: grey) into DIR (created when "
                      "missing)")
      ->check(output_folder());
  command->callback([options] { run(*options); });
}

}  // namespace deformseg::tool
