// Every result of deformseg._deformseg pickles, so that it can come back from a worker process:
// __getstate__ gives a tuple (version, fields...) of plain Python values and NumPy arrays,
// __setstate__ checks it and rebuilds the C++ value. A layout that changes takes a new version; a
// state of another version or layout is refused with a ValueError naming the class. Each class's
// two functions are in the file that binds it; these are the checks they share.
#pragma once

#include "common.h"

#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>

namespace deformseg::python {

constexpr int pickle_version = 1;

// Throws the ValueError "deformseg.TYPE: cannot restore a pickled state: WHY".
[[noreturn]] void refuse_state(const char* type, const std::string& why);

// The fields of `state` after its version: `state` must be a tuple of the version `pickle_version`
// and `fields` values, laid out as `layout` says (for the message).
pybind11::tuple state_fields(const pybind11::object& pickled, const char* type, std::size_t fields,
                             const char* layout);

// Field `index` of `fields` as a T, or a ValueError naming the class and the field.
template <class T>
T state_field(const pybind11::tuple& fields, std::size_t index, const char* type, const char* name) {
  try {
    return fields[index].cast<T>();
  } catch (const pybind11::cast_error&) {
    refuse_state(type,
                 std::string("field '") + name + "' is a " + type_name(fields[index]) + ", not of the type pickled");
  }
}

}  // namespace deformseg::python
