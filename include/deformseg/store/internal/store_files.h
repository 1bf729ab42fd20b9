// The POSIX files of a motion store (store/motion_store.h): read-only memory maps of its immutable
// files, the writer's lock, and a data file written in pieces whose .npy header is filled in last.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/store/internal/crc32.h>
#include <deformseg/internal/file_io.h>
#include <deformseg/store/internal/npy.h>
#include <deformseg/store/internal/utf8.h>

#include <cerrno>
#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace deformseg::store::internal {

/// Thrown (and caught by the store's `open`, which retries once) when a file the manifest lists
/// is missing: an append may have committed and removed it after the manifest was read.
struct Store_file_vanished {
  std::string file;
};

/// A file mapped read-only into memory, whole; unmapped when the last owner goes. A mapping keeps
/// the file's bytes readable after the file is unlinked.
class Mapped_file {
public:
  /// Maps `path`, which must have exactly `expected_bytes` bytes.
  static std::shared_ptr<const Mapped_file> open(const std::filesystem::path& path, std::uint64_t expected_bytes) {
    const std::string file = path.string();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
      if (errno == ENOENT) throw Store_file_vanished{file};
      throw invalid_input(deformseg::internal::join("cannot open: ", deformseg::internal::last_system_error()),
                          {.file = file});
    }
    struct ::stat status {};
    if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
      ::close(fd);
      throw invalid_input("cannot read it: not a regular file", {.file = file});
    }
    const auto bytes = static_cast<std::uint64_t>(status.st_size);
    if (bytes != expected_bytes) {
      ::close(fd);
      throw invalid_input(
          deformseg::internal::join(std::to_string(bytes), " bytes, the manifest says ", std::to_string(expected_bytes),
                                    bytes < expected_bytes ? ": truncated" : ": longer than written"),
          {.file = file});
    }
    auto mapped = std::shared_ptr<Mapped_file>(new Mapped_file);
    mapped->size_ = static_cast<std::size_t>(bytes);
    if (bytes > 0) {
      void* address = ::mmap(nullptr, mapped->size_, PROT_READ, MAP_SHARED, fd, 0);
      if (address == MAP_FAILED) {
        const std::string reason = deformseg::internal::last_system_error();
        ::close(fd);
        throw invalid_input(deformseg::internal::join("cannot map it into memory: ", reason), {.file = file});
      }
      mapped->data_ = static_cast<const char*>(address);
    }
    ::close(fd);  // the mapping keeps the file
    return mapped;
  }

  Mapped_file(const Mapped_file&) = delete;
  Mapped_file& operator=(const Mapped_file&) = delete;
  ~Mapped_file() {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }

  const char* data() const noexcept { return data_; }
  std::size_t size() const noexcept { return size_; }

private:
  Mapped_file() = default;
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

/// An exclusive lock on the file `path` (created when missing), held until destruction: flock,
/// so that the system releases it when the holder dies, even by kill -9.
class File_lock {
public:
  explicit File_lock(const std::filesystem::path& path) {
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw invalid_input(
          deformseg::internal::join("cannot open the store's lock file: ", deformseg::internal::last_system_error()),
          {.file = path.string()});
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const bool busy = errno == EWOULDBLOCK;
      const std::string reason = deformseg::internal::last_system_error();
      ::close(fd_);
      throw invalid_input(
          busy ? "another append to this store is running (it holds this lock file); one writer at a time"
               : deformseg::internal::join("cannot lock the store: ", reason),
          {.file = path.string()});
    }
  }
  File_lock(const File_lock&) = delete;
  File_lock& operator=(const File_lock&) = delete;
  ~File_lock() { ::close(fd_); }  // closing releases the lock

private:
  int fd_ = -1;
};

/// A 1-D or 2-D .npy array of `descr` written in pieces into a temporary file beside `path`, its
/// header (room reserved for the largest shape) written last by `finish`, then renamed into place;
/// removed if never finished. Keeps the CRC-32 of the data bytes (after the header).
class Npy_writer {
public:
  static constexpr std::size_t header_bytes = 128;

  Npy_writer(std::filesystem::path path, std::string descr, std::size_t item_bytes, std::uint64_t columns, bool two_d)
      : path_(std::move(path)), descr_(std::move(descr)), item_bytes_(item_bytes), columns_(columns), two_d_(two_d) {
    partial_ = path_;
    partial_ += ".partial-" + std::to_string(::getpid());
    fd_ = ::open(partial_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) fail(deformseg::internal::join("cannot write: ", deformseg::internal::last_system_error()));
    const std::string zeros(header_bytes, ' ');
    put(zeros.data(), zeros.size());
  }
  Npy_writer(const Npy_writer&) = delete;
  Npy_writer& operator=(const Npy_writer&) = delete;
  ~Npy_writer() {
    if (fd_ >= 0) ::close(fd_);
    if (!finished_) ::unlink(partial_.c_str());
  }

  /// Appends `count` items of `item_bytes` (little-endian already) from `data`.
  void append(const void* data, std::uint64_t count) {
    put(data, count * item_bytes_);
    data_crc_ = crc32(data, count * item_bytes_, data_crc_);
    items_ += count;
  }

  /// The items written so far.
  std::uint64_t items() const noexcept { return items_; }

  /// Writes the header, flushes the file to the disk, renames it into place; returns its bytes.
  std::uint64_t finish() {
    const std::uint64_t rows = two_d_ ? rows_ : items_;
    const std::uint64_t shape[2] = {rows, columns_};
    const std::string header = npy_header(descr_, std::span<const std::uint64_t>(shape, two_d_ ? 2 : 1), header_bytes);
    if (header.size() != header_bytes) fail("internal: a .npy header longer than the room reserved for it");
    if (::pwrite(fd_, header.data(), header.size(), 0) != static_cast<ssize_t>(header.size()) || ::fsync(fd_) != 0 ||
        ::close(fd_) != 0) {
      fd_ = -1;
      fail(deformseg::internal::join("cannot write: ", deformseg::internal::last_system_error()));
    }
    fd_ = -1;
    if (::rename(partial_.c_str(), path_.c_str()) != 0)
      fail(deformseg::internal::join("cannot write: ", deformseg::internal::last_system_error()));
    finished_ = true;
    return header_bytes + items_ * item_bytes_;
  }

  /// For a 2-D array: one more row (of `columns` items, appended before or after).
  void add_row() { ++rows_; }

  std::uint32_t data_crc32() const noexcept { return data_crc_; }
  const std::filesystem::path& path() const noexcept { return path_; }

private:
  [[noreturn]] void fail(const std::string& what) const { throw invalid_input(what, {.file = path_.string()}); }

  void put(const void* data, std::uint64_t bytes) {
    const char* at = static_cast<const char*>(data);
    while (bytes > 0) {
      const ssize_t done = ::write(fd_, at, static_cast<std::size_t>(std::min<std::uint64_t>(bytes, 1u << 30)));
      if (done < 0 && errno == EINTR) continue;
      if (done <= 0) fail(deformseg::internal::join("cannot write: ", deformseg::internal::last_system_error()));
      at += done;
      bytes -= static_cast<std::uint64_t>(done);
    }
  }

  std::filesystem::path path_, partial_;
  std::string descr_;
  std::size_t item_bytes_;
  std::uint64_t columns_;
  bool two_d_;
  int fd_ = -1;
  bool finished_ = false;
  std::uint64_t items_ = 0, rows_ = 0;
  std::uint32_t data_crc_ = 0;
};

}  // namespace deformseg::store::internal
