// _evolving_graph: the spatio-temporal segmentation's evolving graph as plain data.
#include "bindings.h"

#include "inputs.h"

#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/strain/strain.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

// The evolving graph as plain data, which python/deformseg/_graphs.py makes into classes:
// (frames, segments, [(first, last, [(kind, segment or None, triangles, area)], [(u, v)])]).
// The reference: none given, previous, or rest with a reference mesh (as the tool's).
py::tuple evolving(const Animation& a, double threshold, const std::optional<std::string>& reference,
                   const std::optional<std::filesystem::path>& reference_mesh, std::size_t min_triangles,
                   std::size_t min_frames, std::size_t max_island) {
  if (!(threshold >= 0 && threshold <= 1)) refuse("threshold must be in [0, 1]");
  if (reference_mesh && reference == "previous")
    refuse("reference_mesh is a rest pose: it excludes reference='previous'");
  const spatiotemporal::Spatiotemporal_options options{
      .reference = reference_of(reference.value_or(reference_mesh ? "rest" : "previous")),
      .threshold = threshold,
      .min_triangles = min_triangles,
      .min_frames = min_frames,
      .max_island = max_island};
  const spatiotemporal::Evolving_graph graph = [&] {
    Interruptible_call call;
    if (!reference_mesh) return spatiotemporal::evolving_graph(a.mesh, options);
    const strain::Strain_field<float> field =
        field_of(a.mesh, reference_mesh_of(reference_mesh), strain::Strain_options{});
    const std::vector<double> areas = mesh::face_areas(a.mesh, 0);
    const spatiotemporal::Spatiotemporal_segmentation segmentation =
        spatiotemporal::spatiotemporal_segmentation(field, a.mesh.triangles(), options);
    return spatiotemporal::evolving_graph(spatiotemporal::Frame_segments(segmentation, a.mesh.triangles(), areas));
  }();
  py::list key_frames;
  for (const spatiotemporal::Key_frame& k : graph) {
    const spatiotemporal::Segment_graph& g = k.graph;
    py::list nodes, edges;
    for (std::size_t v = 0; v < boost::num_vertices(g); ++v) {
      const bool rigid = g[v].kind == spatiotemporal::Segment_kind::rigid;
      nodes.append(py::make_tuple(rigid ? "rigid" : "deformed", rigid ? py::object(py::none()) : py::int_(g[v].segment),
                                  g[v].triangles, g[v].area));
    }
    for (auto e : boost::make_iterator_range(boost::edges(g)))
      edges.append(py::make_tuple(std::min(boost::source(e, g), boost::target(e, g)),
                                  std::max(boost::source(e, g), boost::target(e, g))));
    key_frames.append(py::make_tuple(k.first_frame, k.last_frame, nodes, edges));
  }
  return py::make_tuple(graph.num_frames(), graph.num_segments(), key_frames);
}

}  // namespace

void bind_spatiotemporal(py::module_& m) {
  using namespace pybind11::literals;
  m.def("_evolving_graph", &evolving, "animation"_a, "threshold"_a = 0.5, "reference"_a = py::none(),
        "reference_mesh"_a = py::none(), "min_triangles"_a = 10, "min_frames"_a = 2, "max_island"_a = 30,
        "The evolving graph as tuples; `deformseg.evolving_graph` makes it an EvolvingGraph. Releases the GIL.");
}

}  // namespace deformseg::python
