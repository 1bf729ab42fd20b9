// The motion store as the tool's commands use it: which clips a command's inputs name, the
// description options a store records, the record that tells an unchanged source from a changed
// one, and describing clips into a store (`deformseg describe`).
#pragma once

#include "inputs.h"
#include "similarity.h"

#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/store/motion_store.h>
#include <deformseg/store/stored_motions.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace deformseg::frontend {

/// The summaries a store's clips get: `search::summarize(view, store_summary_chunks)`.
inline constexpr std::size_t store_summary_chunks = 4;

/// "FILE", "FILE#CLIP" or "FILE#CLIP on BODY": a clip named for reports (`body` "": its own file's),
/// of names as a store keeps them (`store::escaped_name`), which it joins as they are.
std::string clip_name(const std::string& file, const std::string& clip, const std::string& body);

/// One clip an input names: its file, canonical and absolute, its clip's name in a character file
/// ("" for a file of one animation: frames, a point cache), and the body it plays on. One clip on
/// two bodies is two clips, as a store holds them.
struct Clip_source {
  std::string file;
  std::string clip;
  /// The character file whose body the clip plays on, canonical and absolute (a labels row's
  /// `body_file`, else the options' `body`); empty: its own file's body.
  std::string body{};
  /// "FILE", "FILE#CLIP" or "FILE#CLIP on BODY", as reports name the clip: its names as a store
  /// keeps them, UTF-8 whatever their bytes (`store::escaped_name`).
  std::string name() const {
    return clip_name(store::escaped_name(file), store::escaped_name(clip), store::escaped_name(body));
  }
  /// "FILE" or "FILE#CLIP": the clip as an input names it (its body given apart).
  std::string input() const { return clip_name(file, clip, ""); }
};

/// The clips that `inputs` name, in their order, each once (a clip on each of its bodies): an animation (frame files, a folder, a
/// quoted glob, a point cache) is one clip; a glTF file with a clip (FILE.glb#CLIP or
/// `options.clip`) that clip, without one every clip of the file of 2 frames or more at
/// `options.fps` (the others, poses with no motion, named in `poses`); a labels CSV (`.csv`, the
/// header of `evaluate`'s) the clip of each row (a glTF row without a clip takes `options.clip`,
/// or the file's only clip; a row's `body_file`, else `options.body`, is its body).
/// With `unreadable`, a character file that cannot be parsed is left out, noted there ("INPUT:
/// the error"), instead of thrown.
/// @throws invalid_input naming the input that does not exist, a glTF file that cannot be parsed,
/// a clip it does not have, a labels row naming several clips of a file that is not glTF.
std::vector<Clip_source> clip_sources(const std::vector<std::string>& inputs, const Input_options& options,
                                      std::vector<std::string>& poses, std::vector<std::string>* unreadable = nullptr);

/// The clip of each row of the labels CSV `labels` (`evaluate`'s), in the rows' order: a glTF row
/// without a clip takes `options.clip`, or the file's only clip; a row's `body_file`, else
/// `options.body`, is its body. With `unreadable`, a row whose
/// file cannot be parsed for its only clip is left out, noted there, instead of thrown.
/// @throws invalid_input naming the labels file or the glTF file, as `clip_sources`.
std::vector<Clip_source> labelled_clips(const std::string& labels, const Input_options& options,
                                        std::vector<std::string>* unreadable = nullptr);

/// The default policy with the signatures' up direction of `choice` (its policy must be
/// motion-signature and its alignment dtw: what a store holds).
/// @throws invalid_input naming the option otherwise.
similarity::Default_similarity store_policy(const Policy_choice& choice, Front front);

/// The values per row of `policy`'s signatures: lags x quantiles, twice that with an up direction
/// (the vertical rates' quantiles follow the speeds'); the "width" a store's description records.
std::size_t signature_width(const similarity::Default_similarity& policy);

/// The description options a store records for `policy`, as a JSON object: policy, alignment,
/// lags, quantiles, floor, up ([x, y, z] or null), vertical_unit, vertical_weight,
/// signature_rate, scale and width (the values per signature).
std::string store_description(const similarity::Default_similarity& policy);

/// The policy choice a store's description names (its up direction), for describing queries as
/// the store's clips were.
/// @throws invalid_input naming the store when its description is not one this front end writes
/// (another version of deformseg, other options): the message says which member differs.
Policy_choice stored_policy_choice(const store::Motion_store& store);

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
/// @throws invalid_input naming the file when it cannot be read.
store::Store_record source_record(const Clip_source& clip, const Input_options& options, bool hash);

/// True when `stored` was described from the source `now` describes: the same input options,
/// size and topology (or body) file's path, size and time, and the same hash (`hash`, when `stored` has one) or modification time.
bool unchanged(const store::Store_record& stored, const store::Store_record& now, bool hash);

/// True when `stored` is the clip as its source is now: the same input options, size and topology,
/// and the same modification time, or, when it differs, the same hash (if `stored` has one).
bool up_to_date(const store::Store_record& stored, const Clip_source& clip, const Input_options& options);

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

/// Appends the clips of the stores `parts`, in their order, into the store in `folder` (made when
/// missing) as they are: their records, signatures, frames and summaries; a clip the store holds
/// already is replaced at its index. One commit at the end: the store is the merge of stores
/// described apart (a cluster's workers each describe a part; one writer merges them). `say` gets
/// a line per part.
/// @throws invalid_input naming the part or the store when a part cannot be opened, a clip's block
/// in a part does not match its checksum, the parts' descriptions differ from each other or from
/// the store's, or the store cannot be written; the store is then as it was.
Describe_report merge_stores(const std::string& folder, const std::vector<std::string>& parts,
                             const std::function<void(const std::string&)>& say);

/// A store's clip `i` named for reports: "FILE", "FILE#CLIP" or "FILE#CLIP on BODY".
std::string stored_clip_name(const store::Motion_store& store, std::size_t i);

/// The index of `clip` (its file, clip and body) in `store`, if it holds it.
std::optional<std::size_t> find_clip(const store::Motion_store& store, const Clip_source& clip);

}  // namespace deformseg::frontend
