// GedResult and _ged: the graph edit distance of two labelled graphs.
#include "bindings.h"

#include "common.h"
#include "pickling.h"

#include "frontend/ged.h"

#include <deformseg/io/graphviz.h>

#include <pybind11/stl.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

io::Labelled_graph labelled_graph(const std::vector<std::string>& labels,
                                  const std::vector<std::pair<std::size_t, std::size_t>>& edges, const char* which) {
  io::Labelled_graph g(labels.size());
  for (std::size_t v = 0; v < labels.size(); ++v) g[v] = labels[v];
  for (const auto& [u, v] : edges) {
    if (u >= labels.size() || v >= labels.size())
      throw py::value_error(std::string(which) + ": edge (" + std::to_string(u) + ", " + std::to_string(v) +
                            ") names a node past the last, " + std::to_string(labels.size()) + " nodes");
    if (u != v && !boost::edge(u, v, g).second) boost::add_edge(u, v, g);
  }
  return g;
}

ged::Ged_result graph_edit_distance(const std::vector<std::string>& labels_a,
                                    const std::vector<std::pair<std::size_t, std::size_t>>& edges_a,
                                    const std::vector<std::string>& labels_b,
                                    const std::vector<std::pair<std::size_t, std::size_t>>& edges_b,
                                    const std::string& method, long long max_expanded, double max_seconds) {
  const frontend::Ged_request request{
      .method = method,
      .max_expanded = whole_argument("max_expanded", max_expanded, frontend::expansion_counts),
      .max_seconds = number_argument("max_seconds", max_seconds, frontend::non_negative)};
  frontend::check(request, frontend::Front::python);
  const io::Labelled_graph a = labelled_graph(labels_a, edges_a, "g1"), b = labelled_graph(labels_b, edges_b, "g2");
  Interruptible_call call;
  return std::visit([&](const auto& policy) { return policy(a, b, ged::Unit_costs{}); }, frontend::make_ged(request));
}

std::optional<double> bound_or_none(double x) { return std::isinf(x) ? std::nullopt : std::optional(x); }

// GedResult: (1, distance, exact, lower, upper, mapping), upper as stored (inf for none).
py::object ged_state(const ged::Ged_result& r) {
  return py::make_tuple(pickle_version, r.distance, r.exact, r.lower, r.upper, r.mapping);
}

ged::Ged_result ged_of_state(const py::object& state) {
  constexpr const char* type = "GedResult";
  const py::tuple f = state_fields(state, type, 5, "(1, distance, exact, lower, upper, mapping)");
  return {.distance = state_field<double>(f, 0, type, "distance"), .exact = state_field<bool>(f, 1, type, "exact"),
          .lower = state_field<double>(f, 2, type, "lower"), .upper = state_field<double>(f, 3, type, "upper"),
          .mapping = state_field<std::vector<int>>(f, 4, type, "mapping")};
}

}  // namespace

void bind_ged(py::module_& m) {
  using namespace pybind11::literals;
  py::class_<ged::Ged_result>(m, "GedResult", "What `ged` gives: lower <= distance <= upper.")
      .def(py::pickle(&ged_state, &ged_of_state))
      .def_readonly("distance", &ged::Ged_result::distance, "The distance found (exact, or the best upper bound).")
      .def_readonly("exact", &ged::Ged_result::exact, "Whether distance is proven to be the graph edit distance.")
      .def_readonly("lower", &ged::Ged_result::lower, "A proven lower bound.")
      .def_property_readonly("upper", [](const ged::Ged_result& r) { return bound_or_none(r.upper); },
                             "The cost of mapping, an upper bound; None when there is none (a pure lower bound).")
      .def_readonly("mapping", &ged::Ged_result::mapping, "Node i of g1 -> node of g2, or -1 when i is deleted.")
      .def("__repr__", [](const ged::Ged_result& r) {
        return "<deformseg.GedResult distance=" + std::to_string(r.distance) + (r.exact ? " exact>" : ">");
      });

  m.def("_ged", &graph_edit_distance, "labels_a"_a, "edges_a"_a, "labels_b"_a, "edges_b"_a,
        "method"_a = std::string(frontend::ged_methods[0].name),
        "max_expanded"_a = ged::Exact_ged{}.max_expanded, "max_seconds"_a = 0.0,
        "The graph edit distance of two graphs given as node labels and edges; `deformseg.ged` takes graphs. "
        "Releases the GIL.");
  m.attr("EXACT_GED_MAX_EXPANDED") = ged::Exact_ged{}.max_expanded;
}

}  // namespace deformseg::python
