// sample_gltf: one clip of a glTF file sampled into positions and triangles, the file's vertices
// in its order and nothing repaired, for data with no mesh built; and require_clip_choice, the rule
// of the readers that take any animation: a file of several clips needs one named. The file,
// written here, shows a triangle that two clips move up by 1 in 0.5 s: "rise" (LINEAR) and "jump"
// (STEP).
#include <deformseg/exceptions.h>
#include <deformseg/io/gltf.h>

#include <cstdio>
#include <fstream>

namespace {

// 68 bytes: the triangle's 3 positions (36), the key times 0 and 0.5 s (8), and two translations
// (0,0,0) and (0,0,1) (24), as little-endian floats in base64.
const char* two_clips = R"({
  "asset": {"version": "2.0"},
  "buffers": [{"byteLength": 68, "uri": "data:application/octet-stream;base64,)"
                        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAD8"
                        "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAgD8="
                        R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                  {"buffer": 0, "byteOffset": 44, "byteLength": 24}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5126, "count": 2, "type": "SCALAR"},
                {"bufferView": 2, "componentType": 5126, "count": 2, "type": "VEC3"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "nodes": [{"mesh": 0}],
  "scenes": [{"nodes": [0]}],
  "animations": [
    {"name": "rise", "samplers": [{"input": 1, "output": 2}],
     "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]},
    {"name": "jump", "samplers": [{"input": 1, "output": 2, "interpolation": "STEP"}],
     "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
})";

}  // namespace

int main() {
  using namespace deformseg;
  std::ofstream("two_clips.gltf") << two_clips;
  bool refused = false;
  try {
    io::require_clip_choice(io::Gltf_file("two_clips.gltf"), "");  // "jump" or "rise" would pass
  } catch (const invalid_input& e) {
    std::printf("%s\n", e.what());
    refused = true;
  }
  const io::Sampled_gltf rise = io::sample_gltf("two_clips.gltf", {.clip = "rise", .fps = 10});
  const io::Sampled_gltf jump = io::sample_gltf("two_clips.gltf", {.clip = "jump", .fps = 10});
  std::printf("%zu frames of %zu vertices, %zu triangle(s)\nheight of vertex 0, rise:", rise.report.frames,
              rise.num_vertices, rise.triangles.size());
  const auto z = [](const io::Sampled_gltf& s, std::size_t t) { return s.positions[t * 3 * s.num_vertices + 2]; };
  for (std::size_t t = 0; t < rise.report.frames; ++t) std::printf(" %.1f", z(rise, t));
  std::printf("\nheight of vertex 0, jump:");
  for (std::size_t t = 0; t < jump.report.frames; ++t) std::printf(" %.1f", z(jump, t));
  std::printf("\n");
  return refused && rise.report.frames == 6 && z(rise, 3) > 0.5 && z(jump, 3) == 0 && z(jump, 5) == 1 ? 0 : 1;
}
