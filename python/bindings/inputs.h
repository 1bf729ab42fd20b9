// The animations of deformseg._deformseg's functions: made from arrays, or read by the front end
// (frontend/inputs.h) as the tool reads them, with what the reader repaired.
#pragma once

#include "common.h"

#include <deformseg/io/mesh_repair.h>
#include <deformseg/mesh/default_mesh.h>

#include <pybind11/pybind11.h>

#include <optional>

namespace deformseg::python {

// An animation as Python holds it: the library's default model, and what the reader repaired.
struct Animation {
  mesh::Surface_mesh_animation mesh;
  std::optional<io::Repair_report> repair{};
};

// Animation(faces, frames, fps): the arrays checked and copied once into the library's model.
Animation animation_of_arrays(const pybind11::object& faces_like, const pybind11::object& frames_like, double fps);

// The counts of a repair report as a dict, under the names of Repair_report::counts() (the front
// end's repair record, which the tool's reports hold).
pybind11::dict repair_dict(const io::Repair_report& r);

// Refuses an animation of fewer than 2 frames: `which` names the argument.
void require_motion(const mesh::Surface_mesh_animation& a, const char* which);

}  // namespace deformseg::python
