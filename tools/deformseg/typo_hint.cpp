#include "command.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace deformseg::tool {
namespace {

// The Levenshtein distance: the fewest insertions, deletions and substitutions from a to b.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The candidate nearest to `word`, when near enough to be what was meant: at most a third of its
// letters off (two at least), or `word` a start of it.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t d = candidate.starts_with(word) ? 1 : edit_distance(word, candidate);
    if (d < best_distance) best = candidate, best_distance = d;
  }
  return best;
}

bool is_number(const std::string& word) {
  return word.size() > 1 && (std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.');
}

std::vector<std::string> long_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options())
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  return names;
}

}  // namespace

std::string typo_hint(const CLI::App& app, const std::vector<std::string>& arguments) {
  if (arguments.empty()) return {};
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
    commands.push_back(command->get_name());
  const std::string& first = arguments.front();
  if (first.starts_with("-")) return {};
  const auto named = std::ranges::find(commands, first);
  if (named == commands.end()) {
    const std::string guess = nearest(first, commands);
    return guess.empty() ? "" : "unknown command '" + first + "': did you mean '" + guess + "'?";
  }
  const CLI::App* command = app.get_subcommand(first);
  const std::vector<std::string> options = long_names(*command);
  for (std::size_t k = 1; k < arguments.size(); ++k) {
    const std::string word = arguments[k].substr(0, arguments[k].find('='));
    if (!word.starts_with("--") || std::ranges::find(options, word) != options.end() || is_number(word)) continue;
    const std::string guess = nearest(word, options);
    return "unknown option '" + word + "' of " + first + (guess.empty() ? "" : ": did you mean '" + guess + "'?");
  }
  return {};
}

}  // namespace deformseg::tool
