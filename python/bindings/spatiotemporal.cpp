// _evolving_graph: the spatio-temporal segmentation's evolving graph as the front end's report.
#include "bindings.h"

#include "inputs.h"
#include "parameters.h"

#include "frontend/spatiotemporal.h"

#include <deformseg/spatiotemporal/frame_segments.h>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <tuple>

namespace py = pybind11;

namespace deformseg::python {
namespace {

// Each triangle's segment in each frame, (T, F) int32, -1 where it is rigid: what the tool's
// `spatiotemporal --mesh-dir` colours.
py::array_t<std::int32_t> face_segments(const spatiotemporal::Frame_segments& frames) {
  const auto& segmentation = frames.segmentation();
  py::array_t<std::int32_t> labels({py::ssize_t(segmentation.num_frames()), py::ssize_t(segmentation.num_faces())});
  std::int32_t* out = labels.mutable_data();
  for (std::size_t t = 0; t < segmentation.num_frames(); ++t) {
    const auto frame = segmentation.frame_labels(t);
    out = std::copy(frame.begin(), frame.end(), out);
  }
  return labels;
}

// The evolving graph as the front end's report (frontend::evolving_graph_record, the tool's
// `spatiotemporal --json`), which python/deformseg/_graphs.py makes into classes; with
// `with_face_segments`, its "face_segments" too.
py::object evolving(const Animation& a, const frontend::Spatiotemporal_request& request, bool with_face_segments) {
  frontend::check(request, frontend::Front::python);
  std::optional<frontend::Spatiotemporal_result> result;
  {
    Interruptible_call call;
    result = frontend::spatiotemporal_segments(a.mesh, request, 0);
  }
  auto record = python_of(frontend::evolving_graph_record(result->graph)).cast<py::dict>();
  if (with_face_segments) record["face_segments"] = face_segments(result->frames);
  return record;
}

}  // namespace

void bind_spatiotemporal(py::module_& m) {
  define_function<frontend::spatiotemporal_parameters, Types<const Animation&>, Types<bool>,
                  frontend::Spatiotemporal_request>(
      m, "_evolving_graph",
      "The evolving graph as the front end's report (a dict), with face_segments=True also its "
      "\"face_segments\", a (T, F) int32 array; `deformseg.evolving_graph` makes it an EvolvingGraph. "
      "Releases the GIL.",
      &evolving, std::tuple{py::arg("animation")}, std::tuple{py::arg_v("face_segments", false)});
}

}  // namespace deformseg::python
