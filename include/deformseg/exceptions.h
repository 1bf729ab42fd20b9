/// @file exceptions.h
/// @brief The exceptions deformseg throws: for input that breaks a documented precondition
/// (`invalid_input`), and for a call stopped before its end (`cancelled`).
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace deformseg {

/// @brief Where in the input a problem was found: any of a file, a line in it, a frame.
///
/// Lines are counted from 1 and frames from 0, as everywhere in deformseg.
struct Input_location {
  std::string file{};                  ///< the file's path as given; empty when not from a file
  std::optional<std::size_t> line{};   ///< 1-based line in `file`, when the format has lines
  std::optional<std::size_t> frame{};  ///< 0-based frame of the animation, when known
};

/// @brief Thrown when an input breaks a documented precondition: a missing or malformed file,
/// frames that do not match, non-finite coordinates, a face that is not a triangle, ...
///
/// `what()` reads `FILE:LINE: frame K: MESSAGE`, leaving out the parts that are unknown, so that a
/// program can print it as one line. The parts are also available separately.
class invalid_input : public std::invalid_argument {
public:
  /// @brief An error with a message and, optionally, where it was found.
  explicit invalid_input(const std::string& message, Input_location where = {})
      : std::invalid_argument(format(message, where)), message_(message), where_(std::move(where)) {}

  /// @brief The message without the location.
  const std::string& message() const noexcept { return message_; }
  /// @brief Where the problem was found.
  const Input_location& where() const noexcept { return where_; }

  /// @brief The same error, with the parts of `outer` that this one does not know yet filled in,
  /// for a caller that knows more of the context (say, the file a frame came from).
  invalid_input located(const Input_location& outer) const {
    Input_location w = where_;
    if (w.file.empty()) w.file = outer.file;
    if (!w.line) w.line = outer.line;
    if (!w.frame) w.frame = outer.frame;
    return invalid_input(message_, std::move(w));
  }

private:
  static std::string format(const std::string& message, const Input_location& w) {
    // Appends rather than operator+ chains, which GCC 12 misreports under -Wstringop-overflow.
    std::string s;
    if (!w.file.empty()) {
      s.append(w.file);
      if (w.line) s.append(":").append(std::to_string(*w.line));
      s.append(": ");
    }
    if (w.frame) s.append("frame ").append(std::to_string(*w.frame)).append(": ");
    return s.append(message);
  }

  std::string message_;
  Input_location where_;
};

/// @brief Thrown by a call that was stopped before its end because it was asked to stop: its
/// `Progress` callback or an `Interruption_check` returned false (threads.h); the message says
/// which. The one exception of every stopped call of deformseg.
class cancelled : public std::runtime_error {
public:
  /// @brief The exception, with a message saying who stopped the call.
  explicit cancelled(const std::string& message = "the computation was interrupted by its interruption check")
      : std::runtime_error(message) {}
};

}  // namespace deformseg
