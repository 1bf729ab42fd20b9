// Animation (from arrays, pickled, read), read_animation and clips.
#include "bindings.h"

#include "arrays.h"
#include "inputs.h"
#include "parameters.h"
#include "pickling.h"

#include "frontend/inputs.h"

#include <deformseg/io/mesh_repair.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>

namespace py = pybind11;

namespace deformseg::python {
namespace {

// The members of Repair_report in the order of its counts(), to restore them by name.
constexpr std::array repair_members{
    &io::Repair_report::input_vertices,        &io::Repair_report::input_triangles,
    &io::Repair_report::welded_vertices,       &io::Repair_report::degenerate_triangles,
    &io::Repair_report::duplicate_triangles,   &io::Repair_report::non_manifold_edges,
    &io::Repair_report::non_manifold_vertices, &io::Repair_report::duplicated_vertices,
    &io::Repair_report::reoriented_triangles,  &io::Repair_report::unrepairable_triangles,
    &io::Repair_report::dropped_influences,    &io::Repair_report::unweighted_vertices,
    &io::Repair_report::vertices,              &io::Repair_report::triangles};
static_assert(repair_members.size() == std::tuple_size_v<decltype(io::Repair_report{}.counts())>);

std::optional<io::Repair_report> repair_of_state(const py::handle& value) {
  if (value.is_none()) return std::nullopt;
  if (!py::isinstance<py::dict>(value)) refuse_state("Animation", "field 'repair' is neither a dict nor None");
  const auto counts = py::reinterpret_borrow<py::dict>(value);
  io::Repair_report report;
  for (std::size_t k = 0; k < repair_members.size(); ++k) {
    const std::string_view name = report.counts()[k].first;
    const py::str key(name.data(), name.size());
    if (!counts.contains(key)) refuse_state("Animation", "field 'repair' has no count '" + std::string(name) + "'");
    report.*repair_members[k] = state_field<std::size_t>(py::make_tuple(counts[key]), 0, "Animation", "repair");
  }
  return report;
}

// Animation: (1, faces (F, 3) uint32, frames (T, V, 3) float64, fps, repair dict or None). The
// frames are copied bit for bit; the connectivity is rebuilt from the faces in their order.
py::object animation_state(const py::object& self) {
  const Animation& a = self.cast<const Animation&>();
  return py::make_tuple(pickle_version, self.attr("faces"), self.attr("frames"), a.mesh.frames_per_second(),
                        a.repair ? py::object(repair_dict(*a.repair)) : py::object(py::none()));
}

Animation animation_of_state(const py::object& state) {
  const py::tuple f = state_fields(state, "Animation", 4, "(1, faces, frames, fps, repair)");
  const auto faces = py::array::ensure(f[0]), frames = py::array::ensure(f[1]);
  if (!faces || (faces.dtype().kind() != 'i' && faces.dtype().kind() != 'u'))
    refuse_state("Animation", "field 'faces' is not an array of integers");
  if (!frames || frames.dtype().kind() != 'f' || frames.itemsize() != 8)
    refuse_state("Animation", "field 'frames' is not an array of float64");
  Animation a = animation_of_arrays(faces, frames, state_field<double>(f, 2, "Animation", "fps"));
  a.repair = repair_of_state(f[3]);
  return a;
}

}  // namespace

void bind_animation(py::module_& m) {
  using namespace pybind11::literals;
  py::class_<Animation>(m, "Animation",
                        R"doc(An animation of one triangle mesh: fixed connectivity, vertex positions per frame.

Animation(faces, frames, fps=30): from an (F, 3) integer array of vertex indices (each triangle
counter-clockwise seen from outside; together an oriented 2-manifold, with or without boundary)
and a (T, V, 3) float32 or float64 array of positions, sampled at `fps` frames per second.
Raises TypeError for another dtype, ValueError for another shape, InvalidInput for an index out
of range, a non-manifold or inconsistently oriented triangle, a non-finite coordinate (naming the
triangle, or the frame and vertex), or an fps that is not positive. No repair is made: vertex i and face j stay the i-th and j-th given.

What is copied: the library stores one contiguous block of float64 (x, y, z per vertex, frame
after frame) that it owns, so `frames` is copied once: straight from a C-contiguous float32 or
float64 array (float32 converted on the way), through one NumPy conversion first from any other
layout. `frames` and `faces` are then read-only views of that storage, no copy.
Complexity O(T V + F).)doc")
      .def(py::init(&animation_of_arrays), "faces"_a, "frames"_a, "fps"_a = 30.0)
      .def(py::pickle(&animation_state, &animation_of_state))
      .def_property_readonly(
          "frames",
          [](const py::object& self) {
            const mesh::Surface_mesh_animation& a = self.cast<const Animation&>().mesh;
            return view(a.all_positions().data(),
                        {py::ssize_t(a.num_frames()), py::ssize_t(a.num_vertices()), py::ssize_t(3)}, self);
          },
          "The (T, V, 3) float64 positions: a read-only view of the animation's own storage (no copy), "
          "valid as long as it is referenced.")
      .def_property_readonly(
          "faces",
          [](const py::object& self) {
            const mesh::Surface_mesh_animation& a = self.cast<const Animation&>().mesh;
            static_assert(sizeof(mesh::Surface_mesh_animation::Triangle) == 3 * sizeof(std::uint32_t));
            const auto* indices = reinterpret_cast<const std::uint32_t*>(a.triangles().data());
            return view(indices, {py::ssize_t(a.num_faces()), py::ssize_t(3)}, self);
          },
          "The (F, 3) uint32 vertex indices of the triangles: a read-only view (no copy).")
      .def_property_readonly(
          "num_frames", [](const Animation& a) { return a.mesh.num_frames(); }, "T, the number of frames.")
      .def_property_readonly(
          "fps", [](const Animation& a) { return a.mesh.frames_per_second(); },
          "The frame rate, in frames per second: the motion signatures measure rates per "
          "second, so that the same motion sampled at any rate compares as the same.")
      .def_property_readonly(
          "num_vertices", [](const Animation& a) { return a.mesh.num_vertices(); }, "V, the number of vertices.")
      .def_property_readonly(
          "num_faces", [](const Animation& a) { return a.mesh.num_faces(); }, "F, the number of triangles.")
      .def_property_readonly(
          "repair",
          [](const Animation& a) { return a.repair ? py::object(repair_dict(*a.repair)) : py::object(py::none()); },
          "What the reader's repair changed, as a dict of counts (the keys of the tool's `info --json` "
          "'repair': input_vertices, welded_vertices, degenerate_triangles, ..., vertices, triangles); "
          "None for an animation made from arrays.")
      .def("__repr__", [](const Animation& a) {
        return "<deformseg.Animation: " + std::to_string(a.mesh.num_frames()) + " frames, " +
               std::to_string(a.mesh.num_vertices()) + " vertices, " + std::to_string(a.mesh.num_faces()) +
               " triangles>";
      });

  define_function<frontend::input_parameters, Types<const std::filesystem::path&>, Types<>, frontend::Input_options>(
      m, "read_animation",
      R"doc(Reads an animation: a clip of a character file, glTF (.glb, .gltf), FBX (.fbx), Collada
(.dae) or BVH motion capture (.bvh; a file without a mesh plays on a body made from its skeleton,
or on `body`) ("FILE.fbx#CLIP" or `clip`, by name or index:
needed when the file holds several, which are then listed in the error; a file of one clip gives
it; `clips` lists them), a folder of frame files (.obj, .off, .ply, in natural order), a glob
pattern, or a point cache (.pc2, .mdd) with `topology` (a mesh file). `fps` is the frame rate of
every format (`Animation.fps`). A character's vertices are welded by what the file fixes (the same rest
position, skin weights and morph deltas), so that every clip of a file has one mesh.
`Animation.repair` says what the repair changed. A vertex absurdly far for the mesh's own scale
(10^5 times its median radius: corrupt data) gives a UserWarning naming its frame, or is refused
with refuse_defects. With `body`, a clip that moves fewer than half of the body's joints gives a
UserWarning, and one that moves nothing of it is refused. Raises InvalidInput naming the file, line and
frame of the first problem, or for an option that does not apply (clip for frames, topology for
a character file), as the tool does: the rules are the front end's (frontend/inputs.h) that the tool follows.
Complexity linear in the input's size. Releases the GIL.)doc",
      [](const std::filesystem::path& path, const frontend::Input_options& options) {
        frontend::check_clip_applies({path.string()}, options, frontend::Front::python);
        std::optional<frontend::Read_input> read;
        {
          Interruptible_call call;
          read = frontend::read_input(path.string(), options, frontend::Front::python);
        }
        for (const std::string& warning :
             {read->outliers.warning(frontend::Front::python), frontend::body_fit_warning(*read, options)})
          if (!warning.empty() && PyErr_WarnEx(PyExc_UserWarning, (path.string() + ": " + warning).c_str(), 1) < 0)
            throw py::error_already_set();
        return Animation{std::move(read->animation), read->repair};
      },
      std::tuple{py::arg("path")});

  m.def(
      "clips",
      [](const std::filesystem::path& path, double fps) {
        nlohmann::json clips;
        {
          Interruptible_call call;
          clips = frontend::clips_of(path.string(), fps);
        }
        return python_of(clips);
      },
      "path"_a, "fps"_a = frontend::Input_options{}.fps,
      R"doc(The clips of a character file (.glb, .gltf, .fbx, .dae, .bvh), in the file's order: a list of dicts with name, index
(what `read_animation`'s `clip` takes, as does the name), start, end and duration (seconds),
frames (sampled at `fps`, default 30) and channels. Raises InvalidInput naming the file when it is
not a character file or cannot be read. Complexity linear in the file's size. Releases the GIL.)doc");
}

}  // namespace deformseg::python
