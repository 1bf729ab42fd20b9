/// @file io/frame_sequence.h
/// @brief Reads an animation stored as one mesh file per frame: `list_frame_files` and
/// `read_frame_sequence`.
#pragma once

#include <deformseg/color/color.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/internal/text_scanner.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/read_mesh.h>
#include <deformseg/io/triangle_soup.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/off.h>
#include <deformseg/io/ply.h>
#include <deformseg/threads.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace deformseg::io::internal {

/// The natural order of file names: runs of digits compare by their value, so that "2.obj" comes
/// before "10.obj" and "mesh_0009" before "mesh_0010"; other characters compare by their code.
/// Names equal in that order ("1" and "01") fall back to the plain order, so that it is total.
inline bool natural_less(std::string_view a, std::string_view b) {
  const auto digits_from = [](std::string_view s, std::size_t i) {
    std::size_t end = i;
    while (end < s.size() && is_digit(s[end])) ++end;
    return s.substr(i, end - i);
  };
  const auto without_leading_zeros = [](std::string_view run) {
    return run.substr(std::min(run.find_first_not_of('0'), run.size()));
  };
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    if (is_digit(a[i]) && is_digit(b[j])) {
      const std::string_view x = digits_from(a, i);
      const std::string_view y = digits_from(b, j);
      const std::string_view x_value = without_leading_zeros(x);
      const std::string_view y_value = without_leading_zeros(y);
      if (x_value.size() != y_value.size()) return x_value.size() < y_value.size();
      if (x_value != y_value) return x_value < y_value;
      i += x.size();
      j += y.size();
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
      ++i;
      ++j;
    }
  }
  if (a.size() - i != b.size() - j) return a.size() - i < b.size() - j;
  return a < b;
}

/// Whether `name` matches `pattern`, where `*` matches any run of characters and `?` any one.
inline bool glob_match(std::string_view pattern, std::string_view name) {
  std::size_t p = 0;
  std::size_t n = 0;
  std::size_t star = std::string_view::npos;  // the last '*' seen, to retry from on a mismatch
  std::size_t star_n = 0;                     // where in `name` that '*' match ends for now
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_n = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++star_n;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

inline bool has_wildcard(std::string_view s) { return s.find_first_of("*?") != std::string_view::npos; }

inline bool is_frame_extension(const std::string& extension) {
  return extension == ".obj" || extension == ".off" || extension == ".ply";
}

/// Hidden files (".name", such as the "._name" copies macOS leaves) are never frames.
inline bool is_hidden(const std::filesystem::path& path) { return path.filename().string().starts_with('.'); }

/// The .obj, .off and .ply files of `folder`, in any order; all of one format.
inline std::vector<std::filesystem::path> frame_files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::set<std::string> extensions;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string extension = lower_extension(entry.path());
    if (!entry.is_regular_file() || is_hidden(entry.path()) || !is_frame_extension(extension)) continue;
    files.push_back(entry.path());
    extensions.insert(extension);
  }
  if (extensions.size() > 1)
    throw invalid_input(join("the folder holds frames of several formats (", *extensions.begin(), " and ",
                               *std::next(extensions.begin()), "): give a pattern such as \"",
                               (folder / "*").string(), *extensions.begin(), "\" to choose"),
                        {.file = folder.string()});
  return files;
}

/// The files whose name matches the last part of `pattern`, in the folder its other parts name.
inline std::vector<std::filesystem::path> files_matching(const std::filesystem::path& pattern) {
  const std::filesystem::path folder = pattern.parent_path();
  const std::string name_pattern = pattern.filename().string();
  const auto fail = [&](const std::string& message) { throw invalid_input(message, {.file = pattern.string()}); };
  if (has_wildcard(folder.string()))
    fail("wildcards (* and ?) are only read in the file name, not in the folders above it");
  std::error_code error;
  if (!has_wildcard(name_pattern)) {
    if (!std::filesystem::is_regular_file(pattern, error)) fail("cannot open: no such folder or file");
    return {pattern};
  }
  const std::filesystem::path listed = folder.empty() ? std::filesystem::path(".") : folder;
  if (!std::filesystem::is_directory(listed, error))
    fail(join("no such folder: \"", listed.string(), "\""));
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(listed)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && !(is_hidden(name) && !name_pattern.starts_with('.')) &&
        glob_match(name_pattern, name))
      files.push_back(folder / name);
  }
  return files;
}

/// Reads the positions of frames `first` to `files.size() - 1` into their blocks of `positions`
/// (`block` values each), on `threads` threads (0: all). The error of the lowest failing frame is
/// thrown, located at its frame, whatever the number of threads: frames above a failed one are
/// skipped, frames below it are always read.
template <std::floating_point T>
void read_frame_positions(std::span<const std::filesystem::path> files, std::size_t first,
                          std::span<T> positions, std::size_t block, int threads) {
  deformseg::internal::parallel_for(files.size() - first, threads, [&](std::size_t k) {
    const std::size_t t = first + k;
    try {
      io::read_mesh_points(files[t], positions.subspan(t * block, block));
    } catch (const invalid_input& e) {
      throw e.located({.frame = t});
    }
  });
}

}  // namespace deformseg::io::internal

namespace deformseg::io::internal {

/// `io::repair_triangles` of a topology's triangles for `T x 3V` positions, its errors located at
/// the topology.
template <std::floating_point T>
io::Repaired_triangles repaired_topology(std::span<const T> positions, std::size_t num_vertices,
                                         std::span<const std::array<std::uint32_t, 3>> triangles,
                                         const io::Repair_options& options, const Input_location& location) {
  try {
    return io::repair_triangles(positions, num_vertices, triangles, options);
  } catch (const invalid_input& e) {
    throw e.located(location);
  }
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief The frame files of an animation, in natural order.
///
/// @param directory_or_glob either a folder, whose `.obj`, `.off` and `.ply` files (extension in
/// any case, all of one format) are the frames; or a pattern whose file name part may hold `*`
/// (any run of characters) and `?` (any one character), such as `"horse/0*.obj"`; or the path of
/// one file. Hidden files (whose name starts with `.`) are left out unless the pattern starts
/// with `.`.
/// @return the files, in the natural order of their names: runs of digits compare by value, so
/// `2.obj` comes before `10.obj` and `mesh_0009.obj` before `mesh_0010.obj`.
/// @throws invalid_input naming `directory_or_glob` when nothing matches (a folder with no frame
/// file, a pattern that matches no file, a path that does not exist), when a folder holds frames
/// of several formats, or when a wildcard is outside the file name.
/// @par Complexity O(n log n) for n files in the folder.
inline std::vector<std::filesystem::path> list_frame_files(const std::string& directory_or_glob) {
  const std::filesystem::path input(directory_or_glob);
  std::error_code error;
  const bool is_folder = std::filesystem::is_directory(input, error);
  std::vector<std::filesystem::path> files =
      is_folder ? internal::frame_files_in(input) : internal::files_matching(input);
  if (files.empty())
    throw invalid_input(is_folder ? "no frame file (.obj, .off or .ply) in the folder" : "no file matches the pattern",
                        {.file = directory_or_glob});
  std::sort(files.begin(), files.end(), [](const std::filesystem::path& a, const std::filesystem::path& b) {
    return internal::natural_less(a.filename().string(), b.filename().string());
  });
  return files;
}

/// @brief How `read_frame_sequence` reads an animation.
struct Frame_sequence_options {
  /// @brief A mesh file (.obj, .off or .ply) whose faces give the connectivity instead of the
  /// first frame's; every frame is then read for its positions only. Default: none.
  std::optional<std::filesystem::path> topology{};
  /// @brief Fan-triangulate polygons of the connectivity instead of rejecting them (see
  /// `Mesh_read_options`). Default: false.
  bool triangulate = false;
  /// @brief Threads that read frames in parallel: 0 (default) for all the hardware's threads (`thread_count`)
  /// unless `DEFORMSEG_NUM_THREADS` or `OMP_NUM_THREADS` says otherwise; at
  /// most `max_threads`. The result does not depend on it.
  int threads = 0;
  /// @brief How the connectivity is repaired (see `repair_triangles`): by default vertices are
  /// not welded (`weld` false: a frame file's vertices are its own) and degenerate, duplicate
  /// and non-manifold triangles are repaired (`defects` = `Defect_policy::repair`).
  Repair_options repair{};
  /// @brief The animation's frame rate (`Deforming_mesh::frames_per_second`), which frame files do
  /// not give. Default 30.
  double fps = mesh::default_frames_per_second;
};

/// @brief Reads an animation stored as one mesh file per frame (OBJ, OFF or PLY), all with the
/// same vertices in the same order.
///
/// The first frame's file (or `options.topology`) gives the triangles; each frame gives only its
/// positions (`read_mesh_points`; the first frame's are those already read), parsed straight into
/// its block of one contiguous array of `T x 3V` coordinates. The frames are read in parallel;
/// the result, or the error thrown, is the same for any number of threads.
/// `repair_triangles` repairs (or refuses) the triangles: before the frames are read, or after
/// them when it welds (`options.repair.weld`), which compares every frame. Then
/// `make_face_graph<Graph>` builds the connectivity; when the repair keeps every vertex (no
/// welding, no copy), the positions are not copied again.
///
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @tparam Coordinate the stored coordinate type (default `double`); with `float` each number is
/// rounded once, straight from its decimal text.
/// @param directory_or_glob the frames, as for `list_frame_files`: a folder, a pattern with `*` and
/// `?` in the file name part, or one file.
/// @param options `topology` (default: the first frame), `triangulate` (default false), `threads`
/// (default 0: all), `repair` (default: no welding, defects repaired), `fps` (default 30).
/// @param report where to store what the repair changed, when not null (default null).
/// @return the animation, frame `t` from the `t`-th file in natural order; vertex `i` is the
/// file's vertex `i` unless the repair welded or copied vertices (`report`, and
/// `repair_triangles`, say how).
/// @pre every frame has as many vertices as the connectivity, all with finite coordinates. The
/// faces of frames other than the first are not read: they are assumed to be the same.
/// @throws invalid_input naming the file, the frame and, for a malformed number, the line of the
/// first problem: a frame rate that is not positive and finite, no frame file, a file that cannot
/// be read or parsed, a face that is not a triangle, a frame with another vertex count, a non-finite coordinate; with
/// `Defect_policy::refuse`, the first defect of the connectivity, located at its file. When
/// several frames are bad, the lowest one is reported.
/// @par Complexity O(total size of the files), divided among the threads, plus the repair's
/// O(T V + F log F) (O(F log F) without welding).
/// @sa list_frame_files, read_mesh, read_mesh_points, repair_triangles
template <mesh::FaceGraph Graph = mesh::Surface_mesh, std::floating_point Coordinate = double>
mesh::Deforming_mesh<Graph, Coordinate> read_frame_sequence(const std::string& directory_or_glob,
                                                      const Frame_sequence_options& options = {},
                                                      Repair_report* report = nullptr) {
  thread_count(options.threads);
  mesh::check_frames_per_second(options.fps);
  const std::vector<std::filesystem::path> files = list_frame_files(directory_or_glob);
  const std::filesystem::path topology_file = options.topology.value_or(files.front());
  const Input_location topology_location{.file = topology_file.string(),
                                         .frame = options.topology ? std::nullopt : std::optional<std::size_t>(0)};

  Triangle_soup soup;
  try {
    soup = read_mesh(topology_file, {.triangulate = options.triangulate});
  } catch (const invalid_input& e) {
    throw e.located(topology_location);
  }

  // Without welding the repair needs no positions: a defect refused is then reported before the
  // frames are read.
  Repaired_triangles repaired;
  if (!options.repair.weld)
    repaired = internal::repaired_topology(std::span<const Coordinate>(), soup.num_vertices(),
                                           std::span<const std::array<std::uint32_t, 3>>(soup.triangles),
                                           options.repair, topology_location);

  // The first frame's positions are those just read, unless they come from elsewhere or are to
  // be rounded to another type, when reading them again rounds each number once.
  const std::size_t block = soup.points.size();
  mesh::Coordinate_buffer<Coordinate> positions(files.size() * block);  // each number written once, by its frame
  std::size_t first_to_read = 0;
  if (!options.topology && std::same_as<Coordinate, double>) {
    std::copy(soup.points.begin(), soup.points.end(), positions.begin());
    first_to_read = 1;
  }
  soup.points = {};
  internal::read_frame_positions(std::span<const std::filesystem::path>(files), first_to_read,
                                 std::span<Coordinate>(positions), block, options.threads);

  if (options.repair.weld)
    repaired = internal::repaired_topology(std::span<const Coordinate>(positions), block / 3,
                                           std::span<const std::array<std::uint32_t, 3>>(soup.triangles),
                                           options.repair, topology_location);
  auto animation = internal::repaired_animation<Graph, Coordinate>(std::move(positions), block / 3, repaired, report);
  animation.set_frames_per_second(options.fps);
  return animation;
}

}  // namespace deformseg::io

namespace deformseg::io {

/// @brief The mesh file formats `write_sequence` writes.
enum class Mesh_format {
  obj,  ///< Wavefront OBJ, text, no colours
  off,  ///< OFF, text, no colours
  ply   ///< PLY, binary or text, with optional face colours
};

/// @brief Gives the face colours of a frame: one `Rgb` per face, in face index order.
using Face_colors_of_frame = std::function<std::vector<color::Rgb>(std::size_t frame)>;

/// @brief How `write_sequence` names and writes the files.
struct Sequence_write_options {
  /// @brief The format of every file. Default: `Mesh_format::ply`.
  Mesh_format format = Mesh_format::ply;
  /// @brief The start of every file name, before the frame number. Default: `"frame_"`.
  std::string prefix = "frame_";
  /// @brief The fewest digits of the zero-padded frame number; more are used when the last
  /// frame's number needs them, so that all names have the same length. Default: 4.
  std::size_t min_digits = 4;
  /// @brief The face colours of each frame (PLY only), called once per frame in order; empty
  /// (default) for none.
  Face_colors_of_frame face_colors{};
  /// @brief The encoding of PLY files. Default: `Ply_encoding::binary`.
  Ply_encoding ply_encoding = Ply_encoding::binary;
};

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// The extension of the files of `format`, with its dot.
constexpr const char* file_extension(io::Mesh_format format) noexcept {
  switch (format) {
    case io::Mesh_format::obj: return ".obj";
    case io::Mesh_format::off: return ".off";
    case io::Mesh_format::ply: return ".ply";
  }
  return ".ply";
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief The file name `write_sequence` gives frame `frame` of an animation of `num_frames`
/// frames: the prefix, the frame number padded with zeros to the same width for every frame,
/// and the extension, such as `frame_0007.ply`.
///
/// Every name of a sequence has the same length, so that plain (lexicographic) and natural
/// sorting both give the frame order.
/// @param frame the frame, from 0.
/// @param num_frames the number of frames of the animation.
/// @param options `prefix`, `min_digits` and `format`.
/// @return the file name, without a folder.
/// @par Complexity O(length of the name).
inline std::string sequence_file_name(std::size_t frame, std::size_t num_frames,
                                      const Sequence_write_options& options = {}) {
  const std::string last = std::to_string(num_frames == 0 ? 0 : num_frames - 1);
  const std::string number = std::to_string(frame);
  const std::size_t width = std::max({options.min_digits, last.size(), number.size()});
  return internal::join(options.prefix, std::string(width - number.size(), '0'), number,
                        internal::file_extension(options.format));
}

}  // namespace deformseg::io

namespace deformseg::io::internal {

/// Frame `frame` as the bytes of a file of `options.format`, in `bytes`, reused between frames.
template <class Graph, class Coordinate>
void format_frame(const mesh::Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
                  const io::Sequence_write_options& options, const std::filesystem::path& file, std::string& bytes) {
  bytes.clear();
  if (options.format == io::Mesh_format::obj) {
    append_text_mesh(animation, frame, obj_format, bytes);
  } else if (options.format == io::Mesh_format::off) {
    append_text_mesh(animation, frame, off_format, bytes);
  } else {
    const std::vector<color::Rgb> colors = options.face_colors ? options.face_colors(frame) : std::vector<color::Rgb>{};
    check_face_colors(colors.size(), animation.num_faces(), file, frame);
    append_ply(animation, frame, std::span<const color::Rgb>(colors), options.ply_encoding, bytes);
  }
}

}  // namespace deformseg::io::internal

namespace deformseg::io {

/// @brief Writes every frame of an animation into `directory`, one file per frame, named by
/// `sequence_file_name` (`frame_0000.ply`, `frame_0001.ply`, ...).
///
/// Each file is what `write_obj`, `write_off` or `write_ply` writes for its frame, built in one buffer reused
/// from frame to frame and written with one call. Reading the folder back with
/// `read_frame_sequence`, into the same `Coordinate` type, gives the same positions exactly.
///
/// @param animation the animation.
/// @param directory the folder, created with its parents when missing. Files of the same names
/// are replaced; other files in it are left alone, so write into an empty folder to read it
/// back as a sequence.
/// @param options `format` (default PLY), `prefix` (default `"frame_"`), `min_digits` (default
/// 4), `face_colors` (default none; PLY only) and `ply_encoding` (default binary).
/// @return the files written, in frame order; none for an animation without frames.
/// @pre `options.face_colors` is empty for OBJ and OFF, and gives either no colour or one per face for
/// every frame; `options.prefix` is a file name part, without a folder separator.
/// @throws invalid_input naming the file or folder when a precondition fails, the folder cannot
/// be created, or a file cannot be written (the frame, for a wrong number of colours). The
/// frames before the failing one are written.
/// @par Complexity O(T (V + F)).
/// @sa write_obj, write_off, write_ply, sequence_file_name
template <mesh::FaceGraph Graph, std::floating_point Coordinate>
std::vector<std::filesystem::path> write_sequence(const mesh::Deforming_mesh<Graph, Coordinate>& animation,
                                                  const std::filesystem::path& directory,
                                                  const Sequence_write_options& options = {}) {
  if (options.face_colors && options.format != Mesh_format::ply)
    throw invalid_input("face colours need the PLY format: OBJ and OFF files have none", {.file = directory.string()});
  if (options.prefix.find_first_of("/\\") != std::string::npos)
    throw invalid_input(internal::join("the prefix \"", options.prefix, "\" holds a folder separator"),
                        {.file = directory.string()});
  internal::create_folder(directory);

  std::vector<std::filesystem::path> files;
  files.reserve(animation.num_frames());
  std::string bytes;
  for (std::size_t t = 0; t < animation.num_frames(); ++t) {
    files.push_back(directory / sequence_file_name(t, animation.num_frames(), options));
    internal::format_frame(animation, t, options, files.back(), bytes);
    internal::write_file_bytes(files.back(), bytes);
  }
  return files;
}

// The instance of the default types, compiled in deformseg's io library (src/io/frame_sequence.cpp).
/// @cond
extern template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_frame_sequence<mesh::Surface_mesh, double>(const std::string&, const Frame_sequence_options&, Repair_report*);
/// @endcond

}  // namespace deformseg::io
