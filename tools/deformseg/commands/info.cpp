// deformseg info INPUT: what an animation is made of; for a character file (glTF, FBX, Collada, BVH)
// also its clips, skins and meshes; and what repairing its mesh changed.
#include "command.h"
#include "motion_box.h"

#include <deformseg/io/frame_sequence.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace deformseg::tool {
namespace {

struct Info_options {
  std::string input;
  Input_options read;
  bool files = false;
  std::string json;
};

// --files lists a frame sequence's files; a character file or a point cache has none.
void check_files_option(const Info_options& o) {
  if (!o.files) return;
  const std::string format = io::animation_format(o.input);
  if (io::is_character_file(io::split_clip_suffix(o.input).first) || format == "pc2" || format == "mdd")
    throw invalid_input("--files lists the frame files of a folder or glob; this input is one " + format + " file",
                        {.file = io::split_clip_suffix(o.input).first});
}

// What info reports of an animation's frames: its counts, the box around every frame and the
// memory the animation read whole takes.
struct Animation_counts {
  std::size_t frames = 0, vertices = 0, triangles = 0;
  Motion_box box{};
  std::size_t memory_bytes = 0;
};

// The memory an animation of these counts takes read whole (`Deforming_mesh::memory_bytes`: its
// coordinates as doubles, its triangles and index tables), computed, not measured: info reads one
// frame at a time when it can. O(1).
std::size_t whole_animation_bytes(std::size_t frames, std::size_t vertices, std::size_t triangles) {
  using Animation = mesh::Surface_mesh_animation;
  return 3 * vertices * frames * sizeof(Animation::coordinate_type) +
         triangles * (sizeof(Animation::Triangle) + sizeof(Animation::face_descriptor)) +
         vertices * sizeof(Animation::vertex_descriptor);
}

// The counts of an animation read whole.
Animation_counts counted(const mesh::Surface_mesh_animation& animation) {
  return {.frames = animation.num_frames(), .vertices = animation.num_vertices(), .triangles = animation.num_faces(),
          .box = motion_box(animation), .memory_bytes = animation.memory_bytes()};
}

// The counts of an animation read frame by frame, one frame in memory; the box is the same to the
// bit as `motion_box` of the animation read whole (minima and maxima of the same coordinates).
template <class Source>
Animation_counts counted(Source& source) {
  Animation_counts counts{.frames = source.num_frames(), .vertices = source.num_vertices(),
                          .triangles = source.triangles().size()};
  std::vector<typename Source::Coordinate> frame(3 * counts.vertices);
  for (std::size_t t = 0; t < counts.frames; ++t) {
    source.read_frame(std::span(frame));
    for (std::size_t i = 0; i < counts.vertices; ++i)
      for (Eigen::Index k = 0; k < 3; ++k) {
        const double x = double(frame[3 * i + std::size_t(k)]);
        counts.box.low[k] = std::min(counts.box.low[k], x), counts.box.high[k] = std::max(counts.box.high[k], x);
      }
  }
  counts.memory_bytes = whole_animation_bytes(counts.frames, counts.vertices, counts.triangles);
  return counts;
}

nlohmann::json bounding_box(const Motion_box& box) {
  return {{"min", {box.low.x(), box.low.y(), box.low.z()}}, {"max", {box.high.x(), box.high.y(), box.high.z()}}};
}

// The clips of a character file (an FBX, Collada or BVH file's as glTF holds them), the skins and
// meshes of its body (its own, made from its skeleton when it has no mesh, or `body`'s), and the
// clip read.
nlohmann::json gltf_json(const std::string& file, const std::string& body, double fps,
                         const io::Gltf_read_report& read) {
  const nlohmann::json clips = frontend::clips_record(io::gltf_contents(file, fps));
  const io::Gltf_contents contents = io::gltf_contents(body.empty() ? file : body, fps);
  nlohmann::json skins = nlohmann::json::array();
  for (const auto& skin : contents.skins) skins.push_back({{"name", skin.name}, {"joints", skin.joints}});
  nlohmann::json meshes = nlohmann::json::array();
  for (const auto& mesh : contents.meshes) {
    nlohmann::json primitives = nlohmann::json::array();
    for (const auto& p : mesh.primitives)
      primitives.push_back({{"mode", p.mode}, {"vertices", p.vertices}, {"triangles", p.triangles},
                            {"morph_targets", p.morph_targets}});
    meshes.push_back({{"name", mesh.name}, {"skinned", mesh.skinned}, {"instances", mesh.instances},
                      {"primitives", primitives}});
  }
  return {{"clip", {{"name", read.clip}, {"start", read.start}, {"end", read.end}, {"fps", fps}}},
          {"clips", clips},
          {"body", body.empty() ? nlohmann::json() : nlohmann::json(body)},
          {"skeleton_body", contents.skeleton_body},
          {"joints", read.joints},
          {"animated_joints", read.animated_joints},
          {"skins", skins},
          {"meshes", meshes},
          {"skipped", read.skipped}};
}

// What info says of an input, read whole or frame by frame.
struct Info_input {
  std::string file;
  nlohmann::json sources;
  Animation_counts counts;
  io::Repair_report repair;
  std::optional<io::Gltf_read_report> gltf;
};

nlohmann::json describe(const Info_options& options, const Info_input& read) {
  const Animation_counts& counts = read.counts;
  nlohmann::json info = {{"input", read.file},
                         {"sources", read.sources},
                         {"format", io::animation_format(read.file)},
                         {"frames", counts.frames},
                         {"vertices", counts.vertices},
                         {"triangles", counts.triangles},
                         {"bounding_box", bounding_box(counts.box)},
                         {"memory_bytes", counts.memory_bytes},
                         {"repair", frontend::repair_record(read.repair)}};
  if (read.gltf) info["gltf"] = gltf_json(read.file, options.read.body, options.read.fps, *read.gltf);
  if (options.files) {
    nlohmann::json files = nlohmann::json::array();
    for (const auto& file : io::list_frame_files(read.file)) files.push_back(file.string());
    info["files"] = files;
  }
  return info;
}

// The input read frame by frame when it can be (one frame in memory), else whole, as other commands
// read it (welded frame files, which compare every frame).
Info_input read_info_input(const Info_options& options) {
  // info lists the clips of a file whichever it reads: of several, none named, the first.
  frontend::check_clip_applies({options.input}, options.read, frontend::Front::command_line);
  frontend::Stream_read streamed;
  Animation_counts counts;
  if (stream_input(options.input, options.read, true, streamed, [&](auto& source) { counts = counted(source); }))
    return {streamed.name.file, sources(streamed, options.read), counts, streamed.repair, streamed.gltf};
  const frontend::Read_input read = read_input(options.input, options.read, true);
  return {read.name.file, sources({&read, 1}, options.read), counted(read.animation), read.repair, read.gltf};
}

void print_gltf(const nlohmann::json& gltf) {
  const auto& clip = gltf["clip"];
  std::cout << std::fixed << std::setprecision(3) << "clip          \"" << clip["name"].get<std::string>()
            << "\", " << clip["start"].get<double>() << " to " << clip["end"].get<double>() << " s at "
            << clip["fps"].get<double>() << " fps\n"
            << "clips         " << gltf["clips"].size() << '\n';
  for (const auto& c : gltf["clips"])
    std::cout << "  " << std::left << std::setw(34) << c["name"].get<std::string>() << std::right << std::setw(8)
              << c["duration"].get<double>() << " s " << std::setw(5)
              << c["frames"] << " frames\n";
  if (!gltf["body"].is_null())
    std::cout << "body          " << gltf["body"].get<std::string>() << ", " << gltf["animated_joints"] << " of "
              << gltf["joints"] << " joints moved\n";
  if (gltf["skeleton_body"].get<bool>())
    std::cout << "body          made from the skeleton: a tube along each bone (the file has no mesh)\n";
  std::cout << "skins         " << gltf["skins"].size();
  for (const auto& s : gltf["skins"]) std::cout << " (" << s["joints"] << " joints)";
  std::cout << "\nmeshes        " << gltf["meshes"].size() << '\n';
  for (const auto& m : gltf["meshes"]) {
    std::size_t vertices = 0, triangles = 0;
    for (const auto& p : m["primitives"])
      vertices += p["vertices"].get<std::size_t>(), triangles += p["triangles"].get<std::size_t>();
    std::cout << "  " << std::left << std::setw(34) << m["name"].get<std::string>() << std::right
              << (m["skinned"].get<bool>() ? " skinned " : " rigid   ") << std::setw(6) << vertices << " vertices "
              << std::setw(6) << triangles << " triangles\n";
  }
  for (const auto& line : gltf["skipped"]) std::cout << "skipped       " << line.get<std::string>() << '\n';
}

void print(const nlohmann::json& info, const io::Repair_report& repair) {
  const auto& box = info["bounding_box"];
  std::cout << "input         " << info["input"].get<std::string>() << '\n'
            << "format        " << info["format"].get<std::string>() << '\n'
            << "frames        " << info["frames"] << '\n'
            << "vertices      " << info["vertices"] << '\n'
            << "triangles     " << info["triangles"] << '\n'
            << "bounding box  " << point_text(box["min"]) << " to " << point_text(box["max"]) << '\n'
            << "memory        " << info["memory_bytes"].get<std::size_t>() / 1024 << " KiB\n"
            << "repair        " << frontend::describe(repair) << " (read " << repair.input_vertices
            << " vertices, " << repair.input_triangles << " triangles)\n";
  if (info.contains("gltf")) print_gltf(info["gltf"]);
  if (info.contains("files")) {
    std::cout << "files         frame: file, in the order read\n";
    for (std::size_t t = 0; t < info["files"].size(); ++t)
      std::cout << "  " << std::setw(5) << t << ": " << info["files"][t].get<std::string>() << '\n';
  }
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto options = std::make_shared<Info_options>();
  CLI::App* command = app.add_subcommand(
      "info", "Frames, vertices, triangles, bounding box over all frames, format, memory and what "
              "the repair of the mesh changed; for glTF, FBX, Collada and BVH also the clips, skins and meshes "
              "(of a file of several clips with none named, the first clip is read, and named; of a file without "
              "a mesh, the body made from its skeleton). The frames are read one at a time (welded frame files "
              "whole); memory is what the animation takes read whole, as most commands read it: its coordinates "
              "as doubles and its triangles, computed from the counts");
  add_input(*command, options->input, options->read);
  command->add_flag("--files", options->files,
                    "List the frame files of a folder or glob in the order they are read, frame by frame");
  add_json_option(*command, options->json, "the answer");
  command->callback([options] {
    check_files_option(*options);
    const Info_input read = read_info_input(*options);
    const nlohmann::json info = describe(*options, read);
    write_outputs(info, options->json, [&] { print(info, read.repair); });
  });
}

}  // namespace deformseg::tool
