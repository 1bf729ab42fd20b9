// libFuzzer harness of read_gltf on .gltf files (JSON; the seeds hold their buffers as data URIs).
#include "fuzz_support.h"

#include <deformseg/io/gltf.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deformseg::fuzz::run_reader(data, size, ".gltf", [](const std::filesystem::path& path) {
    deformseg::io::read_gltf(path, {});
  });
}
