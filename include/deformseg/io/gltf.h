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
///
/// The header declares: deformseg's io library parses and samples (src/io/gltf.cpp), so that a
/// program that reads glTF compiles no parser. Available when deformseg was built with tinygltf
/// (`DEFORMSEG_HAS_GLTF` in `deformseg/io/config.h`).
#pragma once

#include <deformseg/io/config.h>

#if !DEFORMSEG_HAS_GLTF
#error "deformseg/io/gltf.h needs a deformseg built with tinygltf (Debian: libtinygltf-dev nlohmann-json3-dev)"
#endif

#include <deformseg/exceptions.h>
#include <deformseg/io/character_files.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// tinygltf's model, which a `Gltf_file` may be made from and the FBX, Collada and BVH readers give:
// declared only, so that this header needs no parser (who builds one includes <tiny_gltf.h>).
namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace deformseg::io::internal::gltf {
struct Loaded_file;
}  // namespace deformseg::io::internal::gltf

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

namespace deformseg::io {

class Gltf_file;

/// @brief One clip of a `Gltf_file` sampled a frame at a time (`Gltf_file::frame_sampler`), in
/// the vertex order of `Sampled_gltf`, before any repair: every vertex, or the vertices asked.
///
/// Movable, not copyable: it holds the clip and the scratch of its poses (a private implementation,
/// compiled in deformseg's io library).
class Gltf_frame_sampler {
public:
  /// @brief Moves a sampler (the one moved from may only be destroyed or assigned to).
  Gltf_frame_sampler(Gltf_frame_sampler&&) noexcept;
  /// @brief Moves a sampler into this one.
  Gltf_frame_sampler& operator=(Gltf_frame_sampler&&) noexcept;
  /// @brief Frees the clip and the scratch.
  ~Gltf_frame_sampler();

  /// @brief The number of frames T of the clip at the frame rate asked (1 without animation).
  std::size_t num_frames() const noexcept;
  /// @brief The number of vertices V of a frame: the scene's before any repair, or the number of
  /// vertices asked.
  std::size_t num_vertices() const noexcept;
  /// @brief The clip's name as in the file (maybe empty), as `Gltf_read_report::clip`; empty
  /// for a file without animation.
  std::string clip_name() const;
  /// @brief Writes frame `t`'s `3V` coordinates to `out`.
  /// @pre `out` holds `3V` values and `t < num_frames()`; otherwise throws `invalid_input`.
  /// @throws invalid_input naming the file, the frame and the smallest vertex (numbered as in
  /// `Sampled_gltf`) of a non-finite position.
  /// @par Complexity O(N + J + V I), as one frame of `Gltf_file::sample`, V the vertices sampled.
  void sample_frame(std::size_t t, std::span<double> out);

private:
  friend class Gltf_file;
  struct Impl;  // the clip, the scene it poses and the scratch of its poses (src/io/gltf_frame_sampler.cpp)
  explicit Gltf_frame_sampler(std::unique_ptr<Impl> impl) noexcept;

  std::unique_ptr<Impl> impl_;
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
///
/// Movable, not copyable: the parsed file is held by a private implementation (compiled in
/// deformseg's io library), which stays where it is when the `Gltf_file` moves, so that its
/// samplers and frame sources stay valid.
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
  explicit Gltf_file(const std::filesystem::path& path);

  /// @brief Reads the scene of a model parsed or built in memory (by tinygltf, or by
  /// `fbx_collada_model`), as the constructor from a path reads a file's.
  /// @param name the name errors give as the file's.
  /// @param model the model, kept by the `Gltf_file` (a caller includes <tiny_gltf.h>, which
  /// defines it).
  /// @throws invalid_input naming `name`, for the same malformed scenes as the constructor from a path.
  /// @par Complexity O(size of the model).
  Gltf_file(std::filesystem::path name, tinygltf::Model model);

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
  Gltf_file(const std::filesystem::path& body, const std::filesystem::path& clips);

  /// @brief Moves a file (the one moved from may only be destroyed or assigned to); the parsed
  /// file does not move, so that the samplers and frame sources of the file stay valid.
  Gltf_file(Gltf_file&&) noexcept;
  /// @brief Moves a file into this one.
  Gltf_file& operator=(Gltf_file&&) noexcept;
  /// @brief Frees the parsed file (its samplers must be gone).
  ~Gltf_file();

  /// @brief The file's path as given.
  const std::filesystem::path& path() const noexcept { return path_; }
  /// @brief The names of the file's clips (glTF animations), in the file's order (maybe empty).
  std::vector<std::string> clip_names() const;
  /// @brief The number of vertices V a sampled clip has, before any repair.
  std::size_t num_vertices() const noexcept;

  /// @brief What the file holds, as `gltf_contents(path(), fps)` gives it, from this parse (of a
  /// body played with another file's clips: the body's own): its clips with their frame counts
  /// at `fps`, skins, meshes, vertices and triangles.
  /// @pre `fps > 0`.
  /// @throws invalid_input naming the file, as `gltf_contents` (a malformed clip).
  /// @par Complexity O(size of the model).
  Gltf_contents contents(double fps = 30) const;


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
  Sampled_gltf sample(const Gltf_read_options& options = {}) const;

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
  Repaired_triangles repair(const Repair_options& options = Gltf_read_options{}.repair) const;

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
                                               Gltf_read_report* report = nullptr) const;

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
                                               Gltf_read_report* report = nullptr) const;

private:
  // Samples the source vertices of `repaired` (`sample` of `options` for those vertices alone), as
  // `read` needs them: compiled once in the library, whatever the mesh and coordinate types.
  Sampled_gltf sample_sources(const Repaired_triangles& repaired, const Gltf_read_options& options) const;

  std::filesystem::path path_;
  std::unique_ptr<internal::gltf::Loaded_file> file_;
};

// Member templates defined outside the class, so not inline: a program on the default types calls
// the library's instances (declared below) rather than compiling its own.
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> Gltf_file::read(const Gltf_read_options& options,
                                                        Gltf_read_report* report) const {
  return read<Graph, Coordinate>(repair(options.repair), options, report);
}

template <mesh::FaceGraph Graph, std::floating_point Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> Gltf_file::read(const Repaired_triangles& repaired,
                                                        const Gltf_read_options& options,
                                                        Gltf_read_report* report) const {
  Sampled_gltf sampled = sample_sources(repaired, options);
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
void require_clip_choice(const Gltf_file& file, const std::string& clip);

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
Sampled_gltf sample_gltf(const std::filesystem::path& path, const Gltf_read_options& options = {});

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
Gltf_contents gltf_contents(const std::filesystem::path& path, double fps = 30);

// The instances of the default types, compiled in deformseg's io library (src/io/gltf.cpp).
/// @cond
extern template mesh::Deforming_mesh<mesh::Surface_mesh, double>
Gltf_file::read<mesh::Surface_mesh, double>(const Gltf_read_options&, Gltf_read_report*) const;
extern template mesh::Deforming_mesh<mesh::Surface_mesh, double>
Gltf_file::read<mesh::Surface_mesh, double>(const Repaired_triangles&, const Gltf_read_options&,
                                            Gltf_read_report*) const;
extern template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_gltf<mesh::Surface_mesh, double>(const std::filesystem::path&, const Gltf_read_options&, Gltf_read_report*);
/// @endcond

}  // namespace deformseg::io
