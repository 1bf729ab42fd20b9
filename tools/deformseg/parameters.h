// The command-line face of the front end's tables: each parameter an option of CLI11, spelled
// --rest-frame for the table's rest_frame, with the table's help and, for a name among choices,
// the choices and theirs.
#pragma once

#include <frontend/parameters.h>

#include <deformseg/threads.h>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace deformseg::tool {

/// The check of every `--threads`: 0 (all) to max_threads, refused when the command line is read,
/// before any work.
inline const CLI::Range thread_counts(0, max_threads);

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
    // The front end checks these too, for Python; CLI11 refuses them as the command line is read.
    if (name == "--threads") option->check(thread_counts);
    if (name == "--fps") option->check(CLI::PositiveNumber);
    if (p.kind == frontend::Parameter_kind::choice) {
      std::vector<std::string> names;
      for (const frontend::Choice& choice : p.choices) names.emplace_back(choice.name);
      option->check(CLI::IsMember(names));
    }
  }
}

/// Adds every parameter of `table` (a tuple of `frontend::Parameter`) to `command`, filling
/// `request`.
template <class Table, class Request>
void add_parameters(CLI::App& command, const Table& table, Request& request) {
  frontend::for_each_parameter(table, [&](const auto& p) { add_parameter(command, p, request.*p.member); });
}

}  // namespace deformseg::tool
