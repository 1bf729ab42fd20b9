/// @file io/point_cache.h
/// @brief Point caches: reads and writes Blender/Maya `.pc2` and LightWave/Blender `.mdd` files
/// (`read_pc2`, `read_mdd`, `read_point_cache_info`, `write_pc2`, `write_mdd`).
///
/// A point cache holds the positions of every vertex at every frame as 32-bit floats, and no
/// connectivity: vertex `i` of the cache is vertex index `i` of the topology mesh, in the index
/// order of `Deforming_mesh`.
/// - PC2, little-endian: the 12-byte signature `"POINTCACHE2\0"`, int32 file version (1), int32
///   number of points, float32 start frame, float32 sample rate, int32 number of samples; then,
///   per sample (frame), per point, x, y, z as float32.
/// - MDD, big-endian: int32 number of frames, int32 number of points, one float32 time per frame
///   (in seconds); then, per frame, per point, x, y, z as float32.
///
/// A file is read with one call and written with one call.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace deformseg::io {

/// @brief The point cache formats deformseg reads and writes.
enum class Point_cache_format {
  pc2,  ///< Blender/Maya PC2: little-endian, starts with the signature `"POINTCACHE2"`
  mdd   ///< LightWave/Blender MDD: big-endian, with a time in seconds per frame
};

/// @brief What the header of a point cache says, as `read_point_cache_info` gives it.
struct Point_cache_info {
  Point_cache_format format = Point_cache_format::pc2;  ///< the file's format
  std::size_t num_vertices = 0;                         ///< the number of points V, at least 1
  std::size_t num_frames = 0;                           ///< the number of frames (PC2: samples) T, at least 1
  /// @brief PC2: the scene frame of the first sample, as stored. MDD: 0.
  double start_frame = 0;
  /// @brief PC2: the scene frames between two samples, as stored. MDD: 1.
  double sample_rate = 1;
  /// @brief MDD: the time of each frame in seconds, as stored (T values). PC2: empty, since its
  /// timing is `start_frame` and `sample_rate`.
  std::vector<double> frame_times{};
};

/// @brief The timing `write_pc2` stores in a PC2 header, each rounded to a float32.
struct Pc2_write_options {
  /// @brief The scene frame of the first sample; finite. Default: 0.
  double start_frame = 0;
  /// @brief The scene frames between two samples; finite and positive. Default: 1.
  double sample_rate = 1;
};

}  // namespace deformseg::io

namespace deformseg::io::internal {

inline constexpr std::string_view pc2_signature{"POINTCACHE2\0", 12};
inline constexpr std::uint64_t pc2_header_size = 32;
inline constexpr std::uint64_t mdd_counts_size = 8;
inline constexpr std::uint64_t bytes_per_point = 12;  // x, y, z as float32
inline constexpr std::int32_t max_cache_count = std::numeric_limits<std::int32_t>::max();

[[noreturn]] inline void fail_cache(const std::filesystem::path& path, const std::string& message,
                                    std::optional<std::size_t> frame = std::nullopt) {
  throw invalid_input(message, {.file = path.string(), .frame = frame});
}

/// A count of the header (`what`: "vertices" or "frames"), which must be positive.
inline std::size_t header_count(std::int32_t value, const char* what, const std::filesystem::path& path) {
  if (value < 0) fail_cache(path, join("the header gives a negative number of ", what, ": ", std::to_string(value)));
  if (value == 0) fail_cache(path, join("the header gives 0 ", what, ": the cache is empty"));
  return static_cast<std::size_t>(value);
}

/// The fields of a PC2 header, from the first bytes of the file (32 or fewer when it is shorter).
inline io::Point_cache_info parse_pc2_header(const File_bytes& bytes, const std::filesystem::path& path) {
  constexpr auto little = std::endian::little;
  const char* p = bytes.begin();
  if (bytes.size < pc2_signature.size() || std::string_view(p, pc2_signature.size()) != pc2_signature)
    fail_cache(path, "not a PC2 point cache: it does not start with the signature \"POINTCACHE2\"");
  if (bytes.size < pc2_header_size)
    fail_cache(path, join("truncated header: the file has ", std::to_string(bytes.size), " bytes, a PC2 header 32"));
  if (const auto version = load_word<little, std::int32_t>(p + 12); version != 1)
    fail_cache(path, join("PC2 file version ", std::to_string(version), "; deformseg reads version 1"));

  io::Point_cache_info info{.format = io::Point_cache_format::pc2};
  info.num_vertices = header_count(load_word<little, std::int32_t>(p + 16), "vertices", path);
  info.start_frame = load_word<little, float>(p + 20);
  info.sample_rate = load_word<little, float>(p + 24);
  info.num_frames = header_count(load_word<little, std::int32_t>(p + 28), "frames", path);
  if (!std::isfinite(info.start_frame))
    fail_cache(path, join("the header's start frame is not finite: ", shortest_text(info.start_frame)));
  if (!std::isfinite(info.sample_rate) || info.sample_rate <= 0)
    fail_cache(path,
               join("the header's sample rate is not a finite positive number: ", shortest_text(info.sample_rate)));
  return info;
}

/// The bytes before the first frame of an MDD file of `frames` frames: counts and times.
constexpr std::uint64_t mdd_header_size(std::size_t frames) noexcept {
  return mdd_counts_size + 4 * std::uint64_t(frames);
}

/// The counts of an MDD header, from the first bytes of the file; checks that the file holds
/// the frame times they announce, which `read_mdd_times` then reads.
inline io::Point_cache_info parse_mdd_counts(const File_bytes& bytes, const std::filesystem::path& path) {
  constexpr auto big = std::endian::big;
  if (bytes.size < mdd_counts_size)
    fail_cache(path,
               join("truncated header: the file has ", std::to_string(bytes.size), " bytes, an MDD header at least 8"));
  io::Point_cache_info info{.format = io::Point_cache_format::mdd};
  info.num_frames = header_count(load_word<big, std::int32_t>(bytes.begin()), "frames", path);
  info.num_vertices = header_count(load_word<big, std::int32_t>(bytes.begin() + 4), "vertices", path);
  if (mdd_header_size(info.num_frames) > bytes.file_size)
    fail_cache(path, join("truncated header: its ", std::to_string(info.num_frames), " frame times need ",
                          std::to_string(mdd_header_size(info.num_frames)), " bytes, the file has ",
                          std::to_string(bytes.file_size)));
  return info;
}

/// Reads the frame times of an MDD file into `info`.
/// @pre `bytes` holds the `mdd_header_size(info.num_frames)` first bytes of the file.
inline void read_mdd_times(const File_bytes& bytes, io::Point_cache_info& info, const std::filesystem::path& path) {
  info.frame_times.resize(info.num_frames);
  for (std::size_t t = 0; t < info.num_frames; ++t) {
    info.frame_times[t] = load_word<std::endian::big, float>(bytes.begin() + mdd_counts_size + 4 * t);
    if (!std::isfinite(info.frame_times[t]))
      fail_cache(path, join("the frame's time is not finite: ", shortest_text(info.frame_times[t])), t);
  }
}

/// The bytes before the first frame.
inline std::uint64_t header_size(const io::Point_cache_info& info) noexcept {
  return info.format == io::Point_cache_format::pc2 ? pc2_header_size : mdd_header_size(info.num_frames);
}

/// Checks that a file of `file_size` bytes holds exactly the frames its header announces:
/// names the first incomplete frame of a truncated file, counts the bytes after the last frame.
inline void check_cache_size(const io::Point_cache_info& info, std::uint64_t file_size,
                             const std::filesystem::path& path) {
  const std::uint64_t frame_size = bytes_per_point * info.num_vertices;  // < 2^35: no overflow
  const std::uint64_t body = file_size - header_size(info);              // header checked before
  if (info.num_frames > std::numeric_limits<std::uint64_t>::max() / frame_size)
    fail_cache(path, join("the header gives ", std::to_string(info.num_frames), " frames of ",
                          std::to_string(info.num_vertices), " vertices: more bytes than any file holds"));
  const std::uint64_t expected = frame_size * info.num_frames;
  if (body < expected) {
    const std::uint64_t complete_frames = body / frame_size;
    fail_cache(path,
               join("truncated: the frame has ", std::to_string(body % frame_size), " of its ",
                    std::to_string(frame_size), " bytes; ", std::to_string(expected - body),
                    " bytes are missing for the ", std::to_string(info.num_frames), " frames the header gives"),
               static_cast<std::size_t>(complete_frames));
  }
  if (body > expected)
    fail_cache(path, join(std::to_string(body - expected), " trailing bytes after the last of the ",
                          std::to_string(info.num_frames), " frames the header gives",
                          body - expected == frame_size ? " (exactly one frame more)" : ""));
}

/// Throws unless the cache has as many vertices as the topology.
inline void check_vertex_count(const io::Point_cache_info& info, std::size_t topology_vertices,
                               const std::filesystem::path& path) {
  if (info.num_vertices != topology_vertices)
    fail_cache(path, join("the cache has ", std::to_string(info.num_vertices), " vertices, the topology ",
                          std::to_string(topology_vertices)));
}

/// The header of a whole point cache file in `bytes`, counts checked but not the size.
inline io::Point_cache_info parse_cache_header(io::Point_cache_format format, const File_bytes& bytes,
                                               const std::filesystem::path& path) {
  if (format == io::Point_cache_format::pc2) return parse_pc2_header(bytes, path);
  io::Point_cache_info info = parse_mdd_counts(bytes, path);
  read_mdd_times(bytes, info, path);
  return info;
}

/// The frames of a point cache whose header is `info`, from `first` on, as an animation of
/// `topology`. A non-finite coordinate is reported with its frame and vertex.
template <std::endian order, class Graph, class Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> decode_frames(const char* first, const io::Point_cache_info& info,
                                                mesh::Deforming_mesh<Graph, Coordinate> animation,
                                                const std::filesystem::path& path) {
  animation.reserve_frames(info.num_frames);
  std::vector<Coordinate> xyz(3 * info.num_vertices);
  for (std::size_t t = 0; t < info.num_frames; ++t) {
    for (Coordinate& x : xyz) {
      x = static_cast<Coordinate>(load_word<order, float>(first));
      first += 4;
    }
    try {
      animation.add_frame(std::span<const Coordinate>(xyz));
    } catch (const invalid_input& e) {
      throw e.located({.file = path.string()});
    }
  }
  return animation;
}

/// Reads a whole point cache of `format` as an animation of `topology`.
template <io::Point_cache_format format, class Graph, class Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> read_point_cache(const std::filesystem::path& path, Graph topology) {
  const File_bytes bytes = read_file_bytes(path);
  const io::Point_cache_info info = parse_cache_header(format, bytes, path);
  mesh::Deforming_mesh<Graph, Coordinate> animation(std::move(topology));
  // The vertex count first: a cache of another mesh explains a size that does not match.
  check_vertex_count(info, animation.num_vertices(), path);
  check_cache_size(info, bytes.file_size, path);
  constexpr auto order = format == io::Point_cache_format::pc2 ? std::endian::little : std::endian::big;
  return decode_frames<order>(bytes.begin() + header_size(info), info, std::move(animation), path);
}

/// The positions of every frame of a whole point cache of `format`, checked against a topology
/// of `topology_vertices` vertices as `read_point_cache` does: `T x 3V` coordinates.
template <io::Point_cache_format format, std::floating_point Coordinate>
mesh::Coordinate_buffer<Coordinate> read_point_cache_positions(const std::filesystem::path& path,
                                                               std::size_t topology_vertices) {
  const File_bytes bytes = read_file_bytes(path);
  const io::Point_cache_info info = parse_cache_header(format, bytes, path);
  check_vertex_count(info, topology_vertices, path);
  check_cache_size(info, bytes.file_size, path);
  constexpr auto order = format == io::Point_cache_format::pc2 ? std::endian::little : std::endian::big;
  mesh::Coordinate_buffer<Coordinate> xyz(3 * info.num_vertices * info.num_frames);
  const char* next = bytes.begin() + header_size(info);
  for (std::size_t i = 0; i < xyz.size(); ++i, next += 4) {
    xyz[i] = static_cast<Coordinate>(load_word<order, float>(next));
    if (!std::isfinite(xyz[i]))
      fail_cache(path, join("vertex ", std::to_string(i / 3 % info.num_vertices), " has a non-finite coordinate"),
                 i / (3 * info.num_vertices));
  }
  return xyz;
}

/// The format a point cache's extension names (.pc2 or .mdd, in any case).
inline io::Point_cache_format point_cache_format(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".pc2") return io::Point_cache_format::pc2;
  if (extension == ".mdd") return io::Point_cache_format::mdd;
  fail_cache(path, "not a point cache: the extension is neither .pc2 nor .mdd");
}

/// Throws unless an animation fits in a point cache: at least one frame, counts within int32.
template <class Graph, class Coordinate>
void check_cache_counts(const mesh::Deforming_mesh<Graph, Coordinate>& animation, const std::filesystem::path& path) {
  if (animation.num_frames() == 0) fail_cache(path, "the animation has no frame: a point cache needs at least one");
  for (const auto& [count, what] :
       {std::pair{animation.num_vertices(), "vertices"}, std::pair{animation.num_frames(), "frames"}})
    if (count > std::size_t(max_cache_count))
      fail_cache(path, join(std::to_string(count), " ", what, " are more than a point cache holds (",
                            std::to_string(max_cache_count), ")"));
}

/// A coordinate as a float32; throws, naming the frame and the vertex, when it is out of range.
template <std::floating_point Coordinate>
float to_float32(Coordinate x, std::size_t frame, std::size_t index, const std::filesystem::path& path) {
  if (std::abs(x) > Coordinate(std::numeric_limits<float>::max())) [[unlikely]]
    fail_cache(path, join("vertex ", std::to_string(index / 3), " has the coordinate ", shortest_text(x),
                          ", beyond the range of a float32"),
               frame);
  return static_cast<float>(x);
}

/// Stores every frame's positions as float32 from `out` on, in the byte order `order`.
template <std::endian order, class Graph, class Coordinate>
void encode_frames(const mesh::Deforming_mesh<Graph, Coordinate>& animation, char* out,
                   const std::filesystem::path& path) {
  for (std::size_t t = 0; t < animation.num_frames(); ++t) {
    const std::span<const Coordinate> xyz = animation.frame_positions(t);
    for (std::size_t i = 0; i < xyz.size(); ++i, out += 4) store_word<order>(out, to_float32(xyz[i], t, i, path));
  }
}

/// The size of a point cache file: its header, then 12 bytes per vertex and frame.
template <class Graph, class Coordinate>
std::size_t cache_size(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::uint64_t header) {
  return static_cast<std::size_t>(header + bytes_per_point * animation.num_vertices() * animation.num_frames());
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Reads the header of a point cache, and checks that the file's size matches it, without
/// reading the frames: what a file holds, quickly.
///
/// @param cache a `.pc2` or `.mdd` file; the extension (in any case) gives the format.
/// @return the format, the vertex and frame counts, and the timing: PC2's start frame and sample
/// rate, or MDD's frame times.
/// @throws invalid_input naming the file (and the frame, where there is one) when it is missing
/// or unreadable, has another extension, a wrong signature or version, a negative or zero count,
/// a non-finite timing, or a size other than its header announces (truncated, or trailing bytes).
/// @par Complexity O(1) for PC2; O(T) for MDD, whose header holds the frame times.
/// @sa read_pc2, read_mdd
inline Point_cache_info read_point_cache_info(const std::filesystem::path& cache) {
  const Point_cache_format format = internal::point_cache_format(cache);
  Point_cache_info info;
  std::uint64_t file_size = 0;
  if (format == Point_cache_format::pc2) {
    const internal::File_bytes header = internal::read_file_bytes(cache, internal::pc2_header_size);
    info = internal::parse_pc2_header(header, cache);
    file_size = header.file_size;
  } else {
    // The counts first, which say how many bytes of times follow.
    info = internal::parse_mdd_counts(internal::read_file_bytes(cache, internal::mdd_counts_size), cache);
    const internal::File_bytes header = internal::read_file_bytes(cache, internal::mdd_header_size(info.num_frames));
    internal::read_mdd_times(header, info, cache);
    file_size = header.file_size;
  }
  internal::check_cache_size(info, file_size, cache);
  return info;
}

/// @brief Reads a Blender/Maya PC2 point cache as an animation of `topology`.
///
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`); the file's float32 values
/// convert to either exactly.
/// @param cache the `.pc2` file, read with one call.
/// @param topology the connectivity: vertex `i` of the cache is the vertex of index `i`.
/// @param frames_per_second the animation's frame rate (`Deforming_mesh::frames_per_second`), which
/// a PC2 file does not give. Default 30.
/// @return the animation, frame `t` from sample `t`. The header's start frame and sample rate
/// are not kept: `read_point_cache_info` gives them.
/// @pre the file is a PC2 file of version 1 with as many points as `topology` has vertices, at
/// least one sample, finite coordinates, and exactly the size its header announces; `topology`
/// meets the preconditions of `Deforming_mesh`.
/// @throws invalid_input naming the file, and the frame and vertex where there are some, for a
/// missing or unreadable file, a wrong signature or version, a negative or zero count, a vertex
/// count other than the topology's (both given), a truncated file (the incomplete frame and the
/// bytes missing), trailing bytes, or a non-finite coordinate. Nothing is allocated for the frames
/// before the header is known to match the file.
/// @par Complexity O(T V).
/// @sa read_mdd, read_point_cache_info, write_pc2
template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double>
mesh::Deforming_mesh<Graph, Coordinate> read_pc2(const std::filesystem::path& cache, Graph topology,
                                           double frames_per_second = mesh::default_frames_per_second) {
  auto animation = internal::read_point_cache<Point_cache_format::pc2, Graph, Coordinate>(cache, std::move(topology));
  animation.set_frames_per_second(frames_per_second);
  return animation;
}

/// @brief Reads a LightWave/Blender MDD point cache as an animation of `topology`.
///
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`); the file's float32 values
/// convert to either exactly.
/// @param cache the `.mdd` file, read with one call.
/// @param topology the connectivity: vertex `i` of the cache is the vertex of index `i`.
/// @param frames_per_second the animation's frame rate (`Deforming_mesh::frames_per_second`).
/// Default 30, whatever the file's frame times say.
/// @return the animation, frame `t` from the file's frame `t`. The frame times are not kept:
/// `read_point_cache_info` gives them.
/// @pre the file has as many points as `topology` has vertices, at least one frame, finite
/// times and coordinates, and exactly the size its header announces; `topology` meets the
/// preconditions of `Deforming_mesh`.
/// @throws invalid_input naming the file, and the frame and vertex where there are some, for a
/// missing or unreadable file, a negative or zero count, a vertex count other than the
/// topology's (both given), a truncated file (the incomplete frame and the bytes missing),
/// trailing bytes, or a non-finite time or coordinate. Nothing is allocated for the frames
/// before the header is known to match the file.
/// @par Complexity O(T V).
/// @sa read_pc2, read_point_cache_info, write_mdd
template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double>
mesh::Deforming_mesh<Graph, Coordinate> read_mdd(const std::filesystem::path& cache, Graph topology,
                                           double frames_per_second = mesh::default_frames_per_second) {
  auto animation = internal::read_point_cache<Point_cache_format::mdd, Graph, Coordinate>(cache, std::move(topology));
  animation.set_frames_per_second(frames_per_second);
  return animation;
}

/// @brief Writes an animation as a Blender/Maya PC2 point cache (version 1), with one call.
///
/// Coordinates are rounded to float32: a `float` animation is written exactly, a `double` one
/// to about 7 significant digits.
/// @param animation the animation; vertex `i` is written as point `i`, frame `t` as sample `t`.
/// @param cache the file to write, replaced if it exists; its folder must exist.
/// @param options the header's `start_frame` (default 0) and `sample_rate` (default 1).
/// @pre the animation has at least one frame, at most 2^31 - 1 vertices and frames, and
/// coordinates within the range of float32; `options` are finite, `sample_rate > 0`.
/// @throws invalid_input naming the file (and the frame and vertex of a coordinate out of
/// range) when a precondition fails or the file cannot be written. Not being able to write is
/// reported as invalid input, the path being the caller's; no partial file is left then.
/// @par Complexity O(T V); the whole file is built in memory (12 T V bytes) first.
/// @sa read_pc2, write_mdd
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
void write_pc2(const mesh::Deforming_mesh<Graph, Coordinate>& animation, const std::filesystem::path& cache,
               const Pc2_write_options& options = {}) {
  constexpr auto little = std::endian::little;
  internal::check_cache_counts(animation, cache);
  if (!std::isfinite(options.start_frame) || std::abs(options.start_frame) > std::numeric_limits<float>::max())
    internal::fail_cache(cache, internal::join("start_frame must be a finite float32, not ",
                                               internal::shortest_text(options.start_frame)));
  if (!(options.sample_rate > 0) || options.sample_rate > std::numeric_limits<float>::max())
    internal::fail_cache(cache, internal::join("sample_rate must be a positive finite float32, not ",
                                               internal::shortest_text(options.sample_rate)));

  std::string bytes(internal::cache_size(animation, internal::pc2_header_size), '\0');
  char* out = bytes.data();
  std::memcpy(out, internal::pc2_signature.data(), internal::pc2_signature.size());
  internal::store_word<little>(out + 12, std::int32_t{1});
  internal::store_word<little>(out + 16, static_cast<std::int32_t>(animation.num_vertices()));
  internal::store_word<little>(out + 20, static_cast<float>(options.start_frame));
  internal::store_word<little>(out + 24, static_cast<float>(options.sample_rate));
  internal::store_word<little>(out + 28, static_cast<std::int32_t>(animation.num_frames()));
  internal::encode_frames<little>(animation, out + internal::pc2_header_size, cache);
  internal::write_file_bytes(cache, bytes);
}

/// @brief Writes an animation as a LightWave/Blender MDD point cache, with one call.
///
/// Frame `t` gets the time `t / frames_per_second` seconds, as Blender's exporter does.
/// Coordinates are rounded to float32: a `float` animation is written exactly, a `double` one
/// to about 7 significant digits.
/// @param animation the animation; vertex `i` is written as point `i`, frame `t` as frame `t`.
/// @param cache the file to write, replaced if it exists; its folder must exist.
/// @param frames_per_second the frame rate that gives the frame times; default 25.
/// @pre the animation has at least one frame, at most 2^31 - 1 vertices and frames, and
/// coordinates within the range of float32; `frames_per_second` is finite and positive.
/// @throws invalid_input naming the file (and the frame and vertex of a coordinate out of
/// range) when a precondition fails or the file cannot be written; no partial file is left then.
/// @par Complexity O(T V); the whole file is built in memory (12 T V + 4 T bytes) first.
/// @sa read_mdd, write_pc2
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
void write_mdd(const mesh::Deforming_mesh<Graph, Coordinate>& animation, const std::filesystem::path& cache,
               double frames_per_second = 25) {
  constexpr auto big = std::endian::big;
  internal::check_cache_counts(animation, cache);
  if (!(frames_per_second > 0) || !std::isfinite(frames_per_second))
    internal::fail_cache(cache, internal::join("frames_per_second must be finite and positive, not ",
                                               internal::shortest_text(frames_per_second)));

  const std::size_t frames = animation.num_frames();
  std::string bytes(internal::cache_size(animation, internal::mdd_header_size(frames)), '\0');
  char* out = bytes.data();
  internal::store_word<big>(out, static_cast<std::int32_t>(frames));
  internal::store_word<big>(out + 4, static_cast<std::int32_t>(animation.num_vertices()));
  for (std::size_t t = 0; t < frames; ++t)
    internal::store_word<big>(out + internal::mdd_counts_size + 4 * t, static_cast<float>(double(t) / frames_per_second));
  internal::encode_frames<big>(animation, out + internal::mdd_header_size(frames), cache);
  internal::write_file_bytes(cache, bytes);
}

// The instances of the default types, compiled in deformseg's io library (src/io/point_cache.cpp).
/// @cond
extern template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_pc2<mesh::Surface_mesh, double>(const std::filesystem::path&, mesh::Surface_mesh, double);
extern template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_mdd<mesh::Surface_mesh, double>(const std::filesystem::path&, mesh::Surface_mesh, double);
/// @endcond

}  // namespace deformseg::io
