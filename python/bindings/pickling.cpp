#include "pickling.h"

namespace py = pybind11;

namespace deformseg::python {

void refuse_state(const char* type, const std::string& why) {
  throw py::value_error(std::string("deformseg.") + type + ": cannot restore a pickled state: " + why);
}

py::tuple state_fields(const py::object& pickled, const char* type, std::size_t fields, const char* layout) {
  const std::string expected = std::string("expected the tuple ") + layout;
  if (!py::isinstance<py::tuple>(pickled)) refuse_state(type, expected + ", got a " + type_name(pickled));
  const auto state = py::reinterpret_borrow<py::tuple>(pickled);
  if (state.size() != fields + 1) refuse_state(type, expected + ", got " + std::to_string(state.size()) + " items");
  if (!py::isinstance<py::int_>(state[0]) || state[0].cast<long long>() != pickle_version)
    refuse_state(type, "state version " + py::repr(state[0]).cast<std::string>() + ", this deformseg reads version " +
                           std::to_string(pickle_version) + " (pickled by another version of deformseg?)");
  return py::tuple(state[py::slice(1, py::ssize_t(fields + 1), 1)]);
}

}  // namespace deformseg::python
