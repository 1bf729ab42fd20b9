// UTF-8 as a motion store's strings must be (store/store_record.h): the length of a valid
// sequence, whether a text is valid, and the escape that makes any bytes valid (`escaped_name`).
#pragma once

#include <deformseg/internal/utf8.h>

#include <cstddef>
#include <string_view>

namespace deformseg::store::internal {

/// The length of the valid UTF-8 sequence at `text[at]`, or 0 (shared with the readers' messages).
using deformseg::internal::utf8_sequence_length;

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
