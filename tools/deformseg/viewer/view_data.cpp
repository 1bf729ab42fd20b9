#include "view_data.h"
#include "command.h"
#include "motion_box.h"

#include <deformseg/color/strain_colors.h>
#include <deformseg/exceptions.h>
#include <deformseg/spatiotemporal/body_layout.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/segment_colors.h>
#include <deformseg/strain/strain.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace deformseg::tool {

View_coloring view_coloring(const std::string& name) {
  if (name == "strain") return View_coloring::strain;
  if (name == "previous-strain") return View_coloring::previous_strain;
  if (name == "temporal") return View_coloring::temporal;
  if (name == "segments") return View_coloring::segments;
  if (name == "none") return View_coloring::none;
  throw invalid_input("--color is strain, previous-strain, temporal, segments or none, not " + name);
}

std::string base64(std::span<const std::uint8_t> bytes) {
  static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = std::min<std::size_t>(3, bytes.size() - i);
    const std::uint32_t group = std::uint32_t(bytes[i]) << 16 | (left > 1 ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                (left > 2 ? std::uint32_t(bytes[i + 2]) : 0);
    for (std::size_t k = 0; k < 4; ++k) text += k <= left ? digits[(group >> (18 - 6 * k)) & 63] : '=';
  }
  return text;
}

mesh::Surface_mesh_animation evenly_sampled(const mesh::Surface_mesh_animation& animation, std::size_t max_frames,
                                      std::vector<std::size_t>& numbers) {
  numbers = evenly_spaced_frames(animation.num_frames(), std::max<std::size_t>(max_frames, 1));
  if (numbers.size() == animation.num_frames()) return animation;
  mesh::Surface_mesh_animation sampled(animation.face_graph());
  for (std::size_t t : numbers)
    sampled.add_frame(std::span<const double>(animation.frame_matrix(t).data(), 3 * animation.num_vertices()));
  return sampled;
}

namespace {

// Little-endian bytes of `values`, whatever the host's order.
template <class Word>
std::vector<std::uint8_t> little_endian(const std::vector<Word>& values) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(values.size() * sizeof(Word));
  for (Word v : values)
    for (std::size_t k = 0; k < sizeof(Word); ++k) bytes.push_back(std::uint8_t(v >> (8 * k)));
  return bytes;
}

nlohmann::json rgb(color::Rgb c) { return {c.r, c.g, c.b}; }

// The faces' colours of every frame: a palette and an index into it per face per frame.
struct Face_colors {
  std::vector<color::Rgb> palette{};
  std::vector<std::uint16_t> indices{};  // frame-major
  nlohmann::json legend{};
};

// Each face in the viridis colour of its normalised strain, quantised to 256 steps.
Face_colors strain_colors_of(const strain::Strain_field<float>& field, strain::Strain_reference reference) {
  Face_colors out;
  for (int k = 0; k < 256; ++k) out.palette.push_back(color::strain_color(k / 255.0));
  for (float v : field.values())
    out.indices.push_back(std::uint16_t(std::lround(255 * std::clamp(double(v), 0.0, 1.0))));
  out.legend = {{"kind", "scale"},
                {"title", reference == strain::Strain_reference::rest_pose ? "normalised strain against frame 0"
                                                                    : "normalised strain against the frame before"},
                {"low", 0},
                {"high", 1}};
  return out;
}

// Every face of a frame in the colour of the frame's temporal segment.
Face_colors temporal_colors(const temporal::Temporal_segmentation& segments, std::size_t faces) {
  Face_colors out{.legend = {{"kind", "list"}, {"title", "temporal segment"}, {"items", nlohmann::json::array()}}};
  for (std::size_t k = 0; k < segments.segments.size(); ++k) {
    out.palette.push_back(spatiotemporal::segment_color(std::int32_t(k)));
    out.legend["items"].push_back({{"name", "frames " + std::to_string(segments.segments[k].first) + "-" +
                                                std::to_string(segments.segments[k].last)},
                                   {"color", k}});
  }
  for (std::size_t t = 0; t < segments.frames; ++t)
    out.indices.insert(out.indices.end(), faces, std::uint16_t(segments.segment_of(t)));
  return out;
}

// Each face in its spatio-temporal segment's colour (rigid: grey), as the meshes of
// `spatiotemporal --mesh-dir` and the graph's nodes.
Face_colors segment_colors_of(const spatiotemporal::Spatiotemporal_segmentation& segmentation) {
  Face_colors out{
      .legend = {{"kind", "list"}, {"title", "spatio-temporal segment"}, {"items", nlohmann::json::array()}}};
  std::map<std::int32_t, std::uint16_t> index_of;
  for (std::size_t t = 0; t < segmentation.num_frames(); ++t)
    for (std::int32_t label : segmentation.frame_labels(t)) {
      auto [at, added] = index_of.try_emplace(label, std::uint16_t(out.palette.size()));
      if (added) out.palette.push_back(spatiotemporal::segment_color(label));
      out.indices.push_back(at->second);
    }
  for (const auto& [label, index] : index_of)
    if (out.legend["items"].size() < 16)
      out.legend["items"].push_back({{"name", spatiotemporal::node_label(spatiotemporal::Segment_node{
                                                  .kind = label < 0 ? spatiotemporal::Segment_kind::rigid
                                                                    : spatiotemporal::Segment_kind::deformed,
                                                  .segment = label})},
                                     {"color", index}});
  return out;
}

nlohmann::json colors_json(const Face_colors& colors, View_coloring coloring) {
  static const char* names[] = {"strain", "previous-strain", "temporal", "segments", "none"};
  nlohmann::json palette = nlohmann::json::array();
  for (color::Rgb c : colors.palette) palette.push_back(rgb(c));
  const bool wide = colors.palette.size() > 256;
  std::vector<std::uint8_t> bytes;
  if (wide)
    bytes = little_endian(colors.indices);
  else
    for (std::uint16_t i : colors.indices) bytes.push_back(std::uint8_t(i));
  return {{"mode", names[int(coloring)]}, {"palette", palette}, {"index_bytes", wide ? 2 : 1},
          {"indices", base64(bytes)}, {"legend", colors.legend}};
}

// Positions quantised to 16 bits in the box of the whole motion.
nlohmann::json positions_json(const mesh::Surface_mesh_animation& animation) {
  const auto [low, high] = motion_box(animation);
  const Eigen::Vector3d extent = (high - low).cwiseMax(std::numeric_limits<double>::min());
  std::vector<std::uint16_t> words;
  words.reserve(animation.num_frames() * animation.num_vertices() * 3);
  for (std::size_t t = 0; t < animation.num_frames(); ++t) {
    const auto frame = animation.frame_matrix(t);
    for (Eigen::Index v = 0; v < frame.cols(); ++v)
      for (Eigen::Index a = 0; a < 3; ++a)
        words.push_back(std::uint16_t(std::lround(65535 * (frame(a, v) - low[a]) / extent[a])));
  }
  return {{"box", {{"low", {low.x(), low.y(), low.z()}}, {"high", {high.x(), high.y(), high.z()}}}},
          {"positions", base64(little_endian(words))}};
}

nlohmann::json key_frames_json(const spatiotemporal::Evolving_graph& graph) {
  nlohmann::json key_frames = nlohmann::json::array();
  for (const spatiotemporal::Key_frame& k : graph) {
    nlohmann::json nodes = nlohmann::json::array(), edges = nlohmann::json::array();
    const spatiotemporal::Segment_graph& g = k.graph;
    for (std::size_t v = 0; v < boost::num_vertices(g); ++v) {
      const bool rigid = g[v].kind == spatiotemporal::Segment_kind::rigid;
      nodes.push_back({{"kind", rigid ? "rigid" : "deformed"},
                       {"segment", rigid ? nlohmann::json(nullptr) : nlohmann::json(g[v].segment)},
                       {"area", g[v].area},
                       {"color", rgb(spatiotemporal::segment_color(g[v].segment))}});
    }
    for (auto e : boost::make_iterator_range(boost::edges(g)))
      edges.push_back({boost::source(e, g), boost::target(e, g)});
    key_frames.push_back({{"first", k.first_frame}, {"last", k.last_frame}, {"nodes", nodes}, {"edges", edges}});
  }
  return key_frames;
}

}  // namespace

nlohmann::json view_json(const mesh::Surface_mesh_animation& animation, const std::string& name,
                         const std::vector<std::size_t>& frame_numbers, View_coloring coloring, int threads) {
  const std::size_t faces = animation.num_faces();
  // Each strain once: the rest-pose one serves the temporal segments (their default) and the
  // strain colours, the previous-pose one the spatio-temporal segments (theirs) and its colours.
  const strain::Strain_field<float> rest = strain::compute_strain(animation, {.threads = threads});
  const strain::Strain_field<float> previous =
      strain::compute_strain(animation, {.reference = strain::Strain_reference::previous_pose, .threads = threads});
  const temporal::Temporal_segmentation segments = temporal::temporal_segmentation(rest);
  // The segments and graph of `deformseg spatiotemporal` with its defaults: its parts linked.
  spatiotemporal::Body_layout layout = spatiotemporal::body_layout(animation);
  const spatiotemporal::Spatiotemporal_segmentation segmentation =
      spatiotemporal::spatiotemporal_segmentation(previous, layout);
  const spatiotemporal::Evolving_graph graph =
      spatiotemporal::evolving_graph(spatiotemporal::Frame_segments(segmentation, std::move(layout)));
  Face_colors colors;
  switch (coloring) {
    case View_coloring::strain: colors = strain_colors_of(rest, strain::Strain_reference::rest_pose); break;
    case View_coloring::previous_strain:
      colors = strain_colors_of(previous, strain::Strain_reference::previous_pose);
      break;
    case View_coloring::temporal: colors = temporal_colors(segments, faces); break;
    case View_coloring::segments: colors = segment_colors_of(segmentation); break;
    case View_coloring::none:
      colors = {.palette = {{200, 200, 200}},
                .indices = std::vector<std::uint16_t>(faces * animation.num_frames(), 0),
                .legend = {{"kind", "list"}, {"title", "no colouring"}, {"items", nlohmann::json::array()}}};
      break;
  }
  std::vector<std::uint32_t> corners;
  for (const auto& triangle : animation.triangles()) corners.insert(corners.end(), triangle.begin(), triangle.end());
  nlohmann::json temporal = nlohmann::json::array();
  for (const auto& s : segments.segments) temporal.push_back({{"first", s.first}, {"last", s.last}});
  nlohmann::json out = positions_json(animation);
  out.update(nlohmann::json{{"name", name},
              {"frames", animation.num_frames()},
              {"vertices", animation.num_vertices()},
              {"triangles", faces},
              {"frame_numbers", frame_numbers},
              {"triangle_corners", base64(little_endian(corners))},
              {"color", colors_json(colors, coloring)},
              {"segments", temporal},
              {"key_frames", key_frames_json(graph)}});
  return out;
}

}  // namespace deformseg::tool
