/// @file store/store_record.h
/// @brief What a motion store keeps of a clip: its record (`Store_record`: source file, clip, read
/// options, staleness keys, frames) and where its data is (`Store_block`); how far opening a store
/// verifies it (`Verify`); and `hash_file`, the hash of a source file a record keeps.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/store/internal/file_io.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace deformseg::store {

/// @brief Where a clip's data is in a motion store: set by the store, ignored by `Store_append`.
struct Store_block {
  /// @brief The generation (the append) whose data files hold the clip: `signatures-G.npy`,
  /// `frames-G.npy`, `summaries-G.npy`, G written with 6 digits or more.
  std::uint64_t generation = 0;
  /// @brief The index of the block's first float in `signatures-G.npy`, a multiple of 16 (64 bytes).
  std::uint64_t offset = 0;
  /// @brief The index of the clip's first frame number in `frames-G.npy`.
  std::uint64_t frames_offset = 0;
  /// @brief The clip's row in `summaries-G.npy`.
  std::uint64_t summary_row = 0;
  /// @brief The CRC-32 (zlib's) of the block's signature bytes, then its frame numbers, then its summary.
  std::uint32_t crc32 = 0;
};

/// @brief What a motion store records of one clip besides its description: where it came from,
/// so that a later append can tell an unchanged clip from a changed one, and where its data is.
/// The store keeps the values as given; it interprets none of them but `rows` and `block`.
struct Store_record {
  /// @brief The source file's path, canonical and absolute as the caller gives it; not empty.
  std::string path;
  /// @brief The clip's name in the file; "" for a file of a single animation.
  std::string clip;
  /// @brief The options the clip was read with, as the caller spells them canonically.
  std::string input_options;
  /// @brief The source file's size in bytes.
  std::uint64_t source_size = 0;
  /// @brief The source file's modification time, in nanoseconds since the epoch.
  std::int64_t source_mtime_ns = 0;
  /// @brief A hash of the source file's bytes (`hash_file`), or 0 for none.
  std::uint64_t source_hash = 0;
  /// @brief The path of the file the clip was read with besides its source, "" for none: the
  /// topology (mesh) of a point cache, or the body a character file's clip played on.
  std::string topology_path;
  /// @brief The topology file's size in bytes (0 without one).
  std::uint64_t topology_size = 0;
  /// @brief The topology file's modification time in nanoseconds (0 without one).
  std::int64_t topology_mtime_ns = 0;
  /// @brief The clip's number of frames T.
  std::uint32_t frame_count = 0;
  /// @brief The clip's frames per second; positive and finite.
  double fps = 0;
  /// @brief The described instants R (rows of its signatures): set by the store from the view.
  std::uint32_t rows = 0;
  /// @brief Where its data is: set by the store.
  Store_block block;
};

/// @brief What `Motion_store::open` checks beyond the structure.
enum class Verify {
  /// @brief The manifest, the `.npy` headers and sizes, every record's ranges and strings, and the
  /// checksums of the manifest, the clip table and the strings (all small): O(clips), the default.
  structure,
  /// @brief Also the CRC-32 of every data file and every clip's block: reads every byte.
  checksums
};

/// @brief A 64-bit hash of the bytes of the file `path` (FNV-1a, never 0: 0 means "no hash" in a
/// `Store_record`), for telling a changed source file from a touched one.
/// @throws invalid_input naming the file when it cannot be read.
/// @par Complexity O(file size), in chunks of 1 MiB.
inline std::uint64_t hash_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_input(internal::join("cannot open: ", internal::last_system_error()), {.file = path.string()});
  std::uint64_t hash = 0xcbf29ce484222325ull;
  std::vector<char> chunk(1u << 20);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    for (std::streamsize k = 0; k < in.gcount(); ++k)
      hash = (hash ^ static_cast<unsigned char>(chunk[static_cast<std::size_t>(k)])) * 0x100000001b3ull;
  }
  if (in.bad()) throw invalid_input("cannot read it: a read failed", {.file = path.string()});
  return hash == 0 ? 1 : hash;
}

}  // namespace deformseg::store
