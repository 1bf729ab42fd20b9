// The command-line face of the front end's tables: each parameter an option of CLI11, spelled
// --rest-frame for the table's rest_frame, with the table's help and, for a name among choices,
// the choices and theirs.
#pragma once

#include <frontend/parameters.h>

#include <deformseg/threads.h>

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <optional>
#include <span>
#include <string>
#include <type_traits>

namespace deformseg::tool {

/// The check of a numeric option, named "range": refuses, as the command line is read, a value
/// outside `range` (or, with `whole`, not a whole number), each value of a list in turn, with
/// CLI11's "--count: must be a whole number in [1, 1000000], got -1". Its description ("in [1,
/// 1000000]") follows the option's type in the help.
inline CLI::Validator in_range(const frontend::Range& range, bool whole) {
  return CLI::Validator(
      [range, whole](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0') return "must be a number, got '" + text + "'";
        return frontend::range_message(value, range, whole);
      },
      "in " + frontend::range_text(range), "range");
}

/// `in_range` for a whole-number option.
inline CLI::Validator whole_numbers(const frontend::Range& range) { return in_range(range, true); }
/// `in_range` for a floating-point option.
inline CLI::Validator numbers(const frontend::Range& range) { return in_range(range, false); }

/// The check of a choice option, named "choice": refuses, as the command line is read, a name not
/// among `choices`, in the front end's words, as Python's: "--policy: must be 'a', 'b' or 'c', got
/// 'x'". Its description ("{a,b,c}") follows the option's type in the help.
inline CLI::Validator among(std::span<const frontend::Choice> choices) {
  std::string names;
  for (const frontend::Choice& choice : choices) names.append(names.empty() ? "{" : ",").append(choice.name);
  return CLI::Validator([choices](std::string& text) { return frontend::choice_message(text, choices); },
                        names + "}", "choice");
}

/// The help of a parameter: its own, then, for a name among choices, each choice and its help.
template <class Parameter>
std::string help_of(const Parameter& p) {
  std::string help(p.help);
  for (const frontend::Choice& choice : p.choices)
    help.append(help.back() == '.' || help.back() == ':' ? " " : ". ").append(choice.name).append(": ").append(choice.help);
  return help;
}

/// Adds the parameter `p` of a request, whose member is `value`, to `command`.
template <class Request, class Value>
void add_parameter(CLI::App& command, const frontend::Parameter<Request, Value>& p, Value& value) {
  const std::string name = frontend::spelled(p.name, frontend::Front::command_line);
  if constexpr (std::is_same_v<Value, bool>) {
    command.add_flag(name, value, help_of(p));
  } else if constexpr (std::is_same_v<Value, std::optional<bool>>) {
    // --weld sets it, --no-weld clears it; neither leaves the default.
    CLI::Option* on = command.add_flag_callback(name, [&value] { value = true; }, help_of(p));
    command.add_flag_callback("--no-" + name.substr(2), [&value] { value = false; }, "The opposite of " + name)
        ->excludes(on);
  } else {
    CLI::Option* option = command.add_option(name, value, help_of(p));
    if constexpr (frontend::is_numeric_v<Value>) option->check(in_range(p.range, frontend::is_whole_v<Value>));
    if (frontend::is_choice(p.kind)) option->check(among(p.choices));
  }
}

/// Adds every parameter of `table` (a tuple of `frontend::Parameter`) to `command`, filling
/// `request`.
template <class Table, class Request>
void add_parameters(CLI::App& command, const Table& table, Request& request) {
  frontend::for_each_parameter(table, [&](const auto& p) { add_parameter(command, p, request.*p.member); });
}

}  // namespace deformseg::tool
