// deformseg spatiotemporal INPUT: spatio-temporal segments and the evolving graph of their
// key frames, as JSON, DOT files and meshes coloured by segment.
#include "command.h"

#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/io/graphviz.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/color/segment_colors.h>

#include <iostream>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

struct Spatiotemporal_command_options {
  Input_options input;
  std::optional<std::string> reference;  // none given: previous, or rest with a reference mesh
  std::string reference_mesh;
  spatiotemporal::Spatiotemporal_options segments;
  std::string json;
  std::string dot;
  std::string mesh_dir;
};

nlohmann::json key_frame_json(const spatiotemporal::Key_frame& k) {
  nlohmann::json nodes = nlohmann::json::array(), edges = nlohmann::json::array();
  const spatiotemporal::Segment_graph& g = k.graph;
  for (std::size_t v = 0; v < boost::num_vertices(g); ++v) {
    const bool rigid = g[v].kind == spatiotemporal::Segment_kind::rigid;
    nodes.push_back({{"id", v},
                     {"kind", rigid ? "rigid" : "deformed"},
                     {"segment", rigid ? nlohmann::json(nullptr) : nlohmann::json(g[v].segment)},
                     {"triangles", g[v].triangles},
                     {"area", g[v].area}});
  }
  for (auto e : boost::make_iterator_range(boost::edges(g)))
    edges.push_back(
        {std::min(boost::source(e, g), boost::target(e, g)), std::max(boost::source(e, g), boost::target(e, g))});
  return {{"first", k.first_frame}, {"last", k.last_frame}, {"nodes", nodes}, {"edges", edges}};
}

nlohmann::json document_of(const spatiotemporal::Evolving_graph& graph) {
  nlohmann::json key_frames = nlohmann::json::array();
  for (const spatiotemporal::Key_frame& k : graph) key_frames.push_back(key_frame_json(k));
  return {{"frames", graph.num_frames()}, {"segments", graph.num_segments()}, {"key_frames", key_frames}};
}

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
  if (!o.reference_mesh.empty() && o.reference == "previous")
    throw invalid_input("--reference-mesh is a rest pose: it excludes --reference previous");
  const mesh::Surface_mesh_animation animation = read_input(o.input);
  spatiotemporal::Spatiotemporal_options options = o.segments;
  options.reference = o.reference.value_or(o.reference_mesh.empty() ? "previous" : "rest") == "rest"
                          ? strain::Strain_reference::rest_pose
                          : strain::Strain_reference::previous_pose;
  const std::optional<mesh::Surface_mesh> reference_mesh =
      o.reference_mesh.empty() ? std::nullopt : std::optional(read_reference_mesh(o.reference_mesh));
  progress("segmenting " + std::to_string(animation.num_faces()) + " triangles x " +
           std::to_string(animation.num_frames()) + " frames");
  const spatiotemporal::Spatiotemporal_segmentation segmentation =
      reference_mesh ? spatiotemporal::spatiotemporal_segmentation(naming_reference_mesh(o.reference_mesh, [&] {
                         return strain::compute_strain(animation, *reference_mesh, {.threads = o.input.threads});
                       }), animation.triangles(), options)
                     : spatiotemporal::spatiotemporal_segmentation(animation, options);
  const std::vector<double> areas = mesh::face_areas(animation, 0);
  const spatiotemporal::Frame_segments frames(segmentation, animation.triangles(), areas);
  const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(frames);
  if (!o.dot.empty()) {
    progress("writing " + std::to_string(graph.size()) + " key frame graphs to " + o.dot);
    io::write_key_frames_dot(graph, o.dot);
  }
  if (!o.mesh_dir.empty()) {
    progress("writing " + std::to_string(animation.num_frames()) + " meshes coloured by segment to " + o.mesh_dir);
    io::write_sequence(animation, o.mesh_dir,
                       {.face_colors = [&](std::size_t t) { return color::segment_face_colors(frames, t); }});
  }
  write_outputs(document_of(graph), o.json, [&] { print(graph); });
}

}  // namespace

void add_spatiotemporal_command(CLI::App& app) {
  auto options = std::make_shared<Spatiotemporal_command_options>();
  CLI::App* command = app.add_subcommand(
      "spatiotemporal",
      "Spatio-temporal segments and the evolving graph of their key frames: JSON, DOT, coloured meshes");
  add_input_options(*command, options->input);
  command->add_option("--reference", options->reference,
                      "previous: deformed while it moves (default); rest: deformed while away from frame 0, or "
                      "from --reference-mesh (the default with it)")
      ->check(CLI::IsMember({"previous", "rest"}));
  add_reference_mesh_option(*command, options->reference_mesh);
  command->add_option("--threshold", options->segments.threshold,
                      "A cell is deformed above this normalised strain, in [0, 1]. Default: 0.5")
      ->check(CLI::Range(0.0, 1.0));
  command->add_option("--min-triangles", options->segments.min_triangles,
                      "Segments whose largest slice has fewer triangles become rigid. Default: 10");
  command->add_option("--min-frames", options->segments.min_frames,
                      "Segments lasting fewer frames become rigid. Default: 2");
  command->add_option("--max-island", options->segments.max_island,
                      "Rigid islands of at most this many triangles inside one segment join it (0: none). "
                      "Default: 30");
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
