/// @file write_sequence.h
/// @brief Writes every frame of an animation into a folder, one OBJ, OFF or PLY file per frame:
/// `write_sequence`.
#pragma once

#include <deformseg/color.h>
#include <deformseg/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/io/write_obj.h>
#include <deformseg/io/write_off.h>
#include <deformseg/io/write_ply.h>

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace deformseg::io {

/// @brief The mesh file formats `write_sequence` writes.
enum class Mesh_format {
  obj,  ///< Wavefront OBJ, text, no colours
  off,  ///< OFF, text, no colours
  ply   ///< PLY, binary or text, with optional face colours
};

/// @brief Gives the face colours of a frame: one `Rgb` per face, in face index order.
using Face_colors_of_frame = std::function<std::vector<Rgb>(std::size_t frame)>;

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

namespace deformseg::internal {

/// The extension of the files of `format`, with its dot.
constexpr const char* file_extension(io::Mesh_format format) noexcept {
  switch (format) {
    case io::Mesh_format::obj: return ".obj";
    case io::Mesh_format::off: return ".off";
    case io::Mesh_format::ply: return ".ply";
  }
  return ".ply";
}

}  // namespace deformseg::internal

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

namespace deformseg::internal {

/// Creates `directory` and its parents when missing; throws invalid_input naming it otherwise.
inline void create_folder(const std::filesystem::path& directory) {
  std::error_code error;
  if (std::filesystem::exists(directory, error) && !std::filesystem::is_directory(directory, error))
    throw invalid_input("cannot write into it: it is not a folder", {.file = directory.string()});
  std::filesystem::create_directories(directory, error);
  if (error) throw invalid_input(join("cannot create the folder: ", error.message()), {.file = directory.string()});
}

/// Frame `frame` as the bytes of a file of `options.format`, in `bytes`, reused between frames.
template <class Graph, class Coordinate>
void format_frame(const Deforming_mesh<Graph, Coordinate>& animation, std::size_t frame,
                  const io::Sequence_write_options& options, const std::filesystem::path& file, std::string& bytes) {
  bytes.clear();
  if (options.format == io::Mesh_format::obj) {
    append_obj(animation, frame, bytes);
  } else if (options.format == io::Mesh_format::off) {
    append_off(animation, frame, bytes);
  } else {
    const std::vector<Rgb> colors = options.face_colors ? options.face_colors(frame) : std::vector<Rgb>{};
    check_face_colors(colors.size(), animation.num_faces(), file, frame);
    append_ply(animation, frame, std::span<const Rgb>(colors), options.ply_encoding, bytes);
  }
}

}  // namespace deformseg::internal

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
template <FaceGraph Graph, std::floating_point Coordinate>
std::vector<std::filesystem::path> write_sequence(const Deforming_mesh<Graph, Coordinate>& animation,
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

}  // namespace deformseg::io
