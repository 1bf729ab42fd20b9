// The character files that clips are read from, each parsed once for all its clips: the one parse
// cache of `describe` (store_describe.cpp) and `evaluate` (tools/deformseg/commands/evaluate.cpp).
#pragma once

#include "inputs.h"

#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>

#include <compare>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace deformseg::frontend {

/// A character file as clips are read from it: its path and the body they play on ("": the read
/// options' body, or the file's own).
struct Character_on_body {
  std::string file;
  std::string body{};
  auto operator<=>(const Character_on_body&) const = default;
};

/// Character files parsed (without a body) to list their clips, kept so that describing the clips
/// parses none of them again (`Clip_cache::adopt`). Up to `budget` bytes of files are kept; a file
/// beyond is parsed again when its clips are read.
class Listed_parses {
public:
  /// The default budget, 256 MiB of files.
  static constexpr std::uintmax_t default_budget = std::uintmax_t(256) << 20;

  /// Keeps files up to `budget` bytes in all (default `default_budget`).
  explicit Listed_parses(std::uintmax_t budget = default_budget) : budget_(budget) {}

  /// `file` parsed without a body and kept under its canonical path `path` (as clips name it) when
  /// its size keeps the parses within the budget (replacing an earlier parse of it); else null,
  /// null too when it cannot be parsed (listing it reads it again and says why).
  /// Complexity: the parse's, O(the file's size); nothing beyond the budget.
  std::shared_ptr<const io::Gltf_file> parse(const std::string& file, const std::string& path);

  /// The parse kept for the file at `path`, if any, taken out of this (null when none).
  std::shared_ptr<const io::Gltf_file> take(const std::string& path);

  /// Frees the parses still kept. Complexity O(files).
  void clear() {
    files_.clear();
    bytes_ = 0;
  }

  /// The bytes of files kept, never more than the budget.
  std::uintmax_t bytes() const noexcept { return bytes_; }

  /// How many parses are kept.
  std::size_t size() const noexcept { return files_.size(); }

private:
  struct Kept {
    std::shared_ptr<const io::Gltf_file> parsed;
    std::uintmax_t bytes = 0;
  };

  std::uintmax_t budget_;
  std::map<std::string, Kept> files_;  // by canonical path
  std::uintmax_t bytes_ = 0;
};

/// Each character file of a set of clips parsed once, on its body, by the first of its clips to be
/// read; its connectivity repaired once, by the first clip to ask for it; both freed after its last
/// clip is released, so that the files held at once are those whose clips are being read (clips of
/// several files may be read at once, on several threads). A parse or repair that fails throws
/// again for each of the file's clips, as reading each alone would.
///
/// Thread safety: `acquire`, `connectivity`, `release` and `parses_held` may be called from any
/// thread; the constructor and `adopt` before any of them.
class Clip_cache {
public:
  /// For `clips`, one entry per clip to be read (a file that is not a character file is not
  /// counted), read with `options` (their body, for a clip that names none).
  /// Complexity O(clips log files).
  Clip_cache(const std::vector<Character_on_body>& clips, const Input_options& options);

  /// Takes the parses of `listed` for the files of clips on no body (when `options` name none
  /// either: the listing parsed them so), and frees the others: a file with no clip to read.
  void adopt(Listed_parses& listed);

  /// The parse of `clip`'s file on its body, made when it is the first use.
  /// @pre `clip` is one of the constructor's, not released yet.
  /// @throws invalid_input (or what the parse threw) naming the file, for each clip of a file
  /// that cannot be parsed.
  std::shared_ptr<const io::Gltf_file> acquire(const Character_on_body& clip);

  /// The connectivity of `clip`'s file (acquired), repaired as `read_input` repairs it
  /// (`repair_options`), made when it is the first to ask.
  /// @pre `acquire(clip)` returned.
  /// @throws invalid_input naming the file, for each clip of a file whose repair fails.
  std::shared_ptr<const io::Gltf_connectivity> connectivity(const Character_on_body& clip);

  /// One clip of `clip`'s file read: after the file's last, its parse and connectivity are freed
  /// (those handed out live until their holders let them go).
  /// @pre `clip` is one of the constructor's, released at most once per time it was given.
  void release(const Character_on_body& clip);

  /// How many files are parsed and held now (for tests and reports). Complexity O(files).
  std::size_t parses_held() const;

  /// Releases a clip (`release`) when it goes out of scope: when it is read or has failed.
  class Release {
  public:
    /// Releases `clip` of `cache` at the end of the scope.
    Release(Clip_cache& cache, Character_on_body clip) : cache_(cache), clip_(std::move(clip)) {}
    Release(const Release&) = delete;
    Release& operator=(const Release&) = delete;
    ~Release() { cache_.release(clip_); }

  private:
    Clip_cache& cache_;
    Character_on_body clip_;
  };

private:
  struct File {
    mutable std::mutex mutex;
    std::shared_ptr<const io::Gltf_file> parsed;
    std::shared_ptr<const io::Gltf_connectivity> connectivity;  // refers to `parsed`
    std::exception_ptr parse_error, repair_error;
    std::size_t clips_left = 0;
  };

  std::map<Character_on_body, File> files_;  // made whole by the constructor, never added to after
  Input_options options_;
};

}  // namespace deformseg::frontend
