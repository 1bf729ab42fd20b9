// libFuzzer harness of the PC2 reader: read_point_cache_info, and read_pc2 with a tetrahedron
// (4 vertices) as the topology, each on every input.
#include "fuzz_support.h"

#include <deformseg/default_mesh.h>
#include <deformseg/io/point_cache.h>

#include <array>
#include <vector>

namespace {

const deformseg::Surface_mesh& tetrahedron() {
  static const deformseg::Surface_mesh mesh = deformseg::make_face_graph<deformseg::Surface_mesh>(
      std::vector<std::array<double, 3>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace deformseg;
  const auto& path = fuzz::scratch_input(data, size, ".pc2");
  fuzz::expect_valid_outcome(path, [](const auto& p) { io::read_point_cache_info(p); });
  fuzz::expect_valid_outcome(path, [](const auto& p) { io::read_pc2(p, tetrahedron()); });
  return 0;
}
