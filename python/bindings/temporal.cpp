// frame_distances and temporal_segmentation: intervals of similar poses, as the front end's
// requests ask for them.
#include "bindings.h"

#include "arrays.h"
#include "inputs.h"
#include "parameters.h"

#include "frontend/inputs.h"
#include "frontend/temporal.h"

#include <pybind11/numpy.h>

#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

// The requests' parameters, then the input options' threads.
constexpr auto distance_table = std::tuple_cat(frontend::frame_distance_table,
                                               std::tuple{std::get<6>(frontend::input_parameters)});
constexpr auto temporal_table = std::tuple_cat(frontend::temporal_parameters,
                                               std::tuple{std::get<6>(frontend::input_parameters)});

py::array distances(const Animation& a, const frontend::Frame_distance_request& request,
                    const frontend::Input_options& options) {
  frontend::check(request, frontend::Front::python);
  Eigen::MatrixXf d;
  {
    Interruptible_call call;
    d = frontend::frame_distances(a.mesh, request, options.threads);
  }
  const auto n = py::ssize_t(d.rows());
  const auto item = py::ssize_t(sizeof(float));
  return owning(std::move(d), +[](const Eigen::MatrixXf& x) { return x.data(); }, {n, n}, {item, n * item});
}

std::vector<std::pair<std::size_t, std::size_t>> temporal(const Animation& a, const frontend::Temporal_request& request,
                                                          const frontend::Input_options& options) {
  frontend::check(request, frontend::Front::python);
  frontend::Temporal_result result;
  {
    Interruptible_call call;
    result = frontend::segment(frontend::frame_distances(a.mesh, frontend::distance_request(request), options.threads),
                               request);
  }
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const temporal::Temporal_segment& s : result.segmentation.segments) out.emplace_back(s.first, s.last);
  return out;
}

}  // namespace

void bind_temporal(py::module_& m) {
  using Leading = Types<const Animation&>;
  define_function<distance_table, Leading, Types<>, frontend::Frame_distance_request, frontend::Input_options>(
      m, "frame_distances",
      R"doc(The (T, T) float32 matrix of distances between the frames' normalised rest-pose strains
(the frame descriptors of the temporal segmentation), as the tool's `temporal --matrix` writes it.
Symmetric, zero diagonal; a Fortran-ordered array that owns the library's matrix (no copy).
Complexity O(T F) for the strain, O(T^2 F) for the distances. Releases the GIL.)doc",
      &distances, std::tuple{py::arg("animation"), py::kw_only()});

  define_function<temporal_table, Leading, Types<>, frontend::Temporal_request, frontend::Input_options>(
      m, "temporal_segmentation",
      R"doc(Intervals of similar poses: a list of (first, last) frame intervals, inclusive, covering
0..T-1 in order, from the frame distances of `frame_distances(animation, metric=..., rest_frame=...,
reference_mesh=...)`, as the tool's `temporal` command finds them. Complexity O(T^2 F) for the
distances, then the method's (optimal: O(T^2) per segment count). Releases the GIL.)doc",
      &temporal, std::tuple{py::arg("animation"), py::kw_only()});
}

}  // namespace deformseg::python
