#include "parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace deformseg::frontend {

std::string spelled(std::string_view name, Front front) {
  std::string out = front == Front::python ? "" : "--";
  out.append(name);
  if (front == Front::command_line) std::ranges::replace(out, '_', '-');
  return out;
}

std::string spelled(std::string_view name, std::string_view value, Front front) {
  std::string out = spelled(name, front);
  if (front == Front::python) return out.append("='").append(value).append("'");
  return out.append(" ").append(value);
}

std::string listed(std::span<const Choice> choices) {
  std::string out;
  for (std::size_t k = 0; k < choices.size(); ++k) {
    if (k > 0) out += k + 1 == choices.size() ? " or " : ", ";
    out.append("'").append(choices[k].name).append("'");
  }
  return out;
}

std::string choice_message(std::string_view value, std::span<const Choice> choices) {
  if (std::ranges::any_of(choices, [&](const Choice& c) { return c.name == value; })) return {};
  return std::string("must be ").append(listed(choices)).append(", got '").append(value).append("'");
}

void check_choice(std::string_view name, std::string_view value, std::span<const Choice> choices, Front front) {
  if (const std::string message = choice_message(value, choices); !message.empty())
    refuse(spelled(name, front).append(" ").append(message));
}

namespace {

// A bound as a reader writes it: whole numbers in full, others in the shortest form.
std::string bound_text(double bound) {
  if (std::isinf(bound)) return bound < 0 ? "-inf" : "inf";
  char text[32];
  std::snprintf(text, sizeof text, std::abs(bound) < 1e15 && bound == std::floor(bound) ? "%.0f" : "%g", bound);
  return text;
}

}  // namespace

std::string range_text(const Range& range) {
  const bool min_open = range.min_open || std::isinf(range.min), max_open = range.max_open || std::isinf(range.max);
  // Appended to one string: GCC 12 warns falsely (-Wrestrict) on `"(" + std::string&&` at -O3.
  std::string text = min_open ? "(" : "[";
  text += bound_text(range.min);
  text += ", ";
  text += bound_text(range.max);
  text += max_open ? ")" : "]";
  return text;
}

std::string range_message(double value, const Range& range, bool whole) {
  if (range.contains(value) && (!whole || value == std::floor(value))) return {};
  char got[32];
  std::snprintf(got, sizeof got, "%.15g", value);
  return std::string("must be ") + (whole ? "a whole number in " : "in ") + range_text(range) + ", got " + got;
}

void check_range(std::string_view name, double value, const Range& range, bool whole, Front front) {
  const std::string message = range_message(value, range, whole);
  if (!message.empty()) refuse(spelled(name, front) + " " + message);
}

void refuse(const std::string& message) { throw invalid_input(message); }

}  // namespace deformseg::frontend
