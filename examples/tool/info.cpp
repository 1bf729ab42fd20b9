// deformseg info INPUT: what an animation is made of.
#include "command.h"

#include <iostream>
#include <memory>

namespace deformseg::tool {
namespace {

struct Info_options {
  Input_options input;
  std::string json;
};

nlohmann::json describe(const Info_options& options) {
  const Surface_mesh_animation animation = read_input(options.input);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (std::size_t t = 0; t < animation.num_frames(); ++t) {
    low = low.cwiseMin(animation.frame_matrix(t).rowwise().minCoeff());
    high = high.cwiseMax(animation.frame_matrix(t).rowwise().maxCoeff());
  }
  return {{"input", options.input.input},
          {"format", io::animation_format(options.input.input)},
          {"frames", animation.num_frames()},
          {"vertices", animation.num_vertices()},
          {"triangles", animation.num_faces()},
          {"bounding_box", {{"min", {low.x(), low.y(), low.z()}}, {"max", {high.x(), high.y(), high.z()}}}},
          {"memory_bytes", animation.memory_bytes()}};
}

void print(const nlohmann::json& info) {
  const auto& box = info["bounding_box"];
  std::cout << "input         " << info["input"].get<std::string>() << '\n'
            << "format        " << info["format"].get<std::string>() << '\n'
            << "frames        " << info["frames"] << '\n'
            << "vertices      " << info["vertices"] << '\n'
            << "triangles     " << info["triangles"] << '\n'
            << "bounding box  " << box["min"].dump() << " to " << box["max"].dump() << '\n'
            << "memory        " << info["memory_bytes"].get<std::size_t>() / 1024 << " KiB\n";
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto options = std::make_shared<Info_options>();
  CLI::App* command = app.add_subcommand(
      "info", "Frames, vertices, triangles, bounding box over all frames, format and memory used");
  add_input_options(*command, options->input);
  command->add_option("--json", options->json, "Write the answer as JSON to FILE ('-': standard output)");
  command->callback([options] {
    const nlohmann::json info = describe(*options);
    if (options->json.empty())
      print(info);
    else
      write_json(info, options->json);
  });
}

}  // namespace deformseg::tool
