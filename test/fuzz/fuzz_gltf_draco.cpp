// libFuzzer harness of the Draco decoder's path (KHR_draco_mesh_compression): the input is the
// compressed data of one primitive (POSITION, NORMAL, TEXCOORD_0, JOINTS_0 and WEIGHTS_0 of a
// skinned mesh), put in a .glb whose document is fixed here, then read.
#include "fuzz_support.h"

#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/gltf_document.h>

#include <vector>

namespace gltf_draco_harness {

nlohmann::json draco_document(std::size_t bytes) {
  const auto accessor = [](int type, const char* shape) {
    return nlohmann::json{{"componentType", type}, {"count", 3}, {"type", shape}};
  };
  nlohmann::json draco = {{"bufferView", 0},
                          {"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}, {"JOINTS_0", 3}, {"WEIGHTS_0", 4}}}};
  return {{"asset", {{"version", "2.0"}}},
          {"extensionsUsed", {"KHR_draco_mesh_compression"}},
          {"extensionsRequired", {"KHR_draco_mesh_compression"}},
          {"buffers", {{{"byteLength", bytes}}}},
          {"bufferViews", {{{"buffer", 0}, {"byteLength", bytes}}}},
          {"accessors",
           {accessor(5126, "VEC3"), accessor(5126, "VEC3"), accessor(5126, "VEC2"), accessor(5121, "VEC4"),
            accessor(5126, "VEC4"), accessor(5125, "SCALAR")}},
          {"meshes",
           {{{"primitives",
              {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}, {"JOINTS_0", 3}, {"WEIGHTS_0", 4}}},
                {"indices", 5},
                {"extensions", {{"KHR_draco_mesh_compression", draco}}}}}}}}},
          {"nodes", {{{"mesh", 0}, {"skin", 0}}, {{"name", "joint"}}}},
          {"skins", {{{"joints", {1}}}}},
          {"scenes", {{{"nodes", {0, 1}}}}}};
}


DEFORMSEG_FUZZ_READER(gltf_draco) {
  if (size == 0) return 0;  // a buffer of 0 bytes is not glTF
  const auto glb = deformseg::io::internal::gltf::glb_bytes(draco_document(size), {data, size});
  return deformseg::fuzz::run_reader(glb.data(), glb.size(), ".glb",
                                     [](const std::filesystem::path& path) { deformseg::io::read_gltf(path, {}); });
}

}  // namespace gltf_draco_harness
