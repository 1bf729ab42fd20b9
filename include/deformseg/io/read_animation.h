/// @file io/read_animation.h
/// @brief Reads an animation from any input the library knows: a glTF clip, a folder or glob of
/// frame files, or a point cache with its topology mesh.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/config.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_mesh.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/threads.h>

// glTF is read when deformseg's io library was built with tinygltf (io/config.h says so).
#if DEFORMSEG_HAS_GLTF
#include <deformseg/io/gltf.h>
#endif

#include <algorithm>
#include <cmath>
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
  /// @brief Threads that read frames in parallel: 0 (default) for all the hardware's threads (`thread_count`), at most
  /// `max_threads`.
  int threads = 0;
  /// @brief How the connectivity is repaired (see `repair_triangles`). Default: the format's,
  /// that is degenerate, duplicate and non-manifold triangles repaired, and vertices welded for
  /// glTF (which splits them along seams) but not for frame sequences and point caches.
  std::optional<Repair_options> repair{};
  /// @brief glTF: the clip to read, by name or index (or after a '#' in the input, "Fox.glb#Walk").
  /// Empty (default): the file's only clip, or its rest pose when it has none; a file of several
  /// clips is refused, naming them (see `require_clip_choice`).
  std::string clip{};
  /// @brief The animation's frame rate, in frames per second (`Deforming_mesh::frames_per_second`):
  /// for glTF the rate the clip is sampled at, for frame files and point caches (whose rate the
  /// files do not give) the rate they were sampled at. Default 30.
  double fps = 30;
};

/// @brief "Fox.glb#Walk" split into the character file (glTF, FBX or Collada: see
/// `is_character_file`) and the clip after its last '#': `{"Fox.glb", "Walk"}`; any other input
/// (no '#', or none after a character file's name) whole, with no clip.
/// @par Complexity O(length of the name).
inline std::pair<std::string, std::optional<std::string>> split_clip_suffix(const std::string& input) {
  const std::size_t hash = input.rfind('#');
  if (hash == std::string::npos || !is_character_file(input.substr(0, hash))) return {input, std::nullopt};
  return {input.substr(0, hash), input.substr(hash + 1)};
}

/// @brief The format of an input, by its extension: "gltf", "glb", "fbx", "dae" or "bvh" (with or without
/// a "#CLIP" after it), "pc2" or "mdd" for a point cache, else that of its frame files ("obj", "off" or "ply").
/// @throws invalid_input when the input is a frame sequence with no frame file.
/// @par Complexity that of listing the folder, for a frame sequence.
inline std::string animation_format(const std::string& input) {
  const auto extension = [](const std::filesystem::path& path) { return internal::lower_extension(path).substr(1); };
  const std::string ext = internal::lower_extension(split_clip_suffix(input).first);
  if (ext == ".pc2" || ext == ".mdd" || is_character_file(split_clip_suffix(input).first)) return ext.substr(1);
  return extension(list_frame_files(input).front());
}

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// `read_animation` of a character file (glTF, FBX, Collada, BVH): `Gltf_file::read` with the options
/// that apply to it.
template <class Graph, class Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> read_gltf_input(const std::string& input,
                                                        const io::Animation_read_options& options,
                                                        io::Repair_report* report) {
  if (options.topology)
    throw invalid_input("a character file (glTF, FBX, Collada, BVH) has its own connectivity: no topology mesh applies",
                        {.file = input});
#if DEFORMSEG_HAS_GLTF
  const io::Gltf_file file(input);
  io::require_clip_choice(file, options.clip);
  io::Gltf_read_report read;
  auto animation = file.read<Graph, Coordinate>(
      {.clip = options.clip, .fps = options.fps,
       .repair = options.repair.value_or(io::Gltf_read_options{}.repair), .threads = options.threads},
      &read);
  if (report) *report = read.repair;
  return animation;
#else
  static_cast<void>(report);
  throw invalid_input("this deformseg was built without tinygltf, which reads glTF, FBX, Collada and BVH files (Debian: "
                      "libtinygltf-dev and nlohmann-json3-dev, then build deformseg again)",
                      {.file = input});
#endif
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Reads an animation: a clip of a character file (glTF `.gltf`, `.glb`, see `read_gltf`;
/// FBX `.fbx` or Collada `.dae`, see `fbx_collada_model`; BVH `.bvh`, see `bvh_model`, on the body
/// made from its skeleton; "FILE.glb#CLIP" names the clip, as
/// `options.clip` does; a file of several clips needs one named), a point cache
/// (`.pc2`, `.mdd`, with `options.topology`), or a sequence of frame files given as a folder or a
/// glob pattern (see `read_frame_sequence`).
///
/// For frames and point caches the triangles of the topology (or the first frame) are read, then
/// the positions of every frame, and `repair_triangles` repairs or refuses the triangles (before
/// the positions are read, unless it welds, which compares every frame). Vertex `i` of a point
/// cache is vertex `i` of the topology file. A character's clip is sampled at `options.fps`, then given
/// the connectivity every clip of its file shares (`Gltf_file::repair`: welded by what the file
/// fixes, and repaired). Every format's animation has the frame rate `options.fps`.
///
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`).
/// @param input a glTF, FBX, Collada or BVH file (maybe followed by "#CLIP"), a folder or glob of frame
/// files, or a `.pc2` or `.mdd` file.
/// @param options `topology` (default none), `triangulate` (default false), `threads` (default 0:
/// all), `repair` (default: the format's; defects repaired, glTF welded), `clip` (default: the
/// only one) for glTF, and `fps` (default 30): the rate a glTF clip is sampled at, the rate of
/// frame files and point caches.
/// @param report where to store what the repair changed, when not null (default null).
/// @pre a point cache comes with `options.topology`; a character file comes with no `topology`, a
/// clip (after '#' or in `options.clip`, not both) unless it holds one clip or none, and deformseg
/// was built with tinygltf (`DEFORMSEG_HAS_GLTF` of `deformseg/io/config.h`), and for FBX and
/// Collada with Assimp (`DEFORMSEG_HAS_ASSIMP`); every frame is valid (see the readers).
/// @throws invalid_input naming the file, line or frame of the first problem found; with
/// `Defect_policy::refuse`, the first defect of the connectivity, located at its file.
/// @par Complexity linear in the size of the input, plus the repair's (see `repair_triangles`).
template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double>
mesh::Deforming_mesh<Graph, Coordinate> read_animation(const std::string& input,
                                                       const Animation_read_options& options = {},
                                                       Repair_report* report = nullptr) {
  thread_count(options.threads);
  if (const auto [file, clip] = split_clip_suffix(input); clip) {
    if (!options.clip.empty())
      throw invalid_input("the clip is given twice: by the clip option and after '#'", {.file = input});
    Animation_read_options named = options;
    named.clip = *clip;
    return internal::read_gltf_input<Graph, Coordinate>(file, named, report);
  }
  if (is_character_file(input)) return internal::read_gltf_input<Graph, Coordinate>(input, options, report);
  const Repair_options repair = options.repair.value_or(Repair_options{});
  const std::string format = animation_format(input);
  if (format != "pc2" && format != "mdd")
    return read_frame_sequence<Graph, Coordinate>(input,
                                                  {.topology = options.topology,
                                                   .triangulate = options.triangulate,
                                                   .threads = options.threads,
                                                   .repair = repair,
                                                   .fps = options.fps},
                                                  report);

  mesh::check_frames_per_second(options.fps, {}, {.file = input});
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
  if (!repair.weld)
    repaired = internal::repaired_topology(std::span<const Coordinate>(), vertices, triangles, repair,
                                           topology_location);
  mesh::Coordinate_buffer<Coordinate> positions =
      format == "pc2" ? internal::read_point_cache_positions<Point_cache_format::pc2, Coordinate>(input, vertices)
                      : internal::read_point_cache_positions<Point_cache_format::mdd, Coordinate>(input, vertices);
  if (repair.weld)
    repaired = internal::repaired_topology(std::span<const Coordinate>(positions), vertices, triangles, repair,
                                           topology_location);
  auto animation = internal::repaired_animation<Graph, Coordinate>(std::move(positions), vertices, repaired, report);
  animation.set_frames_per_second(options.fps);
  return animation;
}

// The instance of the default types, compiled in deformseg's io library (src/io/read_animation.cpp).
/// @cond
extern template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_animation<mesh::Surface_mesh, double>(const std::string&, const Animation_read_options&, Repair_report*);
/// @endcond

}  // namespace deformseg::io
