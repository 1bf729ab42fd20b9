/// @file store/store_record.h
/// @brief What a motion store keeps of a clip: its record (`Store_record`: source file, clip, body,
/// read options, staleness keys, frames) and where its data is (`Store_block`); how far opening a store
/// verifies it (`Verify`); `hash_file`, the hash of a source file a record keeps; and
/// `escaped_name`, the UTF-8 text of a name of any bytes, which its record keeps.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/store/internal/utf8.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
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

/// @brief What a motion store records of one clip besides its description: which clip it is
/// (`path`, `clip` and `body`, its key in the store), where it came from, so that a later append can
/// tell an unchanged clip from a changed one, and where its data is. The store keeps the values as
/// given; it interprets none of them but the key, `rows` and `block`. Its strings are UTF-8 without
/// NUL: a name of other bytes (a POSIX file name may be any) is given as `escaped_name` writes it.
struct Store_record {
  /// @brief The source file's path, canonical and absolute as the caller gives it; not empty.
  std::string path;
  /// @brief The clip's name in the file; "" for a file of a single animation.
  std::string clip;
  /// @brief The character file whose body the clip played on, canonical and absolute as the caller
  /// gives it; "" for none (the clip's own file's body, or a file that is not a character file).
  /// A store holds a clip once per body: (path, clip, body) is its key.
  std::string body;
  /// @brief The options the clip was read with, as the caller spells them canonically.
  std::string input_options;
  /// @brief The source file's size in bytes.
  std::uint64_t source_size = 0;
  /// @brief The source file's modification time, in nanoseconds since the epoch.
  std::int64_t source_mtime_ns = 0;
  /// @brief A hash of the source file's bytes (`hash_file`), or 0 for none.
  std::uint64_t source_hash = 0;
  /// @brief The path of the file the clip was read with besides its source, "" for none: the
  /// topology (mesh) of a point cache, or the body a character file's clip played on (then equal to
  /// `body`: its size and time below are the body file's staleness stamp).
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

/// @brief Whether `text` is valid UTF-8 (no overlong form, no surrogate, at most U+10FFFF), as a
/// store's strings must be.
/// @par Complexity O(size of `text`).
/// @par Example
/// @include escaped_name.cpp
inline bool is_utf8(std::string_view text) noexcept { return internal::valid_utf8(text); }

/// @brief `name` (a file's path, a clip's name) as UTF-8 text, which a store's strings must be,
/// whatever its bytes (a POSIX file name is any bytes but '/' and NUL: a Latin-1 name, say): its
/// bytes as they are, but a backslash written `\\` and each byte that is not part of a valid UTF-8
/// sequence written `\xHH` (two upper-case hexadecimal digits); `unescaped_name` reads it back.
/// A name of valid UTF-8 without a backslash is kept as it is.
/// @par Example
/// The Latin-1 file name café.glb, whose é is the one byte E9 (not UTF-8), is kept as `caf\xE9.glb`;
/// in UTF-8 (é the bytes C3 A9) as `café.glb`; the name `a\b` as `a\\b`:
/// @include escaped_name.cpp
/// @par Complexity O(size of `name`).
inline std::string escaped_name(std::string_view name) { return deformseg::internal::escaped_bytes(name, false); }

/// @brief The bytes of the name `escaped_name` wrote as `text`: `\\` a backslash, `\xHH` the byte
/// HH; a backslash in any other sequence is kept as it is. `unescaped_name(escaped_name(s)) == s`
/// for any bytes s.
/// @par Complexity O(size of `text`).
/// @par Example
/// @include escaped_name.cpp
inline std::string unescaped_name(std::string_view text) {
  const auto digit = [](char c) -> int {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
  };
  std::string name;
  name.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '\\') {
      name.push_back('\\');
      ++i;
    } else if (text[i] == '\\' && i + 3 < text.size() && text[i + 1] == 'x' && digit(text[i + 2]) >= 0 &&
               digit(text[i + 3]) >= 0) {
      name.push_back(static_cast<char>(digit(text[i + 2]) * 16 + digit(text[i + 3])));
      i += 3;
    } else {
      name.push_back(text[i]);
    }
  }
  return name;
}

/// @brief A 64-bit hash of the bytes of the file `path` (FNV-1a, never 0: 0 means "no hash" in a
/// `Store_record`), for telling a changed source file from a touched one.
/// @throws invalid_input naming the file when it cannot be read.
/// @par Complexity O(file size), in chunks of 1 MiB.
inline std::uint64_t hash_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw invalid_input(deformseg::internal::join("cannot open: ", deformseg::internal::last_system_error()),
                        {.file = path.string()});
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
