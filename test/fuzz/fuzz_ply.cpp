// libFuzzer harness of read_ply, and of read_mesh_points on what read_ply accepted.
#include "fuzz_support.h"

#include <deformseg/io/ply.h>
#include <deformseg/io/read_mesh.h>

#include <vector>

DEFORMSEG_FUZZ_READER(ply) {
  return deformseg::fuzz::run_reader(data, size, ".ply", [](const std::filesystem::path& path) {
    const deformseg::io::Triangle_soup soup = deformseg::io::read_ply(path, {.triangulate = true});
    std::vector<float> xyz(soup.points.size());
    deformseg::io::read_mesh_points(path, xyz);
  });
}
