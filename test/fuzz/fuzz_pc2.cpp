// libFuzzer harness of the PC2 reader: read_point_cache_info, and read_pc2 with a tetrahedron
// (4 vertices) as the topology, each on every input.
#include "fuzz_point_cache.h"
#include "fuzz_support.h"

#include <deformseg/io/point_cache.h>

DEFORMSEG_FUZZ_READER(pc2) {
  using namespace deformseg;
  const auto& path = fuzz::scratch_input(data, size, ".pc2");
  fuzz::expect_valid_outcome(path, [](const auto& p) { io::read_point_cache_info(p); });
  fuzz::expect_valid_outcome(path, [](const auto& p) { io::read_pc2(p, fuzz::tetrahedron()); });
  return 0;
}
