// What every part of deformseg._deformseg shares: long calls that release the GIL and stop on
// Ctrl-C, the refusal of a bad argument, the front end's reports as Python values.
#pragma once

#include "frontend/parameters.h"

#include <deformseg/threads.h>

#include <nlohmann/json.hpp>

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

namespace deformseg::python {

// The library's long loops call this on the calling thread about every 20 ms (threads.h): a
// signal caught meanwhile runs its Python handler, and what the handler raises
// (KeyboardInterrupt for Ctrl-C) stops the call and comes out of it.
bool no_signal_raised();

// The GIL released for a call that can take long, which Ctrl-C can interrupt.
struct Interruptible_call {
  Interruption_scope scope{&no_signal_raised};
  pybind11::gil_scoped_release release;
};

// A Python progress callback (or None) as the library's Progress, called with the GIL held;
// `progress` must outlive the call it is given to (it is referenced, not copied: a copy of a
// Python object on another thread, without the GIL, would be unsafe).
Progress progress_of(const std::optional<pybind11::function>& progress);

// Throws invalid_input (InvalidInput in Python) with `message`: the front end's.
using frontend::refuse;

// An integer argument `name` as Python gives it, refused outside `range` (and as a whole number)
// as the tool refuses it: "k must be a whole number in [1, 1000000], got -3".
std::size_t whole_argument(const char* name, long long value, const frontend::Range& range);

// A floating-point argument `name`, refused outside `range` as the tool refuses it.
double number_argument(const char* name, double value, const frontend::Range& range);

// A JSON value (the front end's reports) as the Python value of the same shape: dict, list, str,
// int, float, bool or None.
pybind11::object python_of(const nlohmann::json& value);

// The name of the Python type of `value`, for messages.
std::string type_name(const pybind11::handle& value);

}  // namespace deformseg::python
