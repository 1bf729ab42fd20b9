// The foundation's file helpers (deformseg/internal/file_io.h) by the names the readers and writers
// of io use.
#pragma once

#include <deformseg/internal/file_io.h>

namespace deformseg::io::internal {

using deformseg::internal::append_decimal;
using deformseg::internal::append_shortest;
using deformseg::internal::byte_position;
using deformseg::internal::create_folder;
using deformseg::internal::File_bytes;
using deformseg::internal::join;
using deformseg::internal::last_system_error;
using deformseg::internal::load_word;
using deformseg::internal::lower_extension;
using deformseg::internal::read_file_bytes;
using deformseg::internal::shortest_text;
using deformseg::internal::store_word;
using deformseg::internal::Streamed_file;
using deformseg::internal::write_file_bytes;

}  // namespace deformseg::io::internal
