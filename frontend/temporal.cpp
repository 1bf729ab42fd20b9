#include "temporal.h"

namespace deformseg::frontend {

void check(const Frame_distance_request& r, Front front) {
  check_choice("metric", r.metric, frame_metrics, front);
  if (!r.reference_mesh.empty() && r.rest_frame != 0)
    refuse(spelled("reference_mesh", front) + " takes the place of the rest frame: it excludes " +
           spelled("rest_frame", front));
}

void check(const Temporal_request& r, Front front) {
  check_choice("method", r.method, temporal_methods, front);
  check(distance_request(r), front);
  const auto name = [&](const char* parameter) { return spelled(parameter, front); };
  if (r.segments && r.method != "optimal") refuse(name("segments") + " asks for " + spelled("method", "optimal", front));
}

Frame_distance_request distance_request(const Temporal_request& r) {
  return {.metric = r.metric, .rest_frame = r.rest_frame, .reference_mesh = r.reference_mesh};
}

Eigen::MatrixXf frame_distances(const mesh::Surface_mesh_animation& animation, const Frame_distance_request& r,
                                int threads) {
  const strain::Frame_metric metric = r.metric == "l1"       ? strain::Frame_metric::l1
                                      : r.metric == "cosine" ? strain::Frame_metric::cosine
                                                             : strain::Frame_metric::euclidean;
  const auto field = strain_against(animation, r.reference_mesh, {.rest_frame = r.rest_frame, .threads = threads});
  return strain::frame_distances(field, {.metric = metric, .threads = threads});
}

Temporal_result segment(const Eigen::MatrixXf& distances, const Temporal_request& r) {
  const temporal::Segment_cost cost(distances);
  const auto threshold_or = [&](temporal::Segmentation_threshold fallback) {
    return r.threshold ? temporal::Segmentation_threshold{.value = *r.threshold, .relative = !r.absolute} : fallback;
  };
  if (r.method == "binary-split") {
    const temporal::Binary_split policy{.threshold = threshold_or(temporal::Binary_split{}.threshold),
                                        .min_length = r.min_length};
    return {temporal::segment_frames(cost, policy), policy.threshold};
  }
  if (r.method == "greedy") {
    const temporal::Thesis_greedy policy{.threshold = threshold_or(temporal::Thesis_greedy{}.threshold)};
    return {temporal::segment_frames(cost, policy), policy.threshold};
  }
  if (r.method == "barbic") return {temporal::segment_frames(cost, temporal::Barbic_pca{}), std::nullopt};
  const temporal::Optimal_partition policy{.penalty = threshold_or(temporal::Optimal_partition{}.penalty),
                                           .segments = r.segments, .min_length = r.min_length};
  return {temporal::segment_frames(cost, policy), r.segments ? std::nullopt : std::optional(policy.penalty)};
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
