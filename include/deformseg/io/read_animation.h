/// @file read_animation.h
/// @brief Reads an animation from any input the library knows: a folder or glob of frame files,
/// or a point cache with its topology mesh.
#pragma once

#include <deformseg/default_mesh.h>
#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_mesh.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <string>

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
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`).
/// @pre a point cache comes with `options.topology`; every frame is valid (see the readers).
/// @throws invalid_input naming the file, line or frame of the first problem found.
/// @par Complexity linear in the size of the input.
template <FaceGraph Graph = Surface_mesh, std::floating_point Coordinate = double>
Deforming_mesh<Graph, Coordinate> read_animation(const std::string& input,
                                                 const Animation_read_options& options = {}) {
  const std::string format = animation_format(input);
  if (format != "pc2" && format != "mdd")
    return read_frame_sequence<Graph, Coordinate>(
        input, {.topology = options.topology, .triangulate = options.triangulate, .threads = options.threads});

  if (!options.topology)
    throw invalid_input("a ." + format + " point cache needs a topology mesh (.obj, .off or .ply)",
                        {.file = input});
  const Triangle_soup soup = read_mesh(*options.topology, {.triangulate = options.triangulate});
  Graph topology;
  try {
    topology = make_face_graph<Graph>(points_of(soup), soup.triangles);
  } catch (const invalid_input& e) {
    throw e.located({.file = options.topology->string()});
  }
  return format == "pc2" ? read_pc2<Graph, Coordinate>(input, std::move(topology))
                         : read_mdd<Graph, Coordinate>(input, std::move(topology));
}

}  // namespace deformseg::io
