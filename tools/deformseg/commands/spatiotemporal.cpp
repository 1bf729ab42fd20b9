// deformseg spatiotemporal INPUT: spatio-temporal segments and the evolving graph of their
// key frames, as JSON, DOT files and meshes coloured by segment; the input read frame by frame
// where it can be, its strain field and segmentation held, not its coordinates.
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

// The segments of the input, read frame by frame when it can be (its coordinates never held
// whole), else whole; the DOT files and the meshes written as they are asked for.
struct Segmented {
  frontend::Spatiotemporal_result result;
  nlohmann::json sources;
};

void write_dot(const Spatiotemporal_command_options& o, const spatiotemporal::Evolving_graph& graph) {
  if (o.dot.empty()) return;
  progress("writing " + std::to_string(graph.size()) + " key frame graphs to " + o.dot);
  spatiotemporal::write_key_frames_dot(graph, o.dot);
}

void report_segmenting(std::size_t triangles, std::size_t frames) {
  progress("segmenting " + std::to_string(triangles) + " triangles x " + std::to_string(frames) + " frames");
}

void report_meshes(const Spatiotemporal_command_options& o, std::size_t frames) {
  progress("writing " + std::to_string(frames) + " meshes coloured by segment to " + o.mesh_dir);
}

std::optional<Segmented> streamed_segments(const Spatiotemporal_command_options& o) {
  std::optional<Segmented> segmented;
  frontend::Stream_read streamed;
  const auto segment = [&](auto& source) {
    report_segmenting(source.triangles().size(), source.num_frames());
    segmented.emplace(Segmented{frontend::spatiotemporal_segments(source, o.segments, o.read.threads), {}});
    write_dot(o, segmented->result.graph);
    if (o.mesh_dir.empty()) return;
    report_meshes(o, source.num_frames());
    frontend::write_segment_meshes(source, segmented->result.frames, o.mesh_dir);
  };
  if (!frontend::segments_stream(o.segments) || !stream_input(o.input, o.read, false, streamed, segment))
    return std::nullopt;
  segmented->sources = sources(streamed, o.read);
  return segmented;
}

Segmented whole_segments(const Spatiotemporal_command_options& o) {
  const frontend::Read_input input = read_input(o.input, o.read);
  const mesh::Surface_mesh_animation& animation = input.animation;
  report_segmenting(animation.num_faces(), animation.num_frames());
  Segmented segmented{frontend::spatiotemporal_segments(animation, o.segments, o.read.threads),
                      sources({&input, 1}, o.read)};
  write_dot(o, segmented.result.graph);
  if (!o.mesh_dir.empty()) {
    report_meshes(o, animation.num_frames());
    const frontend::Spatiotemporal_result& result = segmented.result;
    const auto colors = [&](std::size_t t) { return spatiotemporal::segment_face_colors(result.frames, t); };
    io::write_sequence(animation, o.mesh_dir, {.face_colors = colors});
  }
  return segmented;
}

void run(const Spatiotemporal_command_options& o) {
  frontend::check(o.segments, frontend::Front::command_line);
  frontend::check_clip_applies({o.input}, o.read, frontend::Front::command_line);
  std::optional<Segmented> streamed = streamed_segments(o);
  const Segmented segmented = streamed ? std::move(*streamed) : whole_segments(o);
  const spatiotemporal::Evolving_graph& graph = segmented.result.graph;
  nlohmann::json document = frontend::evolving_graph_record(graph);
  document["input"] = o.input;
  document["sources"] = segmented.sources;
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
