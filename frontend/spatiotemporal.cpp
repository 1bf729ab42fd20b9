#include "spatiotemporal.h"

#include <deformseg/spatiotemporal/body_layout.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace deformseg::frontend {

void check(const Spatiotemporal_request& r, Front front) {
  if (!r.reference.empty()) check_choice("reference", r.reference, segmentation_reference_choices, front);
  constexpr auto previous = strain::Strain_reference::previous_pose;
  if (!r.reference_mesh.empty() && !r.reference.empty() &&
      entry_named(segmentation_references, r.reference).value == previous)
    refuse(spelled("reference_mesh", front) + " is a rest pose: it excludes " +
           spelled("reference", name_of(segmentation_references, previous), front));
}

spatiotemporal::Spatiotemporal_options segmentation_options(const Spatiotemporal_request& r) {
  // None given: the previous pose, or the rest pose of a reference mesh.
  const strain::Strain_reference reference =
      !r.reference.empty()      ? entry_named(segmentation_references, r.reference).value
      : r.reference_mesh.empty() ? strain::Strain_reference::previous_pose
                                 : strain::Strain_reference::rest_pose;
  return {
      .reference = reference,
      .sigma = r.sigma,
      .threshold = r.threshold,
      .min_triangles = r.min_triangles,
      .min_frames = r.min_frames,
      .max_island = r.max_island,
      .min_area = r.min_area,
      .hysteresis = r.hysteresis,
      .parts = {.contact_distance = r.contact_distance, .rigid_tolerance = r.rigid_tolerance}};
}

bool segments_stream(const Spatiotemporal_request& request) { return request.reference_mesh.empty(); }

std::size_t streamed_chunk_frames(std::size_t vertices) {
  constexpr std::size_t coordinates = std::size_t(1) << 22;  // 32 MB of doubles
  return std::max<std::size_t>(2, coordinates / std::max<std::size_t>(3 * vertices, 1));
}

Spatiotemporal_result spatiotemporal_segments(const mesh::Surface_mesh_animation& animation,
                                              const Spatiotemporal_request& r, int threads) {
  const spatiotemporal::Spatiotemporal_options options = segmentation_options(r);
  strain::Strain_options strain = spatiotemporal::strain_options(options);
  strain.threads = threads;
  const auto field = strain_against(animation, r.reference_mesh, strain);
  spatiotemporal::Body_layout layout = spatiotemporal::body_layout(animation, options.parts);
  auto segmentation = std::make_unique<const spatiotemporal::Spatiotemporal_segmentation>(
      spatiotemporal::spatiotemporal_segmentation(field, layout, options));
  spatiotemporal::Frame_segments frames(*segmentation, std::move(layout));
  spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(frames);
  return {std::move(segmentation), std::move(frames), std::move(graph)};
}

namespace {

nlohmann::json key_frame_record(const spatiotemporal::Key_frame& k) {
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

}  // namespace

nlohmann::json evolving_graph_record(const spatiotemporal::Evolving_graph& graph) {
  nlohmann::json key_frames = nlohmann::json::array();
  for (const spatiotemporal::Key_frame& k : graph) key_frames.push_back(key_frame_record(k));
  return {{"frames", graph.num_frames()}, {"segments", graph.num_segments()}, {"key_frames", key_frames}};
}

}  // namespace deformseg::frontend
