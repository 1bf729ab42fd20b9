#include "temporal.h"

#include <algorithm>
#include <optional>

namespace deformseg::frontend {

void check(const Frame_distance_request& r, Front front) {
  check_choice("metric", r.metric, frame_metric_choices, front);
  if (!r.reference_mesh.empty() && r.rest_frame != 0)
    refuse(spelled("reference_mesh", front) + " takes the place of the rest frame: it excludes " +
           spelled("rest_frame", front));
}

void check(const Temporal_request& r, Front front) {
  check_choice("method", r.method, temporal_method_choices, front);
  check(distance_request(r), front);
  if (r.segments && !entry_named(temporal_methods, r.method).counts)
    refuse(spelled("segments", front) + " asks for " +
           spelled("method", std::ranges::find_if(temporal_methods, &Temporal_method::counts)->name, front));
}

Frame_distance_request distance_request(const Temporal_request& r) {
  return {.metric = r.metric, .rest_frame = r.rest_frame, .reference_mesh = r.reference_mesh};
}

Eigen::MatrixXf frame_distances(const mesh::Surface_mesh_animation& animation, const Frame_distance_request& r,
                                int threads) {
  const strain::Frame_metric metric = entry_named(frame_metrics, r.metric).value;
  const auto field = strain_against(animation, r.reference_mesh, {.rest_frame = r.rest_frame, .threads = threads});
  return strain::frame_distances(field, {.metric = metric, .threads = threads});
}

namespace {

// The request's threshold (relative unless absolute), or `fallback`, the method's own.
temporal::Segmentation_threshold threshold_or(const Temporal_request& r, temporal::Segmentation_threshold fallback) {
  return r.threshold ? temporal::Segmentation_threshold{.value = *r.threshold, .relative = !r.absolute} : fallback;
}

}  // namespace

Temporal_result optimal_segments(const temporal::Segment_cost& cost, const Temporal_request& r) {
  const temporal::Optimal_partition policy{.penalty = threshold_or(r, temporal::Optimal_partition{}.penalty),
                                           .segments = r.segments, .min_length = r.min_length};
  return {temporal::segment_frames(cost, policy), r.segments ? std::nullopt : std::optional(policy.penalty)};
}

Temporal_result binary_split_segments(const temporal::Segment_cost& cost, const Temporal_request& r) {
  const temporal::Binary_split policy{.threshold = threshold_or(r, temporal::Binary_split{}.threshold),
                                      .min_length = r.min_length};
  return {temporal::segment_frames(cost, policy), policy.threshold};
}

Temporal_result greedy_segments(const temporal::Segment_cost& cost, const Temporal_request& r) {
  const temporal::Thesis_greedy policy{.threshold = threshold_or(r, temporal::Thesis_greedy{}.threshold)};
  return {temporal::segment_frames(cost, policy), policy.threshold};
}

Temporal_result barbic_segments(const temporal::Segment_cost& cost, const Temporal_request&) {
  return {temporal::segment_frames(cost, temporal::Barbic_pca{}), std::nullopt};
}

Temporal_result segment(const Eigen::MatrixXf& distances, const Temporal_request& r) {
  return entry_named(temporal_methods, r.method).segment(temporal::Segment_cost(distances), r);
}

nlohmann::json temporal_record(const Temporal_result& result, const Temporal_request& r) {
  nlohmann::json segments = nlohmann::json::array();
  for (const auto& segment : result.segmentation.segments)
    segments.push_back({{"first", segment.first}, {"last", segment.last}, {"cost", segment.cost}});
  nlohmann::json threshold;
  if (result.threshold) threshold = {{"value", result.threshold->value}, {"relative", result.threshold->relative}};
  return {{"frames", result.segmentation.frames}, {"method", r.method}, {"metric", r.metric},
          {"threshold", threshold}, {"segments", segments}};
}

}  // namespace deformseg::frontend
