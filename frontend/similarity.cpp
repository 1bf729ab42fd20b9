#include "similarity.h"

#include <deformseg/io/frame_stream.h>
#include <deformseg/similarity/significance.h>

#include <random>
#include <type_traits>

namespace deformseg::frontend {

void check(const similarity::Policy_choice& choice, Front front) {
  check_choice("policy", choice.policy, similarity_policies, front);
  if (!choice.alignment.empty()) check_choice("alignment", choice.alignment, alignments, front);
  if (!choice.up.empty()) check_choice("up", choice.up, up_directions, front);
  const auto name = [&](const char* parameter) { return spelled(parameter, front); };
  if (choice.threshold && !similarity::is_graph_policy(choice.policy))
    refuse(name("threshold") + " applies to the graph policies only, not to the " + choice.policy + " policy");
  if (!choice.up.empty() && choice.policy != "motion-signature")
    refuse(name("up") + " applies to the motion-signature policy only, not to the " + choice.policy + " policy");
}

void check(const Significance_request& r, const similarity::Policy_choice& choice, Front front) {
  const std::string name = spelled("significance", front);
  if (r.significance == 1) refuse(name + " needs 0 (none) or at least 2 shuffled copies");
  if (r.significance.value_or(0) >= 2 && similarity::is_graph_policy(choice.policy))
    refuse(name + " does not apply to the graph policies, whose frames are key-frame labels");
}

namespace {

std::size_t shuffled_copies(const similarity::Policy_choice& choice, const Significance_request& significance) {
  return significance.significance.value_or(similarity::is_graph_policy(choice.policy) ? 0 : 20);
}

template <class Policy, class Description>
Compared compare_descriptions(const Policy& policy, const Description& da, const Description& db, std::size_t copies,
                              unsigned seed) {
  Compared out{policy.compare(da, db), std::nullopt, 0};
  if constexpr (similarity::ReorderableDescription<Description>) {
    if (copies >= 2) {
      std::mt19937 random(seed);
      out.z_score = similarity::similarity_significance(policy, da, db, copies, random);
      out.shuffled_copies = copies;
    }
  }
  return out;
}

}  // namespace

Compared compare(const mesh::Surface_mesh_animation& a, const mesh::Surface_mesh_animation& b,
                 const similarity::Policy_choice& choice, const Significance_request& significance) {
  return similarity::with_policy_choice(choice, [&](const auto& policy) {
    return compare_descriptions(policy, policy.describe(a), policy.describe(b), shuffled_copies(choice, significance),
                                significance.seed);
  });
}

std::optional<Compared> compare_streamed(const std::array<std::string, 2>& inputs, const Input_options& options,
                                         const similarity::Policy_choice& choice,
                                         const Significance_request& significance, Front front,
                                         std::array<Streamed_input, 2>& streamed) {
  if (choice.policy != "motion-signature") return std::nullopt;
  const std::array<Input_name, 2> names{input_name(inputs[0], options, front), input_name(inputs[1], options, front)};
  for (const Input_name& name : names)
    if (io::is_character_file(name.file) || !reads_frame_by_frame(name.file, options)) return std::nullopt;
  return similarity::with_policy_choice(choice, [&](const auto& policy) -> std::optional<Compared> {
    using Description = typename std::remove_cvref_t<decltype(policy)>::Description;
    if constexpr (!std::is_same_v<Description, similarity::Motion_signature_description>) {
      return std::nullopt;
    } else {
      std::array<std::optional<Description>, 2> described;
      for (std::size_t k = 0; k < 2; ++k) {
        const io::Animation_read_options read = animation_read_options(names[k].file, options);
        described[k] = io::with_frame_source(names[k].file, read, [&](auto& source) -> std::optional<Description> {
          streamed[k].frames = source.num_frames();
          if (streamed[k].frames < 2) return std::nullopt;  // refused by the reader of whole animations, in its words
          Outlier_checked_source checked(source, names[k].file, options.refuse_defects, front, streamed[k].outliers);
          return policy.describe_stream(checked);
        });
        if (!described[k]) return std::nullopt;
      }
      return compare_descriptions(policy, *described[0], *described[1], shuffled_copies(choice, significance),
                                  significance.seed);
    }
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
