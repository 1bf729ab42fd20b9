// Reads the animation named on the command line through deformseg::io and prints its size, or
// the reader's error (a glTF file, when deformseg was built without tinygltf).
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/io/read_animation.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::cerr << "usage: consumer FILE\n";
    return 2;
  }
  const deformseg::mesh::Surface_mesh_animation animation = deformseg::io::read_animation(argv[1]);
  std::cout << "read " << animation.num_frames() << " frames of " << animation.num_faces() << " triangles\n";
  return 0;
} catch (const std::exception& error) {
  std::cout << "error: " << error.what() << '\n';
  return 1;
}
