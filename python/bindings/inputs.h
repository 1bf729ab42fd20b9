// The inputs of deformseg._deformseg's functions: animations (from arrays, or read as the tool reads
// them) and the strain's references (by name, or a reference mesh read from a file).
#pragma once

#include "common.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/mesh_repair.h>
#include <deformseg/strain/strain.h>

#include <pybind11/pybind11.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace deformseg::python {

// An animation as Python holds it: the library's default model, and what the reader repaired.
struct Animation {
  mesh::Surface_mesh_animation mesh;
  std::optional<io::Repair_report> repair{};
};

// Animation(faces, frames, fps): the arrays checked and copied once into the library's model.
Animation animation_of_arrays(const pybind11::object& faces_like, const pybind11::object& frames_like, double fps);

// read_animation: the rules of the tool's input options ("FILE.glb#CLIP", clip and topology only
// where they apply, glTF welded unless weld=False, other formats only with weld=True).
Animation read_input(const std::filesystem::path& path, std::optional<std::string> clip, double fps,
                     std::optional<std::filesystem::path> topology, bool triangulate, std::optional<bool> weld,
                     bool refuse_defects, int threads);

// The counts of a repair report as a dict, under the names of Repair_report::counts().
pybind11::dict repair_dict(const io::Repair_report& r);

// Refuses an animation of fewer than 2 frames: `which` names the argument.
void require_motion(const mesh::Surface_mesh_animation& a, const char* which);

// The strain reference by its name, "rest" or "previous".
strain::Strain_reference reference_of(const std::string& name);

// The tool's --reference-mesh: a rest pose kept apart from the frames (the cat folder's
// cat-reference.obj), read from a mesh file, with the connectivity of the animation as read.
struct Reference_mesh {
  std::string path;
  mesh::Surface_mesh graph;
};

std::optional<Reference_mesh> reference_mesh_of(const std::optional<std::filesystem::path>& path);

// Refuses a reference mesh given with a rest frame: the mesh takes its place.
void check_rest(const std::optional<std::filesystem::path>& reference_mesh, std::size_t rest_frame);

// The strain field of `a` with `options`, against `reference` when there is one; its errors then
// name the reference mesh's file, as the tool's do: a mismatch of connectivity is that file's.
strain::Strain_field<float> field_of(const mesh::Surface_mesh_animation& a,
                                     const std::optional<Reference_mesh>& reference,
                                     const strain::Strain_options& options);

}  // namespace deformseg::python
