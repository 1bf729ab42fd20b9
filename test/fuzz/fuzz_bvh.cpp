// libFuzzer harness of the BVH path: the input, as a .bvh file's text, goes through deformseg's
// checks of what Assimp would get wrong (io/internal/bvh_checks.h), Assimp's BVH reader, the
// adapter into glTF's structures, the body made from the skeleton (io/internal/skeleton_body.h),
// its sampling and repair, and the binding of its clip to the glTF seed's skinned body. Debian's
// Assimp is not instrumented: what is checked is deformseg's code on what Assimp gives it, and
// that no input reaches Assimp with a frame count or a depth that would exhaust it.
#include "fuzz_support.h"

#include <deformseg/io/gltf.h>

// Assimp 5.2's BVH reader leaks the joint it was reading when it throws on a malformed hierarchy
// (about 1 KB per file refused): Assimp's memory, not deformseg's, and outside what deformseg can
// free. LeakSanitizer reads these suppressions at start; they hold for every harness of the
// program, none of which allocates through Assimp but fbx_collada's scenes, which free
// themselves (their destructors are Assimp's, their allocations the harness's).
extern "C" const char* __lsan_default_suppressions() { return "leak:libassimp.so\n"; }

DEFORMSEG_FUZZ_READER(bvh) {
  return deformseg::fuzz::run_reader(data, size, ".bvh", [](const std::filesystem::path& path) {
    try {
      const deformseg::io::Gltf_file file(path);
      file.sample({.fps = 1, .threads = 1});
      file.repair();
    } catch (const deformseg::invalid_input& e) {
      // A file of no bone still plays on a body: go on to the binding, the file named.
      if (e.message().find("no mesh") == std::string::npos) throw;
    }
    const deformseg::io::Gltf_file bound(DEFORMSEG_FUZZ_BODY, path);
    bound.sample({.fps = 1, .threads = 1});
  });
}
