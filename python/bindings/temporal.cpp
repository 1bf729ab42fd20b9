// frame_distances and temporal_segmentation: intervals of similar poses.
#include "bindings.h"

#include "arrays.h"
#include "inputs.h"

#include <deformseg/strain/frame_distances.h>
#include <deformseg/strain/strain.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

strain::Frame_metric metric_of(const std::string& name) {
  if (name == "euclidean") return strain::Frame_metric::euclidean;
  if (name == "l1") return strain::Frame_metric::l1;
  if (name == "cosine") return strain::Frame_metric::cosine;
  refuse("metric must be 'euclidean', 'l1' or 'cosine', got '" + name + "'");
}

// The frame distances of the temporal segmentation: the default strain against `rest_frame`, or
// against the reference mesh.
Eigen::MatrixXf distances_of(const mesh::Surface_mesh_animation& a, strain::Frame_metric metric, std::size_t rest_frame,
                             const std::optional<std::filesystem::path>& reference_mesh, int threads) {
  const strain::Strain_field<float> field = field_of(
      a, reference_mesh_of(reference_mesh), strain::Strain_options{.rest_frame = rest_frame, .threads = threads});
  return frame_distances(field, {.metric = metric, .threads = threads});
}

py::array distances(const Animation& a, const std::string& metric, std::size_t rest_frame,
                    const std::optional<std::filesystem::path>& reference_mesh, int threads) {
  const strain::Frame_metric m = metric_of(metric);
  check_rest(reference_mesh, rest_frame);
  Eigen::MatrixXf d;
  {
    Interruptible_call call;
    d = distances_of(a.mesh, m, rest_frame, reference_mesh, threads);
  }
  const auto n = py::ssize_t(d.rows());
  const auto item = py::ssize_t(sizeof(float));
  return owning(std::move(d), +[](const Eigen::MatrixXf& x) { return x.data(); }, {n, n}, {item, n * item});
}

std::vector<std::pair<std::size_t, std::size_t>> temporal(const Animation& a, const std::string& method,
                                                          std::optional<double> threshold, bool absolute,
                                                          std::optional<std::size_t> segments, std::size_t min_length,
                                                          const std::string& metric, std::size_t rest_frame,
                                                          const std::optional<std::filesystem::path>& reference_mesh,
                                                          int threads) {
  if (method != "optimal" && method != "binary-split" && method != "greedy" && method != "barbic")
    refuse("method must be 'optimal', 'binary-split', 'greedy' or 'barbic', got '" + method + "'");
  const strain::Frame_metric m = metric_of(metric);
  if (segments && method != "optimal") refuse("segments asks for method='optimal'");
  check_rest(reference_mesh, rest_frame);
  if (segments && *segments == 0) refuse("segments must be at least 1");
  if (min_length == 0) refuse("min_length must be at least 1");
  if (threshold && !(*threshold >= 0)) refuse("threshold must be non-negative");
  const auto threshold_or = [&](temporal::Segmentation_threshold fallback) {
    return threshold ? temporal::Segmentation_threshold{.value = *threshold, .relative = !absolute} : fallback;
  };
  temporal::Temporal_segmentation result;
  {
    Interruptible_call call;
    const temporal::Segment_cost cost(distances_of(a.mesh, m, rest_frame, reference_mesh, threads));
    if (method == "binary-split")
      result = temporal::segment_frames(
          cost, temporal::Binary_split{.threshold = threshold_or(temporal::Binary_split{}.threshold),
                                       .min_length = min_length});
    else if (method == "greedy")
      result = temporal::segment_frames(
          cost, temporal::Thesis_greedy{.threshold = threshold_or(temporal::Thesis_greedy{}.threshold)});
    else if (method == "barbic")
      result = temporal::segment_frames(cost, temporal::Barbic_pca{});
    else
      result = temporal::segment_frames(
          cost, temporal::Optimal_partition{.penalty = threshold_or(temporal::Optimal_partition{}.penalty),
                                            .segments = segments,
                                            .min_length = min_length});
  }
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const temporal::Temporal_segment& s : result.segments) out.emplace_back(s.first, s.last);
  return out;
}

}  // namespace

void bind_temporal(py::module_& m) {
  using namespace pybind11::literals;
  m.def("frame_distances", &distances, "animation"_a, py::kw_only(), "metric"_a = "euclidean", "rest_frame"_a = 0,
        "reference_mesh"_a = py::none(), "threads"_a = 0,
        R"doc(The (T, T) float32 matrix of distances between the frames' normalised rest-pose strains
(the frame descriptors of the temporal segmentation): metric "euclidean" (default), "l1" or
"cosine"; the strain against frame `rest_frame` (default 0), or against `reference_mesh` (default
None; as in `strain`). Symmetric, zero diagonal; a
Fortran-ordered array that owns the library's matrix (no copy). Complexity O(T F) for the strain,
O(T^2 F) for the distances. Releases the GIL.)doc");

  m.def("temporal_segmentation", &temporal, "animation"_a, py::kw_only(), "method"_a = "optimal",
        "threshold"_a = py::none(), "absolute"_a = false, "segments"_a = py::none(), "min_length"_a = 1,
        "metric"_a = "euclidean", "rest_frame"_a = 0, "reference_mesh"_a = py::none(), "threads"_a = 0,
        R"doc(Intervals of similar poses: a list of (first, last) frame intervals, inclusive, covering
0..T-1 in order, from the frame distances of `frame_distances(animation, metric=..., rest_frame=...,
reference_mesh=...)`.

method: "optimal" (default; least length-weighted cost with a penalty per segment, or exactly
`segments` segments), "binary-split", "greedy" (the thesis' Algorithm 4-1) or "barbic" (PCA change
detection). threshold: binary-split and greedy, the largest within-segment dissimilarity (default
0.5 and 0.2); optimal, the penalty per segment (default 0.03); relative to the mean frame distance
(optimal: to the one-segment cost) unless `absolute`. min_length (default 1): fewest frames of a
segment (optimal, binary-split). Complexity O(T^2 F) for the distances, then the method's
(optimal: O(T^2) per segment count). Releases the GIL.)doc");
}

}  // namespace deformseg::python
