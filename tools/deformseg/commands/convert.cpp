// deformseg convert INPUT OUT: an animation (a glTF, FBX or Collada clip, a point cache, frames) written as a
// frame sequence, or as a point cache with its topology mesh.
#include "command.h"

#include <deformseg/io/point_cache.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/files.h>
#include <deformseg/io/frame_sequence.h>

#include <filesystem>
#include <memory>

namespace deformseg::tool {
namespace {

struct Convert_options {
  std::string input;
  Input_options read;
  std::string out;
  std::string format = "ply";
  std::string json;
};

// The name of what the input holds, for the point cache and its topology: "Fox" for "Fox.glb",
// the folder's name for a folder of frames.
std::string input_stem(const std::string& input) {
  std::filesystem::path path(input);
  if (!path.has_filename()) path = path.parent_path();  // "frames/"
  const std::string stem = path.stem().string();
  return stem.empty() || stem.find_first_of("*?") != std::string::npos ? "animation" : stem;
}

std::vector<std::filesystem::path> write(const mesh::Surface_mesh_animation& animation, const Convert_options& o) {
  const std::filesystem::path out(o.out);
  if (o.format != "pc2" && o.format != "mdd") {
    const io::Mesh_format format =
        o.format == "obj" ? io::Mesh_format::obj : o.format == "off" ? io::Mesh_format::off : io::Mesh_format::ply;
    return io::write_sequence(animation, out, {.format = format});
  }
  io::create_folder(out);
  const std::string stem = input_stem(io::split_clip_suffix(o.input).first);
  const auto topology = out / (stem + ".obj");
  const auto cache = out / (stem + "." + o.format);
  io::write_obj(animation, 0, topology);
  if (o.format == "pc2")
    io::write_pc2(animation, cache);
  else
    io::write_mdd(animation, cache);
  return {topology, cache};
}

}  // namespace

void add_convert_command(CLI::App& app) {
  auto o = std::make_shared<Convert_options>();
  CLI::App* command = app.add_subcommand(
      "convert", "Write an animation (a clip of a glTF, FBX or Collada file, a point cache, frames) as a frame sequence, or as "
                 "a point cache with its topology mesh");
  add_input(*command, o->input, o->read);
  command->add_option("out", o->out, "Folder to write into (created when missing)")->required()->check(output_folder());
  command->add_option("--format", o->format,
                      "obj, off or ply: a file per frame (frame_0000.ply, ...); pc2 or mdd: a point "
                      "cache NAME.pc2 with NAME.obj as its topology, NAME from the input")
      ->check(CLI::IsMember({"obj", "off", "ply", "pc2", "mdd"}))
      ->capture_default_str();
  add_json_option(*command, o->json, "what was written");
  command->callback([o] {
    const frontend::Read_input read = read_input(o->input, o->read);
    const mesh::Surface_mesh_animation& animation = read.animation;
    progress("writing " + std::to_string(animation.num_frames()) + " frames to " + o->out);
    const auto files = write(animation, *o);
    nlohmann::json written = nlohmann::json::array();
    for (const auto& file : files) written.push_back(file.string());
    const nlohmann::json summary = {{"frames", animation.num_frames()},
                                    {"vertices", animation.num_vertices()},
                                    {"triangles", animation.num_faces()},
                                    {"repair", frontend::repair_record(read.repair)},
                                    {"files", written}};
    write_outputs(summary, o->json, [&] { print_written(summary); });
  });
}

}  // namespace deformseg::tool
