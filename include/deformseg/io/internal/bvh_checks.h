// What Assimp's BVH reader would get wrong without a word, or pay for before it fails, found in
// the file's text before Assimp parses it: position channels it drops (it keeps a joint's
// positions only when the joint has 6 channels), joints of one name (its channels find the first),
// a frame count the file cannot hold (it reserves memory for all of them first), a hierarchy too
// deep for its recursion, a frame time that is not positive (it would fall back to 25 frames per
// second), a file that is not BVH at all (Assimp would try its other readers). Tokens are split
// as Assimp splits them: at white space, a brace alone.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/utf8.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace deformseg::io::internal::bvh {

// The joints' names and the tokens a message quotes are the file's bytes: shown escaped.
using deformseg::internal::printable_text;

/// The deepest joint hierarchy read: Assimp reads one level per recursive call.
inline constexpr std::size_t max_depth = 1'000;

/// The file's tokens, one at a time, with the line each starts on.
class Tokens {
public:
  explicit Tokens(std::string_view text) : text_(text) {}

  /// The next token, empty at the end of the text.
  std::string_view next() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) line_ += text_[at_++] == '\n';
    const std::size_t start = at_;
    if (at_ < text_.size() && (text_[at_] == '{' || text_[at_] == '}')) return text_.substr(at_++, 1);
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(start, at_ - start);
  }

  /// The line of the last token, from 1.
  std::size_t line() const { return line_; }

  /// The tokens left, counted up to `enough` (where counting stops).
  std::size_t count_left(std::size_t enough) {
    std::size_t count = 0;
    while (count < enough && !next().empty()) ++count;
    return count;
  }

private:
  std::string_view text_;
  std::size_t at_ = 0, line_ = 1;
};

/// `token` as a number, or NaN when it is not one.
inline double number(std::string_view token) {
  double value = NAN;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size() ? value : NAN;
}

/// `token` as a whole number in [0, 2^32), or throws naming `what` and the line.
inline std::size_t whole_number(std::string_view token, const std::string& what, std::size_t line) {
  const double value = number(token);
  if (!(value >= 0 && value < 4294967296.0) || value != std::floor(value))
    throw invalid_input(what + " must be a whole number, not '" + printable_text(token) + "'", {.line = line});
  return std::size_t(value);
}

/// A joint's CHANNELS: how many, and whether positions and rotations are among them.
struct Channels {
  std::size_t count = 0;
  bool position = false, rotation = false;
};

/// Reads a CHANNELS list of `joint`.
/// @throws invalid_input for position channels on a joint that has not 6 channels.
inline Channels read_channels(Tokens& tokens, const std::string& joint) {
  const std::string what = "joint '" + printable_text(joint) + "' CHANNELS count";
  Channels channels{.count = whole_number(tokens.next(), what, tokens.line())};
  const std::size_t line = tokens.line();
  for (std::size_t c = 0; c < channels.count; ++c) {
    const std::string_view name = tokens.next();
    if (name.empty()) break;  // the end of the file, which Assimp reports
    channels.position = channels.position || name.ends_with("position");
    channels.rotation = channels.rotation || name.ends_with("rotation");
  }
  if (channels.position && channels.count != 6)
    throw invalid_input("joint '" + printable_text(joint) + "' has " + std::to_string(channels.count) +
                            " channels, some of them positions: Assimp keeps the positions of a joint of 6 channels "
                            "(3 positions, 3 rotations) only, and dropping them would change the motion",
                        {.line = line});
  return channels;
}

/// What a file's hierarchy records: the values of a frame, and the joints whose positions and
/// rotations it records (Assimp gives every joint both, making up those the file does not record).
struct Recorded {
  std::size_t channels = 0;
  std::set<std::string, std::less<>> positions{}, rotations{};
};

/// Checks the hierarchy, up to MOTION.
inline Recorded check_hierarchy(Tokens& tokens) {
  // Assimp picks another reader for a file that does not start so (an OBJ file named .bvh).
  if (tokens.next() != "HIERARCHY")
    throw invalid_input("not a BVH file: it does not start with HIERARCHY", {.line = tokens.line()});
  Recorded recorded;
  std::set<std::string, std::less<>> joints;
  std::string joint;  // the last joint named
  std::size_t depth = 0;
  for (std::string_view token = tokens.next(); !token.empty() && token != "MOTION"; token = tokens.next()) {
    if (token == "ROOT" || token == "JOINT") {
      joint = std::string(tokens.next());
      if (!joints.insert(joint).second)
        throw invalid_input("two joints are named '" + printable_text(joint) +
                                "': their channels could not be told apart",
                            {.line = tokens.line()});
    } else if (token == "{" && ++depth > max_depth) {
      throw invalid_input("the joint hierarchy is deeper than " + std::to_string(max_depth) + " levels",
                          {.line = tokens.line()});
    } else if (token == "}" && depth > 0) {
      --depth;
    } else if (token == "CHANNELS") {
      const Channels channels = read_channels(tokens, joint);
      recorded.channels += channels.count;
      if (channels.position) recorded.positions.insert(joint);
      if (channels.rotation) recorded.rotations.insert(joint);
    }
  }
  return recorded;
}

/// Checks the MOTION header, after the hierarchy of `channels` channels.
inline void check_motion(Tokens& tokens, std::size_t channels) {
  if (tokens.next() != "Frames:") return;  // Assimp names what is missing
  const std::size_t frames = whole_number(tokens.next(), "the frame count", tokens.line());
  if (tokens.next() != "Frame" || tokens.next() != "Time:") return;
  const std::size_t line = tokens.line();
  const double frame_time = number(tokens.next());
  if (!(float(frame_time) > 0) || !std::isfinite(float(frame_time)))
    throw invalid_input("the Frame Time must be a positive number of seconds", {.line = line});
  const double values = double(frames) * double(channels);
  if (values > double(tokens.count_left(std::size_t(std::min(values, 1e18)))))
    throw invalid_input(std::to_string(frames) + " frames of " + std::to_string(channels) +
                            " channels claimed, more values than the file holds",
                        {.line = line});
}

/// Checks a BVH file's text (see the file's comment); Assimp reports what else is malformed.
/// Returns what the file records.
/// @throws invalid_input naming the line of the first problem.
inline Recorded check_text(std::string_view text) {
  Tokens tokens(text);
  Recorded recorded = check_hierarchy(tokens);
  check_motion(tokens, recorded.channels);
  return recorded;
}

}  // namespace deformseg::io::internal::bvh
