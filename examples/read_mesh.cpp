// Reads one mesh file, choosing the reader by its extension (read_mesh), then only its vertex
// positions (read_mesh_points), as the frames of an animation after the first are read.
//
//   read_mesh [FILE.obj|.off|.ply]
//
// Without an argument it writes a small square pyramid, as OBJ and as OFF, into the current
// folder, and reads both: its base is a quad, read with the option `triangulate`.
#include <deformseg/exceptions.h>
#include <deformseg/io/read_mesh.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

void print(const std::string& path, const deformseg::io::Triangle_soup& soup) {
  std::cout << path << ": " << soup.num_vertices() << " vertices, " << soup.triangles.size() << " triangles\n";
  for (std::size_t i = 0; i < std::min<std::size_t>(soup.num_vertices(), 5); ++i)
    std::cout << "  vertex " << i << ": " << soup.points[3 * i] << ' ' << soup.points[3 * i + 1] << ' '
              << soup.points[3 * i + 2] << '\n';
  for (std::size_t j = 0; j < std::min<std::size_t>(soup.triangles.size(), 6); ++j)
    std::cout << "  triangle " << j << ": " << soup.triangles[j][0] << ' ' << soup.triangles[j][1] << ' '
              << soup.triangles[j][2] << '\n';
}

// A square pyramid: 5 vertices, 4 triangles and a quad base, in both formats.
void write_pyramid() {
  std::ofstream("pyramid.obj") << "# a square pyramid\n"
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                                  "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 1 4 3 2\n";
  std::ofstream("pyramid.off") << "OFF\n5 5 8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
                                  "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n4 0 3 2 1\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc > 1) {
      print(argv[1], deformseg::io::read_mesh(argv[1], {.triangulate = true}));
      return 0;
    }
    write_pyramid();
    for (const char* path : {"pyramid.obj", "pyramid.off"})
      print(path, deformseg::io::read_mesh(path, {.triangulate = true}));

    // [error]
    // Without `triangulate`, the quad is an error that names the file and the line.
    try {
      deformseg::io::read_mesh("pyramid.obj");
    } catch (const deformseg::invalid_input& e) {
      std::cout << "without triangulate: " << e.what() << '\n';
    }
    // [error]

    // Positions only: the size of the output says how many vertices the file must have.
    std::vector<double> xyz(3 * 5);
    deformseg::io::read_mesh_points("pyramid.off", xyz);
    std::cout << "apex from read_mesh_points: " << xyz[12] << ' ' << xyz[13] << ' ' << xyz[14] << '\n';
  } catch (const deformseg::invalid_input& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
