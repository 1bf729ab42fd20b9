// What `deformseg view` puts in a page's data.js: each animation's frames as quantised positions,
// its faces' colours frame by frame, its temporal segments and its evolving graph's key frames,
// and, for two animations, their alignment; binary arrays in base64, so that the page works from
// file:// with no server.
#pragma once

#include <deformseg/mesh/default_mesh.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace deformseg::tool {

/// How the page colours the faces.
enum class View_coloring { strain, previous_strain, temporal, segments, none };

/// The colouring of `name` ("strain", "previous-strain", "temporal", "segments", "none").
View_coloring view_coloring(const std::string& name);

/// `bytes` in base64 (RFC 4648, with padding).
std::string base64(std::span<const std::uint8_t> bytes);

/// At most `max_frames` frames of `animation`, evenly spaced from the first to the last (all of
/// them when it has no more); `numbers` receives each kept frame's number in `animation`.
mesh::Surface_mesh_animation evenly_sampled(const mesh::Surface_mesh_animation& animation, std::size_t max_frames,
                                      std::vector<std::size_t>& numbers);

/// The page's description of one animation: `name`, `frames`, `vertices`, `triangles`,
/// `frame_numbers`, `box` (`low`, `high`), `positions` (base64 of little-endian uint16, x y z of
/// each vertex, frame after frame, quantised in the box), `triangles` (their count),
/// `triangle_corners` (base64 of little-endian uint32, 3 vertex indices a triangle),
/// `color` (`mode`, `palette` of [r, g, b], `index_bytes` 1 or 2, `indices`: base64 of a palette
/// index per face per frame, `legend`), `segments` (the temporal segments, `first`, `last`) and
/// `key_frames` (`first`, `last`, `nodes` with `kind`, `segment`, `area`, `color`, and `edges`).
nlohmann::json view_json(const mesh::Surface_mesh_animation& animation, const std::string& name,
                         const std::vector<std::size_t>& frame_numbers, View_coloring coloring, int threads);

}  // namespace deformseg::tool
