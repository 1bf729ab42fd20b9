/// @file io/files.h
/// @brief Files written whole or not at all, the folders they go into, and the text of numbers
/// that read back exactly: what every writer of the library and of the `deformseg` tool uses.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/file_io.h>

#include <atomic>
#include <chrono>
#include <concepts>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace deformseg::io {

/// @brief How far `Atomic_file::commit` carries the file before it returns.
enum class Durability {
  /// @brief The file is renamed into place; its bytes are in the system's page cache, which a
  /// killed process does not lose but a power failure may (the default: no wait for the disk).
  page_cache,
  /// @brief The file's bytes are flushed to the disk (fsync) before the rename, and the folder's
  /// entry after it, so that after a power failure the path holds either the old or the new
  /// file whole. What a commit point needs, such as a motion store's manifest (store/motion_store.h).
  disk
};

namespace internal {
/// Flushes the file or folder `path` to the disk (fsync); throws invalid_input naming it.
inline void flush_to_disk(const std::filesystem::path& path, bool folder) {
  const int fd = ::open(path.c_str(), (folder ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const std::string reason = last_system_error();
    if (fd >= 0) ::close(fd);
    throw invalid_input("cannot flush to the disk: " + reason, {.file = path.string()});
  }
  ::close(fd);
}
}  // namespace internal

/// @brief A file written piece by piece, whole or not at all: the pieces go into a temporary file
/// beside it, renamed over it by `commit`, so that an interrupted write (a full disk, a killed
/// process, an exception before `commit`) leaves what was there intact. A path that exists and
/// is not a regular file (a device such as /dev/null, a pipe) is written directly.
///
/// @code
/// io::Atomic_file out("distances.csv");
/// for (const std::string& line : lines) out.write(line);
/// out.commit();
/// @endcode
///
/// @par Example
/// @include atomic_file.cpp
class Atomic_file {
public:
  /// @brief Opens the temporary file for `path`, whose folder must exist.
  /// @throws invalid_input naming `path` when it is a folder or cannot be written.
  /// @par Complexity O(1).
  explicit Atomic_file(const std::filesystem::path& path) : path_(path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
      throw invalid_input("cannot write: it is a folder, not a file", {.file = path.string()});
    const bool special = std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error);
    if (!special) {
      static std::atomic<unsigned long> opened{0};
      partial_ = path;
      *partial_ += ".partial-" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()) + "-" +
                   std::to_string(opened++);
    }
    guarded([&] { file_ = std::make_unique<internal::Streamed_file>(partial_.value_or(path)); });
  }

  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;

  /// @brief Removes the temporary file unless `commit` was called: the file at `path` is as it was.
  ~Atomic_file() {
    file_.reset();
    std::error_code error;
    if (partial_) std::filesystem::remove(*partial_, error);
  }

  /// @brief Appends `bytes`.
  /// @throws invalid_input naming the file and the system's reason.
  /// @par Complexity O(bytes).
  void write(std::string_view bytes) {
    guarded([&] { file_->write(bytes); });
  }

  /// @brief Closes the file and puts it in the place of `path`.
  /// @param durability `Durability::page_cache` (the default) returns once the file is renamed;
  /// `Durability::disk` also flushes the file to the disk before the rename and its folder after
  /// (POSIX fsync), so that the rename survives a power failure.
  /// @throws invalid_input naming the file and the system's reason; `path` is then as it was
  /// (with `Durability::disk`, unless only the folder's flush failed: the file is then in place).
  /// @par Complexity O(1), plus the time the disk takes with `Durability::disk`.
  void commit(Durability durability = Durability::page_cache) {
    guarded([&] { file_->close(); });
    if (!partial_) return;
    if (durability == Durability::disk) guarded([&] { internal::flush_to_disk(*partial_, false); });
    std::error_code error;
    std::filesystem::rename(*partial_, path_, error);
    if (error) throw invalid_input("cannot write: " + error.message(), {.file = path_.string()});
    partial_.reset();
    if (durability == Durability::disk) {
      const std::filesystem::path folder = path_.has_parent_path() ? path_.parent_path() : ".";
      internal::flush_to_disk(folder, true);
    }
  }

private:
  // Errors name the file the caller named, not the temporary one.
  template <class Step>
  void guarded(const Step& step) {
    try {
      step();
    } catch (const invalid_input& e) {
      throw invalid_input(e.message(), {.file = path_.string()});
    }
  }

  std::filesystem::path path_;
  std::optional<std::filesystem::path> partial_;
  std::unique_ptr<internal::Streamed_file> file_;
};

/// @brief Writes `bytes` to `path`, replacing the file, whole or not at all (see `Atomic_file`).
/// @throws invalid_input naming the file and the system's reason; `path` is then as it was.
/// @par Complexity O(bytes).
inline void write_file(const std::filesystem::path& path, std::string_view bytes) {
  Atomic_file file(path);
  file.write(bytes);
  file.commit();
}

/// @brief Creates the folder `directory` and its parents when missing.
/// @throws invalid_input naming it when it is a file, or cannot be created.
/// @par Complexity O(depth of the path).
inline void create_folder(const std::filesystem::path& directory) { internal::create_folder(directory); }

/// @brief Appends to `out` the shortest decimal text that reads back, as `T`, to `value` exactly
/// (the rule of every number the library writes).
/// @par Complexity O(1).
template <std::floating_point T>
void append_shortest(std::string& out, T value) {
  internal::append_shortest(out, value);
}

}  // namespace deformseg::io
