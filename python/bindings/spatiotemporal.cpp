// _evolving_graph: the spatio-temporal segmentation's evolving graph as the front end's report.
#include "bindings.h"

#include "inputs.h"
#include "parameters.h"

#include "frontend/spatiotemporal.h"

#include <nlohmann/json.hpp>

#include <tuple>

namespace py = pybind11;

namespace deformseg::python {
namespace {

// The evolving graph as the front end's report (frontend::evolving_graph_record, the tool's
// `spatiotemporal --json`), which python/deformseg/_graphs.py makes into classes.
py::object evolving(const Animation& a, const frontend::Spatiotemporal_request& request) {
  frontend::check(request, frontend::Front::python);
  nlohmann::json record;
  {
    Interruptible_call call;
    record = frontend::evolving_graph_record(frontend::spatiotemporal_segments(a.mesh, request, 0).graph);
  }
  return python_of(record);
}

}  // namespace

void bind_spatiotemporal(py::module_& m) {
  define_function<frontend::spatiotemporal_parameters, Types<const Animation&>, Types<>,
                  frontend::Spatiotemporal_request>(
      m, "_evolving_graph",
      "The evolving graph as the front end's report (a dict); `deformseg.evolving_graph` makes it an "
      "EvolvingGraph. Releases the GIL.",
      &evolving, std::tuple{py::arg("animation")});
}

}  // namespace deformseg::python
