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

namespace deformseg::io {

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
  /// @throws invalid_input naming the file and the system's reason; `path` is then as it was.
  /// @par Complexity O(1).
  void commit() {
    guarded([&] { file_->close(); });
    if (!partial_) return;
    std::error_code error;
    std::filesystem::rename(*partial_, path_, error);
    if (error) throw invalid_input("cannot write: " + error.message(), {.file = path_.string()});
    partial_.reset();
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
