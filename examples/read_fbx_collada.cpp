// Reads an FBX or Collada character: what the file holds (gltf_contents), one clip as an
// animation (read_animation, "FILE.dae#CLIP"), and the scene written as glTF (fbx_collada_model),
// which tinygltf saves as a .glb file that reads back the same.
//
// With no argument it first writes a small Collada character itself, strip.dae: a strip of two
// squares on a two-bone skeleton whose second bone bends by 90 degrees in one second.
// Usage: read_fbx_collada [FILE.fbx|FILE.dae [CLIP]]
#include <deformseg/io/read_animation.h>

#if DEFORMSEG_HAS_ASSIMP
#include <deformseg/io/fbx_collada.h>
#include <deformseg/io/gltf.h>

#include <tiny_gltf.h>
#endif

#include <exception>
#include <fstream>
#include <iostream>
#include <string>

namespace {

// A two-bone strip in Collada: vertices at x = 0, 1, 2 and y = 0, 1; "tip" (at x = 1) turns by
// 90 degrees about z from 0 to 1 s (the clip "bend", keys as matrices).
void write_strip(const std::string& path) {
  const std::string xyz = R"(<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>)";
  std::ofstream(path) << R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
 <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
 <library_geometries><geometry id="strip" name="strip"><mesh>
  <source id="p"><float_array id="pa" count="18">0 0 0 1 0 0 2 0 0 0 1 0 1 1 0 2 1 0</float_array>
   <technique_common><accessor source="#pa" count="6" stride="3">)" + xyz + R"(</accessor></technique_common></source>
  <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
  <triangles count="4"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 4 0 4 3 1 2 5 1 5 4</p></triangles>
 </mesh></geometry></library_geometries>
 <library_controllers><controller id="skin"><skin source="#strip">
  <bind_shape_matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</bind_shape_matrix>
  <source id="j"><Name_array id="ja" count="2">root tip</Name_array>
   <technique_common><accessor source="#ja" count="2" stride="1"><param name="JOINT" type="name"/></accessor></technique_common></source>
  <source id="b"><float_array id="ba" count="32">1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 1 0 0 -1 0 1 0 0 0 0 1 0 0 0 0 1</float_array>
   <technique_common><accessor source="#ba" count="2" stride="16"><param name="TRANSFORM" type="float4x4"/></accessor></technique_common></source>
  <source id="w"><float_array id="wa" count="2">1 0.5</float_array>
   <technique_common><accessor source="#wa" count="2" stride="1"><param name="WEIGHT" type="float"/></accessor></technique_common></source>
  <joints><input semantic="JOINT" source="#j"/><input semantic="INV_BIND_MATRIX" source="#b"/></joints>
  <vertex_weights count="6"><input semantic="JOINT" source="#j" offset="0"/><input semantic="WEIGHT" source="#w" offset="1"/>
   <vcount>1 2 1 1 2 1</vcount><v>0 0 0 1 1 1 1 0 0 0 0 1 1 1 1 0</v></vertex_weights>
 </skin></controller></library_controllers>
 <library_animations><animation id="bend" name="bend">
  <source id="t"><float_array id="ta" count="2">0 1</float_array>
   <technique_common><accessor source="#ta" count="2" stride="1"><param name="TIME" type="float"/></accessor></technique_common></source>
  <source id="m"><float_array id="ma" count="32">1 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1 0 -1 0 1 1 0 0 0 0 0 1 0 0 0 0 1</float_array>
   <technique_common><accessor source="#ma" count="2" stride="16"><param name="TRANSFORM" type="float4x4"/></accessor></technique_common></source>
  <sampler id="s"><input semantic="INPUT" source="#t"/><input semantic="OUTPUT" source="#m"/></sampler>
  <channel source="#s" target="tip/transform"/>
 </animation></library_animations>
 <library_visual_scenes><visual_scene id="scene">
  <node id="root" name="root" sid="root" type="JOINT"><matrix sid="transform">1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</matrix>
   <node id="tip" name="tip" sid="tip" type="JOINT"><matrix sid="transform">1 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1</matrix></node>
  </node>
  <node id="body" name="body"><instance_controller url="#skin"><skeleton>#root</skeleton></instance_controller></node>
 </visual_scene></library_visual_scenes>
 <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

}  // namespace

int main(int argc, char** argv) {
#if DEFORMSEG_HAS_ASSIMP
  namespace io = deformseg::io;
  try {
    std::string path = argc > 1 ? argv[1] : "strip.dae";
    if (argc == 1) write_strip(path);

    // [read]
    // What the file holds, as the glTF reader sees it: clips, skins, meshes.
    const io::Gltf_contents contents = io::gltf_contents(path, 30);
    for (const io::Gltf_clip_info& clip : contents.clips)
      std::cout << "clip '" << clip.name << "': " << clip.duration << " s, " << clip.frames << " frames at 30 fps\n";
    std::cout << contents.skins.size() << " skin(s), " << contents.vertices << " vertices before welding\n";
    if (contents.clips.empty()) return 0;

    // One clip as an animation, welded and repaired as glTF clips are.
    const std::string clip = argc > 2 ? argv[2] : contents.clips.front().name;
    const auto animation = io::read_animation(path + "#" + clip, {.fps = 30});
    std::cout << "read '" << clip << "': " << animation.num_frames() << " frames of " << animation.num_vertices()
              << " vertices, " << animation.num_faces() << " triangles\n";

    // The scene in glTF's structures, saved as a .glb file: it reads back as the same clip.
    tinygltf::Model model = io::fbx_collada_model(path);
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, "converted.glb", true, true, false, true)) return 1;
    const auto again = io::read_animation("converted.glb#" + clip, {.fps = 30});
    std::cout << "converted.glb: " << again.num_frames() << " frames of " << again.num_vertices() << " vertices\n";
    // [read]
  } catch (const std::exception& e) {
    std::cerr << "read_fbx_collada: " << e.what() << "\n";
    return 1;
  }
#else
  static_cast<void>(argc), static_cast<void>(argv);
  std::cout << "this deformseg was built without Assimp, which reads FBX and Collada files\n";
#endif
  return 0;
}
