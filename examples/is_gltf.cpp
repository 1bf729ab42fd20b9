// is_gltf: whether an input is a glTF file, by its extension in any case, as read_animation decides
// between the glTF reader and the frame files or point caches.
#include <deformseg/io/read_animation.h>

#include <cstdio>
#include <initializer_list>

int main() {
  int gltf = 0;
  for (const char* input : {"Fox.glb", "scene.GLTF", "frames/*.obj", "walk.pc2", "gltf/frame.obj"}) {
    const bool is = deformseg::io::is_gltf(input);
    std::printf("%-16s %s\n", input, is ? "glTF" : "not glTF");
    gltf += is ? 1 : 0;
  }
  return gltf == 2 ? 0 : 1;
}
