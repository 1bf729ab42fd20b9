// strain: the strain field of an animation, with the tool's names of measures and normalisations.
#include "bindings.h"

#include "arrays.h"
#include "inputs.h"

#include <deformseg/strain/strain.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

// The built-in strain measures by their names.
const std::map<std::string, strain::Strain_measure_choice> strain_measures{
    {"max-principal", strain::Max_principal_strain{}},
    {"green-lagrange", strain::Green_lagrange_strain{}},
    {"frobenius", strain::Frobenius_strain{}},
    {"area-ratio", strain::Area_ratio_strain{}}};

py::array strain(const Animation& a, const std::string& reference, std::size_t rest_frame,
                 const std::optional<std::filesystem::path>& reference_mesh, const std::string& measure,
                 const std::string& normalize, std::optional<double> sigma, double degenerate_tolerance, int threads) {
  const strain::Strain_reference ref = reference_of(reference);
  if (normalize != "gaussian" && normalize != "none")
    refuse("normalize must be 'gaussian' or 'none', got '" + normalize + "'");
  const bool gaussian = normalize == "gaussian";
  if (sigma && !gaussian) refuse("sigma asks for normalize='gaussian'");
  if (sigma && !(*sigma > 0)) refuse("sigma must be positive");
  if (ref == strain::Strain_reference::previous_pose && rest_frame != 0) refuse("rest_frame asks for reference='rest'");
  if (reference_mesh && (ref == strain::Strain_reference::previous_pose || rest_frame != 0))
    refuse("reference_mesh takes the place of the rest frame: it excludes reference='previous' and rest_frame");
  const auto chosen = strain_measures.find(measure);
  if (chosen == strain_measures.end())
    refuse("measure must be 'max-principal', 'green-lagrange', 'frobenius' or 'area-ratio', got '" + measure + "'");
  const strain::Strain_options options{
      .reference = ref,
      .rest_frame = rest_frame,
      .measure = chosen->second,
      .normalization = gaussian ? strain::Strain_normalization_choice(strain::Gaussian_normalization{.sigma = sigma})
                                : strain::No_normalization{},
      .degenerate_tolerance = degenerate_tolerance,
      .threads = threads};
  strain::Strain_field<float> field;
  {
    Interruptible_call call;
    field = field_of(a.mesh, reference_mesh_of(reference_mesh), options);
  }
  const auto shape = std::vector<py::ssize_t>{py::ssize_t(field.num_frames()), py::ssize_t(field.num_faces())};
  return owning(std::move(field), +[](const strain::Strain_field<float>& f) { return f.values().data(); }, shape);
}

}  // namespace

void bind_strain(py::module_& m) {
  using namespace pybind11::literals;
  m.def("strain", &strain, "animation"_a, py::kw_only(), "reference"_a = "rest", "rest_frame"_a = 0,
        "reference_mesh"_a = py::none(), "measure"_a = "max-principal", "normalize"_a = "gaussian",
        "sigma"_a = py::none(), "degenerate_tolerance"_a = 1e-12, "threads"_a = 0,
        R"doc(The strain of every triangle at every frame: a (T, F) float32 array, row t the frame t
(compute_strain; Strain_options' defaults).

reference: "rest" (default; against frame `rest_frame`, default 0) or "previous" (against the
frame before; frame 0's strain is 0). reference_mesh (default None): a mesh file (.obj, .off,
.ply) with the animation's connectivity in another pose, a rest pose kept apart from the frames,
in the place of frame `rest_frame`. measure: "max-principal" (default, max |l - 1| over the
principal stretches l), "green-lagrange", "frobenius" or "area-ratio". normalize: "gaussian"
(default, 1 - exp(-s^2 / 2 sigma^2), sigma the 95th percentile of the strains unless `sigma` gives
it) or "none" (raw strains). degenerate_tolerance (default 1e-12): reference triangles thinner than
this have strain 0. threads: 0 (default) all, at most 1024; the result is the same for any number.
Invariant to rotation, translation and uniform scale of the whole animation. The array owns the
library's result (no copy). Complexity O(T F). Releases the GIL.)doc");
}

}  // namespace deformseg::python
