// The tokenizer and number parser shared by deformseg's text mesh readers (OBJ, OFF).
//
// Why not std::istream: parsing a mesh line by line through a stream costs a virtual call, a
// locale lookup and a copy per token, which caps readers near 40 MB/s. Here the whole file is
// read with one call into a buffer that ends with a '\n' sentinel, so that every line, the last
// included, ends with '\n'; tokens are then parsed in place with std::from_chars (correctly
// rounded; libstdc++ 12 implements it with the fast_float algorithm). Line numbers are not
// counted while scanning: an error counts the newlines before it, which only errors pay for.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/utf8.h>
#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/triangle_soup.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace deformseg::io::internal {

/// Why a face of `corners` vertices cannot be read under `options`, or an empty string when it can.
inline std::string polygon_problem(std::size_t corners, const io::Mesh_read_options& options) {
  if (corners < 3) return join("a face with ", std::to_string(corners), " vertices: a face needs 3");
  if (corners > 3 && !options.triangulate)
    return join("a face with ", std::to_string(corners),
                  " vertices, not a triangle: set the option `triangulate` to fan-triangulate polygons");
  return {};
}

/// Appends the fan triangulation of a polygon of at least 3 corners: (c0, ci, ci+1).
inline void append_fan(std::span<const std::uint32_t> corners,
                       std::vector<std::array<std::uint32_t, 3>>& triangles) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i)
    triangles.push_back({corners[0], corners[i], corners[i + 1]});
}

/// Blanks separate tokens on a line; '\r' is one, so CRLF files read like LF files.
inline bool is_blank(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// A token ends at a blank, at the end of its line, or where a '#' comment starts.
inline bool ends_token(char c) noexcept { return is_blank(c) || c == '\n' || c == '#'; }

inline bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

/// The whole content of a text file, read with one call, followed by a '\n' sentinel.
class Text_file {
public:
  /// Reads `path`; throws invalid_input naming it when it is missing, a folder or unreadable.
  explicit Text_file(const std::filesystem::path& path)
      : path_(path), bytes_(read_file_bytes(path, std::numeric_limits<std::uint64_t>::max(), 1 + padding)) {
    bytes_.data[bytes_.size] = '\n';
  }

  const std::filesystem::path& path() const noexcept { return path_; }
  /// The first character of the text.
  const char* begin() const noexcept { return bytes_.begin(); }
  /// One past the last character of the text, where the '\n' sentinel is.
  const char* end() const noexcept { return bytes_.begin() + bytes_.size; }
  /// The size of the file in bytes.
  std::size_t size() const noexcept { return bytes_.size; }

  /// The 1-based line of `position`.
  std::size_t line_of(const char* position) const {
    return 1 + static_cast<std::size_t>(std::count(begin(), position, '\n'));
  }

  /// Throws invalid_input with `message`, naming the file.
  [[noreturn]] void fail(const std::string& message) const {
    throw invalid_input(message, {.file = path_.string()});
  }
  /// Throws invalid_input with `message`, naming the file and the line of `position`.
  [[noreturn]] void fail_at(const char* position, const std::string& message) const {
    throw invalid_input(message, {.file = path_.string(), .line = line_of(position)});
  }

private:
  // Past the sentinel, zeros, so that looking two characters ahead never leaves the buffer.
  static constexpr std::size_t padding = 8;

  std::filesystem::path path_;
  File_bytes bytes_;
};

/// A cursor over a Text_file that reads tokens line by line.
///
/// Lines are read as: skip_blanks(), look at the first character or word, read numbers, then
/// next_line(). The sentinel makes every look-ahead within a line safe without bound checks.
class Text_scanner {
public:
  explicit Text_scanner(const Text_file& file) noexcept : file_(file), p_(file.begin()) {}

  const Text_file& file() const noexcept { return file_; }
  bool at_end() const noexcept { return p_ >= file_.end(); }
  const char* position() const noexcept { return p_; }
  /// The character `ahead` places on (at most 2, which the padding allows at the sentinel).
  char peek(std::size_t ahead = 0) const noexcept { return p_[ahead]; }
  void advance(std::size_t n) noexcept { p_ += n; }

  void skip_blanks() noexcept {
    while (is_blank(*p_)) ++p_;
  }
  /// At the end of the line or at a comment, where nothing more is read on this line.
  bool at_line_end() const noexcept { return *p_ == '\n' || *p_ == '#'; }
  /// Moves to the start of the next line, with memchr rather than a loop: skipped lines are most
  /// of what a positions-only read sees. Never past the sentinel: from the last line it moves to
  /// the sentinel, where every read stops (past it, a token would run into the padding's zeros).
  void next_line() noexcept {
    const auto left = static_cast<std::size_t>(file_.end() + 1 - p_);
    p_ = std::min(static_cast<const char*>(std::memchr(p_, '\n', left)) + 1, file_.end());
  }
  /// Skips lines that are blank or only a comment.
  void skip_empty_lines() noexcept {
    for (skip_blanks(); !at_end() && at_line_end(); skip_blanks()) next_line();
  }

  /// The token at the cursor (after blanks), which the cursor passes.
  std::string_view word() noexcept {
    skip_blanks();
    const char* start = p_;
    while (!ends_token(*p_)) ++p_;
    return {start, static_cast<std::size_t>(p_ - start)};
  }

  /// Reads a finite floating-point number that ends its token.
  /// Throws invalid_input with the line on a malformed, out-of-range or non-finite number.
  template <std::floating_point T>
  T number() {
    skip_blanks();
    const char* start = p_;
    // from_chars takes no '+' sign, which some writers put before positive values.
    const char* first = start + (*start == '+' && (is_digit(start[1]) || start[1] == '.'));
    T value{};
    const auto [stop, error] = std::from_chars(first, file_.end(), value);
    if (error != std::errc{} || !ends_token(*stop) || !std::isfinite(value)) [[unlikely]]
      fail_number<T>(start, stop, error);
    p_ = stop;
    return value;
  }

  /// Reads a decimal integer, which may be followed by more of its token (as in OBJ's "7/3/1").
  /// Throws invalid_input with the line, saying it expected `what`, when there is none or it has
  /// more than 18 digits. A loop of its own rather than from_chars, which handles any base and is
  /// slower on the short indices of face lines; it stops at 18 digits, which int64 holds, so that
  /// a longer number is refused before it could overflow.
  std::int64_t integer(const char* what) {
    skip_blanks();
    const char* start = p_;
    const bool negative = *p_ == '-';
    p_ += negative;
    constexpr std::size_t longest = 18;
    std::size_t length = 0;
    std::int64_t value = 0;
    for (; length < longest && is_digit(p_[length]); ++length) value = 10 * value + (p_[length] - '0');
    p_ += length;
    if (length == 0 || is_digit(*p_)) [[unlikely]] {
      p_ = start;
      fail_integer(start, what, length != 0);
    }
    return negative ? -value : value;
  }

  /// Reads a non-negative integer that ends its token, such as a count in a header.
  std::size_t count(const char* what) {
    skip_blanks();
    const char* start = p_;
    const std::int64_t value = integer(what);
    if (value < 0 || !ends_token(*p_))
      fail_at(start, join("expected ", what, ", found ", quoted_token_at(start)));
    return static_cast<std::size_t>(value);
  }

  /// Throws invalid_input with `message`, naming the file and the line of `position`.
  [[noreturn]] void fail_at(const char* position, const std::string& message) const {
    file_.fail_at(position, message);
  }

  /// The token starting at `position`, cut to a length that fits in a message, its bytes outside
  /// printable UTF-8 escaped (`printable_text`): a damaged file's bytes never reach the terminal raw.
  static std::string token_at(const char* position) {
    constexpr std::size_t longest = 40;
    std::size_t n = 0;
    while (n < longest && !ends_token(position[n])) ++n;
    std::string token = deformseg::internal::printable_text({position, n});
    if (n == longest) token += "...";
    return token;
  }

  /// The token at `position` in quotes, or "the end of the line" when there is none.
  static std::string quoted_token_at(const char* position) {
    return ends_token(*position) && !is_blank(*position) ? std::string("the end of the line")
                                                         : join("\"", token_at(position), "\"");
  }

private:
  // The failures, out of line so that the parsing loops stay small.
  template <class T>
  [[noreturn, gnu::cold, gnu::noinline]] void fail_number(const char* start, const char* stop, std::errc error) const {
    if (error == std::errc::result_out_of_range)
      fail_at(start, join("number \"", token_at(start), "\" is out of the range of ", type_name<T>()));
    if (error == std::errc{} && ends_token(*stop))
      fail_at(start, join("non-finite coordinate \"", token_at(start), "\""));
    fail_at(start, join("malformed number ", quoted_token_at(start)));
  }

  [[noreturn, gnu::cold, gnu::noinline]] void fail_integer(const char* start, const char* what,
                                                           bool too_long) const {
    if (too_long) fail_at(start, join(what, " \"", token_at(start), "\" is out of range"));
    fail_at(start, join("expected ", what, ", found ", quoted_token_at(start)));
  }

  template <class T>
  static const char* type_name() {
    return std::same_as<T, float> ? "float" : std::same_as<T, double> ? "double" : "long double";
  }

  const Text_file& file_;
  const char* p_;
};

/// Reads the 3 coordinates of a vertex line whose keyword the scanner has passed, leaving the
/// cursor after them: what follows (OBJ's w or colour, OFF's colour or normal) is not read.
template <std::floating_point T>
void read_xyz(Text_scanner& scanner, const char* keyword, T* xyz) {
  for (int k = 0; k < 3; ++k) {
    scanner.skip_blanks();
    if (scanner.at_line_end())
      scanner.fail_at(scanner.position(),
                      join("a ", keyword, " line needs 3 coordinates, it has ", std::to_string(k)));
    xyz[k] = scanner.number<T>();
  }
}

}  // namespace deformseg::io::internal
