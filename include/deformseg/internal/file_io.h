// Whole-file reads and writes, byte order and number formatting, shared by the readers and
// writers of every module: the formats of io, the motion store, the writers of results.
//
// Why whole files: one read or one write call per file is what makes thousands of frames fast;
// a stream written number by number costs a virtual call and a locale lookup per number.
#pragma once

#include <deformseg/exceptions.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cctype>
#include <charconv>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace deformseg::internal {

/// Joins the parts of a message with append (operator+ chains trip GCC 12's -Wrestrict at -O3).
template <class... Parts>
std::string join(const Parts&... parts) {
  std::string text;
  (text.append(parts), ...);
  return text;
}

/// The shortest decimal text that reads back, as `T`, to `value` exactly.
template <std::floating_point T>
std::string shortest_text(T value) {
  char digits[32];
  return {digits, std::to_chars(digits, digits + sizeof digits, value).ptr};
}

/// Appends the shortest decimal text that reads back, as `T`, to `value` exactly.
template <std::floating_point T>
void append_shortest(std::string& out, T value) {
  char digits[32];
  out.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
}

/// Appends an integer in decimal.
template <std::integral T>
void append_decimal(std::string& out, T value) {
  char digits[24];
  out.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
}

/// The message of the last failed C library call, such as "No such file or directory".
inline std::string last_system_error() { return std::generic_category().message(errno); }

/// The first bytes of a file, or all of them, read with one call.
struct File_bytes {
  std::unique_ptr<char[]> data;  ///< `size` bytes
  std::size_t size = 0;          ///< the bytes read
  std::uint64_t file_size = 0;   ///< the bytes in the file, `size` or more

  const char* begin() const noexcept { return data.get(); }
};

/// Reads the first `limit` bytes of `path` (all of them by default) with one call, followed by
/// `slack` zero bytes that a parser may use as sentinels.
/// Throws invalid_input naming the file when it is missing, a folder, or cannot be read.
inline File_bytes read_file_bytes(const std::filesystem::path& path,
                                  std::uint64_t limit = std::numeric_limits<std::uint64_t>::max(),
                                  std::size_t slack = 0) {
  const auto fail = [&](const std::string& message) { throw invalid_input(message, {.file = path.string()}); };
  std::error_code error;
  if (!std::filesystem::exists(path, error)) fail("cannot open: no such file");
  if (std::filesystem::is_directory(path, error)) fail("cannot open: it is a folder, not a file");
  const std::uint64_t file_size = std::filesystem::file_size(path, error);
  if (error) fail(join("cannot read its size: ", error.message()));
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(join("cannot open: ", last_system_error()));

  File_bytes bytes;
  bytes.file_size = file_size;
  bytes.size = static_cast<std::size_t>(std::min(limit, file_size));
  bytes.data = std::make_unique_for_overwrite<char[]>(bytes.size + slack);
  std::fill_n(bytes.data.get() + bytes.size, slack, '\0');
  if (!in.read(bytes.data.get(), static_cast<std::streamsize>(bytes.size)))
    fail(join("cannot read its ", std::to_string(bytes.size), " bytes: it changed while being read, or a read failed"));
  return bytes;
}

/// A file written piece by piece, so that large outputs need no copy in memory. Throws
/// invalid_input naming the file when it cannot be created or written in full, after removing
/// what was written of it: no partial file is left to be mistaken for a whole one.
class Streamed_file {
public:
  explicit Streamed_file(const std::filesystem::path& path) : path_(path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) fail("cannot write: it is a folder, not a file");
    out_.open(path, std::ios::binary | std::ios::trunc);
    if (!out_) fail(join("cannot write: ", last_system_error()));
  }

  void write(std::string_view bytes) {
    out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out_) abandon();
  }

  void close() {
    out_.close();
    if (!out_) abandon();
  }

private:
  [[noreturn]] void fail(const std::string& message) const { throw invalid_input(message, {.file = path_.string()}); }

  [[noreturn]] void abandon() {
    const std::string reason = last_system_error();
    out_.close();
    std::error_code error;
    if (std::filesystem::is_regular_file(path_, error)) std::filesystem::remove(path_, error);  // not a device
    fail(join("cannot write: ", reason));
  }

  std::filesystem::path path_;
  std::ofstream out_;
};

/// Writes `bytes` to `path`, replacing the file, with one call; fails as `Streamed_file`.
inline void write_file_bytes(const std::filesystem::path& path, std::string_view bytes) {
  Streamed_file file(path);
  file.write(bytes);
  file.close();
}

/// Creates `directory` and its parents when missing; throws invalid_input naming it otherwise.
inline void create_folder(const std::filesystem::path& directory) {
  std::error_code error;
  if (std::filesystem::exists(directory, error) && !std::filesystem::is_directory(directory, error))
    throw invalid_input("cannot write into it: it is not a folder", {.file = directory.string()});
  std::filesystem::create_directories(directory, error);
  if (error) throw invalid_input(join("cannot create the folder: ", error.message()), {.file = directory.string()});
}

/// A 4- or 8-byte value the binary formats store: an integer or an IEEE-754 float.
template <class T>
concept Word = std::is_arithmetic_v<T> && (sizeof(T) == 4 || sizeof(T) == 8);

template <Word T>
using Word_bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;

/// Where the byte of significance `k` (0: least significant) of a `size`-byte word is, in `order`.
/// Shifts rather than memcpy so that no assumption on the host's byte order is made; compilers
/// turn the loops below into one load or store, with a byte swap where the orders differ.
constexpr std::size_t byte_position(std::endian order, std::size_t k, std::size_t size) noexcept {
  return order == std::endian::little ? k : size - 1 - k;
}

/// Stores `value` at `out` in the byte order `order`.
template <std::endian order, Word T>
void store_word(char* out, T value) noexcept {
  static_assert(order == std::endian::little || order == std::endian::big);
  const auto bits = std::bit_cast<Word_bits<T>>(value);
  for (std::size_t k = 0; k < sizeof(T); ++k)
    out[byte_position(order, k, sizeof(T))] = static_cast<char>((bits >> (8 * k)) & 0xFFu);
}

/// Loads a `T` stored at `in` in the byte order `order`.
template <std::endian order, Word T>
T load_word(const char* in) noexcept {
  static_assert(order == std::endian::little || order == std::endian::big);
  Word_bits<T> bits = 0;
  for (std::size_t k = 0; k < sizeof(T); ++k)
    bits |= Word_bits<T>(static_cast<unsigned char>(in[byte_position(order, k, sizeof(T))])) << (8 * k);
  return std::bit_cast<T>(bits);
}

/// The extension of `path` (with its dot) in lower case.
inline std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace deformseg::internal
