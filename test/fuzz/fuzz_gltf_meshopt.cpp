// libFuzzer harness of the meshopt decoder's paths (EXT_meshopt_compression): the input's first 4
// bytes choose the counts and the index mode, the next 6 the lengths of the first three of four
// parts (16 bits each), the rest is those parts: the compressed data of a triangle mesh's
// positions (EXPONENTIAL filter), normals (OCTAHEDRAL), indices (TRIANGLES or INDICES) and of a
// clip's rotations (QUATERNION), put in a .glb whose document is made here.
#include "fuzz_support.h"

#include <deformseg/io/gltf.h>
#include <deformseg/io/internal/gltf_document.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

namespace gltf_meshopt_harness {

using Json = nlohmann::json;

// A compressed view of `count` elements of `stride` bytes, decoded from bytes [at, at + length).
Json compressed_view(std::size_t at, std::size_t length, std::size_t count, std::size_t stride, const char* mode,
                     const char* filter, std::size_t& fallback_offset) {
  Json view = {{"buffer", 1}, {"byteOffset", fallback_offset}, {"byteLength", count * stride},
               {"extensions",
                {{"EXT_meshopt_compression",
                  {{"buffer", 0}, {"byteOffset", at}, {"byteLength", length}, {"byteStride", stride},
                   {"count", count}, {"mode", mode}, {"filter", filter}}}}}};
  fallback_offset += count * stride;
  return view;
}


DEFORMSEG_FUZZ_READER(gltf_meshopt) {
  if (size < 10) return 0;
  const std::size_t vertices = 1 + data[0] % 64, indices = 3 * (1 + data[1] % 64), keys = 1 + data[2] % 16;
  const bool sequence = (data[3] & 1) != 0;
  std::array<std::size_t, 5> starts{10};
  for (std::size_t p = 0; p < 3; ++p)
    starts[p + 1] = std::min(size, starts[p] + (std::size_t(data[4 + 2 * p]) | std::size_t(data[5 + 2 * p]) << 8));
  starts[4] = size;
  const auto length = [&](std::size_t p) { return starts[p + 1] - starts[p]; };
  std::size_t fallback = 0;
  Json views = Json::array();
  views.push_back(compressed_view(starts[0], length(0), vertices, 12, "ATTRIBUTES", "EXPONENTIAL", fallback));
  views.push_back(compressed_view(starts[1], length(1), vertices, 4, "ATTRIBUTES", "OCTAHEDRAL", fallback));
  views.push_back(compressed_view(starts[2], length(2), indices, 4, sequence ? "INDICES" : "TRIANGLES", "NONE", fallback));
  views.push_back(compressed_view(starts[3], length(3), keys, 8, "ATTRIBUTES", "QUATERNION", fallback));
  // The keys' times, uncompressed, after the input: 0, 1, 2, ... seconds.
  std::vector<std::uint8_t> bin(data, data + size);
  while (bin.size() % 4 != 0) bin.push_back(0);
  const std::size_t times_at = bin.size();
  for (std::size_t k = 0; k < keys; ++k) {
    const float t = float(k);
    bin.resize(bin.size() + 4);
    std::memcpy(bin.data() + bin.size() - 4, &t, 4);
  }
  views.push_back({{"buffer", 0}, {"byteOffset", times_at}, {"byteLength", keys * 4}});
  const auto accessor = [](int view, int type, std::size_t count, const char* shape, bool normalized) {
    return Json{{"bufferView", view}, {"componentType", type}, {"count", count}, {"type", shape}, {"normalized", normalized}};
  };
  const Json document = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"EXT_meshopt_compression", "KHR_mesh_quantization"}},
      {"extensionsRequired", {"EXT_meshopt_compression", "KHR_mesh_quantization"}},
      {"buffers",
       {{{"byteLength", bin.size()}},
        {{"byteLength", fallback}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}}},
      {"bufferViews", views},
      {"accessors",
       {accessor(0, 5126, vertices, "VEC3", false), accessor(1, 5120, vertices, "VEC3", true),
        accessor(2, 5125, indices, "SCALAR", false), accessor(3, 5122, keys, "VEC4", true),
        {{"bufferView", 4}, {"componentType", 5126}, {"count", keys}, {"type", "SCALAR"}, {"min", {0}},
         {"max", {keys - 1}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"animations",
       {{{"samplers", {{{"input", 4}, {"output", 3}}}},
         {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}}}}}}},
      {"scenes", {{{"nodes", {0}}}}}};
  const auto glb = deformseg::io::internal::gltf::glb_bytes(document, bin);
  return deformseg::fuzz::run_reader(glb.data(), glb.size(), ".glb",
                                     [](const std::filesystem::path& path) { deformseg::io::read_gltf(path, {}); });
}

}  // namespace gltf_meshopt_harness
