// libFuzzer harness of read_off, and of read_mesh_points on what read_off accepted.
#include "fuzz_support.h"

#include <deformseg/io/off.h>
#include <deformseg/io/read_mesh.h>

#include <vector>

DEFORMSEG_FUZZ_READER(off) {
  return deformseg::fuzz::run_reader(data, size, ".off", [](const std::filesystem::path& path) {
    const deformseg::io::Triangle_soup soup = deformseg::io::read_off(path, {.triangulate = true});
    std::vector<float> xyz(soup.points.size());
    deformseg::io::read_mesh_points(path, xyz);
  });
}
