/// @file io/gltf.h
/// @brief Reads glTF 2.0 characters (`.gltf`, `.glb`): one clip of a skinned, morphed, rigidly
/// parented scene sampled into an animation with fixed connectivity (`read_gltf`,
/// `sample_gltf`, or `Gltf_file` for many clips of one file), and what a file holds
/// (`gltf_contents`).
///
/// tinygltf parses the JSON and the buffers; everything else follows the glTF 2.0 specification
/// here: the default scene's node hierarchy, every TRIANGLES primitive of every mesh node
/// instance, linear blend skinning, morph targets, the LINEAR, STEP and CUBICSPLINE samplers,
/// sparse and normalised-integer accessors (KHR_mesh_quantization).
#pragma once

#if !__has_include(<tiny_gltf.h>)
#error "deformseg/io/gltf.h needs tinygltf (Debian: libtinygltf-dev), linked as TinyGLTF::TinyGLTF"
#endif

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/internal/gltf_animation.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/gltf_binding.h>
#include <deformseg/io/internal/gltf_decompression.h>
#include <deformseg/io/internal/gltf_mesh.h>
#include <deformseg/io/internal/gltf_welding.h>
#include <deformseg/io/internal/skeleton_body.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/threads.h>

// FBX, Collada and BVH files are read when deformseg was configured with Assimp (its CMake target then
// defines DEFORMSEG_HAS_ASSIMP and links assimp::assimp).
#if DEFORMSEG_HAS_ASSIMP
#include <deformseg/io/bvh.h>
#include <deformseg/io/fbx_collada.h>
#endif

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::io {

/// @brief How `read_gltf` and `sample_gltf` read a glTF file.
struct Gltf_read_options {
  /// @brief The clip (glTF animation) to sample: empty (default) for the file's first clip; else
  /// the first clip of that name; else, when all digits, the clip of that index.
  std::string clip{};
  /// @brief Frames per second the clip is sampled at, the frame rate of the animation `read`
  /// gives (`Deforming_mesh::frames_per_second`). Default 30.
  double fps = 30;
  /// @brief The repair `read_gltf` applies (see `mesh_repair.h`; welding by what the file fixes,
  /// the same for every clip: see `Gltf_file::repair`). Default: welding on (glTF splits vertices
  /// along UV seams and hard edges), defects repaired.
  Repair_options repair{.weld = true};
  /// @brief Threads that sample frames in parallel: 0 (default) for all the hardware's threads
  /// (`thread_count`), at most `max_threads`. The result does not depend on it.
  int threads = 0;
};

/// @brief What `read_gltf` or `sample_gltf` read.
struct Gltf_read_report {
  /// @brief `clip_index` when the file has no animation (its rest pose is read).
  static constexpr std::size_t no_clip = std::numeric_limits<std::size_t>::max();
  std::string clip{};                 ///< the clip's name as in the file (maybe empty)
  std::size_t clip_index = no_clip;   ///< the clip's index among the file's animations
  double start = 0;                   ///< the smallest key time of the clip, in seconds
  double end = 0;                     ///< the largest key time of the clip, in seconds
  std::size_t frames = 0;             ///< frames sampled
  /// @brief The primitives left out, one line each, e.g. "mesh 'X' primitive 1: mode LINES, skipped".
  std::vector<std::string> skipped{};
  Repair_report repair{};             ///< what the repair changed (`read_gltf` only)
  std::size_t joints = 0;             ///< the joints of the body's skins
  std::size_t animated_joints = 0;    ///< of them, those the clip moves (all of a file's own, usually)
  /// @brief Whether the body was made from the skeleton, the file having no mesh (see `Gltf_file`).
  bool skeleton_body = false;
};

/// @brief A clip sampled, before any repair: the vertices of every TRIANGLES primitive of every
/// mesh instance, primitives in the order of the default scene's depth-first node traversal (a
/// node before its children, children in order), each primitive's vertices in its own order.
struct Sampled_gltf {
  mesh::Coordinate_buffer<double> positions{};  ///< `T x 3V` coordinates, frames one after the other
  std::size_t num_vertices = 0;                 ///< V
  std::vector<std::array<std::uint32_t, 3>> triangles{};  ///< vertex indices in `[0, V)`
  Gltf_read_report report{};        ///< the clip, its times and frames, what was skipped
};

/// @brief One clip of a file.
struct Gltf_clip_info {
  std::string name{};     ///< as in the file (maybe empty)
  double start = 0;       ///< smallest key time, seconds
  double end = 0;         ///< largest key time, seconds
  double duration = 0;    ///< end - start
  std::size_t frames = 0; ///< frames at the fps asked (the sampling rule of `read_gltf`)
  std::size_t channels = 0;  ///< channels that target a node's translation, rotation, scale or weights
};

/// @brief One skin of a file.
struct Gltf_skin_info {
  std::string name{};      ///< as in the file (maybe empty)
  std::size_t joints = 0;  ///< its joint count
};

/// @brief One primitive of a mesh.
struct Gltf_primitive_info {
  std::string mode{};            ///< "TRIANGLES", "LINES", ...
  std::size_t vertices = 0;      ///< the POSITION count (0 without POSITION)
  std::size_t triangles = 0;     ///< for TRIANGLES, the index (or vertex) count / 3; else 0
  std::size_t morph_targets = 0; ///< its morph target count
};

/// @brief One mesh of a file.
struct Gltf_mesh_info {
  std::string name{};                          ///< as in the file (maybe empty)
  std::vector<Gltf_primitive_info> primitives{};  ///< in the file's order
  std::size_t instances = 0;  ///< nodes of the default scene that show it
  bool skinned = false;       ///< whether an instance has a skin (else it is rigid to its nodes)
};

/// @brief What a glTF file holds, as `gltf_contents` lists it.
struct Gltf_contents {
  std::vector<Gltf_clip_info> clips{};    ///< in the file's order
  std::vector<Gltf_skin_info> skins{};    ///< in the file's order
  std::vector<Gltf_mesh_info> meshes{};   ///< in the file's order
  std::size_t nodes = 0;                  ///< all nodes of the file
  std::size_t vertices = 0;   ///< over the scene's TRIANGLES primitive instances, as `sample_gltf` reads
  std::size_t triangles = 0;  ///< likewise
  /// @brief Whether the body was made from the skeleton, the file having no mesh (see `Gltf_file`):
  /// its mesh is then the made body, and the vertices and triangles are its.
  bool skeleton_body = false;
};

}  // namespace deformseg::io

namespace deformseg::io::internal::gltf {

/// The most coordinates (T x 3V) a sampled clip may have: 4 GiB of doubles.
inline constexpr std::size_t max_coordinates = std::size_t(1) << 29;

// Images are never decoded: deformseg needs only the geometry.
inline bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*,
                         int, void*) {
  return true;
}

/// Throws for a required extension deformseg does not know; those that change only the look of a
/// file are let through (compressed geometry is decoded before tinygltf parses the file).
inline void refuse_unread_extension(const std::string& name) {
  const bool known = name == "KHR_mesh_quantization" || name == "KHR_texture_transform" ||
                     name == "KHR_texture_basisu" || name == "EXT_texture_webp" || name == "KHR_lights_punctual" ||
                     name == "KHR_materials_variants" || name.starts_with("KHR_materials_");
  if (!known) throw invalid_input("the file requires the glTF extension " + name + ", which deformseg does not know");
}

/// Refuses any required extension deformseg does not know.
inline void check_extensions(const tinygltf::Model& model) {
  for (const std::string& name : model.extensionsRequired) refuse_unread_extension(name);
}

/// Parses a .gltf or .glb file (told apart by the GLB magic, not the extension), its compressed
/// geometry decoded first, or an FBX, Collada or BVH file (told by its extension) into the same
/// structures.
inline tinygltf::Model load_model(const std::filesystem::path& path) {
  if (is_fbx_or_collada(path) || is_bvh(path)) {
#if DEFORMSEG_HAS_ASSIMP
    return is_bvh(path) ? bvh_model(path) : fbx_collada_model(path);
#else
    throw invalid_input("this deformseg was built without Assimp, which reads FBX, Collada and BVH files (Debian: "
                        "libassimp-dev; link assimp::assimp and define DEFORMSEG_HAS_ASSIMP=1)");
#endif
  }
  const File_bytes read = read_file_bytes(path);  // a missing file or a folder refused as every reader does
  std::span<const unsigned char> file(reinterpret_cast<const unsigned char*>(read.begin()), read.size);
  const std::string base_dir = path.parent_path().string();
  Bytes decompressed;
  if (names_compression(file)) {
    decompressed = decompressed_glb(file, base_dir);
    file = decompressed;
  }
  if (file.size() > std::numeric_limits<unsigned>::max())
    throw invalid_input("a glTF file of " + std::to_string(file.size()) + " bytes: tinygltf reads files under 4 GiB");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&ignore_image, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  bool loaded = false;
  try {
    loaded = is_glb(file) ? loader.LoadBinaryFromMemory(&model, &err, &warn, file.data(), unsigned(file.size()), base_dir)
                          : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(file.data()),
                                                       unsigned(file.size()), base_dir);
  } catch (const std::exception& e) {
    err = e.what();
  }
  if (!loaded) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw invalid_input("not a valid glTF file: " + (err.empty() ? std::string("tinygltf refused it") : err));
  }
  return model;
}

/// The index of the clip `wanted` names (see `Gltf_read_options::clip`), or none when the file
/// has no animation and none was asked.
inline std::optional<std::size_t> select_clip(const tinygltf::Model& model, const std::string& wanted) {
  const std::size_t count = model.animations.size();
  if (wanted.empty()) {
    if (count == 0) return std::nullopt;
    return 0;
  }
  for (std::size_t i = 0; i < count; ++i)
    if (model.animations[i].name == wanted) return i;
  const bool digits = std::all_of(wanted.begin(), wanted.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (digits && wanted.size() < 10 && std::stoul(wanted) < count) return std::stoul(wanted);
  if (count == 0) throw invalid_input("no clip '" + wanted + "': the file has no animation");
  const auto lower = [](std::string text) {
    std::ranges::transform(text, text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
  };
  std::string list, same_letters;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string& name = model.animations[i].name;
    list.append(i == 0 ? "" : ", ").append("'" + name + "'");
    if (same_letters.empty() && lower(name) == lower(wanted)) same_letters = name;
  }
  const std::string hint = same_letters.empty() ? "" : " (clip names are case-sensitive: did you mean '" +
                                                           same_letters + "'?)";
  throw invalid_input("no clip '" + wanted + "'" + hint + "; the file's clips are " + list + " (or an index 0 to " +
                      std::to_string(count - 1) + ")");
}

inline void check_options(const io::Gltf_read_options& options) {
  mesh::check_frames_per_second(options.fps);
  thread_count(options.threads);
}

/// Poses frame `t` of the `frames` frames of `clip` (or the rest pose) sampled at `fps` into `out`:
/// every vertex (3V values), or those of `selection` when not null (3 per output vertex); throws
/// naming the frame and the smallest scene vertex posed with a non-finite coordinate.
inline void pose_frame(const Rig& rig, const Clip* clip, double fps, std::size_t frames, std::size_t t,
                       const Vertex_selection* selection, Pose_scratch& scratch, double* out) {
  const double time = clip ? frame_time(clip->start, clip->end, fps, t, frames) : 0.0;
  if (selection) pose_selected_at(rig, clip, time, *selection, scratch, out);
  else pose_at(rig, clip, time, scratch, out);
  const std::size_t block = 3 * (selection ? selection->input.size() : rig.geometry.vertices);
  if (std::all_of(out, out + block, [](double x) { return std::isfinite(x); })) return;
  std::size_t vertex = rig.geometry.vertices;
  for (std::size_t i = 0; i < block; ++i)
    if (!std::isfinite(out[i])) vertex = std::min<std::size_t>(vertex, selection ? selection->input[i / 3] : i / 3);
  throw invalid_input("vertex " + std::to_string(vertex) + " has a non-finite position", {.frame = t});
}

/// Samples every frame of `clip` (or the rest pose) into `positions`, every vertex or those of
/// `selection` when not null, in parallel; throws the error of the lowest frame with a non-finite
/// coordinate, whatever the number of threads.
inline void sample_frames(const Rig& rig, const Clip* clip, double fps, std::size_t frames, int threads,
                          const Vertex_selection* selection, std::span<double> positions) {
  const std::size_t block = 3 * (selection ? selection->input.size() : rig.geometry.vertices);
  const auto sample = [&](Pose_scratch& scratch, std::size_t t) {
    pose_frame(rig, clip, fps, frames, t, selection, scratch, positions.data() + t * block);
  };
  deformseg::internal::parallel_for_with_locals(frames, threads, 1, [] { return Pose_scratch{}; }, sample);
}

/// A parsed file and the scene's geometry, read once for any number of clips; the clips of
/// another file when it is bound to one (`Gltf_file`'s constructor of a body and its clips).
struct Loaded_file {
  tinygltf::Model model{};
  Rig rig{};
  std::optional<Bound_clips> clips{};
};

/// The model whose animations are the file's clips.
inline const tinygltf::Model& clip_model(const Loaded_file& file) {
  return file.clips ? *file.clips->model : file.model;
}

/// The clip `wanted` names among the file's clips (none for a file without animation), moving
/// the file's nodes, with its index; errors in another file's clips name that file.
inline std::optional<std::pair<std::size_t, Clip>> clip_of(const Loaded_file& file, const std::string& wanted) {
  try {
    const std::optional<std::size_t> index = select_clip(clip_model(file), wanted);
    if (!index) return std::nullopt;
    Clip clip = read_clip(clip_model(file), *index);
    if (file.clips) clip = bound_clip(std::move(clip), file.model, *file.clips);
    return std::pair{*index, std::move(clip)};
  } catch (const invalid_input& e) {
    if (!file.clips) throw;
    throw e.located({.file = file.clips->file});
  }
}

/// What a file without a mesh is told: every command reads a clip on some body.
inline constexpr const char* no_mesh_hint =
    "no mesh: play it on a body with --body FILE (the default scene has no triangle, and no clip moves a "
    "skeleton of bones to make a body from)";

/// Reads the scene of a parsed file; a scene without triangle gets the body made from its
/// skeleton (`add_skeleton_body`), or is refused with `no_mesh_hint`.
inline Loaded_file load_file(tinygltf::Model model) {
  Loaded_file file{.model = std::move(model)};
  check_extensions(file.model);
  file.rig = read_rig(file.model);
  if (file.rig.geometry.triangles.empty() && add_skeleton_body(file.model)) file.rig = read_rig(file.model);
  if (file.rig.geometry.triangles.empty()) throw invalid_input(no_mesh_hint);
  return file;
}

/// Samples the clip `options` names: every vertex, or the scene's vertices `vertices` when not
/// null (then `num_vertices` is their number, and the triangles are left out).
inline io::Sampled_gltf sample(const Loaded_file& file, const io::Gltf_read_options& options,
                               const std::vector<std::uint32_t>* vertices = nullptr) {
  check_options(options);
  const Rig& rig = file.rig;
  io::Sampled_gltf sampled;
  std::optional<std::pair<std::size_t, Clip>> chosen = clip_of(file, options.clip);
  const Clip* clip = chosen ? &chosen->second : nullptr;
  auto& report = sampled.report;
  report.frames = clip ? frame_count(clip->start, clip->end, options.fps) : 1;
  if (clip) {
    report.clip = clip->name;
    report.clip_index = chosen->first;
    report.start = clip->start;
    report.end = clip->end;
    std::tie(report.animated_joints, report.joints) = animated_joints(file.model, *clip);
  }
  report.skeleton_body = has_skeleton_body(file.model);
  report.skipped = rig.geometry.skipped;
  std::optional<Vertex_selection> selection;
  if (vertices) selection = select_vertices(rig.geometry, *vertices);
  sampled.num_vertices = vertices ? vertices->size() : rig.geometry.vertices;
  if (report.frames > max_coordinates / (3 * std::max<std::size_t>(sampled.num_vertices, 1)))
    throw invalid_input(std::to_string(report.frames) + " frames of " + std::to_string(sampled.num_vertices) +
                        " vertices exceed the " + std::to_string(max_coordinates) + " coordinates deformseg samples");
  sampled.positions.resize(report.frames * 3 * sampled.num_vertices);
  sample_frames(rig, clip, options.fps, report.frames, options.threads, selection ? &*selection : nullptr,
                sampled.positions);
  if (!vertices) sampled.triangles = rig.geometry.triangles;
  return sampled;
}

/// The clip `options` names (none for a file without animation) and its frame count at `options.fps`.
inline std::pair<std::optional<Clip>, std::size_t> clip_and_frames(const Loaded_file& file,
                                                                   const io::Gltf_read_options& options) {
  check_options(options);
  std::optional<std::pair<std::size_t, Clip>> chosen = clip_of(file, options.clip);
  if (!chosen) return {std::nullopt, 1};
  const std::size_t frames = frame_count(chosen->second.start, chosen->second.end, options.fps);
  return {std::move(chosen->second), frames};
}

/// The connectivity every clip of the file shares: the scene's vertices welded by what the file
/// fixes (see `gltf_welding.h`) when `options.weld`, then the triangles repaired once; the skin
/// weights' repairs counted (or the first refused).
inline io::Repaired_triangles repair_scene(const Rig& rig, const io::Repair_options& options) {
  const Weight_defects& weights = rig.geometry.weights;
  if (options.defects == io::Defect_policy::refuse && !weights.first.empty()) throw invalid_input(weights.first);
  const std::span<const std::array<std::uint32_t, 3>> triangles(rig.geometry.triangles);
  check_repair_input(std::span<const double>(), rig.geometry.vertices, triangles, options);
  std::size_t skin_joints = 0;
  for (const auto& joints : rig.skins.joints) skin_joints += joints.size();
  std::vector<std::uint32_t> welded;
  if (options.weld) welded = weld_scene_vertices(rig.geometry, skin_joints, options.weld_tolerance);
  io::Repaired_triangles repaired =
      repair_welded(triangles, welding_of(std::move(welded), rig.geometry.vertices), options.defects);
  repaired.report.dropped_influences = weights.dropped_influences;
  repaired.report.unweighted_vertices = weights.unweighted_vertices;
  return repaired;
}

inline io::Gltf_mesh_info mesh_info(const tinygltf::Model& model, std::size_t mesh) {
  io::Gltf_mesh_info info{.name = model.meshes[mesh].name};
  for (std::size_t p = 0; p < model.meshes[mesh].primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = model.meshes[mesh].primitives[p];
    const std::string name = primitive_name(model, mesh, p);
    io::Gltf_primitive_info pi{.mode = mode_name(primitive_mode(primitive)), .morph_targets = primitive.targets.size()};
    if (attribute(primitive, "POSITION") >= 0)
      pi.vertices = accessor_count(model, attribute(primitive, "POSITION"), name);
    if (primitive_mode(primitive) == TINYGLTF_MODE_TRIANGLES)
      pi.triangles = (primitive.indices >= 0 ? accessor_count(model, primitive.indices, name) : pi.vertices) / 3;
    info.primitives.push_back(pi);
  }
  return info;
}

/// What a parsed model holds, its clips' frames counted at `fps` (`io::gltf_contents`).
inline io::Gltf_contents contents(const tinygltf::Model& model, double fps) {
  check_options({.fps = fps});
  check_extensions(model);
  io::Gltf_contents result;
  result.nodes = model.nodes.size();
  result.skeleton_body = has_skeleton_body(model);
  for (std::size_t a = 0; a < model.animations.size(); ++a) {
    const Clip clip = read_clip(model, a);
    result.clips.push_back({.name = clip.name, .start = clip.start, .end = clip.end,
                            .duration = clip.end - clip.start, .frames = frame_count(clip.start, clip.end, fps),
                            .channels = clip.channels.size()});
  }
  for (const tinygltf::Skin& skin : model.skins)
    result.skins.push_back({.name = skin.name, .joints = skin.joints.size()});
  for (std::size_t m = 0; m < model.meshes.size(); ++m) result.meshes.push_back(mesh_info(model, m));
  const Node_forest forest = node_forest(model);
  for (const auto [node, mesh] : mesh_instances(model, forest)) {
    io::Gltf_mesh_info& info = result.meshes[mesh];
    ++info.instances;
    info.skinned = info.skinned || model.nodes[node].skin >= 0;
    for (std::size_t p = 0; p < info.primitives.size(); ++p)
      if (skip_reason(model.meshes[mesh].primitives[p]).empty()) {
        result.vertices += info.primitives[p].vertices;
        result.triangles += info.primitives[p].triangles;
      }
  }
  return result;
}

/// What a file holds, a body made from its skeleton when it has no triangle (as `Gltf_file`
/// reads it); a file of neither is listed as it is (its clips may play on another body).
inline io::Gltf_contents contents(const std::filesystem::path& path, double fps) {
  check_options({.fps = fps});
  tinygltf::Model model = load_model(path);
  io::Gltf_contents result = contents(model, fps);
  if (result.triangles == 0 && add_skeleton_body(model)) result = contents(model, fps);
  return result;
}

}  // namespace deformseg::io::internal::gltf

namespace deformseg::io {

class Gltf_file;

/// @brief One clip of a `Gltf_file` sampled a frame at a time (`Gltf_file::frame_sampler`), in
/// the vertex order of `Sampled_gltf`, before any repair: every vertex, or the vertices asked.
class Gltf_frame_sampler {
public:
  /// @brief The number of frames T of the clip at the frame rate asked (1 without animation).
  std::size_t num_frames() const noexcept { return frames_; }
  /// @brief The number of vertices V of a frame: the scene's before any repair, or the number of
  /// vertices asked.
  std::size_t num_vertices() const noexcept {
    return selection_ ? selection_->input.size() : rig_->geometry.vertices;
  }
  /// @brief The clip's name as in the file (maybe empty), as `Gltf_read_report::clip`; empty
  /// for a file without animation.
  std::string clip_name() const { return clip_ ? clip_->name : std::string(); }
  /// @brief Writes frame `t`'s `3V` coordinates to `out`.
  /// @pre `out` holds `3V` values and `t < num_frames()`; otherwise throws `invalid_input`.
  /// @throws invalid_input naming the file, the frame and the smallest vertex (numbered as in
  /// `Sampled_gltf`) of a non-finite position.
  /// @par Complexity O(N + J + V I), as one frame of `Gltf_file::sample`, V the vertices sampled.
  void sample_frame(std::size_t t, std::span<double> out) {
    if (t >= frames_ || out.size() != 3 * num_vertices())
      throw invalid_input("Gltf_frame_sampler: no frame " + std::to_string(t) + " of " + std::to_string(out.size()) +
                              " coordinates in a clip of " + std::to_string(frames_) + " frames",
                          {.file = path_.string(), .frame = t});
    try {
      internal::gltf::pose_frame(*rig_, clip_ ? &*clip_ : nullptr, fps_, frames_, t,
                                 selection_ ? &*selection_ : nullptr, scratch_, out.data());
    } catch (const invalid_input& e) {
      throw e.located({.file = path_.string()});
    }
  }

private:
  friend class Gltf_file;
  Gltf_frame_sampler(std::filesystem::path path, const internal::gltf::Rig& rig,
                     std::optional<internal::gltf::Clip> clip, std::size_t frames, double fps,
                     std::optional<internal::gltf::Vertex_selection> selection)
      : path_(std::move(path)), rig_(&rig), clip_(std::move(clip)), frames_(frames), fps_(fps),
        selection_(std::move(selection)) {}

  std::filesystem::path path_;
  const internal::gltf::Rig* rig_;
  std::optional<internal::gltf::Clip> clip_;
  std::size_t frames_;
  double fps_;
  std::optional<internal::gltf::Vertex_selection> selection_;
  internal::gltf::Pose_scratch scratch_{};
};

/// @brief A glTF 2.0 file (or an FBX or Collada file, written into glTF's structures by
/// `fbx_collada_model`) parsed once, to sample any number of its clips: parsing dominates the
/// reading of a character of a few thousand vertices, so reading many clips of one file through
/// a `Gltf_file` is many times faster than calling `sample_gltf` for each.
///
/// The scene is the default scene (`scene`), else scene 0, else every root node. Each
/// TRIANGLES primitive (indexed or not) of each mesh node instance adds its vertices; other
/// modes, and primitives without POSITION, are skipped and listed in the report's `skipped`. A
/// rigid mesh moves with its node's world transform; a skinned mesh (a node with `skin`,
/// primitives with JOINTS_0/WEIGHTS_0, and JOINTS_1/WEIGHTS_1 when present) by linear blend
/// skinning with joint matrices world(joint) x inverseBindMatrix (identity when absent), its own
/// node's transform ignored as the specification says. Weights are divided by their sum; a
/// vertex whose weights are all zero stays rigid to its mesh node. Morph targets (POSITION
/// deltas) are added before skinning, with the weights of the clip's `weights` channel, else the
/// node's `weights`, else the mesh's, else 0.
///
/// Frames are at t = start + k / fps while t <= end, plus the end itself when it lies more than
/// a thousandth of a frame off that grid; start and end are the smallest and largest key time
/// over the clip's channels (a clip of 0 s gives 1 frame). Samplers hold their first and last
/// values outside their keys. A file without animation gives its rest pose, 1 frame.
///
/// A file whose scene has no triangle (a BVH clip, an animation-only export) is read on a body
/// made from its skeleton, added to the model as a skinned mesh (`Gltf_read_report::skeleton_body`
/// and `Gltf_contents::skeleton_body` say so): the skeleton is every node a clip moves, with the
/// nodes below them; a closed tube of 8 sides runs along every bone (from a joint's rest origin to
/// a child joint's), of radius an eighth of the bone's length, 58 vertices and 112 triangles per
/// bone, in the order of the joints (parents first). The middle half of a tube moves rigidly with
/// its joint; its rings within a quarter of the bone's length of either end blend linearly
/// towards the joint at that end (the parent's joint at the start, the child joint at the end),
/// by a share that would reach a half at the end itself (the rings end 5% short of it, at a share
/// of 0.4; a cone closes the tube), as skin bends at a joint under linear blend skinning. The body
/// comes from the rest pose alone, so that every clip of one skeleton plays on the same vertices.
/// It is no skin: the tubes overlap at the joints, and nothing keeps their volume. A file of
/// neither triangles nor bones is refused: "no mesh: play it on a body with --body FILE".
class Gltf_file {
public:
  /// @brief Parses `path` and reads the scene's geometry (not its clips).
  /// @param path a `.gltf` (JSON, with external or data-URI buffers) or `.glb` file, told apart
  /// by content; or, when deformseg was built with Assimp (`DEFORMSEG_HAS_ASSIMP`), an FBX or
  /// Collada file (`.fbx`, `.dae`, told by the extension), read as `fbx_collada_model` writes it,
  /// or a BVH file (`.bvh`), read as `bvh_model` writes it.
  /// @throws invalid_input naming the file (and the mesh, accessor or node) for: a file that
  /// does not exist or that tinygltf cannot parse (its message); an FBX or Collada file that
  /// `fbx_collada_model` refuses, or without Assimp; compressed geometry that does not decode, or
  /// whose codec deformseg was built without (`DEFORMSEG_HAS_DRACO`, `DEFORMSEG_HAS_MESHOPT`);
  /// another required extension deformseg does not know (KHR_mesh_quantization is read); a
  /// scene without triangle and without a bone to make a body of ("no mesh: play it on a body
  /// with --body FILE"); an accessor or buffer view outside its buffer, a count that disagrees,
  /// an index out of range; a node hierarchy that is not a forest; more than 2^26 vertices.
  /// @par Complexity O(file size).
  explicit Gltf_file(const std::filesystem::path& path) : path_(path), file_(load(path)) {}

  /// @brief Reads the scene of a model parsed or built in memory (by tinygltf, or by
  /// `fbx_collada_model`), as the constructor from a path reads a file's.
  /// @param name the name errors give as the file's.
  /// @param model the model, kept by the `Gltf_file`.
  /// @throws invalid_input naming `name`, for the same malformed scenes as the constructor from a path.
  /// @par Complexity O(size of the model).
  Gltf_file(std::filesystem::path name, tinygltf::Model model) : path_(std::move(name)) {
    try {
      file_ = internal::gltf::load_file(std::move(model));
    } catch (const invalid_input& e) {
      throw e.located({.file = path_.string()});
    }
  }

  /// @brief The clips of the file `clips` played on the body of the file `body`, as engines bind
  /// an animation to a model: each channel of a clip moves the body's node of the same name as
  /// the node it moves in `clips` (joints, and any node), channels of nodes the body has not are
  /// left out; a name the body has not matches the body's one node of that name without its
  /// namespace ("mixamorig:Hips" and "Hips"). A body node given by a matrix (FBX and Collada bodies
  /// give one to every node their own clips leave still) is held as the translation, rotation and
  /// scale the matrix decomposes into when a clip moves it, as engines do.
  /// `clips` may hold no mesh (an animation-only export) or a body of its own (the same
  /// rig's clips on another character); both files glTF, FBX or Collada. The geometry, skins and
  /// rest pose are the body's; `clip_names` and the clips read are `clips`'s, and
  /// `Gltf_read_report::animated_joints` says how many of the body's joints a clip moves. The
  /// clips' values are carried into the body's frames (`internal::gltf::frame_changes`): their
  /// translations scaled from the clips' units to the body's, and the clips' skeleton root, with
  /// its root motion, placed in the body's world where it stood in its own (another up axis,
  /// other nodes above it); where both files share their frames, the values are kept to the bit.
  /// @throws invalid_input naming the file, as the constructor from a path for `body`, as
  /// tinygltf for `clips`; and, when a clip is read, naming `clips` (and mentioning `body`) for a
  /// clip that does not exist or is malformed, or that moves no vertex of the body (it animates
  /// another skeleton's nodes: the message names a few of them and of the body's joints).
  /// @par Complexity O(size of both files).
  /// @par Example
  /// @snippet read_gltf.cpp bind
  Gltf_file(const std::filesystem::path& body, const std::filesystem::path& clips) : Gltf_file(body) {
    try {
      auto model = std::make_shared<const tinygltf::Model>(internal::gltf::load_model(clips));
      internal::gltf::check_extensions(*model);
      auto body_node = internal::gltf::body_nodes_by_name(file_.model, *model);
      auto change = internal::gltf::frame_changes(file_.model, *model, body_node);
      internal::gltf::make_animatable(file_.model, file_.rig.rest, *model, body_node);
      file_.clips = internal::gltf::Bound_clips{.model = model, .file = clips.string(), .body_file = body.string(),
                                                .body_node = std::move(body_node), .change = std::move(change)};
    } catch (const invalid_input& e) {
      throw e.located({.file = clips.string()});
    }
  }

  /// @brief The file's path as given.
  const std::filesystem::path& path() const noexcept { return path_; }
  /// @brief The names of the file's clips (glTF animations), in the file's order (maybe empty).
  std::vector<std::string> clip_names() const {
    std::vector<std::string> names;
    for (const auto& animation : internal::gltf::clip_model(file_).animations) names.push_back(animation.name);
    return names;
  }
  /// @brief The number of vertices V a sampled clip has, before any repair.
  std::size_t num_vertices() const noexcept { return file_.rig.geometry.vertices; }

  /// @brief What the file holds, as `gltf_contents(path(), fps)` gives it, from this parse (of a
  /// body played with another file's clips: the body's own): its clips with their frame counts
  /// at `fps`, skins, meshes, vertices and triangles.
  /// @pre `fps > 0`.
  /// @throws invalid_input naming the file, as `gltf_contents` (a malformed clip).
  /// @par Complexity O(size of the model).
  Gltf_contents contents(double fps = 30) const {
    try {
      return internal::gltf::contents(file_.model, fps);
    } catch (const invalid_input& e) {
      throw e.located({.file = path_.string()});
    }
  }

  /// @brief Samples one clip, without repair: the vertices in the file's order (see `Sampled_gltf`).
  /// @param options `clip` (default: the first), `fps` (30), `threads` (0: all); `repair` is not
  /// used here.
  /// @return the positions (`T x 3V`), V, the triangles and the report (`repair` left empty).
  /// @pre `options.fps > 0`, `options.threads` from 0 to `max_threads`.
  /// @throws invalid_input naming the file (and the animation, channel, accessor or frame) for a
  /// clip that does not exist (the message lists the file's clips), a malformed sampler, a
  /// non-finite position, more than 10^6 frames or 2^29 coordinates.
  /// @par Complexity O(T (N + J + V I)) for N nodes, J joints, V vertices and I influences per
  /// skinned vertex (4 or 8), the frames shared among the threads.
  Sampled_gltf sample(const Gltf_read_options& options = {}) const {
    try {
      return internal::gltf::sample(file_, options);
    } catch (const invalid_input& e) {
      throw e.located({.file = path_.string()});
    }
  }

  /// @brief Samples one clip a frame at a time, as `sample` samples all of them: frame `t` of
  /// the sampler equals frame `t` of `sample(options)`'s positions, bit for bit, so that a long
  /// clip can be read in memory for one frame (see `Gltf_frame_sampler`).
  /// @param options `clip` (default: the first) and `fps` (30); the others are not used.
  /// @return a sampler that refers to this file, which must outlive it and stay where it is.
  /// @pre `options.fps > 0`.
  /// @throws invalid_input naming the file as `sample` does for a missing clip or a malformed
  /// sampler, or more than 10^6 frames.
  /// @par Complexity O(size of the clip's channels).
  Gltf_frame_sampler frame_sampler(const Gltf_read_options& options = {}) const;

  /// @brief Samples some vertices of one clip a frame at a time: vertex i of frame `t` of the
  /// sampler equals vertex `vertices[i]` of frame `t` of `sample(options)`, bit for bit; the
  /// others are not posed (the vertices that `repair` keeps, say, its `source_vertex`: about 1,100
  /// of the 4,400 of an animal of the shared library, welded along its seams).
  /// @param options `clip` (default: the first) and `fps` (30); the others are not used.
  /// @param vertices vertices numbered as in `Sampled_gltf`, in any order, repeats allowed.
  /// @return a sampler that refers to this file, which must outlive it and stay where it is.
  /// @pre every vertex is below `num_vertices()`; `options.fps > 0`.
  /// @throws invalid_input naming the file as the overload without vertices, or for a vertex
  /// outside the scene.
  /// @par Complexity O(size of the clip's channels + V log V) for V vertices.
  Gltf_frame_sampler frame_sampler(const Gltf_read_options& options, std::span<const std::uint32_t> vertices) const;

  /// @brief The connectivity every clip of the file shares, repaired by `options` and decided
  /// from the file alone, whatever the clip: what `read` gives every clip.
  ///
  /// With `options.weld`, two vertices are welded when they coincide in every frame of every clip
  /// by what the file fixes: their rest positions (POSITION, in their mesh's space) are within
  /// `weld_tolerance` times the diagonal of the bounding box of all rest positions; they have the
  /// same influences (the same joints of the same skins, weights after normalisation within
  /// `weld_tolerance`; or, for a vertex of an unskinned primitive or of no weight, the same node);
  /// and the same morph target deltas (within the same distance) on the same node, unless neither
  /// has any. Vertices that coincide with a welded one join it (transitive closure). The triangles
  /// are then repaired once, as `repair_triangles` steps 2 to 4 do (or the first defect refused).
  /// Two vertices that coincide in one clip only (a hand resting on a hip) are not welded.
  /// @param options `weld` (the glTF default: true), `weld_tolerance` (1e-6), `defects` (repair).
  /// @return as `repair_triangles`: the triangles over the output vertices, the source of every
  /// output vertex and triangle (input vertices in the order of `Sampled_gltf`), the counts.
  /// @pre `options.weld_tolerance` is finite and at least 0.
  /// @throws invalid_input naming the file, as `repair_triangles`.
  /// @par Complexity O(V + F log F) expected (a hash grid on the rest positions, as
  /// `repair_triangles` on frame 0).
  Repaired_triangles repair(const Repair_options& options = Gltf_read_options{}.repair) const {
    try {
      return internal::gltf::repair_scene(file_.rig, options);
    } catch (const invalid_input& e) {
      throw e.located({.file = path_.string()});
    }
  }

  /// @brief Reads one clip as an animation: `sample`, then the connectivity of
  /// `repair(options.repair)`, which every clip of the file shares, each output vertex moving as
  /// its source vertex (welding on by default). Only the source vertices are posed, each once,
  /// which gives their positions in `sample` bit for bit; a non-finite position of a vertex the
  /// repair leaves out (welded to another, or in no triangle) is not seen.
  /// @tparam Graph the connectivity type (default `Surface_mesh`).
  /// @tparam Coordinate the stored coordinate type (default `double`).
  /// @param options `clip` (default: the first), `fps` (30), `repair` (weld, defects repaired),
  /// `threads` (0: all).
  /// @param report where to store the clip read, its times and frames, the primitives skipped
  /// and what the repair changed, when not null.
  /// @pre as `sample` and `repair`.
  /// @throws invalid_input naming the file, as `sample` and `repair`.
  /// @par Complexity that of `sample` for the V' source vertices alone, plus the repair's
  /// O(V + F log F).
  template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double>
  mesh::Deforming_mesh<Graph, Coordinate> read(const Gltf_read_options& options = {},
                                         Gltf_read_report* report = nullptr) const {
    return read<Graph, Coordinate>(repair(options.repair), options, report);
  }

  /// @brief Reads one clip as `read(options, report)` does, with the file's connectivity repaired
  /// beforehand: the clips of one file share it, so that reading several repairs once.
  /// @param repaired `repair(options.repair)` of this file.
  /// @param options `clip` (default: the first), `fps` (30), `threads` (0: all); `repair` is not
  /// used (`repaired` is).
  /// @param report as `read`'s, its `repair` the counts of `repaired`; when not null.
  /// @pre as `read`; `repaired` is this file's repair (another file's would give its triangles
  /// over these vertices; a source vertex outside this scene is refused).
  /// @throws invalid_input naming the file, as `sample`.
  /// @par Complexity that of `sample` for the V' source vertices alone, plus O(V' + F) to build
  /// the animation's connectivity.
  /// @par Example
  /// @include read_gltf.cpp
  template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double>
  mesh::Deforming_mesh<Graph, Coordinate> read(const Repaired_triangles& repaired, const Gltf_read_options& options,
                                         Gltf_read_report* report = nullptr) const {
    Sampled_gltf sampled;
    try {
      sampled = internal::gltf::sample(file_, options, &repaired.source_vertex);
    } catch (const invalid_input& e) {
      throw e.located({.file = path_.string()});
    }
    try {
      mesh::Coordinate_buffer<Coordinate> positions;
      if constexpr (std::is_same_v<Coordinate, double>) positions = std::move(sampled.positions);
      else positions.assign(sampled.positions.begin(), sampled.positions.end());
      mesh::Deforming_mesh<Graph, Coordinate> animation =
          internal::animation_of<Graph, Coordinate>(repaired, std::move(positions), &sampled.report.repair);
      animation.set_frames_per_second(options.fps);
      if (report) *report = std::move(sampled.report);
      return animation;
    } catch (const invalid_input& e) {
      throw e.located({.file = path_.string()});
    }
  }

private:
  static internal::gltf::Loaded_file load(const std::filesystem::path& path) {
    try {
      return internal::gltf::load_file(internal::gltf::load_model(path));
    } catch (const invalid_input& e) {
      throw e.located({.file = path.string()});
    }
  }

  std::filesystem::path path_;
  internal::gltf::Loaded_file file_;
};

inline Gltf_frame_sampler Gltf_file::frame_sampler(const Gltf_read_options& options) const {
  try {
    auto [clip, frames] = internal::gltf::clip_and_frames(file_, options);
    return Gltf_frame_sampler(path_, file_.rig, std::move(clip), frames, options.fps, std::nullopt);
  } catch (const invalid_input& e) {
    throw e.located({.file = path_.string()});
  }
}

inline Gltf_frame_sampler Gltf_file::frame_sampler(const Gltf_read_options& options,
                                                   std::span<const std::uint32_t> vertices) const {
  try {
    auto [clip, frames] = internal::gltf::clip_and_frames(file_, options);
    return Gltf_frame_sampler(path_, file_.rig, std::move(clip), frames, options.fps,
                              internal::gltf::select_vertices(file_.rig.geometry, vertices));
  } catch (const invalid_input& e) {
    throw e.located({.file = path_.string()});
  }
}

/// @brief The rule of the readers that take any animation (`read_animation`, the tool's commands,
/// Python's `read_animation`) for a glTF file and the clip asked: a clip must be named
/// ("FILE.glb#CLIP", or a clip option) when the file holds more than one, rather than the first
/// read unsaid; a file of one clip gives it, a file without animation its rest pose.
/// @param file the file to read.
/// @param clip the clip asked (a name or an index); empty for none.
/// @throws invalid_input naming the file when `clip` is empty and the file holds two clips or
/// more: the message lists them.
/// @par Complexity O(clips).
/// @par Example
/// @include sample_gltf.cpp
inline void require_clip_choice(const Gltf_file& file, const std::string& clip) {
  const std::vector<std::string> names = file.clip_names();
  if (!clip.empty() || names.size() < 2) return;
  std::string list;
  for (const std::string& name : names) list.append(list.empty() ? "" : ", ").append("'" + name + "'");
  throw invalid_input("the file holds " + std::to_string(names.size()) + " clips: name the one to read, as in \"" +
                          file.path().filename().string() + "#" + names.front() + "\" or by the clip option (the " +
                          "clips: " + list + ")",
                      {.file = file.path().string()});
}

/// @brief Samples one clip of a glTF 2.0 file into positions and triangles, without repair:
/// `Gltf_file(path).sample(options)` (see `Gltf_file` for what is read and how).
///
/// @param path a `.gltf` or `.glb` file.
/// @param options `clip` (default: the first), `fps` (30), `threads` (0: all); `repair` is not
/// used here.
/// @return the positions (`T x 3V`, vertices in the file's order: see `Sampled_gltf`), V, the
/// triangles and the report (`repair` left empty).
/// @pre `options.fps > 0`, `options.threads` from 0 to `max_threads`.
/// @throws invalid_input naming the file, as `Gltf_file` and `Gltf_file::sample`.
/// @par Complexity O(file size + T (N + J + V I)): see `Gltf_file::sample`.
/// @sa read_gltf, Gltf_file
/// @par Example
/// @include sample_gltf.cpp
inline Sampled_gltf sample_gltf(const std::filesystem::path& path, const Gltf_read_options& options = {}) {
  return Gltf_file(path).sample(options);
}

/// @brief Reads one clip of a glTF 2.0 file as an animation: `sample_gltf`, then the connectivity
/// every clip of the file shares (`Gltf_file::repair` with `options.repair`, welding on by
/// default); that is, `Gltf_file(path).read<Graph, Coordinate>(options, report)`.
///
/// @tparam Graph the connectivity type (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`).
/// @param path a `.gltf` or `.glb` file.
/// @param options `clip` (default: the first), `fps` (30), `repair` (weld, defects repaired),
/// `threads` (0: all).
/// @param report where to store the clip read, its times and frames, the primitives skipped and
/// what the repair changed, when not null.
/// @pre as `sample_gltf`.
/// @throws invalid_input naming the file, as `sample_gltf` and `Gltf_file::repair`.
/// @par Complexity that of `sample_gltf`, plus the repair's O(V + F log F) and a copy of the positions.
/// @sa sample_gltf, gltf_contents, Gltf_file, Gltf_file::repair
template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double>
mesh::Deforming_mesh<Graph, Coordinate> read_gltf(const std::filesystem::path& path,
                                                  const Gltf_read_options& options = {},
                                                  Gltf_read_report* report = nullptr) {
  return Gltf_file(path).read<Graph, Coordinate>(options, report);
}

/// @brief What a glTF 2.0 file holds: its clips (with their times and frame counts at `fps`),
/// skins, meshes (primitives, instances), and the vertices and triangles `sample_gltf` reads.
///
/// @param path a `.gltf` or `.glb` file.
/// @param fps the frame rate the clips' frame counts are given at. Default 30.
/// @pre `fps > 0`.
/// @throws invalid_input naming the file, for the same malformed files as `sample_gltf`.
/// @par Complexity O(file size).
inline Gltf_contents gltf_contents(const std::filesystem::path& path, double fps = 30) {
  try {
    return internal::gltf::contents(path, fps);
  } catch (const invalid_input& e) {
    throw e.located({.file = path.string()});
  }
}

}  // namespace deformseg::io
