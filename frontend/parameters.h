// The tables the tool and the Python module are both built from: every parameter of a command
// (and of the Python function that does the same) with its name, its help and, for a name among
// choices, those choices with theirs. The tool makes its CLI11 options of them (`--rest-frame`),
// the Python module its keyword arguments (`rest_frame=`), so that the two cannot drift.
#pragma once

#include <deformseg/exceptions.h>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <tuple>

namespace deformseg::frontend {

/// Which face of the library a user meets: the spelling of parameters in messages follows it.
enum class Front { command_line, python };

/// One value of a parameter that takes a name: the name and what it means.
struct Choice {
  std::string_view name;
  std::string_view help;
};

/// How a parameter's value is given, where the two fronts differ.
enum class Parameter_kind {
  value,   ///< a number, a flag or a text
  choice,  ///< a name among `choices`
  file,    ///< a path; empty: none (Python: None)
  clip,    ///< a glTF clip's name or index; empty: the file's only one (Python: a str or an int)
};

/// A parameter: a member of the request `Request` that a command and a Python function fill.
/// `name` is in snake_case, as Python spells it; the tool spells it `--rest-frame`. A text
/// parameter whose default is empty is None by default in Python.
template <class Request, class Value>
struct Parameter {
  using request_type = Request;
  using value_type = Value;
  const char* name;
  Value Request::*member;
  std::string_view help;
  Parameter_kind kind = Parameter_kind::value;
  std::span<const Choice> choices = {};
};

/// A parameter among `choices`.
template <class Request, class Value>
constexpr Parameter<Request, Value> choice_parameter(const char* name, Value Request::*member, std::string_view help,
                                                     std::span<const Choice> choices) {
  return {name, member, help, Parameter_kind::choice, choices};
}

/// `name` as `front` spells it: "--rest-frame" on the command line, "rest_frame" in Python.
std::string spelled(std::string_view name, Front front);

/// `name` given `value`, as `front` spells it: "--normalize gaussian", "normalize='gaussian'".
std::string spelled(std::string_view name, std::string_view value, Front front);

/// The choices' names in a sentence: "'a', 'b' or 'c'".
std::string listed(std::span<const Choice> choices);

/// Refuses, naming the parameter as `front` spells it, a value that is not one of `choices`.
/// @throws invalid_input "--measure must be 'a', 'b' or 'c', got 'x'".
void check_choice(std::string_view name, std::string_view value, std::span<const Choice> choices, Front front);

/// Refuses: `invalid_input(message)`, for the checks of a request.
[[noreturn]] void refuse(const std::string& message);

/// Calls `visit(parameter)` for each parameter of `table`, in order.
template <class Table, class Visit>
void for_each_parameter(const Table& table, const Visit& visit) {
  std::apply([&](const auto&... parameter) { (visit(parameter), ...); }, table);
}

}  // namespace deformseg::frontend
