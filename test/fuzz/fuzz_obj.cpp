// libFuzzer harness of read_obj, and of read_mesh_points on what read_obj accepted.
#include "fuzz_support.h"

#include <deformseg/io/obj.h>
#include <deformseg/io/read_mesh.h>

#include <vector>

DEFORMSEG_FUZZ_READER(obj) {
  return deformseg::fuzz::run_reader(data, size, ".obj", [](const std::filesystem::path& path) {
    const deformseg::io::Triangle_soup soup = deformseg::io::read_obj(path, {.triangulate = true});
    std::vector<float> xyz(soup.points.size());
    deformseg::io::read_mesh_points(path, xyz);
  });
}
