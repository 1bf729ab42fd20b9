#include "common.h"

#include <deformseg/exceptions.h>

namespace py = pybind11;

namespace deformseg::python {

bool no_signal_raised() {
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  return true;
}

void refuse(const std::string& message) { throw invalid_input(message); }

std::string type_name(const py::handle& value) {
  return py::str(py::type::of(value).attr("__name__")).cast<std::string>();
}

}  // namespace deformseg::python
