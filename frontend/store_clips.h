// The clips of a motion store as the tool's commands name them: which clips a command's inputs
// name (`clip_sources`), how reports name a clip, and where a store holds one.
#pragma once

#include "clip_cache.h"
#include "inputs.h"

#include <deformseg/store/motion_store.h>
#include <deformseg/store/store_record.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace deformseg::frontend {

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

/// The clips that `inputs` name, in their order, each once (a clip on each of its bodies): an
/// animation (frame files, a folder, a quoted glob, a point cache) is one clip; a glTF file with a
/// clip (FILE.glb#CLIP or `options.clip`) that clip, without one every clip of the file of 2 frames
/// or more at `options.fps` (the others, poses with no motion, named in `poses`); a labels CSV
/// (`.csv`, the header of `evaluate`'s) the clip of each row (a glTF row without a clip takes
/// `options.clip`, or the file's only clip; a row's `body_file`, else `options.body`, is its body).
/// With `unreadable`, a character file that cannot be parsed is left out, noted there ("INPUT:
/// the error"), instead of thrown. With `parses`, the character files parsed to list their clips
/// (given whole, without a body) are kept there, within its budget, for describing the clips.
/// Complexity: a parse of each character file given whole, a read of each labels file.
/// @throws invalid_input naming the input that does not exist, a glTF file that cannot be parsed,
/// a clip it does not have, a labels row naming several clips of a file that is not glTF.
std::vector<Clip_source> clip_sources(const std::vector<std::string>& inputs, const Input_options& options,
                                      std::vector<std::string>& poses, std::vector<std::string>* unreadable = nullptr,
                                      Listed_parses* parses = nullptr);

/// The clip of each row of the labels CSV `labels` (`evaluate`'s), in the rows' order: a glTF row
/// without a clip takes `options.clip`, or the file's only clip; a row's `body_file`, else
/// `options.body`, is its body. With `unreadable`, a row whose file cannot be parsed for its only
/// clip is left out, noted there, instead of thrown.
/// Complexity: a parse of each character file of a row without a clip.
/// @throws invalid_input naming the labels file or the glTF file, as `clip_sources`.
std::vector<Clip_source> labelled_clips(const std::string& labels, const Input_options& options,
                                        std::vector<std::string>* unreadable = nullptr);

/// The path as a store records it: canonical when it exists (a file, a folder), else (a glob)
/// absolute and normal.
std::string store_path(const std::string& path);

/// A path given or not (a body, a topology) as a store records it: `store_path`, "" for none.
std::string store_path_if_given(const std::string& path);

/// `options` with `body` as their body when it names one (a clip's own), else as they are.
Input_options with_body(const std::string& body, const Input_options& options);

/// A store's clip `i` named for reports: "FILE", "FILE#CLIP" or "FILE#CLIP on BODY".
/// @pre `i < store.size()`.
std::string stored_clip_name(const store::Motion_store& store, std::size_t i);

/// The index of `clip` (its file, clip and body) in `store`, if it holds it. Complexity: the
/// store's `find`.
std::optional<std::size_t> find_clip(const store::Motion_store& store, const Clip_source& clip);

}  // namespace deformseg::frontend
