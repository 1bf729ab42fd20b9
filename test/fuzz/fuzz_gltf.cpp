// libFuzzer harness of read_gltf on .gltf files (JSON; the seeds hold their buffers as data URIs).
#include "fuzz_support.h"

#include <deformseg/io/gltf.h>

DEFORMSEG_FUZZ_READER(gltf) {
  return deformseg::fuzz::run_reader(data, size, ".gltf", [](const std::filesystem::path& path) {
    deformseg::io::read_gltf(path, {});
  });
}
