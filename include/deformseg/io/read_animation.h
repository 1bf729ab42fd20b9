/// @file read_animation.h
/// @brief Reads an animation from any input the library knows: a folder or glob of frame files,
/// or a point cache with its topology mesh.
#pragma once

#include <deformseg/default_mesh.h>
#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_mesh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io {

/// @brief How to read an animation.
struct Animation_read_options {
  /// @brief A mesh file (.obj, .off, .ply) giving the connectivity: required for a point cache;
  /// for a frame sequence it replaces the first frame's faces. Default: none.
  std::optional<std::filesystem::path> topology{};
  /// @brief Fan-triangulate polygons instead of rejecting them. Default: false.
  bool triangulate = false;
  /// @brief Threads that read frames in parallel; 0 (default) uses all.
  int threads = 0;
  /// @brief How the connectivity is repaired (see `repair_triangles`), for frame sequences and
  /// point caches alike: by default vertices are not welded (`weld` false) and degenerate,
  /// duplicate and non-manifold triangles are repaired (`defects` = `Defect_policy::repair`).
  Repair_options repair{};
};

/// @brief The format of an input, by its extension: "pc2" or "mdd" for a point cache, else that
/// of its frame files ("obj", "off" or "ply").
/// @throws invalid_input when the input is a frame sequence with no frame file.
/// @par Complexity that of listing the folder, for a frame sequence.
inline std::string animation_format(const std::string& input) {
  const auto lower_extension = [](const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext.empty() ? ext : ext.substr(1);
  };
  const std::string ext = lower_extension(input);
  if (ext == "pc2" || ext == "mdd") return ext;
  return lower_extension(list_frame_files(input).front());
}

/// @brief Reads an animation: a point cache (`.pc2`, `.mdd`, with `options.topology`), or a
/// sequence of frame files given as a folder or a glob pattern (see `read_frame_sequence`).
///
/// Either way the triangles of the topology (or the first frame) are read, then the positions of
/// every frame, and `repair_triangles` repairs or refuses the triangles (before the positions are
/// read, unless it welds with `options.repair.weld`, which compares every frame). Vertex `i` of a point cache is vertex `i` of the topology file.
///
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`).
/// @param input a folder or glob of frame files, or a `.pc2` or `.mdd` file.
/// @param options `topology` (default none), `triangulate` (default false), `threads` (default 0:
/// all), `repair` (default: no welding, defects repaired).
/// @param report where to store what the repair changed, when not null (default null).
/// @pre a point cache comes with `options.topology`; every frame is valid (see the readers).
/// @throws invalid_input naming the file, line or frame of the first problem found; with
/// `Defect_policy::refuse`, the first defect of the connectivity, located at its file.
/// @par Complexity linear in the size of the input, plus the repair's (see `repair_triangles`).
template <FaceGraph Graph = Surface_mesh, std::floating_point Coordinate = double>
Deforming_mesh<Graph, Coordinate> read_animation(const std::string& input, const Animation_read_options& options = {},
                                                 Repair_report* report = nullptr) {
  const std::string format = animation_format(input);
  if (format != "pc2" && format != "mdd")
    return read_frame_sequence<Graph, Coordinate>(input,
                                                  {.topology = options.topology,
                                                   .triangulate = options.triangulate,
                                                   .threads = options.threads,
                                                   .repair = options.repair},
                                                  report);

  if (!options.topology)
    throw invalid_input("a ." + format + " point cache needs a topology mesh (.obj, .off or .ply)",
                        {.file = input});
  const Input_location topology_location{.file = options.topology->string()};
  Triangle_soup soup;
  try {
    soup = read_mesh(*options.topology, {.triangulate = options.triangulate});
  } catch (const invalid_input& e) {
    throw e.located(topology_location);
  }
  const std::size_t vertices = soup.num_vertices();
  const std::span<const std::array<std::uint32_t, 3>> triangles(soup.triangles);
  // Without welding the repair needs no positions: a defect refused is reported before the cache is read.
  Repaired_triangles repaired;
  if (!options.repair.weld)
    repaired = internal::repaired_topology(std::span<const Coordinate>(), vertices, triangles, options.repair,
                                           topology_location);
  std::vector<Coordinate> positions =
      format == "pc2" ? internal::read_point_cache_positions<Point_cache_format::pc2, Coordinate>(input, vertices)
                      : internal::read_point_cache_positions<Point_cache_format::mdd, Coordinate>(input, vertices);
  if (options.repair.weld)
    repaired = internal::repaired_topology(std::span<const Coordinate>(positions), vertices, triangles, options.repair,
                                           topology_location);
  return internal::repaired_animation<Graph, Coordinate>(std::move(positions), vertices, repaired, report);
}

}  // namespace deformseg::io
