#include "common.h"

#include <deformseg/exceptions.h>

namespace py = pybind11;

namespace deformseg::python {

std::size_t whole_argument(const char* name, long long value, const frontend::Range& range) {
  frontend::check_range(name, double(value), range, true, frontend::Front::python);
  return std::size_t(value);
}

double number_argument(const char* name, double value, const frontend::Range& range) {
  frontend::check_range(name, value, range, false, frontend::Front::python);
  return value;
}

bool no_signal_raised() {
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  return true;
}

Progress progress_of(const std::optional<py::function>& progress) {
  if (!progress) return {};
  return [&progress](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire acquire;
    const py::object go = (*progress)(done, total);
    return go.is_none() || go.cast<bool>();
  };
}

py::object python_of(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(value.get<long long>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(value.get<unsigned long long>());
    case nlohmann::json::value_t::number_float: return py::float_(value.get<double>());
    case nlohmann::json::value_t::string: return py::str(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const nlohmann::json& item : value) list.append(python_of(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = python_of(item);
      return dict;
    }
    default: refuse("a report holds a value that is not JSON data");  // binary or discarded: never made
  }
}

std::string type_name(const py::handle& value) {
  return py::str(py::type::of(value).attr("__name__")).cast<std::string>();
}

}  // namespace deformseg::python
