// The encodings of a motion store's files (store/motion_store.h): the clip table's fixed rows,
// the data files' names, the checksums of the manifest and the clip table, the manifest's JSON.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/store/internal/crc32.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/store/store_record.h>

#include <nlohmann/json.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

namespace deformseg::store::internal {

inline constexpr std::string_view store_format_name = "deformseg-motion-store";
// Version 2 keys a clip by its body too: its strings are five (path, clip, input options, topology
// path, body), version 1's four. Version 1 stores are read, and become version 2 at their next append.
inline constexpr std::uint64_t store_version = 2;
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
  using deformseg::internal::store_word;
  const Store_record& r = row.numbers;
  store_word<le>(out + 0, r.block.generation);
  store_word<le>(out + 8, r.block.offset);
  store_word<le>(out + 16, r.rows);
  store_word<le>(out + 20, r.block.frames_offset);
  store_word<le>(out + 28, r.block.summary_row);
  store_word<le>(out + 36, r.frame_count);
  store_word<le>(out + 40, r.fps);
  store_word<le>(out + 48, r.block.crc32);
  store_word<le>(out + 52, r.source_size);
  store_word<le>(out + 60, r.source_mtime_ns);
  store_word<le>(out + 68, r.source_hash);
  store_word<le>(out + 76, r.topology_size);
  store_word<le>(out + 84, r.topology_mtime_ns);
  store_word<le>(out + 92, row.strings);
  store_word<le>(out + 100, row.strings_length);
}

inline Clip_row decode_clip_row(const char* in) {
  constexpr auto le = std::endian::little;
  using deformseg::internal::load_word;
  Clip_row row;
  Store_record& r = row.numbers;
  r.block.generation = load_word<le, std::uint64_t>(in + 0);
  r.block.offset = load_word<le, std::uint64_t>(in + 8);
  r.rows = load_word<le, std::uint32_t>(in + 16);
  r.block.frames_offset = load_word<le, std::uint64_t>(in + 20);
  r.block.summary_row = load_word<le, std::uint64_t>(in + 28);
  r.frame_count = load_word<le, std::uint32_t>(in + 36);
  r.fps = load_word<le, double>(in + 40);
  r.block.crc32 = load_word<le, std::uint32_t>(in + 48);
  r.source_size = load_word<le, std::uint64_t>(in + 52);
  r.source_mtime_ns = load_word<le, std::int64_t>(in + 60);
  r.source_hash = load_word<le, std::uint64_t>(in + 68);
  r.topology_size = load_word<le, std::uint64_t>(in + 76);
  r.topology_mtime_ns = load_word<le, std::int64_t>(in + 84);
  row.strings = load_word<le, std::uint64_t>(in + 92);
  row.strings_length = load_word<le, std::uint32_t>(in + 100);
  return row;
}

/// The name of a store file of `kind` ("signatures", "clips", ...) of generation `generation`.
inline std::string store_file_name(std::string_view kind, std::uint64_t generation) {
  std::string digits = std::to_string(generation);
  if (digits.size() < 6) digits.insert(0, 6 - digits.size(), '0');
  return deformseg::internal::join(kind, "-", digits, ".npy");
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

/// The strings of a clip in `strings-G.npy` of a store of `version`: path, clip, input options,
/// topology path, and from version 2 on, body.
inline constexpr std::size_t clip_string_count(std::uint64_t version) { return version >= 2 ? 5 : 4; }

/// "clip 12 (/data/walk.glb#Walk on /data/body.glb)", as errors name a clip (" on BODY" when it has one).
inline std::string clip_name(std::size_t index, std::string_view path, std::string_view clip, std::string_view body) {
  std::string name = deformseg::internal::join("clip ", std::to_string(index), " (", path);
  if (!clip.empty()) name.append("#").append(clip);
  if (!body.empty()) name.append(" on ").append(body);
  return name.append(")");
}

/// The manifest's checksum text for the manifest bytes before its "checksum" member.
inline std::string checksum_text(std::string_view covered) {
  char digits[9];
  const std::uint32_t crc = crc32(covered.data(), covered.size());
  constexpr char hex[] = "0123456789abcdef";
  for (int k = 0; k < 8; ++k) digits[k] = hex[(crc >> (28 - 4 * k)) & 0xFu];
  digits[8] = '\0';
  return deformseg::internal::join("crc32:", digits);
}

/// The manifest's end: its "checksum" member in the one form a reader accepts, for the bytes
/// `covered` before it, then the object's closing brace and a newline.
inline std::string checksum_suffix(std::string_view covered) {
  return deformseg::internal::join("\"checksum\": \"", checksum_text(covered), "\"}\n");
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
      throw invalid_input(
          deformseg::internal::join("not valid here: JSON nested more than ", std::to_string(most_depth), " deep"),
          {.file = file});
    return true;
  };
  try {
    return Json::parse(text, shallow);
  } catch (const Json::parse_error& e) {
    const std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;  // nlohmann counts the bytes read, the failing one too
    throw invalid_input(
        deformseg::internal::join("not valid JSON at byte ", std::to_string(byte), ": ", json_error_text(e)),
        {.file = file});
  } catch (const Json::exception& e) {
    throw invalid_input(deformseg::internal::join("not valid JSON: ", json_error_text(e)), {.file = file});
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

}  // namespace deformseg::store::internal
