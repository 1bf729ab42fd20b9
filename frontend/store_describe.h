// Describing clips into a motion store (`deformseg describe`): which clips a run describes, in
// which order, and the run itself, on several threads, committed as it goes.
#pragma once

#include "inputs.h"
#include "store_clips.h"

#include <deformseg/similarity/motion_similarity.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace deformseg::frontend {

/// What `describe_into_store` did, each clip named ("FILE", "FILE#CLIP" or "FILE#CLIP on BODY").
struct Describe_report {
  std::vector<std::string> described;    ///< new clips, added
  std::vector<std::string> redescribed;  ///< changed clips, replaced at their index
  std::vector<std::string> skipped;      ///< unchanged clips
  /// Clips left out because they could not be read or described (with `skip_unreadable`), each
  /// "NAME: the error".
  std::vector<std::string> unreadable;
  std::vector<std::string> poses;        ///< clips of 1 frame left out (`describe_inputs`), no motion
  std::size_t clips = 0;                 ///< the store's clips after the run
};

/// How many clips of a run `describe_into_store` commits at a time: at most that many are lost
/// when the run is killed.
inline constexpr std::size_t store_commit_clips = 64;

/// How `describe_into_store` runs.
struct Describe_run {
  bool hash = false;             ///< tell a changed source by its bytes' hash, not its time
  bool skip_unreadable = false;  ///< leave out the clips that cannot be read or described
  Front front = Front::command_line;  ///< how an error names the options
};

/// Describes `clips` read with `options` by `policy` into the store in `folder` (made when
/// missing), with their summaries: new clips added, changed ones replaced in place, unchanged ones
/// skipped (see `unchanged`, with `run.hash`). Each clip is read frame by frame (`policy`'s `describe_stream`, the
/// same values as `describe` of the clip read whole), in memory that grows with the signatures'
/// longest lag, not with the clip: all but point caches and frame sequences welded
/// (`options.weld`), which are read whole. Clips are described on `options.threads` threads (a
/// glTF file parsed once for its clips), a batch of at least 32 at a time, each batch appended in
/// the clips' order, and committed every `store_commit_clips` clips of the run and at its end: the
/// store is the same, byte for byte, whatever the number of threads; at most that many clips are
/// read at once; a run that is killed keeps every clip committed, and a second run describes the
/// rest (the others are unchanged).
///
/// A clip that cannot be read or described stops the run, the clips before it committed; with
/// `run.skip_unreadable` it is left out (`Describe_report::unreadable`) and the run goes on.
///
/// `say` gets a line per file ("describing 12 clip(s) of FILE") and one per clip described, with
/// the rates so far and the time left, from the thread that described it (under a lock), and one
/// per clip left out.
/// @throws invalid_input naming the file and clip that cannot be read or described, or the store
/// when it cannot be written or was made with other options; the store then holds what was
/// committed before.
Describe_report describe_into_store(const std::string& folder, const std::vector<Clip_source>& clips,
                                    const Input_options& options, const similarity::Default_similarity& policy,
                                    const Describe_run& run, const std::function<void(const std::string&)>& say);

/// `describe_into_store` of the clips that `inputs` name (`clip_sources`): `say` gets their count
/// and a line per pose left out (`Describe_report::poses`); with `run.skip_unreadable`, an input
/// whose clips cannot even be listed (a character file that does not parse) is left out too, named
/// first in `Describe_report::unreadable`.
/// @throws invalid_input as `clip_sources` and `describe_into_store`.
Describe_report describe_inputs(const std::string& folder, const std::vector<std::string>& inputs,
                                const Input_options& options, const similarity::Default_similarity& policy,
                                const Describe_run& run, const std::function<void(const std::string&)>& say);

/// What describing `clips` into a store would do, before any is described.
struct Description_plan {
  /// The indices in `clips` of those to describe, in the order they are appended (a file's
  /// together, files in the order of their first clips).
  std::vector<std::size_t> order;
  /// `skipped` filled (the unchanged clips), `clips` the store's count now.
  Describe_report report;
};

/// Which of `clips`, read with `options`, the store in `folder` lacks or holds changed (see
/// `unchanged`): what `describe_into_store` would describe, in its order. A missing folder is an
/// empty store.
/// @throws invalid_input naming the store when it cannot be opened or holds clips described with
/// other options than `policy`'s, or the file whose record cannot be made.
Description_plan plan_description(const std::string& folder, const std::vector<Clip_source>& clips,
                                  const Input_options& options, const similarity::Default_similarity& policy,
                                  bool hash);

}  // namespace deformseg::frontend
