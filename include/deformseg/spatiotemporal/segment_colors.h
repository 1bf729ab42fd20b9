/// @file spatiotemporal/segment_colors.h
/// @brief Colours of spatio-temporal segments, the same in every frame, for meshes coloured by
/// segment: `segment_color`, `segment_face_colors`, and `put_face_segments`, the node of each
/// face in a face property map.
#pragma once

#include <deformseg/color/color.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/spatiotemporal/frame_segments.h>
#include <deformseg/strain/strain.h>

#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace deformseg::spatiotemporal {

/// @brief The colour of a segment: light grey for `Spatiotemporal_segmentation::rigid` (or any
/// negative id), else a saturated colour of its own, the hue turning by the golden angle from one
/// id to the next, so that segments with nearby ids (often neighbours in time) look different.
/// The same id has the same colour in every frame and every run.
/// @par Complexity O(1).
inline color::Rgb segment_color(std::int32_t segment) {
  if (segment < 0) return {200, 200, 200};
  constexpr double golden_turn = 0.381966011250105;  // 1 - 1 / phi, of a full turn
  const double hue = std::fmod(0.05 + golden_turn * double(segment), 1.0) * 6.0;
  const double value = segment % 2 == 0 ? 0.95 : 0.75;  // alternate brightness for close hues
  const double saturation = 0.8;
  const double x = value * saturation * (1 - std::abs(std::fmod(hue, 2.0) - 1));
  const double c = value * saturation, m = value - c;
  double r = 0, g = 0, b = 0;
  switch (int(hue)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
  }
  const auto channel = [m](double v) { return std::uint8_t(std::lround(255 * (v + m))); };
  return {channel(r), channel(g), channel(b)};
}

/// @brief The colour of each triangle in frame `t`: `segment_color` of the deformed segment it
/// belongs to, light grey for a rigid one; in face index order, ready for `io::write_ply` or
/// `io::Sequence_write_options::face_colors`.
/// @throws invalid_input when `t >= frames.num_frames()`.
/// @par Complexity O(F).
inline std::vector<color::Rgb> segment_face_colors(const Frame_segments& frames, std::size_t t) {
  const auto labels = frames.segmentation().frame_labels(t);
  std::vector<color::Rgb> colors(labels.size());
  for (std::size_t f = 0; f < labels.size(); ++f) colors[f] = segment_color(labels[f]);
  return colors;
}

/// @brief Writes the node of each face in frame `t`'s segment graph (`Frame_segments::graph`, and
/// so the key frame's graph of `evolving_graph`) into a face property map: face f gets the node of
/// triangle `index(f)`, with `index` the face index map of `np` (default: the graph's initialized one).
/// @tparam FacePropertyMap a writable property map from the graph's face descriptors to an
/// integer type that holds the node count.
/// @param frames the frames' segments.
/// @param t the frame.
/// @param graph the connectivity (`animation.face_graph()`), or a mesh with the same faces in the
/// same order.
/// @param map where to write.
/// @param np optional CGAL named parameters: `face_index_map`, as for `strain::put_strain_frame`.
/// @throws invalid_input when `t` is out of range or the graph has another number of faces.
/// @par Complexity O(F + E), as `Frame_segments::face_nodes`.
template <mesh::FaceGraph Graph, class FacePropertyMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void put_face_segments(const Frame_segments& frames, std::size_t t, const Graph& graph, FacePropertyMap map,
                       const NamedParameters& np = CGAL::parameters::default_values()) {
  const std::vector<std::uint32_t> nodes = frames.face_nodes(t);
  deformseg::strain::internal::for_each_face_index(
      graph, nodes.size(), [&](auto f, std::size_t j) { put(map, f, nodes[j]); }, np);
}

}  // namespace deformseg::spatiotemporal
