// The library's exceptions as Python exceptions.
#include "bindings.h"

#include <deformseg/exceptions.h>
#include <deformseg/similarity/motion_similarity.h>

namespace py = pybind11;

namespace deformseg::python {

void bind_errors(py::module_& m) {
  // invalid_input -> InvalidInput(ValueError), its message kept, its location as attributes.
  static py::exception<invalid_input> invalid(m, "InvalidInput", PyExc_ValueError);
  invalid.doc() = "Input that breaks a documented precondition (deformseg::invalid_input). A ValueError whose "
                  "message reads 'FILE:LINE: frame K: MESSAGE' (unknown parts left out); `file` (str or None), "
                  "`line` (int or None, from 1) and `frame` (int or None, from 0) give the parts.";
  static py::exception<similarity::similarity_stopped> stopped(m, "SimilarityStopped", PyExc_RuntimeError);
  stopped.doc() = "similarity_matrix was stopped: its progress callback returned False.";
  py::register_exception_translator([](std::exception_ptr error) {
    if (!error) return;
    try {
      std::rethrow_exception(error);
    } catch (const invalid_input& e) {
      py::object instance = py::reinterpret_borrow<py::object>(invalid.ptr())(e.what());
      const Input_location& w = e.where();
      instance.attr("file") = w.file.empty() ? py::object(py::none()) : py::str(w.file);
      instance.attr("line") = w.line ? py::object(py::int_(*w.line)) : py::object(py::none());
      instance.attr("frame") = w.frame ? py::object(py::int_(*w.frame)) : py::object(py::none());
      instance.attr("message") = e.message();
      PyErr_SetObject(invalid.ptr(), instance.ptr());
    } catch (const similarity::similarity_stopped& e) {
      stopped(e.what());
    }
  });
}

}  // namespace deformseg::python
