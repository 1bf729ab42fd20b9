// strain: the strain field of an animation, as the front end's strain request asks for it.
#include "bindings.h"

#include "arrays.h"
#include "inputs.h"
#include "parameters.h"

#include "frontend/inputs.h"
#include "frontend/strain.h"

#include <pybind11/numpy.h>

#include <tuple>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

// The strain request's parameters, then the input options' threads.
constexpr auto strain_table = std::tuple_cat(frontend::strain_parameters,
                                             std::tuple{std::get<6>(frontend::input_parameters)});
static_assert(std::string_view(std::get<6>(frontend::input_parameters).name) == "threads");

py::array strain(const Animation& a, const frontend::Strain_request& request, const frontend::Input_options& options) {
  frontend::check(request, frontend::Front::python);
  strain::Strain_field<float> field;
  {
    Interruptible_call call;
    field = frontend::strain_field(a.mesh, request, options.threads);
  }
  const auto shape = std::vector<py::ssize_t>{py::ssize_t(field.num_frames()), py::ssize_t(field.num_faces())};
  return owning(std::move(field), +[](const strain::Strain_field<float>& f) { return f.values().data(); }, shape);
}

}  // namespace

void bind_strain(py::module_& m) {
  define_function<strain_table, Types<const Animation&>, Types<>, frontend::Strain_request, frontend::Input_options>(
      m, "strain",
      R"doc(The strain of every triangle at every frame: a (T, F) float32 array, row t the frame t
(compute_strain; Strain_options' defaults), as the tool's `strain` command computes it.
Invariant to rotation, translation and uniform scale of the whole animation. The array owns the
library's result (no copy). Complexity O(T F). Releases the GIL.)doc",
      &strain, std::tuple{py::arg("animation"), py::kw_only()});
}

}  // namespace deformseg::python
