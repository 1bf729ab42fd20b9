// MotionMatch and find_motion: where a short motion occurs in a long animation.
#include "bindings.h"

#include "inputs.h"
#include "pickling.h"

#include <deformseg/similarity/find_motion.h>

#include <pybind11/stl.h>

#include <cstddef>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

std::vector<similarity::Motion_match> find(const Animation& query, const Animation& long_animation, long long count,
                                           double shortest) {
  const similarity::Find_motion_options options{.count = whole_argument("count", count, frontend::result_counts),
                                                .shortest = number_argument("shortest", shortest,
                                                                            frontend::window_shares)};
  Interruptible_call call;
  return similarity::find_motion(query.mesh, long_animation.mesh, options);
}

// MotionMatch: (1, first, last, value, alignment).
py::object motion_match_state(const similarity::Motion_match& m) {
  return py::make_tuple(pickle_version, m.first, m.last, m.value, m.alignment);
}

similarity::Motion_match motion_match_of_state(const py::object& state) {
  constexpr const char* type = "MotionMatch";
  const py::tuple f = state_fields(state, type, 4, "(1, first, last, value, alignment)");
  return {.first = state_field<std::size_t>(f, 0, type, "first"),
          .last = state_field<std::size_t>(f, 1, type, "last"),
          .value = state_field<double>(f, 2, type, "value"),
          .alignment = state_field<decltype(similarity::Motion_match::alignment)>(f, 3, type, "alignment")};
}

}  // namespace

void bind_find_motion(py::module_& m) {
  using namespace pybind11::literals;
  py::class_<similarity::Motion_match>(m, "MotionMatch",
                                       "A window of a long animation that matches a query (find_motion).")
      .def(py::pickle(&motion_match_state, &motion_match_of_state))
      .def_readonly("first", &similarity::Motion_match::first, "The window's first frame in the long animation.")
      .def_readonly("last", &similarity::Motion_match::last, "Its last frame (inclusive).")
      .def_readonly("value", &similarity::Motion_match::value,
                    "The similarity of the query to the window's frames cut out as an animation of their own, "
                    "in [0, 1]: 1 for an exact, moved or scaled copy.")
      .def_readonly("alignment", &similarity::Motion_match::alignment,
                    "The warping path: (frame of the query, frame of the long animation).")
      .def("__repr__", [](const similarity::Motion_match& x) {
        return "<deformseg.MotionMatch frames " + std::to_string(x.first) + "-" + std::to_string(x.last) +
               " value=" + std::to_string(x.value) + ">";
      });

  m.def("find_motion", &find, "query"_a, "long_animation"_a, "count"_a = similarity::Find_motion_options{}.count, py::kw_only(), "shortest"_a = 0.5,
        R"doc(Where a short motion occurs in a long animation: at most `count` (default 3, as
Find_motion_options and the tool's `find`) non-overlapping windows of `long_animation`,
best first, each a MotionMatch (first, last, value, alignment), by motion signatures: windows
proposed by a slope-bounded subsequence DTW, each re-described alone and scored against the query
(value 1 for an exact, moved or scaled copy, found at its frames). shortest (default 0.5): a
window lasts from `shortest` to 1 / `shortest` times the query's duration. Complexity two
descriptions, O(count Tq Tl / shortest^2), then a few descriptions of candidate windows per match.
Releases the GIL.)doc");
}

}  // namespace deformseg::python
