#include "inputs.h"

#include "arrays.h"

#include <deformseg/io/read_animation.h>
#include <deformseg/io/read_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {

Animation animation_of_arrays(const py::object& faces_like, const py::object& frames_like, double fps) {
  mesh::check_frames_per_second(fps);
  const py::array frames = as_array(frames_like, "frames");
  const py::array faces = as_array(faces_like, "faces");
  std::vector<double> positions = positions_of(frames);
  const auto vertices = std::size_t(frames.shape(1));
  const auto triangles = triangles_of(faces, vertices);
  Interruptible_call call;
  std::vector<std::array<double, 3>> rest(vertices);
  std::copy_n(positions.data(), 3 * vertices, rest.front().data());
  mesh::Surface_mesh graph = mesh::make_face_graph<mesh::Surface_mesh>(rest, triangles);
  mesh::Surface_mesh_animation mesh(std::move(graph), std::move(positions));
  mesh.set_frames_per_second(fps);
  return {std::move(mesh), std::nullopt};
}

py::dict repair_dict(const io::Repair_report& r) {
  py::dict d;
  for (const auto& [name, count] : r.counts()) d[py::str(name.data(), name.size())] = count;
  return d;
}

Animation read_input(const std::filesystem::path& path, std::optional<std::string> clip, double fps,
                     std::optional<std::filesystem::path> topology, bool triangulate, std::optional<bool> weld,
                     bool refuse_defects, int threads) {
  auto [input, named_clip] = io::split_clip_suffix(path.string());
  if (named_clip) {
    if (clip) throw invalid_input("the clip is given twice: by clip= and after '#'", {.file = path.string()});
    clip = std::move(named_clip);
  }
  const bool gltf = io::is_gltf(input);
  const auto location = Input_location{.file = input};
  if (!gltf && clip) throw invalid_input("clip applies to glTF files only", location);
  if (gltf && topology) throw invalid_input("topology does not apply to a glTF file: it has its own", location);
  mesh::check_frames_per_second(fps, {}, location);
  try {
    thread_count(threads);
  } catch (const invalid_input& e) {
    throw e.located(location);
  }
  const io::Repair_options repair{.weld = weld.value_or(gltf),
                                  .defects = refuse_defects ? io::Defect_policy::refuse : io::Defect_policy::repair};
  io::Animation_read_options options{.topology = topology, .triangulate = triangulate, .threads = threads,
                                     .repair = repair, .clip = clip.value_or(""), .fps = fps};
  Interruptible_call call;
  io::Repair_report report;
  mesh::Surface_mesh_animation mesh = io::read_animation(input, options, &report);
  return {std::move(mesh), report};
}

void require_motion(const mesh::Surface_mesh_animation& a, const char* which) {
  if (a.num_frames() < 2)
    throw invalid_input(std::string(which) + ": an animation of " + std::to_string(a.num_frames()) +
                        " frame: a motion needs at least 2");
}

strain::Strain_reference reference_of(const std::string& name) {
  if (name == "rest") return strain::Strain_reference::rest_pose;
  if (name == "previous") return strain::Strain_reference::previous_pose;
  refuse("reference must be 'rest' or 'previous', got '" + name + "'");
}

std::optional<Reference_mesh> reference_mesh_of(const std::optional<std::filesystem::path>& path) {
  if (!path) return std::nullopt;
  const io::Triangle_soup soup = io::read_mesh(*path);
  return Reference_mesh{path->string(), mesh::make_face_graph<mesh::Surface_mesh>(io::points_of(soup), soup.triangles)};
}

strain::Strain_field<float> field_of(const mesh::Surface_mesh_animation& a,
                                     const std::optional<Reference_mesh>& reference,
                                     const strain::Strain_options& options) {
  if (!reference) return strain::compute_strain(a, options);
  try {
    return strain::compute_strain(a, reference->graph, options);
  } catch (const invalid_input& error) {
    throw invalid_input(std::string(error.what()) + " (the reference mesh must have the connectivity of the "
                        "animation as read: its num_vertices and num_faces)", {.file = reference->path});
  }
}

void check_rest(const std::optional<std::filesystem::path>& reference_mesh, std::size_t rest_frame) {
  if (reference_mesh && rest_frame != 0)
    refuse("reference_mesh takes the place of the rest frame: it excludes rest_frame");
}

}  // namespace deformseg::python
