// UTF-8 shared by the modules that take text from files: the length of a valid sequence (the motion
// store keeps its strings valid, store/internal/utf8.h) and the printable form of bytes that a
// message quotes from a file (the readers of io), so that a damaged file cannot put raw bytes, an
// invalid sequence or a terminal's control codes into an error message.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace deformseg::internal {

/// The length (1 to 4) of the valid UTF-8 sequence at `text[at]` (no overlong form, no surrogate,
/// at most U+10FFFF), or 0 when the bytes there are not one. @pre at < text.size().
inline std::size_t utf8_sequence_length(std::string_view text, std::size_t at) noexcept {
  const auto c = static_cast<unsigned char>(text[at]);
  std::size_t extra = 0;
  std::uint32_t code = 0;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) { extra = 1; code = c & 0x1Fu; }
  else if (c >= 0xE0 && c <= 0xEF) { extra = 2; code = c & 0x0Fu; }
  else if (c >= 0xF0 && c <= 0xF4) { extra = 3; code = c & 0x07u; }
  else return 0;
  if (text.size() - at <= extra) return 0;
  for (std::size_t k = 1; k <= extra; ++k) {
    const auto next = static_cast<unsigned char>(text[at + k]);
    if ((next & 0xC0u) != 0x80u) return 0;
    code = (code << 6) | (next & 0x3Fu);
  }
  const std::uint32_t smallest[] = {0, 0x80, 0x800, 0x10000};
  if (code < smallest[extra] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return extra + 1;
}

/// True when the valid UTF-8 `sequence` is a control character (U+0000 to U+001F, DEL, U+0080 to
/// U+009F), which a terminal may act on rather than show. @pre `sequence` is one valid sequence.
inline bool is_control_character(std::string_view sequence) noexcept {
  const auto first = static_cast<unsigned char>(sequence[0]);
  if (sequence.size() == 1) return first < 0x20 || first == 0x7F;
  return sequence.size() == 2 && first == 0xC2 && static_cast<unsigned char>(sequence[1]) < 0xA0;
}

/// @brief `bytes` with a backslash written `\\` and every byte not part of a valid UTF-8 sequence
/// (with `controls`, also those of a control character: `is_control_character`) written `\xHH`
/// (upper-case hexadecimal); the rest as it is. What `printable_text` and `store::escaped_name`
/// share; reversed by `store::unescaped_name`.
/// @par Complexity O(size of `bytes`).
inline std::string escaped_bytes(std::string_view bytes, bool controls) {
  constexpr char hex[] = "0123456789ABCDEF";
  std::string text;
  text.reserve(bytes.size());
  for (std::size_t i = 0; i < bytes.size();) {
    const std::size_t length = utf8_sequence_length(bytes, i);
    if (length == 0 || (controls && is_control_character(bytes.substr(i, length)))) {  // each byte escaped
      for (const std::size_t end = i + std::max<std::size_t>(length, 1); i < end; ++i) {
        const auto byte = static_cast<unsigned char>(bytes[i]);
        text.append("\\x").push_back(hex[byte >> 4]);
        text.push_back(hex[byte & 0xFu]);
      }
      continue;
    }
    if (bytes[i] == '\\') text.push_back('\\');
    text.append(bytes.substr(i, length));
    i += length;
  }
  return text;
}

/// @brief Bytes quoted from a file as a message may show them (`escaped_bytes` with the control
/// characters escaped), so that a damaged file cannot put raw bytes or a terminal's control codes
/// into an error message.
/// @par Example
/// The bytes of `v`, E9 (a Latin-1 é), 1B (a terminal's escape) and `[2J` give the text
/// `v\xE9\x1B[2J`; `café` in UTF-8 stays `café`.
/// @par Complexity O(size of `bytes`).
inline std::string printable_text(std::string_view bytes) { return escaped_bytes(bytes, true); }

}  // namespace deformseg::internal
