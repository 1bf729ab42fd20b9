// libFuzzer harness of the MDD reader: read_point_cache_info, and read_mdd with a tetrahedron
// (4 vertices) as the topology, each on every input.
#include "fuzz_point_cache.h"
#include "fuzz_support.h"

#include <deformseg/io/point_cache.h>

DEFORMSEG_FUZZ_READER(mdd) {
  using namespace deformseg;
  const auto& path = fuzz::scratch_input(data, size, ".mdd");
  fuzz::expect_valid_outcome(path, [](const auto& p) { io::read_point_cache_info(p); });
  fuzz::expect_valid_outcome(path, [](const auto& p) { io::read_mdd(p, fuzz::tetrahedron()); });
  return 0;
}
