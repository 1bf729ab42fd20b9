// The parsed glTF file behind `Gltf_file` (io/gltf.h): tinygltf's loading of a file (compressed
// geometry decoded first, FBX, Collada and BVH files written into glTF's structures), the scene
// read once, and the sampling and contents of its clips. The library compiles it (src/io/); the
// readers' tests and fuzz harnesses include it for the parts they exercise alone.
#pragma once

#include <deformseg/io/config.h>

#if !DEFORMSEG_HAS_GLTF
#error "deformseg/io/internal/gltf_file.h needs a deformseg built with tinygltf (DEFORMSEG_HAS_GLTF)"
#endif

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/gltf_animation.h>
#include <deformseg/io/internal/gltf_binding.h>
#include <deformseg/io/internal/gltf_decompression.h>
#include <deformseg/io/internal/gltf_mesh.h>
#include <deformseg/io/internal/gltf_welding.h>
#include <deformseg/io/internal/skeleton_body.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/threads.h>

// FBX, Collada and BVH files are read when deformseg was built with Assimp.
#if DEFORMSEG_HAS_ASSIMP
#include <deformseg/io/bvh.h>
#include <deformseg/io/fbx_collada.h>
#endif

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
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
#include <utility>
#include <vector>

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
                        "libassimp-dev, then build deformseg again)");
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
    const auto size = unsigned(file.size());
    loaded = is_glb(file) ? loader.LoadBinaryFromMemory(&model, &err, &warn, file.data(), size, base_dir)
                          : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(file.data()),
                                                       size, base_dir);
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
