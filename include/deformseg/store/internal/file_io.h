// The foundation's file helpers (deformseg/internal/file_io.h) by the names the store uses.
#pragma once

#include <deformseg/internal/file_io.h>

namespace deformseg::store::internal {

using deformseg::internal::append_decimal;
using deformseg::internal::File_bytes;
using deformseg::internal::join;
using deformseg::internal::last_system_error;
using deformseg::internal::load_word;
using deformseg::internal::read_file_bytes;
using deformseg::internal::store_word;

}  // namespace deformseg::store::internal
