/// @file store/store_append.h
/// @brief `Store_append`: clips added to and replaced in a motion store as one transaction, all
/// of them or none, with one writer at a time.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/io/files.h>
#include <deformseg/signatures/motion_signature_view.h>
#include <deformseg/store/internal/manifest.h>
#include <deformseg/store/internal/npy.h>
#include <deformseg/store/internal/store_files.h>
#include <deformseg/store/motion_store.h>
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
/// store::Store_append append(folder, R"({"policy": "motion-signature", "width": 64})", 0);
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
    io::create_folder(folder_);
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

  /// @brief The index of the clip of this path, clip and body, in the store or among the clips this
  /// append added (so that a clip met twice in one append is replaced, not added twice); none if absent.
  /// @par Complexity O(log n) string comparisons.
  std::optional<std::size_t> find(std::string_view path, std::string_view clip, std::string_view body = {}) const {
    if (const std::optional<std::size_t> at = base_.find(path, clip, body)) return at;
    const auto added = added_keys_.find(Key{path, clip, body});
    if (added == added_keys_.end()) return std::nullopt;
    return added->second;
  }

  /// @brief Adds a clip at the end: its record (strings and source fields; `rows` and `block` are
  /// set by the store), its signatures, one frame number per row, and its summary.
  /// @pre `view.rows >= 1`, `view.width` equal to the store's (any, for the first clip of a new
  /// store), `frames.size() == view.rows`, `summary.size() == summary_width`; `record.path` not
  /// empty; the strings valid UTF-8 without NUL; `record.fps` positive and finite; no clip of the
  /// same (path, clip, body) in the store or in this append (replace it instead): the same clip on
  /// another body is another clip.
  /// @returns its index. @throws invalid_input naming the clip when a precondition fails.
  /// @par Complexity O(its floats) (written to the new data file).
  std::size_t add(Store_record record, signatures::Motion_signature_view view, std::span<const std::uint32_t> frames,
                  std::span<const float> summary) {
    const std::size_t index = size();
    check_clip(index, record, view, frames, summary);
    if (base_.find(record.path, record.clip, record.body) || added_keys_.count(key_of(record)))
      throw invalid_input(
          deformseg::internal::join(internal::clip_name(index, record.path, record.clip, record.body),
                                    ": the store already holds this clip; replace it rather than add it"),
          {.file = folder_.string()});
    write_block(record, view, frames, summary);
    added_keys_[key_of(record)] = index;
    added_.push_back(std::move(record));
    return index;
  }

  /// @brief Replaces clip `index` (of the store or of this append) by a new description of the same
  /// (path, clip, body), keeping its index: as `add` otherwise.
  /// @pre `index < size()`, and the record names the same path, clip and body as the one it replaces.
  /// @throws invalid_input naming the clip when a precondition fails.
  /// @par Complexity O(its floats).
  void replace(std::size_t index, Store_record record, signatures::Motion_signature_view view,
               std::span<const std::uint32_t> frames, std::span<const float> summary) {
    if (index >= size())
      throw invalid_input(deformseg::internal::join("cannot replace clip ", std::to_string(index),
                                                    ": the store will hold ", std::to_string(size()), " clips"),
                          {.file = folder_.string()});
    check_clip(index, record, view, frames, summary);
    const Store_record old = index < base_.size() ? base_.record(index) : added_[index - base_.size()];
    if (key_of(old) != key_of(record))
      throw invalid_input(deformseg::internal::join(
                              internal::clip_name(index, old.path, old.clip, old.body), ": cannot be replaced by ",
                              internal::clip_name(index, record.path, record.clip, record.body), ", another clip"),
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
    io::Atomic_file manifest(folder_ / "store.json");
    manifest.write(manifest_text(segments, files));
    manifest.commit(io::Durability::disk);
    remove_replaced_files(files);
    finish_commit();
  }

private:
  using Key = std::tuple<std::string, std::string, std::string>;

  static Key key_of(const Store_record& r) { return {r.path, r.clip, r.body}; }

  internal::Json parse_object(std::string_view json, std::string_view what) const {
    internal::Json value = internal::parse_json(json, folder_.string(), internal::max_json_depth - 1);
    if (!value.is_object())
      throw invalid_input(deformseg::internal::join(what, " must be a JSON object"), {.file = folder_.string()});
    return value;
  }

  void check_same_options() const {
    const std::string file = (folder_ / "store.json").string();
    const internal::Json stored = internal::parse_json(base_.description(), file);
    if (const auto key = internal::first_different_member(stored, description_)) {
      const auto value = [&](const internal::Json& object) {
        return object.contains(*key) ? internal::json_text(object.at(*key)) : std::string("not given");
      };
      throw invalid_input(
          deformseg::internal::join("the store was described with other options: \"", *key, "\" is ", value(stored),
                                    " in the store, ", value(description_),
                                    " in this append; a store holds descriptions made with one set of options"),
          {.file = file});
    }
    const internal::Json layout = internal::parse_json(base_.summary_layout(), file);
    if (base_.summary_width() != summary_width_ || internal::first_different_member(layout, summary_layout_))
      throw invalid_input(deformseg::internal::join(
                              "the store's summaries are of another layout (", std::to_string(base_.summary_width()),
                              " floats, ", base_.summary_layout(), ") than this append's (",
                              std::to_string(summary_width_), " floats, ", internal::json_text(summary_layout_), ")"),
                          {.file = file});
  }

  void check_no_other_files() const {
    for (const auto& entry : std::filesystem::directory_iterator(folder_)) {
      const std::string name = entry.path().filename().string();
      if (name != "lock" && !internal::is_store_file_name(name))
        throw invalid_input(
            deformseg::internal::join("not a motion store: the folder has no store.json and holds other files (", name,
                                      "); a new store is made in a missing or empty folder"),
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

  void check_clip(std::size_t index, const Store_record& r, const signatures::Motion_signature_view& view,
                  std::span<const std::uint32_t> frames, std::span<const float> summary) {
    const std::string name = internal::clip_name(index, r.path, r.clip, r.body);
    const auto fail = [&](const std::string& what) {
      throw invalid_input(deformseg::internal::join(name, ": ", what), {.file = folder_.string()});
    };
    if (committed_) fail("the append is already committed");
    if (r.path.empty()) fail("its path is empty");
    for (const std::string* text : {&r.path, &r.clip, &r.input_options, &r.topology_path, &r.body})
      if (text->find('\0') != std::string::npos || !internal::valid_utf8(*text))
        fail("a string that is not UTF-8 without NUL");
    if (!(r.fps > 0) || !std::isfinite(r.fps)) fail("its fps is not positive and finite");
    if (view.rows == 0 || view.rows > std::numeric_limits<std::uint32_t>::max())
      fail("its description has no row, or more than 2^32 - 1");
    if (view.width == 0 || view.width > internal::max_width)
      fail("its description has no value per row, or more than 65536");
    if (width_ != 0 && view.width != width_)
      fail(deformseg::internal::join("its description has ", std::to_string(view.width),
                                     " values per row, the store's ", std::to_string(width_)));
    if (frames.size() != view.rows)
      fail(deformseg::internal::join(std::to_string(frames.size()), " frame numbers for ", std::to_string(view.rows),
                                     " rows"));
    if (summary.size() != summary_width_)
      fail(deformseg::internal::join("a summary of ", std::to_string(summary.size()), " floats, the store's have ",
                                     std::to_string(summary_width_)));
  }

  void open_data_files() {
    const auto path = [&](const char* kind) { return folder_ / internal::store_file_name(kind, generation_); };
    signatures_ = std::make_unique<internal::Npy_writer>(path("signatures"), "'<f4'", 4, 1, false);
    frames_ = std::make_unique<internal::Npy_writer>(path("frames"), "'<u4'", 4, 1, false);
    summaries_ = std::make_unique<internal::Npy_writer>(path("summaries"), "'<f4'", 4, summary_width_, true);
  }

  void write_block(Store_record& r, const signatures::Motion_signature_view& view,
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
      for (const std::string* text : {&r.path, &r.clip, &r.input_options, &r.topology_path, &r.body})
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
    io::Atomic_file out(folder_ / name);
    out.write(header);
    out.write(data);
    out.commit(io::Durability::disk);
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

}  // namespace deformseg::store
