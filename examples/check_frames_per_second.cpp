// check_frames_per_second: the one check of a frame rate, for a reader or a function of one's own
// that takes one: positive and finite, else invalid_input with the caller's name and file.
#include <deformseg/exceptions.h>
#include <deformseg/mesh/deforming_mesh.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>

int main() {
  using namespace deformseg;
  int refused = 0;
  for (const double fps : {24.0, 0.0, -30.0, std::nan("")}) {
    try {
      mesh::check_frames_per_second(fps, "read_my_format", {.file = "walk.anim"});
      std::printf("%g fps: accepted\n", fps);
    } catch (const invalid_input& e) {
      std::printf("%g fps: %s\n", fps, e.what());
      ++refused;
    }
  }
  return refused == 3 ? 0 : 1;
}
