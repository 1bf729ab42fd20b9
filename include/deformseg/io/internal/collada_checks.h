// What Assimp's Collada reader drops without a word, found in the file's text: a morph controller
// (which it does not import under a skin), and channels whose target names nothing in the file
// (it drops them, and with them the clip when none is left).
#pragma once

#include <deformseg/exceptions.h>

#include <cstddef>
#include <set>
#include <string>
#include <string_view>

namespace deformseg::io::internal::collada {

/// Whether the file has a morph controller.
inline bool has_morph(std::string_view text) { return text.find("<morph") != std::string_view::npos; }

/// The value of attribute `name` in the tag that starts at `tag` (up to its '>'), or empty.
inline std::string_view attribute(std::string_view text, std::size_t tag, std::string_view name) {
  const std::size_t end = text.find('>', tag);
  const std::string_view element = text.substr(tag, end == std::string_view::npos ? std::string_view::npos : end - tag);
  for (std::size_t at = element.find(name); at != std::string_view::npos; at = element.find(name, at + 1)) {
    const bool whole = at > 0 && (element[at - 1] == ' ' || element[at - 1] == '\n' || element[at - 1] == '\t');
    const std::size_t quote = at + name.size() + 1;
    if (!whole || quote >= element.size() || element[at + name.size()] != '=') continue;
    const char mark = element[quote];
    if (mark != '"' && mark != '\'') continue;
    const std::size_t close = element.find(mark, quote + 1);
    if (close != std::string_view::npos) return element.substr(quote + 1, close - quote - 1);
  }
  return {};
}

/// Every `id` attribute of the file.
inline std::set<std::string, std::less<>> ids(std::string_view text) {
  std::set<std::string, std::less<>> result;
  for (std::size_t at = text.find(" id="); at != std::string_view::npos; at = text.find(" id=", at + 1)) {
    const std::size_t tag = text.rfind('<', at);
    if (tag != std::string_view::npos) result.emplace(attribute(text, tag, "id"));
  }
  return result;
}

/// Refuses a `<channel>` whose target ("ID/transform", "ID.X", "ID(0)") names no element of the file.
/// @throws invalid_input naming the channel's target.
inline void check_channel_targets(std::string_view text) {
  std::set<std::string, std::less<>> known;
  bool listed = false;
  for (std::size_t at = text.find("<channel"); at != std::string_view::npos; at = text.find("<channel", at + 1)) {
    const std::string_view target = attribute(text, at, "target");
    const std::string_view id = target.substr(0, target.find_first_of("/.("));
    if (id.empty()) continue;
    if (!listed) known = ids(text), listed = true;
    if (!known.contains(id))
      throw invalid_input("a Collada <channel> targets '" + std::string(target) + "', but nothing in the file has the id '" +
                          std::string(id) + "': Assimp would drop the channel, and leaving it out would change the motion");
  }
}

}  // namespace deformseg::io::internal::collada
