#include "store_policy.h"

#include "registry.h"

#include <deformseg/exceptions.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <variant>

namespace deformseg::frontend {

namespace {

nlohmann::json up_json(const std::optional<Eigen::Vector3d>& up) {
  if (!up) return nullptr;
  return {(*up)[0], (*up)[1], (*up)[2]};
}

}  // namespace

similarity::Default_similarity store_policy(const Policy_choice& choice, Front front) {
  check(choice, front);
  const similarity::Any_policy policy = make_policy(choice);
  if (const auto* signatures = std::get_if<similarity::Default_similarity>(&policy)) return *signatures;
  throw invalid_input("a motion store holds the motion signatures aligned by dtw, not " +
                      spelled("policy", choice.policy, front) + " with " +
                      spelled("alignment", alignment_name(choice), front));
}

std::size_t signature_width(const similarity::Default_similarity& policy) {
  const signatures::Motion_signature_options& s = policy.signatures;
  return (s.up ? 2 : 1) * s.lags.size() * s.bands * (s.sides ? 2 : 1) * s.quantiles;
}

std::string store_description(const similarity::Default_similarity& policy) {
  const signatures::Motion_signature_options& s = policy.signatures;
  const std::size_t width = signature_width(policy);
  // The store's policy is the registry's default (store_policy refuses any other).
  const Policy_entry& stored = similarity_policies[0];
  nlohmann::json description = {
      {"policy", stored.name},        {"alignment", stored.alignment}, {"lags", s.lags},
      {"quantiles", s.quantiles},     {"floor", s.floor},           {"up", up_json(s.up)},
      {"vertical_unit", s.vertical_unit}, {"vertical_weight", s.vertical_weight},
      {"signature_rate", policy.signature_rate}, {"scale", policy.scale}, {"width", width}};
  if (s.bands > 1) description["bands"] = s.bands;  // absent: one band, as every store before them
  if (s.sides) description["sides"] = up_json(s.sides);  // absent: the whole width
  return description.dump();
}

Policy_choice stored_policy_choice(const store::Motion_store& store) {
  const std::string manifest = (store.folder() / "store.json").string();
  const nlohmann::json stored = nlohmann::json::parse(store.description(), nullptr, false);
  if (!stored.is_object() || !stored.contains("up"))
    throw invalid_input("the store's description is not one of motion signatures: " + store.description(),
                        {.file = manifest});
  Policy_choice choice;
  for (const Choice& up : up_direction_choices)
    if (up_json(up_direction(up.name)) == stored["up"]) choice.up = up.name;
  if (const auto bands = stored.find("bands"); bands != stored.end() && bands->is_number_unsigned())
    choice.bands = bands->get<std::size_t>();
  for (const Choice& side : side_direction_choices)
    if (stored.contains("sides") && up_json(side_direction(std::string(side.name))) == stored["sides"])
      choice.sides = side.name;
  const nlohmann::json expected = nlohmann::json::parse(store_description(store_policy(choice, Front::command_line)));
  for (const auto& [key, value] : expected.items())
    if (!stored.contains(key) || stored[key] != value)
      throw invalid_input("the store was described with other options than this deformseg uses: its \"" + key +
                              "\" is " + (stored.contains(key) ? stored[key].dump() : "missing") + ", not " +
                              value.dump() + "; describe the clips again into a new store",
                          {.file = manifest});
  return choice;
}

}  // namespace deformseg::frontend
