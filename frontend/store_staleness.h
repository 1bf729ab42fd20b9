// What a motion store records of a clip's source, and telling an unchanged source from a changed
// one: the input options it was read with, its files' size, time and hash, its topology's or body's.
#pragma once

#include "inputs.h"
#include "store_clips.h"

#include <deformseg/store/store_record.h>

#include <string>

namespace deformseg::frontend {

/// The input options as a store records them: the options that change what is read (fps,
/// topology, triangulate, weld as it applies to `file`, refuse_defects, body), as canonical JSON,
/// the paths escaped (`store::escaped_name`).
std::string input_options_text(const std::string& file, const Input_options& options);

/// The input options a record holds (`input_options_text`), read back, their paths unescaped
/// (`store::unescaped_name`); the defaults when the text is not one this front end writes (the
/// clip then reads as changed).
Input_options recorded_input_options(const store::Store_record& record);

/// The record of `clip` as its source is now (path, clip, body, options, size, modification time,
/// topology or body file's stamp; the file's hash with `hash`), without frame count and fps. Its
/// names (path, clip, body, topology, and the paths in its options) are escaped
/// (`store::escaped_name`): a store keeps UTF-8, and a file name may be any bytes.
/// Complexity: a stat of each file of the source; with `hash`, a read of every byte.
/// @throws invalid_input naming the file when it cannot be read.
store::Store_record source_record(const Clip_source& clip, const Input_options& options, bool hash);

/// True when `stored` was described from the source `now` describes: the same input options,
/// size and topology (or body) file's path, size and time, and the same hash (`hash`, when
/// `stored` has one) or modification time.
bool unchanged(const store::Store_record& stored, const store::Store_record& now, bool hash);

/// True when `stored` is the clip as its source is now: the same input options, size and topology,
/// and the same modification time, or, when it differs, the same hash (if `stored` has one).
/// Complexity: as `source_record`, the source's bytes read only when its time differs.
/// @throws invalid_input naming the file when it cannot be read.
bool up_to_date(const store::Store_record& stored, const Clip_source& clip, const Input_options& options);

}  // namespace deformseg::frontend
