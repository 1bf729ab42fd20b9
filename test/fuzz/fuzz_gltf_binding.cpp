// libFuzzer harness of Gltf_file's binding of a file's clips to another file's body: the input is
// the clips' .gltf file, played on a fixed skinned body (the glTF seed skinned_animated.gltf,
// DEFORMSEG_FUZZ_BODY), every clip read; errors must name the clips' file.
#include "fuzz_support.h"

#include <deformseg/io/gltf.h>

#include <string>

DEFORMSEG_FUZZ_READER(gltf_binding) {
  return deformseg::fuzz::run_reader(data, size, ".gltf", [](const std::filesystem::path& path) {
    const deformseg::io::Gltf_file bound(DEFORMSEG_FUZZ_BODY, path);
    for (std::size_t k = 0; k < bound.clip_names().size(); ++k) bound.read({.clip = std::to_string(k)});
  });
}
