// Reads BVH motion capture: the skeleton and its clip as the glTF reader holds them (bvh_model,
// is_bvh), then the clip as an animation on the body made from the skeleton (read_animation: a
// tube along each bone, since a BVH file has no mesh).
//
// With no argument it first writes a small BVH file itself, arm.bvh: a root, an elbow and a wrist
// in a row along x, the elbow turning by 90 degrees about z over 10 frames at 30 fps.
// Usage: read_bvh [FILE.bvh]
#include <deformseg/io/read_animation.h>

#if DEFORMSEG_HAS_ASSIMP
#include <deformseg/io/bvh.h>
#include <deformseg/io/gltf.h>

#include <tiny_gltf.h>  // the model bvh_model gives
#endif

#include <exception>
#include <fstream>
#include <iostream>
#include <string>

namespace {

void write_arm(const std::string& path) {
  std::ofstream out(path);
  out << "HIERARCHY\nROOT shoulder\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation "
         "Yrotation\n  JOINT elbow\n  {\n    OFFSET 1 0 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "    JOINT wrist\n    {\n      OFFSET 1 0 0\n      CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "      End Site\n      {\n        OFFSET 0.5 0 0\n      }\n    }\n  }\n}\n"
         "MOTION\nFrames: 11\nFrame Time: 0.0333333\n";
  for (int frame = 0; frame <= 10; ++frame) out << "0 0 0 0 0 0 " << 9 * frame << " 0 0 0 0 0\n";
}

}  // namespace

int main(int argc, char** argv) {
#if DEFORMSEG_HAS_ASSIMP
  namespace io = deformseg::io;
  try {
    const std::string path = argc > 1 ? argv[1] : "arm.bvh";
    if (argc == 1) write_arm(path);
    if (!io::is_bvh(path)) return 1;

    // The skeleton and its one clip, in glTF's structures: a node per joint and end site.
    const tinygltf::Model model = io::bvh_model(path);
    std::cout << model.nodes.size() << " nodes, " << model.animations.size() << " clip '"
              << model.animations.front().name << "'\n";

    // The clip on the body made from its skeleton, as every command reads it.
    io::Gltf_read_report report;
    const io::Gltf_file file(path);
    const auto animation = file.read({.fps = 30}, &report);
    std::cout << "read: " << animation.num_frames() << " frames of " << animation.num_vertices() << " vertices, "
              << animation.num_faces() << " triangles, body made from the skeleton: "
              << (report.skeleton_body ? "yes" : "no") << '\n';
    return report.skeleton_body && animation.num_frames() == 11 ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "read_bvh: " << e.what() << "\n";
    return 1;
  }
#else
  static_cast<void>(argc), static_cast<void>(argv);
  std::cout << "this deformseg was built without Assimp, which reads BVH files\n";
  return 0;
#endif
}
