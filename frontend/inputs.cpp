#include "inputs.h"

#include <deformseg/io/read_animation.h>
#include <deformseg/io/read_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/threads.h>

#include <utility>

namespace deformseg::frontend {

void check(const Input_options& options, Front front) {
  mesh::check_frames_per_second(options.fps, spelled("fps", front));
  thread_count(options.threads, spelled("threads", front));
}

Input_name input_name(const std::string& input, const Input_options& options, Front front) {
  auto [file, clip] = io::split_clip_suffix(input);
  const auto refuse_for = [&](const std::string& message) { throw invalid_input(message, {.file = file}); };
  const bool character = io::is_character_file(file);
  if (!character && !options.clip.empty())
    refuse_for(spelled("clip", front) + " applies to character files (glTF, FBX, Collada, BVH) only");
  if (!character && !options.body.empty())
    refuse_for(spelled("body", front) + " applies to character files (glTF, FBX, Collada, BVH) only");
  const std::string extension = io::internal::lower_extension(file);
  if (!character && options.topology.empty() && (extension == ".pc2" || extension == ".mdd"))
    refuse_for("a " + extension + " point cache needs a topology mesh (.obj, .off or .ply): give it with " +
               spelled("topology", front));
  if (character && !options.topology.empty())
    refuse_for(spelled("topology", front) + " does not apply to a character file (glTF, FBX, Collada, BVH): it has its own");
  return {std::move(file), clip.value_or(options.clip)};
}

void check_clip_applies(const std::vector<std::string>& inputs, const Input_options& options, Front front) {
  if (options.clip.empty() || inputs.empty()) return;
  for (const std::string& input : inputs)
    if (!io::split_clip_suffix(input).second) return;
  throw invalid_input("the clip is given twice: after '#' and by " + spelled("clip", front),
                      {.file = io::split_clip_suffix(inputs.front()).first});
}

io::Gltf_file character_file(const std::string& file, const Input_options& options) {
  return options.body.empty() ? io::Gltf_file(file) : io::Gltf_file(options.body, file);
}

io::Repair_options repair_options(const std::string& file, const Input_options& options) {
  return {.weld = options.weld.value_or(io::is_character_file(file)),
          .defects = options.refuse_defects ? io::Defect_policy::refuse : io::Defect_policy::repair};
}

namespace {

Read_input read_gltf(Input_name name, const Input_options& options, bool first_clip_by_default) {
  const io::Gltf_file file = character_file(name.file, options);
  if (!first_clip_by_default) io::require_clip_choice(file, name.clip);
  io::Gltf_read_report report;
  mesh::Surface_mesh_animation animation = file.read(
      {.clip = name.clip, .fps = options.fps, .repair = repair_options(name.file, options), .threads = options.threads},
      &report);
  io::Repair_report repair = report.repair;
  return {std::move(animation), std::move(name), std::move(repair), std::move(report)};
}

Read_input read_animation_file(Input_name name, const Input_options& options, bool first_clip_by_default) {
  if (io::is_character_file(name.file)) return read_gltf(std::move(name), options, first_clip_by_default);
  io::Repair_report repair;
  mesh::Surface_mesh_animation animation =
      io::read_animation(name.file, animation_read_options(name.file, options), &repair);
  return {std::move(animation), std::move(name), repair, std::nullopt};
}

}  // namespace

io::Animation_read_options animation_read_options(const std::string& file, const Input_options& options) {
  io::Animation_read_options read{.triangulate = options.triangulate, .threads = options.threads,
                                  .repair = repair_options(file, options), .fps = options.fps};
  if (!options.topology.empty()) read.topology = options.topology;
  return read;
}

bool reads_frame_by_frame(const std::string& file, const Input_options& options) {
  if (repair_options(file, options).weld) return false;
  if (!options.topology.empty()) return true;
  const std::string format = io::animation_format(file);
  return format != "pc2" && format != "mdd";
}

Read_input read_input(const std::string& input, const Input_options& options, Front front,
                      bool first_clip_by_default) {
  check(options, front);
  Read_input read = read_animation_file(input_name(input, options, front), options, first_clip_by_default);
  check_outliers(read, options.refuse_defects, front);
  return read;
}

void Outliers::note(const io::Outlying_vertex& outlier, const std::string& file, bool refuse_defects, Front front) {
  if (refuse_defects)
    throw invalid_input(outlier.text() + ": corrupt coordinates? (read with a warning without " +
                            spelled("refuse_defects", front) + ")",
                        {.file = file});
  if (!first) first = outlier;
  ++frames;
}

std::string Outliers::warning(Front front) const {
  if (!first) return "";
  return first->text() + " (in " + std::to_string(frames) + " frame(s)): corrupt coordinates? They are read as they are; " +
         spelled("refuse_defects", front) + " refuses them";
}

void check_outliers(Read_input& read, bool refuse_defects, Front front) {
  const mesh::Surface_mesh_animation& animation = read.animation;
  if (animation.num_frames() == 0) return;
  const io::Outlier_check check(animation.frame_positions(0));
  for (std::size_t t = 0; t < animation.num_frames(); ++t)
    if (const std::optional<io::Outlying_vertex> outlier = check(animation.frame_positions(t), t))
      read.outliers.note(*outlier, read.name.file, refuse_defects, front);
}

namespace {

std::string body_fit_warning(const std::optional<io::Gltf_read_report>& gltf, const Input_options& options) {
  if (options.body.empty() || !gltf || 2 * gltf->animated_joints >= gltf->joints) return "";
  return "clip '" + gltf->clip + "' moves " + std::to_string(gltf->animated_joints) + " of the " +
         std::to_string(gltf->joints) + " joints of the body " + options.body +
         ": the others keep their rest pose (a body of another skeleton, or joints named otherwise?)";
}

}  // namespace

std::string body_fit_warning(const Read_input& read, const Input_options& options) {
  return body_fit_warning(read.gltf, options);
}

std::string body_fit_warning(const Stream_read& read, const Input_options& options) {
  return body_fit_warning(read.gltf, options);
}

bool streams(const std::string& input, const Input_options& options, Front front) {
  check(options, front);
  const Input_name name = input_name(input, options, front);
  return io::is_character_file(name.file) || reads_frame_by_frame(name.file, options);
}

io::Gltf_read_report clip_report(const io::Gltf_file& file, const io::Repaired_triangles& repaired,
                                 const std::string& clip, double fps) {
  // The report comes with a read: one of the first triangle alone gives it for 9 coordinates a frame.
  io::Repaired_triangles one;
  if (!repaired.triangles.empty()) {
    one.triangles = {{0, 1, 2}};
    for (const std::uint32_t v : repaired.triangles.front()) one.source_vertex.push_back(repaired.source_vertex[v]);
    one.source_triangle = {repaired.source_triangle.front()};
  }
  io::Gltf_read_report report;
  file.read(one, {.clip = clip, .fps = fps, .threads = 1}, &report);
  report.repair = repaired.report;
  return report;
}

void require_motion(const mesh::Surface_mesh_animation& animation, const std::string& input) {
  if (animation.num_frames() < 2)
    throw invalid_input("an animation of " + std::to_string(animation.num_frames()) +
                            " frame: a motion needs at least 2 (an unquoted glob gives one input per file: quote it)",
                        {.file = input});
}

nlohmann::json input_record(const Read_input& read, double fps) {
  nlohmann::json record = input_record(read.name.file, fps);
  if (read.gltf) record["clip"] = read.gltf->clip;
  return record;
}

nlohmann::json input_record(const std::string& file, double fps) {
  return {{"file", file}, {"clip", nullptr}, {"fps", fps}};
}

nlohmann::json clips_record(const io::Gltf_contents& contents) {
  nlohmann::json clips = nlohmann::json::array();
  for (std::size_t k = 0; k < contents.clips.size(); ++k) {
    const io::Gltf_clip_info& clip = contents.clips[k];
    clips.push_back({{"name", clip.name}, {"index", k}, {"start", clip.start}, {"end", clip.end},
                     {"duration", clip.duration}, {"frames", clip.frames}, {"channels", clip.channels}});
  }
  return clips;
}

nlohmann::json clips_of(const std::string& path, double fps) {
  mesh::check_frames_per_second(fps, "fps", {.file = path});
  if (!io::is_character_file(path))
    throw invalid_input("clips are listed for character files (.glb, .gltf, .fbx, .dae, .bvh) only", {.file = path});
  return clips_record(io::gltf_contents(path, fps));
}

nlohmann::json repair_record(const io::Repair_report& report) {
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [name, count] : report.counts()) counts[std::string(name)] = count;
  return counts;
}

std::string describe(const io::Repair_report& r) {
  std::string words;
  const auto add = [&](std::size_t count, const char* what) {
    if (count == 0) return;
    if (!words.empty()) words += ", ";
    words += std::to_string(count) + " " + what;
  };
  add(r.welded_vertices, "vertices welded");
  add(r.degenerate_triangles, "degenerate triangles dropped");
  add(r.duplicate_triangles, "duplicate triangles dropped");
  add(r.non_manifold_edges, "non-manifold edges");
  add(r.non_manifold_vertices, "non-manifold vertices");
  add(r.duplicated_vertices, "vertices duplicated to make them manifold");
  add(r.reoriented_triangles, "triangles reoriented");
  add(r.unrepairable_triangles, "unrepairable triangles dropped");
  add(r.dropped_influences, "skin influences dropped (bad weight or joint)");
  add(r.unweighted_vertices, "skinned vertices without weight bound to their mesh's node");
  return words.empty() ? "nothing" : words;
}

mesh::Surface_mesh read_reference_mesh(const std::string& path) {
  const io::Triangle_soup soup = io::read_mesh(path);
  return mesh::make_face_graph<mesh::Surface_mesh>(io::points_of(soup), soup.triangles);
}

}  // namespace deformseg::frontend
