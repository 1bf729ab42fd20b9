#include "inputs.h"

#include "arrays.h"

#include "frontend/inputs.h"

#include <deformseg/exceptions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {

Animation animation_of_arrays(const py::object& faces_like, const py::object& frames_like, double fps) {
  mesh::check_frames_per_second(fps);
  const py::array frames = as_array(frames_like, "frames");
  const py::array faces = as_array(faces_like, "faces");
  mesh::Coordinate_buffer<double> positions = positions_of(frames);
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

py::dict repair_dict(const io::Repair_report& r) { return python_of(frontend::repair_record(r)); }

void require_motion(const mesh::Surface_mesh_animation& a, const char* which) {
  if (a.num_frames() < 2)
    throw invalid_input(std::string(which) + ": an animation of " + std::to_string(a.num_frames()) +
                        " frame: a motion needs at least 2");
}

}  // namespace deformseg::python
