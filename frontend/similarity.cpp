#include "similarity.h"

#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/frame_stream.h>
#include <deformseg/io/gltf.h>
#include <deformseg/similarity/significance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <random>
#include <ranges>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace deformseg::frontend {

namespace {

Eigen::Vector3d vector_of(const Axis_direction& direction) {
  return direction.sign * Eigen::Vector3d::Unit(direction.axis);
}

}  // namespace

std::optional<Eigen::Vector3d> up_direction(std::string_view name) {
  if (name.empty()) return Eigen::Vector3d::UnitY();
  const std::optional<Axis_direction>& direction = entry_named(up_directions, name).value;
  return direction ? std::optional(vector_of(*direction)) : std::nullopt;  // none: speeds alone
}

std::optional<Eigen::Vector3d> side_direction(std::string_view name) {
  if (name.empty()) return std::nullopt;
  return vector_of(entry_named(side_directions, name).value);
}

const Policy_entry& policy_entry(const Policy_choice& choice) {
  return entry_named(similarity_policies, choice.policy);
}

std::string alignment_name(const Policy_choice& choice) {
  return choice.alignment.empty() ? std::string(policy_entry(choice).alignment) : choice.alignment;
}

namespace {

// `Policy` aligning by `alignment`'s, its options set by `set(policy)`.
template <template <alignment::AlignmentPolicy, class...> class Policy, class Set>
similarity::Any_policy aligned_policy(const similarity::Any_alignment& alignment, const Set& set) {
  return std::visit(
      [&](const auto& aligner) -> similarity::Any_policy {
        Policy<std::remove_cvref_t<decltype(aligner)>> policy{};
        policy.alignment = aligner;
        set(policy);
        return policy;
      },
      alignment);
}

// The evolving-graph policy aligning by `alignment`, segmenting as `segmentation` with the
// threshold of `choice` (given), its segmentation, edit distances and clustering on `threads`.
similarity::Any_policy graph_policy(const similarity::Any_alignment& alignment,
                                    const spatiotemporal::Spatiotemporal_options& segmentation,
                                    const Policy_choice& choice, int threads) {
  return aligned_policy<similarity::Graph_similarity>(alignment, [&](auto& policy) {
    policy.segmentation = segmentation;
    policy.segmentation.threshold = *choice.threshold;
    policy.threads = policy.segmentation.threads = policy.clustering.threads = threads;
  });
}

}  // namespace

similarity::Any_policy signature_policy(const similarity::Any_alignment& alignment, const Policy_choice& choice,
                                        int threads) {
  return aligned_policy<similarity::Motion_signature_similarity>(alignment, [&](auto& policy) {
    policy.signatures.up = up_direction(choice.up);
    policy.signatures.bands = choice.bands.value_or(1);
    policy.signatures.sides = side_direction(choice.sides);
    policy.signatures.threads = threads;
  });
}

similarity::Any_policy histogram_policy(const similarity::Any_alignment& alignment, const Policy_choice&,
                                        int threads) {
  return aligned_policy<similarity::Strain_distribution_similarity>(alignment, [&](auto& policy) {
    policy.histograms.strain.threads = policy.histograms.histogram.threads = threads;
  });
}

similarity::Any_policy thesis_graph_policy(const similarity::Any_alignment& alignment, const Policy_choice& choice,
                                           int threads) {
  return graph_policy(alignment, similarity::thesis_segmentation(), choice, threads);
}

similarity::Any_policy character_graph_policy(const similarity::Any_alignment& alignment,
                                              const Policy_choice& choice, int threads) {
  return graph_policy(alignment, similarity::character_segmentation(), choice, threads);
}

similarity::Any_policy self_similarity_policy(const similarity::Any_alignment& alignment, const Policy_choice&,
                                              int) {  // its loops are its alignment's, on one thread
  return aligned_policy<similarity::Self_similarity_matching>(alignment, [](auto&) {});
}

similarity::Any_policy make_policy(const Policy_choice& choice, int threads) {
  const Policy_entry& entry = policy_entry(choice);
  Policy_choice given = choice;
  if (entry.threshold) given.threshold = choice.threshold.value_or(*entry.threshold);
  return entry.make(entry_named(similarity_alignments, alignment_name(choice)).value, given, threads);
}

void check(const Policy_choice& choice, Front front) {
  check_choice("policy", choice.policy, policy_choices, front);
  if (!choice.alignment.empty()) check_choice("alignment", choice.alignment, alignment_choices, front);
  if (!choice.up.empty()) check_choice("up", choice.up, up_direction_choices, front);
  if (!choice.sides.empty()) check_choice("sides", choice.sides, side_direction_choices, front);
  const Policy_entry& policy = policy_entry(choice);
  const auto name = [&](const char* parameter) { return spelled(parameter, front); };
  if (choice.threshold && !policy.threshold)
    refuse(name("threshold") + " applies to the graph policies only, not to the " + choice.policy + " policy");
  if (!choice.up.empty() && !policy.up)
    refuse(name("up") + " applies to the motion-signature policy only, not to the " + choice.policy + " policy");
  for (const auto& [parameter, given] : {std::pair{"bands", choice.bands.has_value()},
                                         std::pair{"sides", !choice.sides.empty()}})
    if (given && !policy.up)
      refuse(name(parameter) + " applies to the motion-signature policy only, not to the " + choice.policy +
             " policy");
  if (choice.bands.value_or(1) > 1 && !up_direction(choice.up))
    refuse(name("bands") + " " + std::to_string(*choice.bands) + " needs an up direction, not " +
           spelled("up", name_of(up_directions, std::optional<Axis_direction>()), front));
}

void check(const Comparison_request& r, const Policy_choice& choice, Front front) {
  if (r.explain && policy_entry(choice).name != similarity_policies[0].name)
    refuse(spelled("explain", front) + " applies to the motion-signature policy only, not to the " + choice.policy +
           " policy");
  const std::string name = spelled("significance", front);
  if (r.significance == 1) refuse(name + " needs 0 (none) or at least 2 shuffled copies");
  if (r.significance.value_or(0) >= 2 && policy_entry(choice).key_frames)
    refuse(name + " does not apply to the graph policies, whose frames are key-frame labels");
}

namespace {

std::size_t shuffled_copies(const Policy_choice& choice, const Comparison_request& request) {
  return request.significance.value_or(policy_entry(choice).key_frames ? 0 : 20);
}

// Whether `Policy` describes a stream of frames, a few at a time (the motion signatures).
template <class Policy>
constexpr bool describes_streams =
    std::is_same_v<typename Policy::Description, similarity::Motion_signature_description>;

template <class Policy, class Description>
Compared compare_descriptions(const Policy& policy, const Description& da, const Description& db,
                              const Policy_choice& choice, const Comparison_request& request, int threads) {
  Compared out{policy.compare(da, db), std::nullopt, 0};
  if constexpr (similarity::ReorderableDescription<Description>) {
    if (const std::size_t copies = shuffled_copies(choice, request); copies >= 2) {
      std::mt19937 random(request.seed);
      out.z_score = similarity::similarity_significance(policy, da, db, copies, random, threads);
      out.shuffled_copies = copies;
    }
  }
  if constexpr (describes_streams<Policy>)
    if (request.explain) out.explanation = policy.explain(da, db);
  return out;
}

}  // namespace

Compared compare(const mesh::Surface_mesh_animation& a, const mesh::Surface_mesh_animation& b,
                 const Policy_choice& choice, const Comparison_request& request, int threads) {
  return similarity::visit_policy(make_policy(choice, threads), [&](const auto& policy) {
    return compare_descriptions(policy, policy.describe(a), policy.describe(b), choice, request, threads);
  });
}

namespace {

// The animations at `addresses`, as a random-access range of animations.
auto animations_at(Animation_addresses addresses) {
  return addresses | std::views::transform([](const mesh::Surface_mesh_animation* animation)
                                               -> const mesh::Surface_mesh_animation& { return *animation; });
}

}  // namespace

Eigen::MatrixXd similarity_matrix(Animation_addresses animations, const Policy_choice& choice,
                                  const Progress& progress, int threads) {
  return similarity::visit_policy(make_policy(choice), [&](const auto& policy) {
    return similarity::similarity_matrix(animations_at(animations), policy, progress, threads);
  });
}

Eigen::MatrixXd similarity_matrix(std::span<const mesh::Surface_mesh_animation> animations,
                                  const Policy_choice& choice, const Progress& progress, int threads) {
  std::vector<const mesh::Surface_mesh_animation*> addresses;
  for (const mesh::Surface_mesh_animation& animation : animations) addresses.push_back(&animation);
  return similarity_matrix(addresses, choice, progress, threads);
}

Eigen::MatrixXd similarity_matrix(Animation_addresses queries, Animation_addresses database,
                                  const Policy_choice& choice, const Progress& progress, int threads) {
  return similarity::visit_policy(make_policy(choice), [&](const auto& policy) {
    return similarity::similarity_matrix(animations_at(queries), animations_at(database), policy, progress, threads);
  });
}

Read_matrix similarity_matrix(const Animation_source& source, const Policy_choice& choice, const Progress& progress,
                              int threads) {
  thread_count(threads, "similarity_matrix");
  return similarity::visit_policy(make_policy(choice), [&](const auto& policy) {
    using Description = typename std::remove_cvref_t<decltype(policy)>::Description;
    const std::size_t n = source.count;
    std::vector<std::optional<Description>> made(n);
    std::vector<std::optional<Left_out>> lost(n);
    deformseg::internal::parallel_for_reporting(n, threads, progress, 0, n + n * (n + 1) / 2, [&](std::size_t i) {
      std::optional<mesh::Surface_mesh_animation> animation;
      try {
        animation.emplace(source.read(i));
      } catch (const invalid_input& e) {
        lost[i].emplace(Left_out{i, true, e});
        return;
      }
      try {
        made[i].emplace(policy.describe(*animation));
      } catch (const invalid_input& e) {
        lost[i].emplace(Left_out{i, false, e});
      }
    });
    Read_matrix out;
    std::vector<Description> descriptions;
    for (std::size_t i = 0; i < n; ++i) {
      if (!made[i]) {
        out.left_out.push_back(std::move(*lost[i]));
        continue;
      }
      descriptions.push_back(std::move(*made[i]));
      out.kept.push_back(i);
    }
    Progress pairs;  // the steps after the descriptions
    if (progress) pairs = [&](std::size_t done, std::size_t total) { return progress(n + done, n + total); };
    out.similarity = similarity::described_similarity_matrix(std::span<const Description>(descriptions), policy,
                                                             pairs, threads);
    return out;
  });
}

std::optional<Compared> compare_streamed(const std::array<std::string, 2>& inputs, const Input_options& options,
                                         const Policy_choice& choice,
                                         const Comparison_request& request, Front front,
                                         std::array<Streamed_input, 2>& streamed) {
  const similarity::Any_policy any = make_policy(choice, options.threads);
  const auto streams = [](const auto& policy) { return describes_streams<std::remove_cvref_t<decltype(policy)>>; };
  if (!similarity::visit_policy(any, streams)) return std::nullopt;
  const std::array<Input_name, 2> names{input_name(inputs[0], options, front), input_name(inputs[1], options, front)};
  for (const Input_name& name : names)
    if (!io::is_character_file(name.file) && !reads_frame_by_frame(name.file, options)) return std::nullopt;
  return similarity::visit_policy(any, [&](const auto& policy) -> std::optional<Compared> {
    using Policy = std::remove_cvref_t<decltype(policy)>;
    if constexpr (!describes_streams<Policy>) {
      return std::nullopt;
    } else {
      using Description = typename Policy::Description;
      std::array<std::optional<Description>, 2> described;
      for (std::size_t k = 0; k < 2; ++k) {
        const auto describe = [&](auto& source) -> std::optional<Description> {
          streamed[k].frames = source.num_frames();
          if (streamed[k].frames < 2) return std::nullopt;  // refused by the reader of whole animations, in its words
          Outlier_checked_source checked(source, names[k].file, options.refuse_defects, front, streamed[k].outliers);
          return policy.describe_stream(checked);
        };
        if (io::is_character_file(names[k].file)) {
          // As read_input reads it: parsed on its body, the clip chosen, the connectivity repaired.
          const io::Gltf_file gltf = character_file(names[k].file, options);
          io::require_clip_choice(gltf, names[k].clip);
          io::Gltf_frame_source source(
              gltf, {.clip = names[k].clip, .fps = options.fps, .repair = repair_options(names[k].file, options)});
          streamed[k].clip = source.clip_name();
          streamed[k].repair = source.connectivity().repaired().report;
          described[k] = describe(source);
        } else {
          described[k] = io::with_frame_source(names[k].file, animation_read_options(names[k].file, options), describe);
        }
        if (!described[k]) return std::nullopt;
      }
      return compare_descriptions(policy, *described[0], *described[1], choice, request, options.threads);
    }
  });
}

nlohmann::json similarity_record(const Compared& compared, const Policy_choice& choice) {
  const similarity::Similarity& s = compared.similarity;
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& [i, j] : s.alignment) pairs.push_back({i, j});
  return {{"policy", choice.policy},
          {"alignment_policy", alignment_name(choice)},
          {"similarity", s.value},
          {"score", s.score},
          {"labels_a", s.labels_a},
          {"labels_b", s.labels_b},
          {"alignment", pairs},
          {"compared", s.compared},
          {"z_score", compared.z_score ? nlohmann::json(*compared.z_score) : nlohmann::json()},
          {"shuffled_copies", compared.shuffled_copies},
          {"explanation", compared.explanation ? explanation_record(*compared.explanation) : nlohmann::json()}};
}

nlohmann::json explanation_record(const similarity::Motion_signature_explanation& explanation) {
  nlohmann::json channels = nlohmann::json::array();
  for (const similarity::Signature_channel& c : explanation.channels)
    channels.push_back({{"kind", c.kind == similarity::Signature_channel::Kind::speed ? "speed" : "vertical_rate"},
                        {"lag", c.lag},
                        {"band", c.band},
                        {"side", c.side},
                        {"half", c.upper_half ? "upper" : "lower"},
                        {"share", c.share},
                        {"mean_difference", c.mean_difference}});
  return {{"pairs", explanation.pairs}, {"channels", channels}};
}

std::vector<std::string> explanation_lines(const similarity::Motion_signature_explanation& explanation,
                                           std::size_t bands, std::size_t most) {
  std::vector<const similarity::Signature_channel*> order;
  for (const similarity::Signature_channel& c : explanation.channels) order.push_back(&c);
  std::ranges::stable_sort(order, std::greater{}, &similarity::Signature_channel::share);
  std::vector<std::string> lines;
  for (const similarity::Signature_channel* c : order | std::views::take(most)) {
    const bool speed = c->kind == similarity::Signature_channel::Kind::speed;
    char text[200];
    std::string where = bands > 1 ? "height band " + std::to_string(c->band + 1) + " of " +
                                        std::to_string(bands) + ", counted from the ground"
                                  : "the surface";
    if (c->side != 0) where += c->side < 0 ? ", its negative side" : ", its positive side";
    std::snprintf(text, sizeof text, "%5.1f%%  %s at lag %.3g s, the %s half of %s: ", 100 * c->share,
                  speed ? "speeds" : "vertical rates", c->lag,
                  speed ? (c->upper_half ? "faster" : "slower") : (c->upper_half ? "rising" : "falling"),
                  where.c_str());
    std::string line = text;
    if (speed)
      std::snprintf(text, sizeof text, "A %.2fx as fast as B", std::exp(c->mean_difference));
    else
      std::snprintf(text, sizeof text, "A %s B by %.2f (asinh units)", c->mean_difference >= 0 ? "above" : "below",
                    std::abs(c->mean_difference));
    lines.push_back(line + text);
  }
  return lines;
}

}  // namespace deformseg::frontend
