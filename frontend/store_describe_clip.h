// Describing one clip for a motion store, frame by frame where its format allows: its signatures
// and summary, as `deformseg describe` appends them (store_describe.cpp).
#pragma once

#include "inputs.h"
#include "store_clips.h"

#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/similarity/motion_similarity.h>

#include <cstdint>
#include <memory>
#include <string>

namespace deformseg::frontend {

/// A clip described, kept until its turn to be appended to the store.
struct Described_clip {
  std::uint32_t frame_count = 0;  ///< the frames read
  double fps = 0;                 ///< their rate
  similarity::Motion_signature_description description;  ///< the signatures
  search::Motion_summary summary;  ///< `search::summarize` of them, `store_summary_chunks` chunks
  std::string warning;  ///< of outlying vertices (`Outliers::warning`), said when it is appended
};

/// Describes `clip` by `policy` as `read_input` reads it, frame by frame (`policy`'s
/// `describe_stream`, the same values as `describe` of the clip read whole): a glTF clip from
/// `gltf`, parsed on the clip's body, with `connectivity`, the file's (welded, when it is, by what
/// the file fixes); a point cache or frame sequence through `io::with_frame_source` with the same
/// topology, triangulation, repair and fps, when it `reads_frame_by_frame`; any other read whole.
/// @param gltf null for a clip of another format than a character file's.
/// @param connectivity `gltf`'s (`Clip_cache::connectivity`), null with it.
/// Complexity: the description's, in memory that grows with the signatures' longest lag, not with
/// the clip (the clip's for those read whole).
/// @throws invalid_input naming the file and frame that cannot be read, or the clip that cannot
/// be described (a pose of one frame).
Described_clip describe_clip(const Clip_source& clip, const io::Gltf_file* gltf,
                             std::shared_ptr<const io::Gltf_connectivity> connectivity, const Input_options& options,
                             const similarity::Default_similarity& policy, Front front);

}  // namespace deformseg::frontend
