// UTF-8 as a motion store's strings must be (store/store_record.h): the length of a valid
// sequence, whether a text is valid, and the escape that makes any bytes valid (`escaped_name`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace deformseg::store::internal {

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

/// True when `text` is valid UTF-8 (no overlong form, no surrogate, at most U+10FFFF).
inline bool valid_utf8(std::string_view text) noexcept {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) return false;
    i += length;
  }
  return true;
}

}  // namespace deformseg::store::internal
