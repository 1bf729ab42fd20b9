// How every command and every Python function reads an animation: the input options, the same
// under the same names everywhere, and the rules of which applies to which format.
#pragma once

#include "parameters.h"

#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/io/outlying_vertices.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/mesh/default_mesh.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace deformseg::frontend {

/// How to read the inputs of a command or a function; one set for all its inputs.
struct Input_options {
  std::string clip{};         ///< glTF, FBX, Collada, BVH: a clip's name or index; empty: the input's own, or the only one
  double fps = 30;            ///< glTF's sampling rate; frame files' and point caches' playing rate
  std::string topology{};     ///< the connectivity of point caches; empty: none
  bool triangulate = false;   ///< fan-triangulate polygons instead of refusing them
  std::optional<bool> weld{};  ///< none: the format's rule (character files welded, others not)
  bool refuse_defects = false;  ///< fail on degenerate or non-manifold triangles instead of repairing them
  int threads = 0;              ///< 0: all
  std::string body{};           ///< character files: the body their clips play on (`io::Gltf_file`); empty: their own
};

/// The input options' table.
inline constexpr std::tuple input_parameters{
    Parameter<Input_options, std::string>{
        "clip", &Input_options::clip,
        "glTF, FBX, Collada, BVH: the clip to read, by name or index, for every input that names none after '#' "
        "(FILE.glb#CLIP); required for a file of several clips",
        Parameter_kind::clip},
    numeric_parameter("fps", &Input_options::fps,
                      "Frames per second: glTF, FBX, Collada and BVH clips are sampled at it; frame files and point "
                      "caches play at it. Default: 30",
                      Range{.min = 0, .max = 1000, .min_open = true}),
    Parameter<Input_options, std::string>{"topology", &Input_options::topology,
                                          "A mesh file giving the connectivity of point caches (required for them)",
                                          Parameter_kind::file},
    Parameter<Input_options, bool>{"triangulate", &Input_options::triangulate,
                                   "Fan-triangulate polygons instead of refusing them"},
    Parameter<Input_options, std::optional<bool>>{
        "weld", &Input_options::weld,
        "Weld the vertices that coincide in every frame. Default: glTF, FBX, Collada and BVH files welded (every clip of a file then has "
        "one mesh), frame sequences and point caches not"},
    Parameter<Input_options, bool>{"refuse_defects", &Input_options::refuse_defects,
                                   "Fail on degenerate, duplicate or non-manifold triangles instead of repairing them"},
    numeric_parameter("threads", &Input_options::threads, "Threads to use (0: all); results do not depend on it",
                      thread_counts),
    Parameter<Input_options, std::string>{
        "body", &Input_options::body,
        "glTF, FBX, Collada, BVH: a character file whose body the inputs' clips play on, each channel moving the "
        "body's node of the same name (the inputs then give clips: animation-only exports, or another body of "
        "the same rig)",
        Parameter_kind::file},
};

/// Checks the options before any input is read (fps, threads).
/// @throws invalid_input naming the option as `front` spells it.
void check(const Input_options& options, Front front);

/// An input and the clip it names: "Fox.glb#Walk" is the file Fox.glb and the clip Walk.
struct Input_name {
  std::string file;
  std::string clip;  ///< empty: none named
};

/// `input` split into its file and its clip (after '#', else `options.clip`), refusing what does
/// not apply to its format: a clip or a body for a file that is not a character file, a topology
/// for one.
/// @throws invalid_input naming the input.
Input_name input_name(const std::string& input, const Input_options& options, Front front);

/// Refuses a clip option that applies to none of `inputs`: each names its own after '#'.
/// @throws invalid_input "the clip is given twice", naming the first input.
void check_clip_applies(const std::vector<std::string>& inputs, const Input_options& options, Front front);

/// The character file `file` parsed once for its clips, played on `options.body` when it names one.
/// @throws invalid_input naming the file, as `io::Gltf_file`'s constructors.
io::Gltf_file character_file(const std::string& file, const Input_options& options);

/// The repair `options` ask of the input file `file`: welded by the format's rule unless `weld`
/// says, defects repaired unless `refuse_defects`.
io::Repair_options repair_options(const std::string& file, const Input_options& options);

/// How `read_input` reads the animation file `file` that is not glTF (frame files, a folder, a
/// point cache): with `options`' topology, triangulation, threads, repair (`repair_options`) and fps.
io::Animation_read_options animation_read_options(const std::string& file, const Input_options& options);

/// True when the animation file `file`, not glTF, can be read frame by frame
/// (`io::with_frame_source`) as `read_input` reads it whole: not welded (welding compares every
/// frame), and a point cache only with its topology (without, the reader of whole caches refuses
/// it, in its words).
bool reads_frame_by_frame(const std::string& file, const Input_options& options);

/// Vertices absurdly far for their mesh's own scale (`io::Outlier_check`) in an animation: corrupt
/// coordinates, read as they are unless refused.
struct Outliers {
  std::optional<io::Outlying_vertex> first{};  ///< the farthest of the first frame that has one
  std::size_t frames = 0;                      ///< the frames that have one

  /// Notes `outlier` of the file `file`, or refuses it with `refuse_defects` (named as `front`
  /// spells it).
  /// @throws invalid_input naming the file, the frame and the vertex, with `refuse_defects`.
  void note(const io::Outlying_vertex& outlier, const std::string& file, bool refuse_defects, Front front);
  /// A warning's words ("frame 12 vertex 40 lies ... (in 3 frame(s)): corrupt coordinates? ...
  /// --refuse-defects refuses them", the option as `front` spells it); empty when there are none.
  std::string warning(Front front) const;
};

/// A frame source (`signatures::FrameSource`) whose frames are checked for outlying vertices as
/// `check_outliers` checks a whole animation's, noted in `outliers` (those of the first pass: a
/// source may be rewound and read again) or refused with `refuse_defects`.
template <class Source>
class Outlier_checked_source {
public:
  using Coordinate = typename Source::Coordinate;

  /// @param file names the source in a refusal. `source`, `file` and `outliers` must outlive this.
  Outlier_checked_source(Source& source, const std::string& file, bool refuse_defects, Front front,
                         Outliers& outliers)
      : source_(source), file_(file), refuse_defects_(refuse_defects), front_(front), outliers_(outliers) {}
  std::size_t num_vertices() const { return source_.num_vertices(); }
  std::size_t num_frames() const { return source_.num_frames(); }
  double frames_per_second() const { return source_.frames_per_second(); }
  auto triangles() const { return source_.triangles(); }
  void read_frame(std::span<Coordinate> out) {
    source_.read_frame(out);
    const std::size_t t = next_++;
    if (t == 0 && !check_) check_ = std::make_unique<io::Outlier_check>(std::span<const Coordinate>(out));
    if (t < checked_) return;  // a frame of the first pass, read again
    checked_ = t + 1;
    if (const std::optional<io::Outlying_vertex> outlier = (*check_)(std::span<const Coordinate>(out), t))
      outliers_.note(*outlier, file_, refuse_defects_, front_);
  }
  void rewind() {
    source_.rewind();
    next_ = 0;
  }

private:
  Source& source_;
  const std::string& file_;
  bool refuse_defects_;
  Front front_;
  Outliers& outliers_;
  // Made from frame 0 when it is read; held apart, which keeps GCC 12 from taking an optional's
  // members for uninitialised where it inlines the check into a caller's loop.
  std::unique_ptr<io::Outlier_check> check_;
  std::size_t next_ = 0, checked_ = 0;
};

/// An animation read, with what reading it found.
struct Read_input {
  mesh::Surface_mesh_animation animation;
  Input_name name;
  io::Repair_report repair{};
  std::optional<io::Gltf_read_report> gltf{};  ///< for a glTF input
  Outliers outliers{};
};

/// A warning's words when `read`'s clip, played on the body `options.body`, moves fewer than half
/// of the body's joints ("clip 'Walk' moves 3 of the 24 joints of the body B.glb: ..."); empty
/// otherwise (no body given, a body without skin, or half its joints moved or more).
std::string body_fit_warning(const Read_input& read, const Input_options& options);

/// What reading an input frame by frame (`with_input_stream`) found: a `Read_input` without its
/// animation, the same name, repair and glTF report as `read_input` gives, and the outliers of
/// the frames read.
struct Stream_read {
  Input_name name{};
  io::Repair_report repair{};
  std::optional<io::Gltf_read_report> gltf{};  ///< for a character file
  Outliers outliers{};                         ///< noted as the frames are read
};

/// `body_fit_warning` of an input read frame by frame.
std::string body_fit_warning(const Stream_read& read, const Input_options& options);

/// True when `input` can be read frame by frame as `read_input` reads it whole
/// (`with_input_stream`): a character file's clip (welded, when it is, by what the file fixes), or
/// an animation file that `reads_frame_by_frame`.
/// @throws invalid_input as `read_input` for options and names it refuses before reading.
/// @par Complexity O(1): no file is read.
bool streams(const std::string& input, const Input_options& options, Front front);

/// The report `read_input` gives a character file's clip (`io::Gltf_read_report`: the clip, its
/// times and frames, what was skipped, the joints moved, `repaired`'s counts), without sampling
/// the clip's vertices: only those of one triangle are posed, 9 coordinates a frame.
/// @param file the parsed file; `repaired` its repair (`io::Gltf_connectivity::repaired`).
/// @param clip the clip's name or index (empty: the first); `fps` its sampling rate.
/// @throws invalid_input naming the file, as `io::Gltf_file::read`.
/// @par Complexity O(T (N + J)) for T frames, N nodes and J joints.
io::Gltf_read_report clip_report(const io::Gltf_file& file, const io::Repaired_triangles& repaired,
                                 const std::string& clip, double fps);

/// Reads `input` frame by frame as `read_input` reads it whole: calls `f(source)` once with a
/// `signatures::FrameSource` of its frames, vertices and triangles (those of `read_input`'s
/// animation, the same bits), whose frames are checked for outliers as `read_input` checks them
/// (noted in `read.outliers`, or refused with `refuse_defects`); fills `read`'s name, repair and
/// glTF report before `f` is called. Returns what `f` returns.
/// @pre `streams(input, options, front)`; one frame of the source is in memory at a time.
/// @throws invalid_input naming the file, the clip, the frame or the option, as `read_input`.
/// @par Complexity opening the source (a character file parsed and repaired, a topology read),
/// then what `f` reads.
template <class F>
decltype(auto) with_input_stream(const std::string& input, const Input_options& options, Front front,
                                 bool first_clip_by_default, Stream_read& read, F&& f) {
  check(options, front);
  read.name = input_name(input, options, front);
  const auto checked = [&](auto& source) -> decltype(auto) {
    Outlier_checked_source checked_source(source, read.name.file, options.refuse_defects, front, read.outliers);
    return f(checked_source);
  };
  if (io::is_character_file(read.name.file)) {
    const io::Gltf_file gltf = character_file(read.name.file, options);
    if (!first_clip_by_default) io::require_clip_choice(gltf, read.name.clip);
    io::Gltf_frame_source source(
        gltf, {.clip = read.name.clip, .fps = options.fps, .repair = repair_options(read.name.file, options)});
    read.repair = source.connectivity().repaired().report;
    read.gltf = clip_report(gltf, source.connectivity().repaired(), read.name.clip, options.fps);
    return checked(source);
  }
  return io::with_frame_source(read.name.file, animation_read_options(read.name.file, options),
                               [&](auto& source) -> decltype(auto) {
                                 // A character file, the one source without repair(), was opened above.
                                 if constexpr (requires { source.repair(); }) read.repair = source.repair();
                                 return checked(source);
                               });
}

/// Looks for vertices absurdly far for the mesh's own scale (`io::Outlier_check`) in every frame
/// of `read`'s animation, noting them in `read.outliers` (`Outliers::note`).
/// @throws invalid_input naming the file, frame and vertex, with `refuse_defects`.
void check_outliers(Read_input& read, bool refuse_defects, Front front);

/// Reads `input` as `options` say (the one input of a command or a function: see
/// `check_clip_applies`); a glTF file of several clips needs one named, unless
/// `first_clip_by_default`.
/// @throws invalid_input naming the file, the clip, the frame or the option.
Read_input read_input(const std::string& input, const Input_options& options, Front front,
                      bool first_clip_by_default = false);

/// Refuses an animation of fewer than 2 frames, which has no motion to compare.
/// @throws invalid_input naming `input`.
void require_motion(const mesh::Surface_mesh_animation& animation, const std::string& input);

/// What an input was, for a report: {"file", "clip" (its name as read, or null), "fps"}.
nlohmann::json input_record(const Read_input& read, double fps);

/// The same for the file `file` of an input not read whole (not glTF, so no clip).
nlohmann::json input_record(const std::string& file, double fps);

/// The clips of a glTF file as a report: [{"name", "index", "start", "end", "duration", "frames",
/// "channels"}], frames counted at the rate `contents` were listed at.
nlohmann::json clips_record(const io::Gltf_contents& contents);

/// The clips of the character file `path` (glTF, FBX, Collada, BVH; one without '#'), as `clips_record`.
/// @throws invalid_input naming the file, when it is not a character file or cannot be read.
nlohmann::json clips_of(const std::string& path, double fps);

/// The repair report as JSON: every count, by name.
nlohmann::json repair_record(const io::Repair_report& report);

/// The repair report in words, "12 vertices welded, 3 degenerate triangles dropped", or "nothing".
std::string describe(const io::Repair_report& report);

/// The mesh of a reference-mesh file: a rest pose kept apart from the frames, with the
/// connectivity of the animation as read.
mesh::Surface_mesh read_reference_mesh(const std::string& path);

}  // namespace deformseg::frontend
