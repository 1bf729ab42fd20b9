// Module functions whose keyword arguments are made from the front end's tables of parameters
// (frontend/parameters.h), as the tool makes its options of them: one name, one default, one help
// text per parameter for both, so that they cannot drift. A function is defined by its table (a
// constexpr std::tuple of frontend::Parameter), the arguments before and after the table's, and a
// body that takes those arguments and the requests the table's parameters filled.
#pragma once

#include "common.h"

#include "frontend/parameters.h"

#include <deformseg/exceptions.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

namespace deformseg::python {

// A glTF clip as Python gives it: its name, or its index in the file.
using Clip = std::variant<std::string, long long>;

// The text of a clip: the name, or the index in decimal, which the glTF reader takes as an index.
inline std::string clip_text(const Clip& clip) {
  if (const auto* name = std::get_if<std::string>(&clip)) return *name;
  const long long index = std::get<long long>(clip);
  if (index < 0) refuse("clip must be a name or an index from 0, got " + std::to_string(index));
  return std::to_string(index);
}

// A numeric value as Python gives it: an integral one as a signed integer (so that -1 reaches the
// range check instead of pybind11's refusal of the type), an optional one as an optional.
template <class Value>
struct Python_number {
  using type = std::conditional_t<std::is_integral_v<Value>, long long, Value>;
};
template <class Value>
struct Python_number<std::optional<Value>> {
  using type = std::optional<typename Python_number<Value>::type>;
};

// The parameter `I` of `table` as a Python argument: its C++ type as Python takes it (a path or
// None for a file, a name or an index or None for a clip, None for an empty text, a signed integer
// for a count or an index), its default, and how its value goes into the request, a number checked
// against the parameter's range first.
template <const auto& table, std::size_t I>
struct Argument {
  static constexpr const auto& parameter = std::get<I>(table);
  using Parameter = std::remove_cvref_t<decltype(parameter)>;
  using Request = typename Parameter::request_type;
  using Value = typename Parameter::value_type;

  static constexpr bool is_text = std::is_same_v<Value, std::string>;
  static constexpr bool is_file = is_text && parameter.kind == frontend::Parameter_kind::file;
  static constexpr bool is_clip = is_text && parameter.kind == frontend::Parameter_kind::clip;
  static constexpr bool is_none_by_default = is_text && frontend::is_empty_by_default(parameter.kind);
  static constexpr bool is_number = frontend::is_numeric_v<Value>;

  using type = std::conditional_t<
      is_file, std::optional<std::filesystem::path>,
      std::conditional_t<
          is_clip, std::optional<Clip>,
          std::conditional_t<is_none_by_default, std::optional<std::string>,
                             std::conditional_t<is_number, typename Python_number<Value>::type, Value>>>>;

  static pybind11::arg_v annotation() {
    if constexpr (std::is_same_v<type, Value> || is_number)
      return pybind11::arg_v(parameter.name, Request{}.*parameter.member);
    else
      return pybind11::arg_v(parameter.name, pybind11::none());
  }

  // A number in the parameter's range, as the request's type.
  template <class Number>
  static auto checked(Number value) {
    frontend::check_range(parameter.name, double(value), parameter.range, frontend::is_whole_v<Value>,
                          frontend::Front::python);
    return value;
  }

  template <class Requests>
  static void fill(Requests& requests, type value) {
    Value& target = std::get<Request>(requests).*parameter.member;
    if constexpr (is_file)
      target = value ? value->string() : std::string();
    else if constexpr (is_clip)
      target = value ? clip_text(*value) : std::string();
    else if constexpr (is_number && frontend::is_optional_v<Value>)
      target = value ? std::optional(static_cast<typename Value::value_type>(checked(*value))) : std::nullopt;
    else if constexpr (is_number)
      target = static_cast<Value>(checked(value));
    else if constexpr (std::is_same_v<type, Value>)
      target = std::move(value);
    else
      target = value.value_or(std::string());
  }
};

// The lines of the docstring that the table gives: a line per parameter (with its range, for a
// number), and one per choice.
template <class Table>
std::string parameter_help(const Table& table) {
  std::string out;
  frontend::for_each_parameter(table, [&](const auto& parameter) {
    out.append(parameter.name).append(": ").append(parameter.help);
    using Value = typename std::remove_cvref_t<decltype(parameter)>::value_type;
    if constexpr (frontend::is_numeric_v<Value>)
      out.append(frontend::is_whole_v<Value> ? " (a whole number in " : " (in ")
          .append(frontend::range_text(parameter.range))
          .append(")");
    out.append("\n");
    for (const frontend::Choice& choice : parameter.choices)
      out.append("    '").append(choice.name).append("': ").append(choice.help).append("\n");
  });
  return out;
}

template <class... T>
struct Types {};

template <const auto& table, class Leading, class Trailing, class... Requests>
struct Table_function;

// The function of `table`: (Leading..., the table's arguments..., Trailing...); `body` is called
// with (leading..., the requests filled..., trailing...).
template <const auto& table, class... Leading, class... Trailing, class... Requests>
struct Table_function<table, Types<Leading...>, Types<Trailing...>, Requests...> {
  template <class Body, std::size_t... I>
  static auto make(Body body, std::index_sequence<I...>) {
    return [body](Leading... leading, typename Argument<table, I>::type... values, Trailing... trailing) {
      std::tuple<Requests...> requests{};
      (Argument<table, I>::fill(requests, std::move(values)), ...);
      return body(std::forward<Leading>(leading)..., std::get<Requests>(requests)...,
                  std::forward<Trailing>(trailing)...);
    };
  }
};

// Defines `name` in `m`: the arguments annotated `leading` (their C++ types `Leading`), those of
// `table` (each `name=default`, filling `Requests`), then those annotated `trailing`. The
// docstring is `summary`, then the table's help under "Parameters:".
template <const auto& table, class Leading, class Trailing, class... Requests, class Body, class... Before,
          class... After>
void define_function(pybind11::module_& m, const char* name, std::string_view summary, Body body,
                     std::tuple<Before...> leading, std::tuple<After...> trailing = {}) {
  constexpr std::size_t size = std::tuple_size_v<std::remove_cvref_t<decltype(table)>>;
  auto function = Table_function<table, Leading, Trailing, Requests...>::make(std::move(body),
                                                                             std::make_index_sequence<size>());
  std::string doc(summary);
  doc.append("\n\nParameters:\n").append(parameter_help(table));
  const auto annotations = [&]<std::size_t... I>(std::index_sequence<I...>) {
    return std::tuple{Argument<table, I>::annotation()...};
  }(std::make_index_sequence<size>());
  std::apply(
      [&](const auto&... all) { m.def(name, std::move(function), all..., doc.c_str()); },
      std::tuple_cat(leading, annotations, trailing));
}

}  // namespace deformseg::python
