// Lists what a glTF 2.0 file holds (gltf_contents): its clips with their times and frame counts,
// its skins, its meshes and their primitives.
//
// With no argument it lists a small .gltf it writes itself as text: one triangle shown twice
// (once as TRIANGLES, once as LINES, which the reader skips), and a clip "rise" of 0.5 s.
// Usage: gltf_contents [FILE.gltf|FILE.glb [FPS]]
#include <deformseg/io/gltf.h>

#include <exception>
#include <fstream>
#include <iostream>
#include <string>

namespace {

// 68 bytes: the triangle's 3 positions (36), the key times 0 and 0.5 s (8), and two translations
// (0,0,0) and (0,0,1) (24), as little-endian floats in base64.
const char* small_gltf = R"({
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
  "meshes": [{"name": "triangle", "primitives": [{"attributes": {"POSITION": 0}},
                                                 {"attributes": {"POSITION": 0}, "mode": 1}]}],
  "nodes": [{"name": "lift", "mesh": 0}],
  "scenes": [{"nodes": [0]}],
  "animations": [{"name": "rise", "samplers": [{"input": 1, "output": 2}],
                  "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
})";

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string path = "triangle.gltf";
    if (argc > 1)
      path = argv[1];
    else
      std::ofstream(path) << small_gltf;
    const double fps = argc > 2 ? std::stod(argv[2]) : 30;

    const deformseg::io::Gltf_contents contents = deformseg::io::gltf_contents(path, fps);
    std::cout << path << ": " << contents.nodes << " node(s); the scene shows " << contents.vertices
              << " vertices and " << contents.triangles << " triangles\n";
    for (const auto& clip : contents.clips)
      std::cout << "clip '" << clip.name << "': " << clip.start << " to " << clip.end << " s (" << clip.duration
                << " s), " << clip.frames << " frames at " << fps << " fps, " << clip.channels << " channel(s)\n";
    for (const auto& skin : contents.skins) std::cout << "skin '" << skin.name << "': " << skin.joints << " joints\n";
    for (const auto& mesh : contents.meshes) {
      std::cout << "mesh '" << mesh.name << "': " << mesh.instances << " instance(s), "
                << (mesh.skinned ? "skinned" : "rigid") << "\n";
      for (const auto& primitive : mesh.primitives)
        std::cout << "  " << primitive.mode << ": " << primitive.vertices << " vertices, " << primitive.triangles
                  << " triangles, " << primitive.morph_targets << " morph target(s)\n";
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "gltf_contents: " << e.what() << "\n";
    return 1;
  }
}
