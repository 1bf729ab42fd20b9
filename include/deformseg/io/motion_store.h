/// @file io/motion_store.h
/// @brief A motion store: the descriptions of many clips kept in a folder, written once and read
/// back memory-mapped, so that a later search or matrix need not read and describe them again.
/// `Motion_store` reads one; `Store_append` adds and replaces clips as one transaction. The format
/// (a folder of `.npy` files and a JSON manifest, readable with NumPy alone) is described field by
/// field in doc/store_format.md (@ref store_format); `python/deformseg/store_format.py` is its
/// second reader.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/files.h>
#include <deformseg/io/internal/crc32.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/internal/npy.h>
#include <deformseg/io/internal/store_files.h>
#include <deformseg/similarity/motion_signature_view.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace deformseg::io {

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

class Store_append;

namespace internal {

inline constexpr std::string_view store_format_name = "deformseg-motion-store";
inline constexpr std::uint64_t store_version = 1;
inline constexpr std::uint64_t block_alignment_floats = 16;
inline constexpr std::uint64_t max_manifest_bytes = 4u << 20;
inline constexpr std::uint64_t max_width = 1u << 16;

/// The clip table's dtype (packed little-endian fields) and its fields' byte offsets.
inline constexpr std::string_view clip_table_descr =
    "[('segment', '<u8'), ('offset', '<u8'), ('rows', '<u4'), ('frames_offset', '<u8'), ('summary_row', '<u8'), "
    "('frame_count', '<u4'), ('fps', '<f8'), ('block_crc32', '<u4'), ('source_size', '<u8'), "
    "('source_mtime_ns', '<i8'), ('source_hash', '<u8'), ('topology_size', '<u8'), ('topology_mtime_ns', '<i8'), "
    "('strings', '<u8'), ('strings_length', '<u4')]";
inline constexpr std::size_t clip_row_bytes = 104;

/// One row of the clip table: a record's numbers, the offset of its strings in `strings-G.npy`.
struct Clip_row {
  Store_record numbers;  // the string members unused
  std::uint64_t strings = 0;
  std::uint32_t strings_length = 0;
};

inline void encode_clip_row(char* out, const Clip_row& row) {
  constexpr auto le = std::endian::little;
  const Store_record& r = row.numbers;
  store<le>(out + 0, r.block.generation);
  store<le>(out + 8, r.block.offset);
  store<le>(out + 16, r.rows);
  store<le>(out + 20, r.block.frames_offset);
  store<le>(out + 28, r.block.summary_row);
  store<le>(out + 36, r.frame_count);
  store<le>(out + 40, r.fps);
  store<le>(out + 48, r.block.crc32);
  store<le>(out + 52, r.source_size);
  store<le>(out + 60, r.source_mtime_ns);
  store<le>(out + 68, r.source_hash);
  store<le>(out + 76, r.topology_size);
  store<le>(out + 84, r.topology_mtime_ns);
  store<le>(out + 92, row.strings);
  store<le>(out + 100, row.strings_length);
}

inline Clip_row decode_clip_row(const char* in) {
  constexpr auto le = std::endian::little;
  Clip_row row;
  Store_record& r = row.numbers;
  r.block.generation = load<le, std::uint64_t>(in + 0);
  r.block.offset = load<le, std::uint64_t>(in + 8);
  r.rows = load<le, std::uint32_t>(in + 16);
  r.block.frames_offset = load<le, std::uint64_t>(in + 20);
  r.block.summary_row = load<le, std::uint64_t>(in + 28);
  r.frame_count = load<le, std::uint32_t>(in + 36);
  r.fps = load<le, double>(in + 40);
  r.block.crc32 = load<le, std::uint32_t>(in + 48);
  r.source_size = load<le, std::uint64_t>(in + 52);
  r.source_mtime_ns = load<le, std::int64_t>(in + 60);
  r.source_hash = load<le, std::uint64_t>(in + 68);
  r.topology_size = load<le, std::uint64_t>(in + 76);
  r.topology_mtime_ns = load<le, std::int64_t>(in + 84);
  row.strings = load<le, std::uint64_t>(in + 92);
  row.strings_length = load<le, std::uint32_t>(in + 100);
  return row;
}

/// The name of a store file of `kind` ("signatures", "clips", ...) of generation `generation`.
inline std::string store_file_name(std::string_view kind, std::uint64_t generation) {
  std::string digits = std::to_string(generation);
  if (digits.size() < 6) digits.insert(0, 6 - digits.size(), '0');
  return join(kind, "-", digits, ".npy");
}

/// True for the names of files a store's writer makes (data files, tables, temporary files):
/// those an append may remove when the manifest does not list them.
inline bool is_store_file_name(std::string_view name) {
  for (const std::string_view kind : {"signatures-", "frames-", "summaries-", "clips-", "strings-"})
    if (name.starts_with(kind)) return name.ends_with(".npy") || name.find(".npy.partial-") != std::string_view::npos;
  return name.starts_with("store.json.partial-");
}

/// A file the manifest lists: its size and the CRC-32 of its data (the bytes after its header).
struct Store_file {
  std::uint64_t bytes = 0;
  std::uint32_t data_crc32 = 0;
};

/// "clip 12 (/data/walk.glb#Walk)", as errors name a clip.
inline std::string clip_name(std::size_t index, std::string_view path, std::string_view clip) {
  std::string name = join("clip ", std::to_string(index), " (", path);
  if (!clip.empty()) name.append("#").append(clip);
  return name.append(")");
}

/// The manifest's checksum text for the manifest bytes before its "checksum" member.
inline std::string checksum_text(std::string_view covered) {
  char digits[9];
  const std::uint32_t crc = crc32(covered.data(), covered.size());
  constexpr char hex[] = "0123456789abcdef";
  for (int k = 0; k < 8; ++k) digits[k] = hex[(crc >> (28 - 4 * k)) & 0xFu];
  digits[8] = '\0';
  return join("crc32:", digits);
}

/// The manifest's end: its "checksum" member in the one form a reader accepts, for the bytes
/// `covered` before it, then the object's closing brace and a newline.
inline std::string checksum_suffix(std::string_view covered) {
  return join("\"checksum\": \"", checksum_text(covered), "\"}\n");
}

/// The size of `checksum_suffix`'s text.
inline constexpr std::size_t checksum_suffix_bytes = std::string_view(R"("checksum": "crc32:01234567"})").size() + 1;

/// The manifest's text: `object` (a JSON object without "checksum") indented by nlohmann's dump,
/// then its "checksum" member, which covers every byte before it.
inline std::string with_checksum(const nlohmann::ordered_json& object) {
  std::string text = object.dump(1);
  text.resize(text.rfind('}'));  // the closing brace, after "\n"
  text.back() = ',';
  text.append("\n ");
  return text.append(checksum_suffix(text));
}

/// The JSON of a store: nlohmann's, members kept in their order (the manifest's, the caller's
/// options'); numbers compare by value (3e-3 equals 0.003).
using Json = nlohmann::ordered_json;

/// The deepest nesting of a store's manifest: dumping and comparing values recurse. The options
/// it holds (its "description" and "summary") are nested one less.
inline constexpr int max_json_depth = 64;

/// The text of a nlohmann error without its "[json.exception...] " and "parse error at ...: " prefixes.
inline std::string json_error_text(const nlohmann::json::exception& e) {
  std::string_view text = e.what();
  if (const std::size_t at = text.find("] "); at != std::string_view::npos) text.remove_prefix(at + 2);
  if (text.starts_with("parse error"))
    if (const std::size_t at = text.find(": "); at != std::string_view::npos) text.remove_prefix(at + 2);
  return std::string(text);
}

/// Parses the JSON text `text` (RFC 8259, strict: nlohmann's parser), nested at most `most_depth` deep.
/// @throws invalid_input naming `file`, and the byte (from 0) where the text breaks for a syntax error.
inline Json parse_json(std::string_view text, const std::string& file, int most_depth = max_json_depth) {
  const auto shallow = [&](int depth, Json::parse_event_t event, Json&) {
    const bool opens = event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start;
    if (opens && depth >= most_depth)
      throw invalid_input(join("not valid here: JSON nested more than ", std::to_string(most_depth), " deep"),
                          {.file = file});
    return true;
  };
  try {
    return Json::parse(text, shallow);
  } catch (const Json::parse_error& e) {
    const std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;  // nlohmann counts the bytes read, the failing one too
    throw invalid_input(join("not valid JSON at byte ", std::to_string(byte), ": ", json_error_text(e)),
                        {.file = file});
  } catch (const Json::exception& e) {
    throw invalid_input(join("not valid JSON: ", json_error_text(e)), {.file = file});
  }
}

/// The compact text of `value` (nlohmann's dump), as errors and `Motion_store::description` give it.
inline std::string json_text(const Json& value) {
  return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

/// The first member name whose value differs between the objects `a` and `b` (in `a`'s order,
/// then the names only `b` has), or nothing when they hold the same members with the same values.
inline std::optional<std::string> first_different_member(const Json& a, const Json& b) {
  for (const auto& [key, value] : a.items())
    if (!b.contains(key) || b.at(key) != value) return key;
  for (const auto& [key, value] : b.items())
    if (!a.contains(key)) return key;
  return std::nullopt;
}

}  // namespace internal

/// @brief A motion store opened for reading: the descriptions of its clips, memory-mapped, their
/// records, and a lookup by (path, clip). Clip `i` is the `i`-th of the clip table; a clip keeps
/// its index across appends (a replaced one too), new clips come at the end.
///
/// The files of a store are never modified once written (an append writes new ones and a new
/// manifest), so an open store stays valid while others append; a mapping keeps a file readable
/// even after an append removes it. Copies share the mappings. Reading needs a little-endian
/// POSIX system (the blocks are mapped as they are).
///
/// @par Example
/// @include motion_store.cpp
class Motion_store {
public:
  /// @brief An empty store of no folder: `size() == 0`.
  Motion_store() = default;

  /// @brief Opens the store in `folder`, checking it (see `Verify`).
  /// @throws invalid_input naming the file (and the clip, where one is at fault) when the folder is
  /// not a store, is of a newer version, or is truncated or corrupted; the message says what and where.
  /// @par Complexity O(clips + files + manifest) with `Verify::structure`; plus O(bytes) with
  /// `Verify::checksums`. Memory O(clips) besides the mappings.
  static Motion_store open(const std::filesystem::path& folder, Verify verify = Verify::structure) {
    if constexpr (std::endian::native != std::endian::little)
      throw invalid_input("a motion store is read on little-endian machines only", {.file = folder.string()});
    try {
      return open_once(folder, verify);
    } catch (const internal::Store_file_vanished&) {
      // An append committed and removed a file after we read the manifest: its new manifest holds.
      try {
        return open_once(folder, verify);
      } catch (const internal::Store_file_vanished& vanished) {
        throw invalid_input("cannot open: no such file, though the manifest lists it", {.file = vanished.file});
      }
    }
  }

  /// @brief The store's folder.
  const std::filesystem::path& folder() const noexcept { return folder_; }
  /// @brief The number of appends committed (0 for an empty store of no folder).
  std::uint64_t generation() const noexcept { return generation_; }
  /// @brief The number of clips.
  std::size_t size() const noexcept { return entries_.size(); }
  /// @brief The values per signature, the same for every clip (0 while the store holds none).
  std::size_t width() const noexcept { return width_; }
  /// @brief The floats of each clip's summary (possibly 0).
  std::size_t summary_width() const noexcept { return summary_width_; }
  /// @brief The description's options the store was made with: a JSON object, as nlohmann::json's
  /// compact text (members in their order, no spaces: `{"policy":"motion-signature","width":64}`).
  const std::string& description() const noexcept { return description_; }
  /// @brief The layout of the summaries as their writer gave it: a JSON object, compact text as `description`'s.
  const std::string& summary_layout() const noexcept { return summary_layout_; }

  /// @brief Clip `i`'s signatures, `rows x width()` floats dimension-major, in the store's mapping.
  /// @pre `i < size()` (not checked). Valid while a copy of this store exists.
  /// @par Complexity O(1).
  similarity::Motion_signature_view view(std::size_t i) const {
    const Entry& e = entries_[i];
    return {segments_[e.segment].signatures + e.record.block.offset, e.record.rows, width_};
  }

  /// @brief Clip `i`'s frame numbers, one per row of its signatures.
  /// @pre `i < size()` (not checked). @par Complexity O(1).
  std::span<const std::uint32_t> frames(std::size_t i) const {
    const Entry& e = entries_[i];
    return {segments_[e.segment].frames + e.record.block.frames_offset, e.record.rows};
  }

  /// @brief Clip `i`'s summary: `summary_width()` floats, as its writer gave them.
  /// @pre `i < size()` (not checked). @par Complexity O(1).
  std::span<const float> summary(std::size_t i) const {
    const Entry& e = entries_[i];
    return {segments_[e.segment].summaries + e.record.block.summary_row * summary_width_, summary_width_};
  }

  /// @brief Clip `i`'s record, strings copied.
  /// @pre `i < size()` (not checked). @par Complexity O(its strings).
  Store_record record(std::size_t i) const {
    const Entry& e = entries_[i];
    Store_record r = e.record;
    r.path = e.path;
    r.clip = e.clip;
    r.input_options = e.input_options;
    r.topology_path = e.topology_path;
    return r;
  }

  /// @brief The index of the clip of `path` and `clip` ("" for a single-animation file), if any.
  /// @par Complexity O(log size()).
  std::optional<std::size_t> find(std::string_view path, std::string_view clip) const {
    const auto key = std::pair{path, clip};
    const auto at = std::lower_bound(by_key_.begin(), by_key_.end(), key, [&](std::size_t i, const auto& k) {
      return std::pair{entries_[i].path, entries_[i].clip} < k;
    });
    if (at == by_key_.end() || std::pair{entries_[*at].path, entries_[*at].clip} != key) return std::nullopt;
    return *at;
  }

private:
  friend class Store_append;

  struct Entry {
    Store_record record;  // numbers only; the strings are the views below
    std::size_t segment = 0;
    std::string_view path, clip, input_options, topology_path;
  };
  struct Segment {
    std::uint64_t generation = 0;
    std::shared_ptr<const internal::Mapped_file> files[3];
    const float* signatures = nullptr;
    const std::uint32_t* frames = nullptr;
    const float* summaries = nullptr;
    std::uint64_t floats = 0, frame_count = 0, summary_rows = 0;
  };
  struct Manifest {
    std::uint64_t generation = 0, width = 0, summary_width = 0, clips = 0;
    std::vector<std::uint64_t> segments;
    std::map<std::string, internal::Store_file> files;
    std::string description, summary_layout;
  };

  std::string path_of(std::string_view name) const { return (folder_ / name).string(); }

  static Motion_store open_once(const std::filesystem::path& folder, Verify verify) {
    Motion_store store;
    store.folder_ = folder;
    const Manifest manifest = store.read_manifest();
    store.generation_ = manifest.generation;
    store.width_ = manifest.width;
    store.summary_width_ = manifest.summary_width;
    store.description_ = manifest.description;
    store.summary_layout_ = manifest.summary_layout;
    store.files_ = manifest.files;
    store.map_tables(manifest);
    for (const std::uint64_t generation : manifest.segments) store.map_segment(generation, verify);
    store.read_clips(verify);
    return store;
  }

  // ---- The manifest --------------------------------------------------------------------------

  Manifest read_manifest() const {
    const std::string file = path_of("store.json");
    std::error_code error;
    if (!std::filesystem::is_directory(folder_, error))
      throw invalid_input("not a motion store: no such folder", {.file = folder_.string()});
    if (!std::filesystem::exists(folder_ / "store.json", error))
      throw invalid_input("not a motion store: the folder has no store.json", {.file = folder_.string()});
    const internal::File_bytes bytes =
        internal::read_file_bytes(folder_ / "store.json", internal::max_manifest_bytes + 1);
    if (bytes.file_size > internal::max_manifest_bytes)
      throw invalid_input(internal::join("a manifest of ", std::to_string(bytes.file_size),
                                         " bytes; a store's manifest has at most 4 MiB"),
                          {.file = file});
    const std::string_view text(bytes.begin(), bytes.size);
    const internal::Json json = internal::parse_json(text, file);
    return parse_manifest(json, text, file);
  }

  static const char* kind_name(internal::Json::value_t kind) {
    using V = internal::Json::value_t;
    return kind == V::object   ? "an object"
           : kind == V::array  ? "an array"
           : kind == V::string ? "a string"
                               : "a number";
  }

  // The member `key` of `object`, of `kind` (number_unsigned: any number).
  static const internal::Json& member(const internal::Json& object, std::string_view key, internal::Json::value_t kind,
                                      const std::string& file) {
    const auto value = object.find(std::string(key));
    const bool found = value != object.end();
    if (!found || (kind == internal::Json::value_t::number_unsigned ? !value->is_number() : value->type() != kind))
      throw invalid_input(internal::join("the manifest's \"", key, "\" is ", found ? "not " : "missing: it must be ",
                                         kind_name(kind)),
                          {.file = file});
    return *value;
  }

  static std::uint64_t count(const internal::Json& value, std::string_view what, const std::string& file,
                             std::uint64_t most = std::numeric_limits<std::uint64_t>::max()) {
    if (!value.is_number_unsigned() || value.get<std::uint64_t>() > most)
      throw invalid_input(internal::join("the manifest's ", what, " (", internal::json_text(value).substr(0, 40),
                                         ") is not a count of at most ", std::to_string(most)),
                          {.file = file});
    return value.get<std::uint64_t>();
  }

  static std::uint64_t count_member(const internal::Json& object, std::string_view key, const std::string& file,
                                    std::uint64_t most = std::numeric_limits<std::uint64_t>::max()) {
    return count(member(object, key, internal::Json::value_t::number_unsigned, file), internal::join("\"", key, "\""),
                 file, most);
  }

  // The manifest must end with its "checksum" member in the form `checksum_suffix` writes, whose
  // CRC-32 is that of every byte before it.
  static void check_format_and_checksum(const internal::Json& json, std::string_view text, const std::string& file) {
    const auto format = json.is_object() ? json.find("format") : json.end();
    if (format == json.end() || !format->is_string() ||
        format->get_ref<const std::string&>() != internal::store_format_name)
      throw invalid_input("not a motion store: its manifest has no \"format\": \"deformseg-motion-store\"",
                          {.file = file});
    const auto version = json.find("version");
    if (version == json.end() || !version->is_number_unsigned() || version->get<std::uint64_t>() == 0)
      throw invalid_input("the manifest's \"version\" is missing or not a positive count", {.file = file});
    const std::string newer = internal::join("store version ", internal::json_text(*version),
                                             " is newer than this deformseg, which reads version ",
                                             std::to_string(internal::store_version));
    const std::size_t covered = text.size() - std::min(text.size(), internal::checksum_suffix_bytes);
    const bool named = !json.empty() && std::prev(json.end()).key() == "checksum";
    const bool sums = named && text.substr(covered) == internal::checksum_suffix(text.substr(0, covered));
    if (version->get<std::uint64_t>() > internal::store_version)
      throw invalid_input(
          sums ? newer : internal::join(newer, " (or its manifest is corrupted: its checksum does not match)"),
          {.file = file});
    if (!sums)
      throw invalid_input(
          named ? "its checksum does not match its contents: the manifest is corrupted"
                : "the manifest does not end with its \"checksum\": it is corrupted or not written by deformseg",
          {.file = file});
  }

  Manifest parse_manifest(const internal::Json& json, std::string_view text, const std::string& file) const {
    using V = internal::Json::value_t;
    check_format_and_checksum(json, text, file);
    Manifest m;
    m.generation = count_member(json, "generation", file, 999'999'999);
    m.width = count_member(json, "width", file, internal::max_width);
    m.summary_width = count_member(json, "summary_width", file, internal::max_width);
    m.clips = count_member(json, "clips", file);
    m.description = internal::json_text(member(json, "description", V::object, file));
    m.summary_layout = internal::json_text(member(json, "summary", V::object, file));
    for (const internal::Json& g : member(json, "segments", V::array, file)) {
      const std::uint64_t generation = count(g, "segment", file, m.generation);
      if (generation == 0 || (!m.segments.empty() && generation <= m.segments.back()))
        throw invalid_input("the manifest's \"segments\" are not increasing generations from 1", {.file = file});
      m.segments.push_back(generation);
    }
    std::vector<std::string> expected{internal::store_file_name("clips", m.generation),
                                      internal::store_file_name("strings", m.generation)};
    for (const std::uint64_t g : m.segments)
      for (const char* kind : {"signatures", "frames", "summaries"})
        expected.push_back(internal::store_file_name(kind, g));
    for (const internal::Json& f : member(json, "files", V::array, file)) {
      if (!f.is_object())
        throw invalid_input("the manifest's \"files\" holds a value that is not an object", {.file = file});
      const std::string& name = member(f, "name", V::string, file).get_ref<const std::string&>();
      if (std::find(expected.begin(), expected.end(), name) == expected.end() || m.files.count(name))
        throw invalid_input(internal::join("the manifest lists \"", name.substr(0, 80),
                                           "\", which is not one of the store's files or is listed twice"),
                            {.file = file});
      m.files[name] = {count_member(f, "bytes", file),
                       static_cast<std::uint32_t>(count_member(f, "data_crc32", file, 0xFFFFFFFFu))};
    }
    for (const std::string& name : expected)
      if (!m.files.count(name))
        throw invalid_input(internal::join("the manifest does not list ", name, ", a file of the store"),
                            {.file = file});
    return m;
  }

  // ---- The files -----------------------------------------------------------------------------

  // Maps the listed file `name` and checks its header; returns the map and its rows.
  std::pair<std::shared_ptr<const internal::Mapped_file>, std::uint64_t> map_file(
      const std::string& name, std::string_view descr, std::size_t item_bytes, std::size_t dimensions,
      std::uint64_t columns, bool check_crc) const {
    const internal::Store_file& listed = files_.at(name);
    const std::string file = path_of(name);
    auto mapped = internal::Mapped_file::open(folder_ / name, listed.bytes);
    const std::uint64_t rows =
        internal::check_npy(mapped->data(), mapped->size(), file, descr, item_bytes, dimensions, columns);
    if (check_crc) {
      const std::size_t offset = mapped->size() - static_cast<std::size_t>(rows * item_bytes * columns);
      if (internal::crc32(mapped->data() + offset, mapped->size() - offset) != listed.data_crc32)
        throw invalid_input("its checksum does not match the manifest's: the file is corrupted", {.file = file});
    }
    return {std::move(mapped), rows};
  }

  static std::size_t data_offset(const internal::Mapped_file& f, std::uint64_t data_bytes) {
    return f.size() - static_cast<std::size_t>(data_bytes);
  }

  void map_tables(const Manifest& m) {
    const std::string clips_name = internal::store_file_name("clips", m.generation);
    auto [clips, rows] = map_file(clips_name, internal::clip_table_descr, internal::clip_row_bytes, 1, 1, true);
    if (rows != m.clips)
      throw invalid_input(
          internal::join("it holds ", std::to_string(rows), " clips, the manifest says ", std::to_string(m.clips)),
          {.file = path_of(clips_name)});
    auto [strings, bytes] = map_file(internal::store_file_name("strings", m.generation), "'|u1'", 1, 1, 1, true);
    clip_table_ = std::move(clips);
    clip_rows_ = rows;
    strings_ = std::move(strings);
    strings_bytes_ = bytes;
  }

  void map_segment(std::uint64_t generation, Verify verify) {
    const bool crc = verify == Verify::checksums;
    Segment s;
    s.generation = generation;
    auto [sig, floats] = map_file(internal::store_file_name("signatures", generation), "'<f4'", 4, 1, 1, crc);
    auto [fr, frame_count] = map_file(internal::store_file_name("frames", generation), "'<u4'", 4, 1, 1, crc);
    auto [su, summary_rows] =
        map_file(internal::store_file_name("summaries", generation), "'<f4'", 4, 2, summary_width_, crc);
    s.signatures = reinterpret_cast<const float*>(sig->data() + data_offset(*sig, floats * 4));
    s.frames = reinterpret_cast<const std::uint32_t*>(fr->data() + data_offset(*fr, frame_count * 4));
    s.summaries = reinterpret_cast<const float*>(su->data() + data_offset(*su, summary_rows * 4 * summary_width_));
    s.floats = floats;
    s.frame_count = frame_count;
    s.summary_rows = summary_rows;
    s.files[0] = std::move(sig);
    s.files[1] = std::move(fr);
    s.files[2] = std::move(su);
    segments_.push_back(std::move(s));
  }

  // ---- The clip table ------------------------------------------------------------------------

  [[noreturn]] void clip_error(const std::string& what) const {
    throw invalid_input(what, {.file = path_of(internal::store_file_name("clips", generation_))});
  }

  void read_strings(std::size_t i, std::uint64_t offset, std::uint32_t length, Entry& e) const {
    const char* base = strings_->data() + data_offset(*strings_, strings_bytes_);
    if (offset > strings_bytes_ || length > strings_bytes_ - offset)
      clip_error(internal::join("clip ", std::to_string(i), ": its strings at byte ", std::to_string(offset), " (",
                                std::to_string(length), " bytes) run past the end of ",
                                path_of(internal::store_file_name("strings", generation_))));
    std::string_view text(base + offset, length);
    std::string_view* parts[] = {&e.path, &e.clip, &e.input_options, &e.topology_path};
    for (std::string_view* part : parts) {
      const std::size_t end = text.find('\0');
      if (end == std::string_view::npos)
        clip_error(internal::join("clip ", std::to_string(i), ": its strings are not 4 NUL-terminated strings"));
      *part = text.substr(0, end);
      if (!internal::valid_utf8(*part))
        clip_error(internal::join("clip ", std::to_string(i), ": its strings are not valid UTF-8"));
      text.remove_prefix(end + 1);
    }
    if (!text.empty() || e.path.empty())
      clip_error(internal::join("clip ", std::to_string(i),
                                ": its strings are not 4 NUL-terminated strings, the path not empty"));
  }

  void check_entry(std::size_t i, const Entry& e, Verify verify) const {
    const Store_record& r = e.record;
    const std::string name = internal::clip_name(i, e.path, e.clip);
    const Segment& s = segments_[e.segment];
    const auto past = [&](std::string_view kind, std::string_view what) {
      clip_error(internal::join(name, ": ", what, " run past the end of ",
                                path_of(internal::store_file_name(kind, s.generation))));
    };
    if (r.rows == 0) clip_error(internal::join(name, ": 0 rows; a clip has at least one"));
    if (!(r.fps > 0) || !std::isfinite(r.fps)) clip_error(internal::join(name, ": its fps is not positive and finite"));
    if (r.block.offset % internal::block_alignment_floats != 0)
      clip_error(
          internal::join(name, ": its block at float ", std::to_string(r.block.offset), " is not 64-byte aligned"));
    const std::uint64_t floats = std::uint64_t{r.rows} * width_;
    if (r.block.offset > s.floats || floats > s.floats - r.block.offset)
      past("signatures", internal::join(std::to_string(r.rows), " rows of ", std::to_string(width_),
                                        " floats at float ", std::to_string(r.block.offset)));
    if (r.block.frames_offset > s.frame_count || r.rows > s.frame_count - r.block.frames_offset)
      past("frames",
           internal::join(std::to_string(r.rows), " frame numbers at ", std::to_string(r.block.frames_offset)));
    if (r.block.summary_row >= s.summary_rows)
      past("summaries", internal::join("its summary row ", std::to_string(r.block.summary_row), " would"));
    if (verify == Verify::checksums) {
      const similarity::Motion_signature_view v{s.signatures + r.block.offset, r.rows, width_};
      std::uint32_t crc = internal::crc32(v.values, floats * 4);
      crc = internal::crc32(s.frames + r.block.frames_offset, std::size_t{r.rows} * 4, crc);
      crc = internal::crc32(s.summaries + r.block.summary_row * summary_width_, summary_width_ * 4, crc);
      if (crc != r.block.crc32)
        clip_error(internal::join(name, ": its block's checksum does not match: its data in generation ",
                                  std::to_string(s.generation), " is corrupted"));
    }
  }

  void read_clips(Verify verify) {
    const auto rows = static_cast<std::size_t>(clip_rows_);
    const char* table = clip_table_->data() + data_offset(*clip_table_, rows * internal::clip_row_bytes);
    entries_.resize(rows);
    for (std::size_t i = 0; i < rows; ++i) {
      const internal::Clip_row row = internal::decode_clip_row(table + i * internal::clip_row_bytes);
      Entry& e = entries_[i];
      e.record = row.numbers;
      read_strings(i, row.strings, row.strings_length, e);
      const auto segment = std::lower_bound(segments_.begin(), segments_.end(), row.numbers.block.generation,
                                            [](const Segment& s, std::uint64_t g) { return s.generation < g; });
      if (segment == segments_.end() || segment->generation != row.numbers.block.generation)
        clip_error(internal::join(internal::clip_name(i, e.path, e.clip), ": its generation ",
                                  std::to_string(row.numbers.block.generation), " is not among the store's segments"));
      e.segment = static_cast<std::size_t>(segment - segments_.begin());
      check_entry(i, e, verify);
    }
    by_key_.resize(rows);
    for (std::size_t i = 0; i < rows; ++i) by_key_[i] = i;
    const auto key = [&](std::size_t i) { return std::pair{entries_[i].path, entries_[i].clip}; };
    std::sort(by_key_.begin(), by_key_.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    for (std::size_t k = 1; k < rows; ++k)
      if (key(by_key_[k - 1]) == key(by_key_[k]))
        clip_error(internal::join(internal::clip_name(by_key_[k], entries_[by_key_[k]].path, entries_[by_key_[k]].clip),
                                  ": the same clip as clip ", std::to_string(by_key_[k - 1])));
  }

  std::filesystem::path folder_;
  std::uint64_t generation_ = 0;
  std::size_t width_ = 0, summary_width_ = 0;
  std::string description_ = "{}", summary_layout_ = "{}";
  std::map<std::string, internal::Store_file> files_;
  std::shared_ptr<const internal::Mapped_file> clip_table_, strings_;
  std::uint64_t strings_bytes_ = 0, clip_rows_ = 0;
  std::vector<Segment> segments_;
  std::vector<Entry> entries_;
  std::vector<std::size_t> by_key_;
};

/// @brief Adds and replaces clips of a motion store as one transaction: all of them or none.
///
/// The constructor takes the store's lock (one writer at a time: a second `Store_append` on the
/// same folder, in any process, throws at once rather than waits), opens the store as it is (or
/// starts a new one in a missing or empty folder) and removes what killed appends left behind.
/// `add` and `replace` write the clips' data into new files; `commit` writes the new clip table
/// and the new manifest, whose rename is the commit point, flushed to the disk. Destroyed without
/// `commit` (an exception, a return), or killed at any point (even `kill -9`), the append leaves
/// the store as it was: the manifest in place references only files it did not touch.
///
/// @code
/// io::Store_append append(folder, R"({"policy": "motion-signature", "width": 64})", 0);
/// append.add(record, description_view, frames, {});
/// append.commit();
/// @endcode
class Store_append {
public:
  /// @brief Starts an append to the store in `folder`.
  /// @param folder The store's folder; a missing or empty folder (created when missing) gets a new store.
  /// @param description_json The options the descriptions were made with, a JSON object nested at
  /// most 63 deep: a new store records it; an existing one must hold the same members with the same
  /// values (numbers compared by value: 3e-3 equals 0.003).
  /// @param summary_width The floats of every clip's summary (0 for none); an existing store's must be equal.
  /// @param summary_json How the summaries are laid out, a JSON object (nested at most 63 deep) the
  /// store keeps and does not interpret (default `{}`); an existing store's must be equal.
  /// @throws invalid_input naming the folder or file when another append holds the lock, the folder
  /// holds other files and no store, the store cannot be read, or the options differ from the
  /// store's (naming the first member that differs).
  /// @par Complexity that of `Motion_store::open`, plus the folder's listing.
  Store_append(const std::filesystem::path& folder, std::string_view description_json, std::size_t summary_width,
               std::string_view summary_json = "{}")
      : folder_(folder), summary_width_(summary_width) {
    if constexpr (std::endian::native != std::endian::little)
      throw invalid_input("a motion store is written on little-endian machines only", {.file = folder.string()});
    create_folder(folder_);
    lock_ = std::make_unique<internal::File_lock>(folder_ / "lock");
    description_ = parse_object(description_json, "the description's options");
    summary_layout_ = parse_object(summary_json, "the summary's layout");
    if (summary_width > internal::max_width)
      throw invalid_input("a summary of more than 65536 floats", {.file = folder_.string()});
    std::error_code error;
    if (std::filesystem::exists(folder_ / "store.json", error)) {
      base_ = Motion_store::open(folder_);
      check_same_options();
    } else {
      check_no_other_files();
    }
    width_ = base_.width();
    generation_ = base_.generation() + 1;
    remove_unlisted_files();
  }

  Store_append(const Store_append&) = delete;
  Store_append& operator=(const Store_append&) = delete;

  /// @brief Leaves the store as it was unless `commit` was called; removes the new data files.
  ~Store_append() = default;

  /// @brief The store as it was when the append started (for finding clips to replace).
  const Motion_store& store() const noexcept { return base_; }

  /// @brief The number of clips the store will hold once committed.
  std::size_t size() const noexcept { return base_.size() + added_.size(); }

  /// @brief Adds a clip at the end: its record (strings and source fields; `rows` and `block` are
  /// set by the store), its signatures, one frame number per row, and its summary.
  /// @pre `view.rows >= 1`, `view.width` equal to the store's (any, for the first clip of a new
  /// store), `frames.size() == view.rows`, `summary.size() == summary_width`; `record.path` not
  /// empty; the strings valid UTF-8 without NUL; `record.fps` positive and finite; no clip of the
  /// same (path, clip) in the store or in this append (replace it instead).
  /// @returns its index. @throws invalid_input naming the clip when a precondition fails.
  /// @par Complexity O(its floats) (written to the new data file).
  std::size_t add(Store_record record, similarity::Motion_signature_view view, std::span<const std::uint32_t> frames,
                  std::span<const float> summary) {
    const std::size_t index = size();
    check_clip(index, record, view, frames, summary);
    if (base_.find(record.path, record.clip) || added_keys_.count({record.path, record.clip}))
      throw invalid_input(internal::join(internal::clip_name(index, record.path, record.clip),
                                         ": the store already holds this clip; replace it rather than add it"),
                          {.file = folder_.string()});
    write_block(record, view, frames, summary);
    added_keys_[{record.path, record.clip}] = index;
    added_.push_back(std::move(record));
    return index;
  }

  /// @brief Replaces clip `index` (of the store or of this append) by a new description of the same
  /// (path, clip), keeping its index: as `add` otherwise.
  /// @pre `index < size()`, and the record names the same path and clip as the one it replaces.
  /// @throws invalid_input naming the clip when a precondition fails.
  /// @par Complexity O(its floats).
  void replace(std::size_t index, Store_record record, similarity::Motion_signature_view view,
               std::span<const std::uint32_t> frames, std::span<const float> summary) {
    if (index >= size())
      throw invalid_input(internal::join("cannot replace clip ", std::to_string(index), ": the store will hold ",
                                         std::to_string(size()), " clips"),
                          {.file = folder_.string()});
    check_clip(index, record, view, frames, summary);
    const Store_record old = index < base_.size() ? base_.record(index) : added_[index - base_.size()];
    if (old.path != record.path || old.clip != record.clip)
      throw invalid_input(internal::join(internal::clip_name(index, old.path, old.clip), ": cannot be replaced by ",
                                         internal::clip_name(index, record.path, record.clip), ", another clip"),
                          {.file = folder_.string()});
    write_block(record, view, frames, summary);
    if (index < base_.size()) replaced_[index] = std::move(record);
    else added_[index - base_.size()] = std::move(record);
  }

  /// @brief Makes the clips added and replaced part of the store, all at once, flushed to the disk;
  /// then removes the files no longer referenced and releases the lock. Nothing happens when nothing
  /// was added or replaced to a store that exists.
  /// @pre Not called before. @throws invalid_input naming the file that cannot be written; the
  /// store is then as it was.
  /// @par Complexity O(clips + their strings), plus the flushes.
  void commit() {
    if (committed_) throw invalid_input("this append is already committed", {.file = folder_.string()});
    if (base_.generation() > 0 && added_.empty() && replaced_.empty()) {
      finish_commit();
      return;
    }
    std::map<std::string, internal::Store_file> files;
    if (signatures_) {
      finish_data_file(*signatures_, files);
      finish_data_file(*frames_, files);
      finish_data_file(*summaries_, files);
    }
    std::string strings;
    std::string table = clip_table(strings);
    write_table("clips", internal::clip_table_descr, std::move(table), internal::clip_row_bytes, files);
    write_table("strings", "'|u1'", std::move(strings), 1, files);
    std::vector<std::uint64_t> segments = referenced_segments();
    for (const std::uint64_t g : segments)
      for (const char* kind : {"signatures", "frames", "summaries"})
        if (g != generation_)
          files[internal::store_file_name(kind, g)] = base_.files_.at(internal::store_file_name(kind, g));
    Atomic_file manifest(folder_ / "store.json");
    manifest.write(manifest_text(segments, files));
    manifest.commit(Durability::disk);
    remove_replaced_files(files);
    finish_commit();
  }

private:
  using Key = std::pair<std::string, std::string>;

  internal::Json parse_object(std::string_view json, std::string_view what) const {
    internal::Json value = internal::parse_json(json, folder_.string(), internal::max_json_depth - 1);
    if (!value.is_object())
      throw invalid_input(internal::join(what, " must be a JSON object"), {.file = folder_.string()});
    return value;
  }

  void check_same_options() const {
    const std::string file = (folder_ / "store.json").string();
    const internal::Json stored = internal::parse_json(base_.description(), file);
    if (const auto key = internal::first_different_member(stored, description_)) {
      const auto value = [&](const internal::Json& object) {
        return object.contains(*key) ? internal::json_text(object.at(*key)) : std::string("not given");
      };
      throw invalid_input(internal::join("the store was described with other options: \"", *key, "\" is ",
                                         value(stored), " in the store, ", value(description_),
                                         " in this append; a store holds descriptions made with one set of options"),
                          {.file = file});
    }
    const internal::Json layout = internal::parse_json(base_.summary_layout(), file);
    if (base_.summary_width() != summary_width_ || internal::first_different_member(layout, summary_layout_))
      throw invalid_input(
          internal::join("the store's summaries are of another layout (", std::to_string(base_.summary_width()),
                         " floats, ", base_.summary_layout(), ") than this append's (", std::to_string(summary_width_),
                         " floats, ", internal::json_text(summary_layout_), ")"),
          {.file = file});
  }

  void check_no_other_files() const {
    for (const auto& entry : std::filesystem::directory_iterator(folder_)) {
      const std::string name = entry.path().filename().string();
      if (name != "lock" && !internal::is_store_file_name(name))
        throw invalid_input(internal::join("not a motion store: the folder has no store.json and holds other files (",
                                           name, "); a new store is made in a missing or empty folder"),
                            {.file = folder_.string()});
    }
  }

  // The files of killed appends: store files that the manifest does not list.
  void remove_unlisted_files() const {
    std::vector<std::filesystem::path> orphans;
    for (const auto& entry : std::filesystem::directory_iterator(folder_)) {
      const std::string name = entry.path().filename().string();
      if (internal::is_store_file_name(name) && !base_.files_.count(name)) orphans.push_back(entry.path());
    }
    for (const auto& path : orphans) {
      std::error_code error;
      std::filesystem::remove(path, error);
    }
  }

  void check_clip(std::size_t index, const Store_record& r, const similarity::Motion_signature_view& view,
                  std::span<const std::uint32_t> frames, std::span<const float> summary) {
    const std::string name = internal::clip_name(index, r.path, r.clip);
    const auto fail = [&](const std::string& what) {
      throw invalid_input(internal::join(name, ": ", what), {.file = folder_.string()});
    };
    if (committed_) fail("the append is already committed");
    if (r.path.empty()) fail("its path is empty");
    for (const std::string* text : {&r.path, &r.clip, &r.input_options, &r.topology_path})
      if (text->find('\0') != std::string::npos || !internal::valid_utf8(*text))
        fail("a string that is not UTF-8 without NUL");
    if (!(r.fps > 0) || !std::isfinite(r.fps)) fail("its fps is not positive and finite");
    if (view.rows == 0 || view.rows > std::numeric_limits<std::uint32_t>::max())
      fail("its description has no row, or more than 2^32 - 1");
    if (view.width == 0 || view.width > internal::max_width)
      fail("its description has no value per row, or more than 65536");
    if (width_ != 0 && view.width != width_)
      fail(internal::join("its description has ", std::to_string(view.width), " values per row, the store's ",
                          std::to_string(width_)));
    if (frames.size() != view.rows)
      fail(internal::join(std::to_string(frames.size()), " frame numbers for ", std::to_string(view.rows), " rows"));
    if (summary.size() != summary_width_)
      fail(internal::join("a summary of ", std::to_string(summary.size()), " floats, the store's have ",
                          std::to_string(summary_width_)));
  }

  void open_data_files() {
    const auto path = [&](const char* kind) { return folder_ / internal::store_file_name(kind, generation_); };
    signatures_ = std::make_unique<internal::Npy_writer>(path("signatures"), "'<f4'", 4, 1, false);
    frames_ = std::make_unique<internal::Npy_writer>(path("frames"), "'<u4'", 4, 1, false);
    summaries_ = std::make_unique<internal::Npy_writer>(path("summaries"), "'<f4'", 4, summary_width_, true);
  }

  void write_block(Store_record& r, const similarity::Motion_signature_view& view,
                   std::span<const std::uint32_t> frames, std::span<const float> summary) {
    if (!signatures_) open_data_files();
    width_ = view.width;
    const std::uint64_t padding =
        (internal::block_alignment_floats - signatures_->items() % internal::block_alignment_floats) %
        internal::block_alignment_floats;
    const float zeros[internal::block_alignment_floats] = {};
    signatures_->append(zeros, padding);
    r.rows = static_cast<std::uint32_t>(view.rows);
    r.block = {.generation = generation_, .offset = signatures_->items(), .frames_offset = frames_->items(),
               .summary_row = summary_rows_++, .crc32 = 0};
    const std::uint64_t floats = std::uint64_t{view.rows} * view.width;
    signatures_->append(view.values, floats);
    frames_->append(frames.data(), frames.size());
    summaries_->append(summary.data(), summary.size());
    summaries_->add_row();
    std::uint32_t crc = internal::crc32(view.values, floats * 4);
    crc = internal::crc32(frames.data(), frames.size() * 4, crc);
    r.block.crc32 = internal::crc32(summary.data(), summary.size() * 4, crc);
  }

  void finish_data_file(internal::Npy_writer& writer, std::map<std::string, internal::Store_file>& files) {
    const std::uint64_t bytes = writer.finish();
    files[writer.path().filename().string()] = {bytes, writer.data_crc32()};
  }

  // The clip table of every clip after the commit, and their strings into `strings`.
  std::string clip_table(std::string& strings) const {
    std::string table(size() * internal::clip_row_bytes, '\0');
    for (std::size_t i = 0; i < size(); ++i) {
      const auto replaced = replaced_.find(i);
      const Store_record r = i >= base_.size()          ? added_[i - base_.size()]
                             : replaced != replaced_.end() ? replaced->second
                                                           : base_.record(i);
      internal::Clip_row row{r, strings.size(), 0};
      for (const std::string* text : {&r.path, &r.clip, &r.input_options, &r.topology_path})
        strings.append(*text).push_back('\0');
      row.strings_length = static_cast<std::uint32_t>(strings.size() - row.strings);
      internal::encode_clip_row(table.data() + i * internal::clip_row_bytes, row);
    }
    return table;
  }

  void write_table(const char* kind, std::string_view descr, std::string data, std::size_t item_bytes,
                   std::map<std::string, internal::Store_file>& files) const {
    const std::string name = internal::store_file_name(kind, generation_);
    const std::uint64_t shape[1] = {data.size() / item_bytes};
    const std::string header = internal::npy_header(descr, shape);
    Atomic_file out(folder_ / name);
    out.write(header);
    out.write(data);
    out.commit(Durability::disk);
    files[name] = {header.size() + data.size(), internal::crc32(data.data(), data.size())};
  }

  std::vector<std::uint64_t> referenced_segments() const {
    std::vector<std::uint64_t> segments;
    for (std::size_t i = 0; i < size(); ++i) {
      const auto replaced = replaced_.find(i);
      segments.push_back(i >= base_.size() || replaced != replaced_.end() ? generation_
                                                                          : base_.entries_[i].record.block.generation);
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    return segments;
  }

  std::string manifest_text(const std::vector<std::uint64_t>& segments,
                            const std::map<std::string, internal::Store_file>& files) const {
    internal::Json manifest;
    manifest["format"] = std::string(internal::store_format_name);
    manifest["version"] = internal::store_version;
    manifest["generation"] = generation_;
    manifest["width"] = width_;
    manifest["summary_width"] = summary_width_;
    manifest["clips"] = size();
    manifest["description"] = description_;
    manifest["summary"] = summary_layout_;
    manifest["segments"] = segments;
    internal::Json& listed = manifest["files"] = internal::Json::array();
    for (const auto& [name, file] : files)
      listed.push_back({{"name", name}, {"bytes", file.bytes}, {"data_crc32", file.data_crc32}});
    return internal::with_checksum(manifest);
  }

  // The previous generation's files that the new manifest does not list; its clip table and
  // strings stay, for a reader that has just read the previous manifest (the next append removes them).
  void remove_replaced_files(const std::map<std::string, internal::Store_file>& files) const {
    for (const auto& [name, file] : base_.files_) {
      if (files.count(name) || name == internal::store_file_name("clips", base_.generation()) ||
          name == internal::store_file_name("strings", base_.generation()))
        continue;
      std::error_code error;
      std::filesystem::remove(folder_ / name, error);
    }
  }

  void finish_commit() {
    committed_ = true;
    signatures_.reset();
    frames_.reset();
    summaries_.reset();
    lock_.reset();
  }

  std::filesystem::path folder_;
  std::size_t summary_width_ = 0, width_ = 0;
  std::uint64_t generation_ = 0, summary_rows_ = 0;
  std::unique_ptr<internal::File_lock> lock_;
  internal::Json description_, summary_layout_;
  Motion_store base_;
  std::vector<Store_record> added_;
  std::map<std::size_t, Store_record> replaced_;
  std::map<Key, std::size_t> added_keys_;
  std::unique_ptr<internal::Npy_writer> signatures_, frames_, summaries_;
  bool committed_ = false;
};

}  // namespace deformseg::io
