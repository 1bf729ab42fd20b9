// Graph edit distances as a command and a Python function ask for them: the method by name and
// the limits of the exact search.
#pragma once

#include "parameters.h"
#include "registry.h"

#include <cstddef>
#include <string>
#include <tuple>

namespace deformseg::frontend {

/// A graph edit distance as the user asks for it.
struct Ged_request {
  std::string method{ged_methods[0].name};
  std::size_t max_expanded = ged::Exact_ged{}.max_expanded;
  double max_seconds = 0;
};

/// The graph edit distance request's table.
inline constexpr std::tuple ged_parameters{
    choice_parameter("method", &Ged_request::method, "The graph edit distance method", ged_method_choices),
    numeric_parameter("max_expanded", &Ged_request::max_expanded,
                      "exact: the most partial mappings expanded before reporting bounds. Default: 200000",
                      expansion_counts),
    numeric_parameter("max_seconds", &Ged_request::max_seconds,
                      "exact: a time limit per pair in seconds (0: none, the default)", non_negative),
};

/// Checks a request's method before any graph is read; its numbers' ranges are the table's,
/// refused where the values come in.
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Ged_request& request, Front front);

/// The library's policy that a checked request names, with its limits where they apply.
/// @pre `check(request, front)` passed; else std::logic_error.
Any_ged make_ged(const Ged_request& request);

}  // namespace deformseg::frontend
