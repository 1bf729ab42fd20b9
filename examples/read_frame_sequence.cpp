// Reads an animation stored as one OBJ, OFF or PLY file per frame: the files in natural order
// (list_frame_files), then the whole sequence, frames read in parallel (read_frame_sequence).
//
//   read_frame_sequence [FOLDER | "PATTERN"]      e.g.  read_frame_sequence "horse-gallop/*.obj"
//
// Without an argument it writes a folder of 12 frames of a waving strip of triangles into the
// current folder, named frame_1.obj ... frame_12.obj, and reads it.
#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

// A strip of 2 x 6 vertices and 10 triangles whose far end rises with the frame.
std::string strip_frame(int frame) {
  std::string text = "# frame " + std::to_string(frame) + "\n";
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 2; ++j)
      text += "v " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(0.01 * frame * i * i) + "\n";
  for (int i = 0; i < 5; ++i) {
    const int a = 2 * i + 1;  // OBJ counts vertices from 1
    text += "f " + std::to_string(a) + " " + std::to_string(a + 2) + " " + std::to_string(a + 3) + "\n";
    text += "f " + std::to_string(a) + " " + std::to_string(a + 3) + " " + std::to_string(a + 1) + "\n";
  }
  return text;
}

std::string write_strip_frames() {
  const std::filesystem::path folder = "read_frame_sequence_frames";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  for (int t = 1; t <= 12; ++t) std::ofstream(folder / ("frame_" + std::to_string(t) + ".obj")) << strip_frame(t - 1);
  return folder.string();
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string input = argc > 1 ? argv[1] : write_strip_frames();

    // [read]
    const auto files = deformseg::io::list_frame_files(input);
    std::cout << files.size() << " frame files in natural order (frame_9 before frame_10):";
    for (std::size_t t = 0; t < files.size(); t += std::max<std::size_t>(1, files.size() / 6))
      std::cout << ' ' << files[t].filename().string();
    std::cout << " ... " << files.back().filename().string() << '\n';

    const auto start = std::chrono::steady_clock::now();
    const auto animation = deformseg::io::read_frame_sequence(input);  // all threads; {.threads = 1} for one
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // [read]
    std::cout << animation.num_frames() << " frames, " << animation.num_vertices() << " vertices, "
              << animation.num_faces() << " triangles, read in " << seconds << " s\n";

    // The path of the last vertex through the animation.
    const std::size_t last = animation.num_vertices() - 1;
    for (std::size_t t = 0; t < animation.num_frames(); t += std::max<std::size_t>(1, animation.num_frames() / 6)) {
      const auto xyz = animation.frame_positions(t);
      std::cout << "  frame " << t << ": vertex " << last << " at " << xyz[3 * last] << ' ' << xyz[3 * last + 1]
                << ' ' << xyz[3 * last + 2] << '\n';
    }
  } catch (const deformseg::invalid_input& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
