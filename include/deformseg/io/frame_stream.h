/// @file io/frame_stream.h
/// @brief Animations read one frame at a time (models of `signatures::FrameSource`): a point
/// cache read from its file frame by frame (`Point_cache_frame_source`), a sequence of frame
/// files read file by file (`Frame_sequence_source`), a glTF clip sampled frame by frame
/// (`Gltf_frame_source`), and `with_frame_source`, which opens any input `read_animation` reads.
///
/// Each gives the frames, the vertices and the triangles that `read_animation` gives the same input
/// (the triangles as a `Deforming_mesh<Surface_mesh>` numbers them), so that what is computed from
/// the stream equals what is computed from the animation read whole; but it holds one frame at a
/// time, and can be read again from its start (`rewind`), re-reading a file's header then.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/config.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/io/read_mesh.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::io {

/// @brief How `Point_cache_frame_source` and `Frame_sequence_source` read an animation.
struct Frame_stream_options {
  /// @brief The mesh file (.obj, .off, .ply) of the connectivity: required for a point cache; for
  /// a frame sequence it replaces the first frame's faces. Default: none.
  std::optional<std::filesystem::path> topology{};
  /// @brief Fan-triangulate polygons instead of rejecting them. Default: false.
  bool triangulate = false;
  /// @brief The repair of the connectivity (`repair_triangles`). Default: defects repaired, no
  /// welding; welding, which compares every frame, is refused for a stream.
  Repair_options repair{};
  /// @brief The animation's frame rate, which these files do not give. Default 30.
  double fps = mesh::default_frames_per_second;
};

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// The triangles of `repaired` as a `Deforming_mesh<Surface_mesh>` of them numbers them (each in
/// the order of its face's halfedge cycle), built on the output vertices' `first_frame`.
template <std::floating_point T>
std::vector<std::array<std::uint32_t, 3>> animation_triangles(const io::Repaired_triangles& repaired,
                                                              mesh::Coordinate_buffer<T> first_frame) {
  const auto animation = animation_of<mesh::Surface_mesh, T>(repaired, std::move(first_frame), nullptr);
  const auto triangles = animation.triangles();
  return {triangles.begin(), triangles.end()};
}

/// The output vertices' coordinates from an input frame: output vertex i as input vertex source[i].
template <class In, class Out>
void gather_sources(std::span<const In> frame, std::span<const std::uint32_t> source, std::span<Out> out) {
  for (std::size_t i = 0; i < source.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) out[3 * i + k] = static_cast<Out>(frame[3 * std::size_t(source[i]) + k]);
}

/// Reads a connectivity mesh, its errors located at it.
inline io::Triangle_soup read_connectivity(const std::filesystem::path& path, bool triangulate,
                                           const Input_location& location) {
  try {
    return io::read_mesh(path, {.triangulate = triangulate});
  } catch (const invalid_input& e) {
    throw e.located(location);
  }
}

/// The repair of a stream's connectivity, which must not weld.
inline io::Repaired_triangles stream_repair(const io::Triangle_soup& soup, const io::Repair_options& options,
                                            const Input_location& location) {
  if (options.weld)
    throw invalid_input("a streamed animation is not welded (welding compares every frame): read it whole",
                        location);
  return repaired_topology(std::span<const double>(), soup.num_vertices(),
                           std::span<const std::array<std::uint32_t, 3>>(soup.triangles), options, location);
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief A `.pc2` or `.mdd` point cache read from its file one frame at a time, as `float` (the
/// cache's own precision), with the connectivity of a topology mesh: a `signatures::FrameSource`.
///
/// Its frames, vertices and triangles are those of `read_animation` of the same cache and
/// topology (without welding); the whole file is never in memory.
class Point_cache_frame_source {
public:
  /// @brief The coordinate type frames are read in.
  using Coordinate = float;

  /// @brief Opens `cache`, reads its header and the topology mesh `options.topology`, and repairs
  /// the connectivity as `read_animation` does.
  /// @throws invalid_input naming the file: as `read_point_cache_info` (a bad header, a size that
  /// does not match it), for a missing topology, a vertex count other than the topology's, a
  /// repair that welds, or as `read_mesh` and `repair_triangles` on the topology.
  /// @par Complexity O(V + F log F) and one frame read.
  Point_cache_frame_source(std::filesystem::path cache, const Frame_stream_options& options)
      : path_(std::move(cache)), fps_(options.fps) {
    mesh::check_frames_per_second(fps_, {}, {.file = path_.string()});
    if (!options.topology)
      throw invalid_input("a point cache needs a topology mesh (.obj, .off or .ply)", {.file = path_.string()});
    const Input_location location{.file = options.topology->string()};
    const Triangle_soup soup = internal::read_connectivity(*options.topology, options.triangulate, location);
    input_vertices_ = soup.num_vertices();
    const Repaired_triangles repaired = internal::stream_repair(soup, options.repair, location);
    sources_ = repaired.source_vertex;
    repair_ = repaired.report;
    open();
    mesh::Coordinate_buffer<float> first(3 * sources_.size());
    read_frame(std::span<float>(first));
    triangles_ = internal::animation_triangles(repaired, std::move(first));
    open();
  }

  /// @brief V, the vertices after the repair.
  std::size_t num_vertices() const noexcept { return sources_.size(); }
  /// @brief T, as the header read last says.
  std::size_t num_frames() const noexcept { return info_.num_frames; }
  /// @brief The frame rate given (`Frame_stream_options::fps`).
  double frames_per_second() const noexcept { return fps_; }
  /// @brief The repaired triangles, as `read_animation` numbers them.
  std::span<const std::array<std::uint32_t, 3>> triangles() const noexcept { return triangles_; }
  /// @brief What the repair of the topology changed, as `read_animation`'s report says it.
  const Repair_report& repair() const noexcept { return repair_; }

  /// @brief Reads the next frame's `3V` coordinates into `out`.
  /// @throws invalid_input naming the file and the frame past the last frame, for a frame the file
  /// no longer holds (changed since its header was read), or for a non-finite coordinate (and its
  /// vertex).
  /// @par Complexity O(V).
  void read_frame(std::span<float> out) {
    if (next_ >= info_.num_frames || out.size() != 3 * num_vertices())
      internal::fail_cache(path_, "no frame to read: the cache has " + std::to_string(info_.num_frames), next_);
    bytes_.resize(internal::bytes_per_point * input_vertices_);
    if (!file_.read(bytes_.data(), std::streamsize(bytes_.size())))
      internal::fail_cache(path_, "the frame cannot be read: the file is shorter than when its header was read",
                           next_);
    decoded_.resize(3 * input_vertices_);
    const bool little = info_.format == Point_cache_format::pc2;
    for (std::size_t i = 0; i < decoded_.size(); ++i) {
      const char* at = bytes_.data() + 4 * i;
      decoded_[i] =
          little ? internal::load_word<std::endian::little, float>(at) : internal::load_word<std::endian::big, float>(at);
      if (!std::isfinite(decoded_[i]))
        internal::fail_cache(path_, internal::join("vertex ", std::to_string(i / 3), " has a non-finite coordinate"),
                             next_);
    }
    internal::gather_sources(std::span<const float>(decoded_), std::span<const std::uint32_t>(sources_), out);
    ++next_;
  }

  /// @brief Reads the header again (the file may have changed) and goes back to frame 0.
  /// @throws invalid_input as the constructor for the cache's header and size.
  /// @par Complexity O(1) for PC2, O(T) for MDD.
  void rewind() { open(); }

private:
  void open() {
    info_ = read_point_cache_info(path_);
    internal::check_vertex_count(info_, input_vertices_, path_);
    file_ = std::ifstream(path_, std::ios::binary);
    file_.seekg(std::streamoff(internal::header_size(info_)));
    if (!file_) internal::fail_cache(path_, "cannot open the file: " + internal::last_system_error());
    next_ = 0;
  }

  std::filesystem::path path_;
  double fps_;
  std::size_t input_vertices_ = 0;
  std::vector<std::uint32_t> sources_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  Repair_report repair_{};
  Point_cache_info info_{};
  std::ifstream file_;
  std::vector<char> bytes_;
  std::vector<float> decoded_;
  std::size_t next_ = 0;
};

/// @brief A sequence of frame files (OBJ, OFF, PLY) read one file at a time, as `double`: a
/// `signatures::FrameSource` whose frames, vertices and triangles are those of
/// `read_frame_sequence` of the same input (without welding).
class Frame_sequence_source {
public:
  /// @brief The coordinate type frames are read in.
  using Coordinate = double;

  /// @brief Lists the frame files of `directory_or_glob` (`list_frame_files`) and reads the
  /// connectivity: `options.topology`, else the first frame's faces.
  /// @throws invalid_input naming the file: as `list_frame_files`, `read_mesh` and
  /// `repair_triangles`, or for a repair that welds.
  /// @par Complexity O(n log n) for n files, plus reading the connectivity's file.
  Frame_sequence_source(std::string directory_or_glob, const Frame_stream_options& options)
      : input_(std::move(directory_or_glob)), fps_(options.fps) {
    mesh::check_frames_per_second(fps_, {}, {.file = input_});
    files_ = list_frame_files(input_);
    const std::filesystem::path topology_file = options.topology.value_or(files_.front());
    const Input_location location{.file = topology_file.string(),
                                  .frame = options.topology ? std::nullopt : std::optional<std::size_t>(0)};
    Triangle_soup soup = internal::read_connectivity(topology_file, options.triangulate, location);
    input_vertices_ = soup.num_vertices();
    const Repaired_triangles repaired = internal::stream_repair(soup, options.repair, location);
    sources_ = repaired.source_vertex;
    repair_ = repaired.report;
    // The first frame's positions as read_frame_sequence takes them: those of its mesh file.
    if (!options.topology) first_frame_ = std::move(soup.points);
    mesh::Coordinate_buffer<double> first(3 * sources_.size());
    read_frame(std::span<double>(first));
    triangles_ = internal::animation_triangles(repaired, std::move(first));
    next_ = 0;
  }

  /// @brief V, the vertices after the repair.
  std::size_t num_vertices() const noexcept { return sources_.size(); }
  /// @brief T, the frame files listed last.
  std::size_t num_frames() const noexcept { return files_.size(); }
  /// @brief The frame rate given (`Frame_stream_options::fps`).
  double frames_per_second() const noexcept { return fps_; }
  /// @brief The repaired triangles, as `read_frame_sequence` numbers them.
  std::span<const std::array<std::uint32_t, 3>> triangles() const noexcept { return triangles_; }
  /// @brief What the repair of the connectivity changed, as `read_frame_sequence`'s report says it.
  const Repair_report& repair() const noexcept { return repair_; }

  /// @brief Reads the next frame file's `3V` coordinates into `out` (`read_mesh_points`).
  /// @throws invalid_input naming the file and the frame past the last frame, or as
  /// `read_mesh_points` (a missing or malformed file, another vertex count, a non-finite number).
  /// @par Complexity O(size of the file).
  void read_frame(std::span<double> out) {
    if (next_ >= files_.size() || out.size() != 3 * num_vertices())
      throw invalid_input("no frame to read: the sequence has " + std::to_string(files_.size()),
                          {.file = input_, .frame = next_});
    read_.resize(3 * input_vertices_);
    if (next_ == 0 && !first_frame_.empty()) {
      std::copy(first_frame_.begin(), first_frame_.end(), read_.begin());
    } else {
      try {
        read_mesh_points(files_[next_], std::span<double>(read_));
      } catch (const invalid_input& e) {
        throw e.located({.file = files_[next_].string(), .frame = next_});
      }
    }
    internal::gather_sources(std::span<const double>(read_), std::span<const std::uint32_t>(sources_), out);
    ++next_;
  }

  /// @brief Lists the frame files again (files may have come or gone) and goes back to frame 0.
  /// @throws invalid_input as `list_frame_files`.
  void rewind() {
    files_ = list_frame_files(input_);
    next_ = 0;
  }

private:
  std::string input_;
  double fps_;
  std::vector<std::filesystem::path> files_;
  std::size_t input_vertices_ = 0;
  std::vector<std::uint32_t> sources_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  Repair_report repair_{};
  std::vector<double> first_frame_;
  std::vector<double> read_;
  std::size_t next_ = 0;
};

#if DEFORMSEG_HAS_GLTF
/// @brief The connectivity every clip of a `Gltf_file` shares, as `Gltf_frame_source` gives it:
/// the file's `Gltf_file::repair` and its triangles numbered as `Gltf_file::read` numbers them.
/// Made once for a file and shared by the sources of its clips, so that no clip welds and repairs
/// the scene again.
class Gltf_connectivity {
public:
  /// @brief The connectivity of `file`, which must outlive it and stay where it is, repaired by
  /// `repair` (default: `Gltf_read_options`'s, welding on).
  /// @throws invalid_input naming the file, as `Gltf_file::repair`.
  /// @par Complexity O(V + F log F): the repair's, and a `Surface_mesh` built once for the order
  /// of the triangles.
  explicit Gltf_connectivity(const Gltf_file& file, const Repair_options& repair = Gltf_read_options{}.repair)
      : file_(&file), repaired_(file.repair(repair)) {
    // The order of a Surface_mesh's triangles does not depend on where its vertices are.
    mesh::Coordinate_buffer<double> anywhere(3 * repaired_.source_vertex.size(), 0.0);
    triangles_ = internal::animation_triangles(repaired_, std::move(anywhere));
  }

  /// @brief The file.
  const Gltf_file& file() const noexcept { return *file_; }
  /// @brief The repair: output vertex i moves as the file's vertex `source_vertex[i]`.
  const Repaired_triangles& repaired() const noexcept { return repaired_; }
  /// @brief The repaired triangles, as `Gltf_file::read` numbers them.
  std::span<const std::array<std::uint32_t, 3>> triangles() const noexcept { return triangles_; }

private:
  const Gltf_file* file_;
  Repaired_triangles repaired_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
};

/// @brief One clip of a `Gltf_file` sampled one frame at a time (`Gltf_file::frame_sampler`), as
/// `double`, with the connectivity `Gltf_file::read` gives every clip (welded by what the file
/// fixes, repaired): a `signatures::FrameSource` whose frames, vertices and triangles are those
/// of `Gltf_file::read` with the same options. Only the vertices that the repair keeps are posed.
class Gltf_frame_source {
public:
  /// @brief The coordinate type frames are read in.
  using Coordinate = double;

  /// @brief The clip `options.clip` of `file`, which must outlive the source and stay where it
  /// is, sampled at `options.fps`, with the connectivity of `file.repair(options.repair)`.
  /// @throws invalid_input naming the file, as `Gltf_file::frame_sampler` and `Gltf_file::repair`.
  /// @par Complexity the repair's O(V + F log F).
  Gltf_frame_source(const Gltf_file& file, const Gltf_read_options& options)
      : Gltf_frame_source(std::make_shared<const Gltf_connectivity>(file, options.repair), options) {}

  /// @brief The clip `options.clip` of `connectivity.file()`, sampled at `options.fps`, with
  /// `connectivity` (made once for the file's clips; `options.repair` is not used).
  /// @throws invalid_input naming the file, as `Gltf_file::frame_sampler`.
  /// @par Complexity O(size of the clip's channels + V log V) for V output vertices.
  Gltf_frame_source(std::shared_ptr<const Gltf_connectivity> connectivity, const Gltf_read_options& options)
      : connectivity_(std::move(connectivity)),
        sampler_(connectivity_->file().frame_sampler(
            options, std::span<const std::uint32_t>(connectivity_->repaired().source_vertex))),
        fps_(options.fps) {}

  /// @brief V, the vertices after welding and repair.
  std::size_t num_vertices() const noexcept { return connectivity_->repaired().source_vertex.size(); }
  /// @brief T, the clip's frames at the frame rate asked.
  std::size_t num_frames() const noexcept { return sampler_.num_frames(); }
  /// @brief The frame rate the clip is sampled at.
  double frames_per_second() const noexcept { return fps_; }
  /// @brief The repaired triangles, as `Gltf_file::read` numbers them.
  std::span<const std::array<std::uint32_t, 3>> triangles() const noexcept { return connectivity_->triangles(); }
  /// @brief The clip's name as in the file (maybe empty), as `Gltf_read_report::clip`.
  std::string clip_name() const { return sampler_.clip_name(); }
  /// @brief The connectivity the source shares: the file's repair (`repaired().report` says what
  /// it changed) and its triangles.
  const Gltf_connectivity& connectivity() const noexcept { return *connectivity_; }

  /// @brief Samples the next frame's `3V` coordinates into `out`: those of the vertices the
  /// repair keeps, each posed once.
  /// @throws invalid_input naming the file and the frame past the last frame or for a non-finite
  /// position (of a vertex kept).
  /// @par Complexity one frame of `Gltf_file::sample` for the V vertices kept.
  void read_frame(std::span<double> out) {
    if (out.size() != 3 * num_vertices())
      throw invalid_input("Gltf_frame_source: a frame of " + std::to_string(out.size()) + " coordinates",
                          {.frame = next_});
    sampler_.sample_frame(next_, out);
    ++next_;
  }
  /// @brief Goes back to frame 0 (the parsed file does not change).
  void rewind() noexcept { next_ = 0; }

private:
  std::shared_ptr<const Gltf_connectivity> connectivity_;
  Gltf_frame_sampler sampler_;
  double fps_;
  std::size_t next_ = 0;
};
#endif

/// @brief Calls `f(source)` with a frame source of `input`, which is any input `read_animation`
/// reads: a glTF clip (`Gltf_frame_source`; "FILE.glb#CLIP" or `options.clip` names it), a point
/// cache (`Point_cache_frame_source`, with `options.topology`) or a sequence of frame files
/// (`Frame_sequence_source`); returns what `f` returns.
/// @param input a glTF, FBX or Collada file (maybe followed by "#CLIP"), a folder or glob of frame files, or a
/// `.pc2` or `.mdd` file, as for `read_animation`.
/// @param options as `read_animation`: `topology`, `triangulate`, `repair` (default: the format's,
/// which welds glTF only; welding a point cache or frame files is refused), `clip`, `fps`
/// (default 30); `threads` is not used.
/// @param f called once with the source (an lvalue of one of the three source types), which
/// lives for the call only.
/// @throws invalid_input as the source's constructor, and as `read_animation` for a clip given
/// twice, a topology given with a glTF file, or a file of several clips and none named.
/// @par Complexity that of opening the source.
template <class F>
decltype(auto) with_frame_source(const std::string& input, const Animation_read_options& options, F&& f) {
  if (const auto [file, clip] = split_clip_suffix(input); clip || is_character_file(input)) {
    if (clip && !options.clip.empty())
      throw invalid_input("the clip is given twice: by the clip option and after '#'", {.file = input});
    if (options.topology)
      throw invalid_input("a character file (glTF, FBX, Collada, BVH) has its own connectivity: no topology mesh applies",
                          {.file = input});
#if DEFORMSEG_HAS_GLTF
    const Gltf_file gltf(file);
    const std::string name = clip ? *clip : options.clip;
    require_clip_choice(gltf, name);
    Gltf_frame_source source(
        gltf, {.clip = name, .fps = options.fps, .repair = options.repair.value_or(Gltf_read_options{}.repair)});
    return f(source);
#else
    throw invalid_input("this deformseg was built without tinygltf, which reads glTF, FBX, Collada and BVH files", {.file = input});
#endif
  }
  const Frame_stream_options stream{.topology = options.topology,
                                    .triangulate = options.triangulate,
                                    .repair = options.repair.value_or(Repair_options{}),
                                    .fps = options.fps};
  const std::string format = animation_format(input);
  if (format == "pc2" || format == "mdd") {
    Point_cache_frame_source source(input, stream);
    return f(source);
  }
  Frame_sequence_source source(input, stream);
  return f(source);
}

}  // namespace deformseg::io
