#include "store_describe_clip.h"

#include "store_policy.h"

#include <deformseg/exceptions.h>
#include <deformseg/io/read_animation.h>

#include <array>
#include <cstddef>
#include <span>
#include <utility>

namespace deformseg::frontend {

namespace {

// The whole animation of `clip` as read_input reads it, its outliers checked; a glTF clip from
// `gltf`, its file parsed once.
Read_input read_whole(const Clip_source& clip, const io::Gltf_file* gltf, const Input_options& options, Front front) {
  if (!gltf) {
    Input_options frames = options;
    frames.clip.clear();
    return read_input(clip.file, frames, front);
  }
  Read_input read{gltf->read({.clip = clip.clip, .fps = options.fps, .repair = repair_options(clip.file, options),
                              .threads = options.threads}),
                  {clip.file, clip.clip}};
  check_outliers(read, options.refuse_defects, front);
  return read;
}

// A description's error, named by its clip (a reader's names its file and frame already).
invalid_input of_clip(const Clip_source& clip, const invalid_input& error) {
  return invalid_input(clip.name() + ": " + error.what());
}

Described_clip summarized(std::size_t frames, double fps, similarity::Motion_signature_description description) {
  search::Motion_summary summary = search::summarize(similarity::view(description), store_summary_chunks);
  return {std::uint32_t(frames), fps, std::move(description), std::move(summary), {}};
}

Described_clip describe_whole(const Clip_source& clip, const io::Gltf_file* gltf, const Input_options& options,
                              const similarity::Default_similarity& policy, Front front) {
  const Read_input read = read_whole(clip, gltf, options, front);
  const mesh::Surface_mesh_animation& animation = read.animation;
  require_motion(animation, clip.name());
  try {
    Described_clip described =
        summarized(animation.num_frames(), mesh::frames_per_second(animation), policy.describe(animation));
    described.warning = read.outliers.warning(front);
    return described;
  } catch (const invalid_input& e) {
    throw of_clip(clip, e);
  }
}

// A frame source that notes when reading fails: the reader's errors name the file and the frame
// already and are passed on as they are, the description's get the clip's name (as read whole).
template <signatures::FrameSource Source>
class Noting_source {
public:
  using Coordinate = typename Source::Coordinate;

  explicit Noting_source(Source& source) : source_(source) {}
  std::size_t num_vertices() const { return source_.num_vertices(); }
  std::size_t num_frames() const { return source_.num_frames(); }
  double frames_per_second() const { return source_.frames_per_second(); }
  std::span<const std::array<std::uint32_t, 3>> triangles() const { return source_.triangles(); }
  void read_frame(std::span<Coordinate> out) {
    noting([&] { source_.read_frame(out); });
  }
  void rewind() {
    noting([&] { source_.rewind(); });
  }
  bool failed() const { return failed_; }

private:
  template <class Read>
  void noting(const Read& read) {
    try {
      read();
    } catch (...) {
      failed_ = true;
      throw;
    }
  }

  Source& source_;
  bool failed_ = false;
};

// `policy.describe_stream(source)`: the same signatures as `describe` of the animation read whole,
// holding the frames the longest lag needs, not the clip's.
template <signatures::FrameSource Source>
Described_clip describe_streamed(Source& source, const Clip_source& clip, const io::Gltf_file* gltf,
                                 const Input_options& options, const similarity::Default_similarity& policy,
                                 Front front) {
  if (source.num_frames() < 2) return describe_whole(clip, gltf, options, policy, front);  // refused as before
  Outliers outliers;
  Outlier_checked_source<Source> checked(source, clip.file, options.refuse_defects, front, outliers);
  Noting_source noting(checked);
  similarity::Motion_signature_description description;
  try {
    description = policy.describe_stream(noting);
  } catch (const invalid_input& e) {
    if (noting.failed()) throw;
    throw of_clip(clip, e);
  }
  Described_clip described = summarized(source.num_frames(), source.frames_per_second(), std::move(description));
  described.warning = outliers.warning(front);
  return described;
}

}  // namespace

Described_clip describe_clip(const Clip_source& clip, const io::Gltf_file* gltf,
                             std::shared_ptr<const io::Gltf_connectivity> connectivity, const Input_options& options,
                             const similarity::Default_similarity& policy, Front front) {
  if (gltf) {
    io::Gltf_frame_source source(std::move(connectivity), {.clip = clip.clip, .fps = options.fps});
    return describe_streamed(source, clip, gltf, options, policy, front);
  }
  if (!reads_frame_by_frame(clip.file, options)) return describe_whole(clip, nullptr, options, policy, front);
  return io::with_frame_source(clip.file, animation_read_options(clip.file, options), [&](auto& source) {
    return describe_streamed(source, clip, nullptr, options, policy, front);
  });
}

}  // namespace deformseg::frontend
