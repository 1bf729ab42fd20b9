#include "parameters.h"

#include <algorithm>

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

void check_choice(std::string_view name, std::string_view value, std::span<const Choice> choices, Front front) {
  if (std::ranges::any_of(choices, [&](const Choice& c) { return c.name == value; })) return;
  refuse(spelled(name, front).append(" must be ").append(listed(choices)).append(", got '").append(value).append("'"));
}

void refuse(const std::string& message) { throw invalid_input(message); }

}  // namespace deformseg::frontend
