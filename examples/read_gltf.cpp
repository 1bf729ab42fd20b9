// Reads a glTF 2.0 character: what the file holds (gltf_contents), one clip as an animation
// (read_gltf), every clip of it parsed once (Gltf_file) and its connectivity repaired once for
// them all (read whole, a frame at a time, or the repair's vertices sampled), and the clips of an
// animation-only file (no mesh, as a motion library exports them) played on its body.
//
// With no argument it first writes a small skinned character itself, bend.gltf: a strip of
// 2 x 4 squares on a two-bone skeleton whose second bone bends by 90 degrees in one second
// (clip "bend"), and swings back and forth (clip "swing").
// Usage: read_gltf [FILE.gltf|FILE.glb [CLIP]]
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// Appends `values` to the model's one buffer as a new buffer view and accessor; gives its index.
template <class T>
int add_accessor(tinygltf::Model& model, const std::vector<T>& values, int component_type, int type, int components) {
  auto& bytes = model.buffers[0].data;
  const std::size_t offset = bytes.size();
  bytes.resize(offset + values.size() * sizeof(T));
  std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
  while (bytes.size() % 4 != 0) bytes.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = values.size() * sizeof(T);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size()) - 1;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = values.size() / std::size_t(components);
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

int add_floats(tinygltf::Model& model, const std::vector<float>& values, int type, int components) {
  return add_accessor(model, values, TINYGLTF_COMPONENT_TYPE_FLOAT, type, components);
}

// A channel rotating `node` about z through `angles` (radians) at `times`.
void add_rotation(tinygltf::Model& model, tinygltf::Animation& clip, int node, const std::vector<float>& times,
                  const std::vector<float>& angles) {
  std::vector<float> quaternions;
  for (float a : angles) quaternions.insert(quaternions.end(), {0, 0, std::sin(a / 2), std::cos(a / 2)});
  tinygltf::AnimationSampler sampler;
  sampler.input = add_floats(model, times, TINYGLTF_TYPE_SCALAR, 1);
  sampler.output = add_floats(model, quaternions, TINYGLTF_TYPE_VEC4, 4);
  clip.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = int(clip.samplers.size()) - 1;
  channel.target_node = node;
  channel.target_path = "rotation";
  clip.channels.push_back(channel);
}

// A strip of 2 x 4 unit squares along x on two bones (the second from x = 2), in a .gltf with
// its buffer embedded.
void write_bending_strip(const std::string& path) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.buffers.resize(1);
  std::vector<float> positions;
  std::vector<std::uint8_t> joints;
  std::vector<float> weights;
  for (int y = 0; y <= 2; ++y)
    for (int x = 0; x <= 4; ++x) {
      positions.insert(positions.end(), {float(x), float(y), 0});
      const float tip = x < 2 ? 0.0f : x == 2 ? 0.5f : 1.0f;  // the middle column is half on each bone
      joints.insert(joints.end(), {0, 1, 0, 0});
      weights.insert(weights.end(), {1 - tip, tip, 0, 0});
    }
  std::vector<std::uint16_t> indices;
  for (std::uint16_t y = 0; y < 2; ++y)
    for (std::uint16_t x = 0; x < 4; ++x) {
      const std::uint16_t a = std::uint16_t(y * 5 + x), b = std::uint16_t(a + 1), c = std::uint16_t(a + 5),
                          d = std::uint16_t(c + 1);
      indices.insert(indices.end(), {a, b, d, a, d, c});
    }
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] = add_floats(model, positions, TINYGLTF_TYPE_VEC3, 3);
  primitive.attributes["JOINTS_0"] =
      add_accessor(model, joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, 4);
  primitive.attributes["WEIGHTS_0"] = add_floats(model, weights, TINYGLTF_TYPE_VEC4, 4);
  primitive.indices = add_accessor(model, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 1);
  tinygltf::Mesh mesh;
  mesh.name = "strip";
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);

  tinygltf::Node root, tip, body;
  root.name = "root";
  root.children = {1};
  tip.name = "tip";
  tip.translation = {2, 0, 0};
  body.name = "body";
  body.mesh = 0;
  body.skin = 0;
  model.nodes = {root, tip, body};
  tinygltf::Skin skin;
  skin.joints = {0, 1};
  skin.inverseBindMatrices = add_floats(model, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,  //
                                                1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -2, 0, 0, 1},
                                        TINYGLTF_TYPE_MAT4, 16);
  model.skins.push_back(skin);
  tinygltf::Scene scene;
  scene.nodes = {0, 2};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  const float quarter = float(std::acos(-1.0) / 2);
  tinygltf::Animation bend, swing;
  bend.name = "bend";
  add_rotation(model, bend, 1, {0, 1}, {0, quarter});
  swing.name = "swing";
  add_rotation(model, swing, 1, {0, 0.5f, 1.5f, 2}, {0, quarter, -quarter, 0});
  model.animations = {bend, swing};

  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToFile(&model, path, false, true, true, false))
    throw std::runtime_error("cannot write " + path);
}

// The clips of `path` alone, as an animation library exports them: its nodes and animations, no
// mesh, no skin.
void write_animation_only(const std::string& path, const std::string& out) {
  tinygltf::TinyGLTF gltf;
  tinygltf::Model model;
  std::string error, warning;
  if (!gltf.LoadASCIIFromFile(&model, &error, &warning, path)) throw std::runtime_error(error);
  for (tinygltf::Node& node : model.nodes) node.mesh = node.skin = -1;
  model.meshes.clear();
  model.skins.clear();
  if (!gltf.WriteGltfSceneToFile(&model, out, false, true, true, false)) throw std::runtime_error("cannot write " + out);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::cout << std::fixed << std::setprecision(3);
    std::string path = "bend.gltf";
    if (argc > 1)
      path = argv[1];
    else
      write_bending_strip(path);

    // [read]
    // What the file holds, at 30 frames per second.
    const deformseg::io::Gltf_contents contents = deformseg::io::gltf_contents(path);
    std::cout << path << ": " << contents.vertices << " vertices, " << contents.triangles << " triangles, "
              << contents.skins.size() << " skin(s), " << contents.clips.size() << " clip(s)\n";
    for (const auto& clip : contents.clips)
      std::cout << "  clip '" << clip.name << "': " << clip.start << " to " << clip.end << " s, " << clip.frames
                << " frames at 30 fps, " << clip.channels << " channel(s)\n";

    // One clip as an animation, welded and repaired: the default clip is the first.
    deformseg::io::Gltf_read_report report;
    const auto animation =
        deformseg::io::read_gltf(path, {.clip = argc > 2 ? argv[2] : "", .fps = 10}, &report);
    std::cout << "read clip '" << report.clip << "' at 10 fps: " << animation.num_frames() << " frames of "
              << animation.num_vertices() << " vertices and " << animation.num_faces() << " triangles\n";
    for (const std::string& skipped : report.skipped) std::cout << "  " << skipped << "\n";
    const std::size_t last = animation.num_vertices() - 1;
    const auto first_frame = animation.frame_positions(0),
               last_frame = animation.frame_positions(animation.num_frames() - 1);
    std::cout << "  vertex " << last << " moves from (" << first_frame[3 * last] << ", " << first_frame[3 * last + 1]
              << ") to (" << last_frame[3 * last] << ", " << last_frame[3 * last + 1] << ")\n";
    // [read]

    // Every clip of the file, parsed once.
    const deformseg::io::Gltf_file file(path);
    for (const std::string& clip : file.clip_names()) {
      const deformseg::io::Sampled_gltf sampled = file.sample({.clip = clip});
      std::cout << "sampled clip '" << clip << "': " << sampled.report.frames << " frames of "
                << sampled.num_vertices << " vertices, in the file's order\n";
    }

    // [once]
    // The clips share the file's connectivity, repaired once: read whole, or a frame at a time
    // (a Gltf_frame_source, as the motion signatures stream it), or the repair's vertices sampled.
    const deformseg::io::Repaired_triangles repaired = file.repair();
    const auto connectivity = std::make_shared<const deformseg::io::Gltf_connectivity>(file);
    for (const std::string& clip : file.clip_names()) {
      const auto whole = file.read(repaired, {.clip = clip});
      deformseg::io::Gltf_frame_source frames(connectivity, {.clip = clip});
      std::vector<double> frame(3 * frames.num_vertices());
      bool same = frames.clip_name() == clip && whole.all_positions().size() == frames.num_frames() * frame.size();
      for (std::size_t t = 0; same && t < frames.num_frames(); ++t) {
        frames.read_frame(frame);
        same = std::ranges::equal(frame, whole.frame_positions(t));
      }
      deformseg::io::Gltf_frame_sampler kept = file.frame_sampler({.clip = clip}, repaired.source_vertex);
      kept.sample_frame(0, frame);
      same = same && std::ranges::equal(frame, whole.frame_positions(0));
      std::cout << "clip '" << clip << "' read with the repair made once: " << whole.num_vertices()
                << " vertices of the file's " << file.num_vertices() << "; frame by frame, "
                << (same ? "the same frames" : "other frames") << "\n";
      if (!same) return 1;
    }
    // [once]

    // [bind]
    // The clips of an animation-only file played on the body: matched by the nodes' names.
    write_animation_only(path, "moves.gltf");
    const deformseg::io::Gltf_file bound(path, "moves.gltf");
    for (const std::string& clip : bound.clip_names()) {
      deformseg::io::Gltf_read_report moved;
      const auto played = bound.read({.clip = clip}, &moved);
      const bool same = std::ranges::equal(played.all_positions(), file.read({.clip = clip}).all_positions());
      std::cout << "clip '" << clip << "' of moves.gltf on the body: " << played.num_frames() << " frames, "
                << moved.animated_joints << " of " << moved.joints << " joints moved, "
                << (same ? "the body's own frames" : "other frames") << "\n";
      if (!same) return 1;
    }
    // [bind]
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "read_gltf: " << e.what() << "\n";
    return 1;
  }
}
