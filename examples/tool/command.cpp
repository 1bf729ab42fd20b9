#include "command.h"

#include <stb/stb_image_write.h>

#include <fstream>
#include <iostream>

namespace deformseg::tool {

void add_input_options(CLI::App& command, Input_options& options) {
  command.add_option("input", options.input,
                     "A folder of frames (.obj, .off, .ply; natural order), a quoted glob "
                     "pattern, or a point cache (.pc2, .mdd) with --topology")
      ->required();
  command.add_option("--topology", options.topology,
                     "Mesh file giving the connectivity (required for a point cache)");
  command.add_flag("--triangulate", options.triangulate,
                   "Fan-triangulate polygons instead of rejecting them");
  command.add_option("--threads", options.threads, "Threads to use (0: all)")
      ->check(CLI::NonNegativeNumber);
}

Surface_mesh_animation read_input(const Input_options& options) {
  progress("reading " + options.input);
  io::Animation_read_options read{.triangulate = options.triangulate, .threads = options.threads};
  if (!options.topology.empty()) read.topology = options.topology;
  return io::read_animation(options.input, read);
}

void write_json(const nlohmann::json& document, const std::string& path) {
  if (path == "-") {
    std::cout << document.dump(2) << '\n';
    return;
  }
  std::ofstream out(path);
  if (!(out << document.dump(2) << '\n'))
    throw std::runtime_error("cannot write " + path);
}

void progress(const std::string& line) { std::cerr << "deformseg: " << line << '\n'; }

void write_png(const Image& image, const std::string& path) {
  if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.pixels.data(), image.width * 3))
    throw std::runtime_error("cannot write " + path);
}

}  // namespace deformseg::tool
