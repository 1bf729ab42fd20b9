// The tables the tool and the Python module are both built from: every parameter of a command
// (and of the Python function that does the same) with its name, its help and, for a name among
// choices, those choices with theirs. The tool makes its CLI11 options of them (`--rest-frame`),
// the Python module its keyword arguments (`rest_frame=`), so that the two cannot drift.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/threads.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

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
  value,            ///< a number, a flag or a text
  choice,           ///< a name among `choices`
  optional_choice,  ///< a name among `choices`; empty: a default that depends on others (Python: None)
  file,             ///< a path; empty: none (Python: None)
  clip,             ///< a glTF clip's name or index; empty: the file's only one (Python: a str or an int)
};

/// Whether a parameter of `kind` takes a name among its choices.
constexpr bool is_choice(Parameter_kind kind) {
  return kind == Parameter_kind::choice || kind == Parameter_kind::optional_choice;
}

/// Whether a text parameter of `kind` is empty by default, which Python gives as None. The Python
/// module reads it from the kind, not from the default itself, which it cannot read at compile time
/// with every compiler (Clang 16 cannot construct GCC 12's `std::string` in a constant expression);
/// test/frontend/parameter_defaults.cpp checks that every table's defaults agree.
constexpr bool is_empty_by_default(Parameter_kind kind) {
  return kind == Parameter_kind::optional_choice || kind == Parameter_kind::file || kind == Parameter_kind::clip;
}

/// The values a numeric parameter takes: from `min` to `max`, each end in the range unless said
/// open. An integral parameter takes whole numbers in it; an infinite end is open.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< (min, ...: min itself is refused
  bool max_open = false;  ///< ..., max): max itself is refused

  /// Whether `value` is in the range (NaN never is).
  bool contains(double value) const {
    return (min_open || std::isinf(min) ? value > min : value >= min) &&
           (max_open || std::isinf(max) ? value < max : value <= max);
  }
};

/// The whole numbers from 0 (an index, or a count that may be none) to `most`.
constexpr Range counts(double most = 1e9) { return {.min = 0, .max = most}; }
/// The whole numbers from 1 to `most` (a count of at least one).
constexpr Range positive_counts(double most = 1e9) { return {.min = 1, .max = most}; }
/// The shares of a whole, [0, 1].
constexpr Range shares{.min = 0, .max = 1};
/// The finite numbers above 0.
constexpr Range positive{.min = 0, .min_open = true};
/// The finite numbers from 0.
constexpr Range non_negative{.min = 0};
/// The thread counts: 0 (all) to `max_threads`.
constexpr Range thread_counts{.min = 0, .max = max_threads};
/// How many results to find (a search's k, find's count): 1 to a million.
constexpr Range result_counts = positive_counts(1e6);
/// find's shortest window, a share of the query's duration: (0, 1].
constexpr Range window_shares{.min = 0, .max = 1, .min_open = true};
/// The exact edit distance's most partial mappings expanded.
constexpr Range expansion_counts = counts(1e15);

/// `range` as a reader writes it: "[0, 1]", "(0, 1000]", "[0, inf)".
std::string range_text(const Range& range);

/// Refuses, naming the parameter as `front` spells it, a value outside `range` (or, with
/// `whole`, not a whole number): "--count must be a whole number in [1, 1000000], got -1".
/// @throws invalid_input
void check_range(std::string_view name, double value, const Range& range, bool whole, Front front);

/// The message of `check_range` without the parameter's name: "must be in [0, 1], got 2"; empty
/// for a value in the range.
std::string range_message(double value, const Range& range, bool whole);

/// A parameter: a member of the request `Request` that a command and a Python function fill.
/// `name` is in snake_case, as Python spells it; the tool spells it `--rest-frame`. A text
/// parameter is empty by default exactly when its kind says so (`is_empty_by_default`), and then
/// None by default in Python.
template <class Request, class Value>
struct Parameter {
  using request_type = Request;
  using value_type = Value;
  const char* name;
  Value Request::*member;
  std::string_view help;
  Parameter_kind kind = Parameter_kind::value;
  std::span<const Choice> choices = {};
  Range range = {};  ///< a numeric parameter's values (see `numeric_parameter`)
};

/// A parameter among `choices`.
template <class Request, class Value>
constexpr Parameter<Request, Value> choice_parameter(const char* name, Value Request::*member, std::string_view help,
                                                     std::span<const Choice> choices) {
  return {name, member, help, Parameter_kind::choice, choices};
}

/// A parameter among `choices`, empty by default: a default that depends on other parameters.
template <class Request, class Value>
constexpr Parameter<Request, Value> optional_choice_parameter(const char* name, Value Request::*member,
                                                              std::string_view help, std::span<const Choice> choices) {
  return {name, member, help, Parameter_kind::optional_choice, choices};
}

/// Whether a parameter of type `Value` is numeric: an integral (not bool) or floating-point
/// value, or an optional one.
template <class Value>
struct numeric_value : std::bool_constant<std::is_arithmetic_v<Value> && !std::is_same_v<Value, bool>> {
  using type = Value;
};
template <class Value>
struct numeric_value<std::optional<Value>> : numeric_value<Value> {};
template <class Value>
inline constexpr bool is_numeric_v = numeric_value<Value>::value;
/// Whether `Value` is a `std::optional`.
template <class Value>
inline constexpr bool is_optional_v = false;
template <class Value>
inline constexpr bool is_optional_v<std::optional<Value>> = true;
/// Whether a numeric parameter of type `Value` takes whole numbers.
template <class Value>
inline constexpr bool is_whole_v = is_numeric_v<Value> && std::is_integral_v<typename numeric_value<Value>::type>;

/// A numeric parameter (an integral or floating-point value, or an optional one) taking the values
/// of `range`; the tool and the Python module refuse any other before any work.
template <class Request, class Value>
constexpr Parameter<Request, Value> numeric_parameter(const char* name, Value Request::*member, std::string_view help,
                                                      Range range) {
  return {name, member, help, Parameter_kind::value, {}, range};
}

/// `name` as `front` spells it: "--rest-frame" on the command line, "rest_frame" in Python.
std::string spelled(std::string_view name, Front front);

/// `name` given `value`, as `front` spells it: "--normalize gaussian", "normalize='gaussian'".
std::string spelled(std::string_view name, std::string_view value, Front front);

/// The choices' names in a sentence: "'a', 'b' or 'c'".
std::string listed(std::span<const Choice> choices);

/// The message of `check_choice` without the parameter's name: "must be 'a', 'b' or 'c', got 'x'";
/// empty for one of `choices`.
std::string choice_message(std::string_view value, std::span<const Choice> choices);

/// Refuses, naming the parameter as `front` spells it, a value that is not one of `choices`.
/// @throws invalid_input "--measure must be 'a', 'b' or 'c', got 'x'".
void check_choice(std::string_view name, std::string_view value, std::span<const Choice> choices, Front front);

/// The choices of a table whose entries have more than a name and a help (the similarity policies,
/// the alignments): the names and helps, in the table's order, for its parameter.
template <class Entry, std::size_t N>
constexpr std::array<Choice, N> choices_of(const std::array<Entry, N>& entries) {
  std::array<Choice, N> out{};
  for (std::size_t k = 0; k < N; ++k) out[k] = {entries[k].name, entries[k].help};
  return out;
}

/// Refuses: `invalid_input(message)`, for the checks of a request.
[[noreturn]] void refuse(const std::string& message);

/// Calls `visit(parameter)` for each parameter of `table`, in order.
template <class Table, class Visit>
void for_each_parameter(const Table& table, const Visit& visit) {
  std::apply([&](const auto&... parameter) { (visit(parameter), ...); }, table);
}

}  // namespace deformseg::frontend
