#include "similarity.h"

#include <deformseg/similarity/significance.h>

#include <random>
#include <type_traits>

namespace deformseg::frontend {

void check(const similarity::Policy_choice& choice, Front front) {
  check_choice("policy", choice.policy, similarity_policies, front);
  if (!choice.alignment.empty()) check_choice("alignment", choice.alignment, alignments, front);
  if (!choice.up.empty()) check_choice("up", choice.up, up_directions, front);
  const auto name = [&](const char* parameter) { return spelled(parameter, front); };
  if (choice.threshold && choice.policy != "graph")
    refuse(name("threshold") + " applies to the graph policy only, not to the " + choice.policy + " policy");
  if (choice.threshold && !(*choice.threshold >= 0 && *choice.threshold <= 1))
    refuse(name("threshold") + " must be in [0, 1], not " + std::to_string(*choice.threshold));
  if (!choice.up.empty() && choice.policy != "motion-signature")
    refuse(name("up") + " applies to the motion-signature policy only, not to the " + choice.policy + " policy");
}

void check(const Significance_request& r, const similarity::Policy_choice& choice, Front front) {
  const std::string name = spelled("significance", front);
  if (r.significance == 1) refuse(name + " needs 0 (none) or at least 2 shuffled copies");
  if (r.significance.value_or(0) >= 2 && choice.policy == "graph")
    refuse(name + " does not apply to the graph policy, whose frames are key-frame labels");
}

Compared compare(const mesh::Surface_mesh_animation& a, const mesh::Surface_mesh_animation& b,
                 const similarity::Policy_choice& choice, const Significance_request& significance) {
  const std::size_t copies = significance.significance.value_or(choice.policy == "graph" ? 0 : 20);
  return similarity::with_policy_choice(choice, [&](const auto& policy) {
    const auto da = policy.describe(a), db = policy.describe(b);
    Compared out{policy.compare(da, db), std::nullopt, 0};
    if constexpr (similarity::ReorderableDescription<std::remove_cvref_t<decltype(db)>>) {
      if (copies >= 2) {
        std::mt19937 random(significance.seed);
        out.z_score = similarity::similarity_significance(policy, da, db, copies, random);
        out.shuffled_copies = copies;
      }
    }
    return out;
  });
}

nlohmann::json similarity_record(const Compared& compared, const similarity::Policy_choice& choice) {
  const similarity::Similarity& s = compared.similarity;
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& [i, j] : s.alignment) pairs.push_back({i, j});
  return {{"policy", choice.policy},
          {"alignment_policy", similarity::alignment_name(choice)},
          {"similarity", s.value},
          {"score", s.score},
          {"labels_a", s.labels_a},
          {"labels_b", s.labels_b},
          {"alignment", pairs},
          {"compared", s.compared},
          {"z_score", compared.z_score ? nlohmann::json(*compared.z_score) : nlohmann::json()},
          {"shuffled_copies", compared.shuffled_copies}};
}

}  // namespace deformseg::frontend
