/// @file store/motion_store.h
/// @brief A motion store: the descriptions of many clips kept in a folder, written once and read
/// back memory-mapped, so that a later search or matrix need not read and describe them again.
/// `Motion_store` reads one; `Store_append` (store/store_append.h) adds and replaces clips as one
/// transaction. The format (a folder of `.npy` files and a JSON manifest, readable with NumPy
/// alone) is described field by field in doc/store_format.md (@ref store_format); `python/deformseg/store_format.py` is its
/// second reader.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/io/character_files.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/store/internal/manifest.h>
#include <deformseg/store/internal/npy.h>
#include <deformseg/store/internal/store_files.h>
#include <deformseg/store/store_record.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

namespace deformseg::store {

/// @brief A motion store opened for reading: the descriptions of its clips, memory-mapped, their
/// records, and a lookup by (path, clip, body): one clip played on N bodies is N clips of the
/// store. Clip `i` is the `i`-th of the clip table; a clip keeps its index across appends (a
/// replaced one too), new clips come at the end.
///
/// Stores of version 1 (before bodies were part of the key) are read: a record of a character file
/// (`io::is_character_file`: glTF, FBX, Collada, BVH) whose `topology_path` names a file is read with
/// that file as its body (version 1 kept the body there; a character file has no other topology),
/// any other record body-less. The next append that adds or replaces a clip writes the store as
/// version 2.
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
  /// @brief The format's version the store was written in: 1 (clips keyed by path and clip) or 2
  /// (by path, clip and body); an empty store of no folder gives the version appends write.
  std::uint64_t version() const noexcept { return version_; }
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
  signatures::Motion_signature_view view(std::size_t i) const {
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

  /// @brief Checks clip `i`'s block (its signatures, frame numbers and summary) against the checksum
  /// its writer recorded: what `Verify::checksums` checks of every clip on opening, for one clip, so
  /// that a reader of a few clips verifies what it reads at the cost of reading it once.
  /// @pre `i < size()` (not checked).
  /// @throws invalid_input naming the clip table's file and the clip when the block was changed
  /// since it was written ("its block's checksum does not match").
  /// @par Complexity O(rows × width() + summary_width()).
  void verify_clip(std::size_t i) const {
    const Entry& e = entries_[i];
    const Store_record& r = e.record;
    const Segment& s = segments_[e.segment];
    std::uint32_t crc = internal::crc32(s.signatures + r.block.offset, std::size_t{r.rows} * width_ * 4);
    crc = internal::crc32(s.frames + r.block.frames_offset, std::size_t{r.rows} * 4, crc);
    crc = internal::crc32(s.summaries + r.block.summary_row * summary_width_, summary_width_ * 4, crc);
    if (crc != r.block.crc32)
      clip_error(deformseg::internal::join(internal::clip_name(i, e.path, e.clip, e.body),
                                           ": its block's checksum does not match: its data in generation ",
                                           std::to_string(s.generation), " is corrupted"));
  }

  /// @brief Clip `i`'s record, strings copied.
  /// @pre `i < size()` (not checked). @par Complexity O(its strings).
  Store_record record(std::size_t i) const {
    const Entry& e = entries_[i];
    Store_record r = e.record;
    r.path = e.path;
    r.clip = e.clip;
    r.body = e.body;
    r.input_options = e.input_options;
    r.topology_path = e.topology_path;
    return r;
  }

  /// @brief The index of the clip of `path` and `clip` ("" for a single-animation file) played on
  /// `body` (default "": its own file's body), if any: the key of `Store_record`.
  /// @par Complexity O(log size()).
  std::optional<std::size_t> find(std::string_view path, std::string_view clip, std::string_view body = {}) const {
    const Key key{path, clip, body};
    const auto at = std::lower_bound(by_key_.begin(), by_key_.end(), key,
                                     [&](std::size_t i, const Key& k) { return key_of(i) < k; });
    if (at == by_key_.end() || key_of(*at) != key) return std::nullopt;
    return *at;
  }

private:
  friend class Store_append;

  struct Entry {
    Store_record record;  // numbers only; the strings are the views below
    std::size_t segment = 0;
    std::string_view path, clip, input_options, topology_path, body;
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
    std::uint64_t version = 0, generation = 0, width = 0, summary_width = 0, clips = 0;
    std::vector<std::uint64_t> segments;
    std::map<std::string, internal::Store_file> files;
    std::string description, summary_layout;
  };

  std::string path_of(std::string_view name) const { return (folder_ / name).string(); }

  // A clip's key, which no two clips share: (path, clip, body).
  using Key = std::tuple<std::string_view, std::string_view, std::string_view>;
  Key key_of(std::size_t i) const { return {entries_[i].path, entries_[i].clip, entries_[i].body}; }

  static Motion_store open_once(const std::filesystem::path& folder, Verify verify) {
    Motion_store store;
    store.folder_ = folder;
    const Manifest manifest = store.read_manifest();
    store.version_ = manifest.version;
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
    const deformseg::internal::File_bytes bytes =
        deformseg::internal::read_file_bytes(folder_ / "store.json", internal::max_manifest_bytes + 1);
    if (bytes.file_size > internal::max_manifest_bytes)
      throw invalid_input(deformseg::internal::join("a manifest of ", std::to_string(bytes.file_size),
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
      throw invalid_input(deformseg::internal::join("the manifest's \"", key, "\" is ",
                                                    found ? "not " : "missing: it must be ", kind_name(kind)),
                          {.file = file});
    return *value;
  }

  static std::uint64_t count(const internal::Json& value, std::string_view what, const std::string& file,
                             std::uint64_t most = std::numeric_limits<std::uint64_t>::max()) {
    if (!value.is_number_unsigned() || value.get<std::uint64_t>() > most)
      throw invalid_input(
          deformseg::internal::join("the manifest's ", what, " (", internal::json_text(value).substr(0, 40),
                                    ") is not a count of at most ", std::to_string(most)),
          {.file = file});
    return value.get<std::uint64_t>();
  }

  static std::uint64_t count_member(const internal::Json& object, std::string_view key, const std::string& file,
                                    std::uint64_t most = std::numeric_limits<std::uint64_t>::max()) {
    return count(member(object, key, internal::Json::value_t::number_unsigned, file),
                 deformseg::internal::join("\"", key, "\""), file, most);
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
    const std::string newer = deformseg::internal::join("store version ", internal::json_text(*version),
                                                        " is newer than this deformseg, which reads version ",
                                                        std::to_string(internal::store_version));
    const std::size_t covered = text.size() - std::min(text.size(), internal::checksum_suffix_bytes);
    const bool named = !json.empty() && std::prev(json.end()).key() == "checksum";
    const bool sums = named && text.substr(covered) == internal::checksum_suffix(text.substr(0, covered));
    if (version->get<std::uint64_t>() > internal::store_version)
      throw invalid_input(
          sums ? newer
               : deformseg::internal::join(newer, " (or its manifest is corrupted: its checksum does not match)"),
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
    m.version = json.at("version").get<std::uint64_t>();
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
        throw invalid_input(deformseg::internal::join("the manifest lists \"", name.substr(0, 80),
                                                      "\", which is not one of the store's files or is listed twice"),
                            {.file = file});
      m.files[name] = {count_member(f, "bytes", file),
                       static_cast<std::uint32_t>(count_member(f, "data_crc32", file, 0xFFFFFFFFu))};
    }
    for (const std::string& name : expected)
      if (!m.files.count(name))
        throw invalid_input(deformseg::internal::join("the manifest does not list ", name, ", a file of the store"),
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
      throw invalid_input(deformseg::internal::join("it holds ", std::to_string(rows), " clips, the manifest says ",
                                                    std::to_string(m.clips)),
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
      clip_error(deformseg::internal::join("clip ", std::to_string(i), ": its strings at byte ", std::to_string(offset),
                                           " (", std::to_string(length), " bytes) run past the end of ",
                                           path_of(internal::store_file_name("strings", generation_))));
    std::string_view text(base + offset, length);
    const std::size_t count = internal::clip_string_count(version_);
    const std::string expected = deformseg::internal::join(std::to_string(count), " NUL-terminated strings");
    std::string_view* parts[] = {&e.path, &e.clip, &e.input_options, &e.topology_path, &e.body};
    for (std::string_view* part : std::span(parts).first(count)) {
      const std::size_t end = text.find('\0');
      if (end == std::string_view::npos)
        clip_error(deformseg::internal::join("clip ", std::to_string(i), ": its strings are not ", expected));
      *part = text.substr(0, end);
      if (!internal::valid_utf8(*part))
        clip_error(deformseg::internal::join("clip ", std::to_string(i), ": its strings are not valid UTF-8"));
      text.remove_prefix(end + 1);
    }
    if (!text.empty() || e.path.empty())
      clip_error(deformseg::internal::join("clip ", std::to_string(i), ": its strings are not ", expected,
                                           ", the path not empty"));
    if (version_ < 2 && io::is_character_file(e.path)) e.body = e.topology_path;  // where version 1 kept the body
  }

  void check_entry(std::size_t i, const Entry& e, Verify verify) const {
    const Store_record& r = e.record;
    const std::string name = internal::clip_name(i, e.path, e.clip, e.body);
    const Segment& s = segments_[e.segment];
    const auto past = [&](std::string_view kind, std::string_view what) {
      clip_error(deformseg::internal::join(name, ": ", what, " run past the end of ",
                                           path_of(internal::store_file_name(kind, s.generation))));
    };
    if (r.rows == 0) clip_error(deformseg::internal::join(name, ": 0 rows; a clip has at least one"));
    if (!(r.fps > 0) || !std::isfinite(r.fps))
      clip_error(deformseg::internal::join(name, ": its fps is not positive and finite"));
    if (r.block.offset % internal::block_alignment_floats != 0)
      clip_error(deformseg::internal::join(name, ": its block at float ", std::to_string(r.block.offset),
                                           " is not 64-byte aligned"));
    const std::uint64_t floats = std::uint64_t{r.rows} * width_;
    if (r.block.offset > s.floats || floats > s.floats - r.block.offset)
      past("signatures", deformseg::internal::join(std::to_string(r.rows), " rows of ", std::to_string(width_),
                                                   " floats at float ", std::to_string(r.block.offset)));
    if (r.block.frames_offset > s.frame_count || r.rows > s.frame_count - r.block.frames_offset)
      past("frames", deformseg::internal::join(std::to_string(r.rows), " frame numbers at ",
                                               std::to_string(r.block.frames_offset)));
    if (r.block.summary_row >= s.summary_rows)
      past("summaries", deformseg::internal::join("its summary row ", std::to_string(r.block.summary_row), " would"));
    if (verify == Verify::checksums) verify_clip(i);
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
        clip_error(deformseg::internal::join(internal::clip_name(i, e.path, e.clip, e.body), ": its generation ",
                                             std::to_string(row.numbers.block.generation),
                                             " is not among the store's segments"));
      e.segment = static_cast<std::size_t>(segment - segments_.begin());
      check_entry(i, e, verify);
    }
    by_key_.resize(rows);
    for (std::size_t i = 0; i < rows; ++i) by_key_[i] = i;
    std::sort(by_key_.begin(), by_key_.end(), [&](std::size_t a, std::size_t b) { return key_of(a) < key_of(b); });
    for (std::size_t k = 1; k < rows; ++k)
      if (key_of(by_key_[k - 1]) == key_of(by_key_[k])) {
        const Entry& e = entries_[by_key_[k]];
        clip_error(deformseg::internal::join(internal::clip_name(by_key_[k], e.path, e.clip, e.body),
                                             ": the same clip as clip ", std::to_string(by_key_[k - 1])));
      }
  }

  std::filesystem::path folder_;
  std::uint64_t version_ = internal::store_version, generation_ = 0;
  std::size_t width_ = 0, summary_width_ = 0;
  std::string description_ = "{}", summary_layout_ = "{}";
  std::map<std::string, internal::Store_file> files_;
  std::shared_ptr<const internal::Mapped_file> clip_table_, strings_;
  std::uint64_t strings_bytes_ = 0, clip_rows_ = 0;
  std::vector<Segment> segments_;
  std::vector<Entry> entries_;
  std::vector<std::size_t> by_key_;
};

}  // namespace deformseg::store
