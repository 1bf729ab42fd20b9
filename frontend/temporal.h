// The temporal segmentation as a command and a Python function ask for it: methods and frame
// metrics by name, the threshold relative or absolute, the strain against a frame or a reference
// mesh.
#pragma once

#include "parameters.h"
#include "registry.h"
#include "strain.h"

#include <deformseg/strain/frame_distances.h>
#include <deformseg/temporal/temporal_segmentation.h>

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <tuple>

namespace deformseg::frontend {

/// The frame distances as the user asks for them: the default strain against a rest frame or a
/// reference mesh.
struct Frame_distance_request {
  std::string metric{frame_metrics[0].name};
  std::size_t rest_frame = 0;
  std::string reference_mesh{};
};

/// A temporal segmentation as the user asks for it.
struct Temporal_request {
  std::string method{temporal_methods[0].name};
  std::optional<double> threshold{};
  bool absolute = false;
  std::optional<std::size_t> segments{};
  std::size_t min_length = 1;
  std::string metric{frame_metrics[0].name};
  std::size_t rest_frame = 0;
  std::string reference_mesh{};
};

/// The parameters of the frame distances, which the segmentation shares.
template <class Request>
constexpr std::tuple<Parameter<Request, std::string>, Parameter<Request, std::size_t>,
                     Parameter<Request, std::string>>
frame_distance_parameters() {
  return {choice_parameter("metric", &Request::metric, "The distance between the frames' strains",
                           frame_metric_choices),
          numeric_parameter("rest_frame", &Request::rest_frame, "The rest pose of the strain. Default: 0", counts()),
          reference_mesh_parameter<Request>()};
}

/// The frame distances' table.
inline constexpr auto frame_distance_table = frame_distance_parameters<Frame_distance_request>();

/// The temporal segmentation's table.
inline constexpr auto temporal_parameters = std::tuple_cat(
    std::tuple{
        choice_parameter("method", &Temporal_request::method, "The segmentation method", temporal_method_choices),
        numeric_parameter(
            "threshold", &Temporal_request::threshold,
            "binary-split and greedy: the largest within-segment dissimilarity (default 0.5 and 0.2); optimal: the "
            "penalty per segment (default 0.03); relative to the mean frame distance (optimal: to the one-segment "
            "cost) unless absolute",
            non_negative),
        Parameter<Temporal_request, bool>{"absolute", &Temporal_request::absolute,
                                          "The threshold is absolute, in frame distance units"},
        numeric_parameter("segments", &Temporal_request::segments, "Exactly this many segments (method optimal)",
                          positive_counts()),
        numeric_parameter("min_length", &Temporal_request::min_length,
                          "Fewest frames of a segment (optimal, binary-split). Default: 1", positive_counts())},
    frame_distance_parameters<Temporal_request>());

/// Checks a request's choices and combinations before any input is read; its numbers' ranges are
/// the table's, refused where the values come in (the tool's options, Python's keywords).
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Frame_distance_request& request, Front front);
void check(const Temporal_request& request, Front front);

/// The frame distances of `animation`'s normalised strain, as `request` asks.
Eigen::MatrixXf frame_distances(const mesh::Surface_mesh_animation& animation, const Frame_distance_request& request,
                                int threads);

/// A temporal segmentation and the threshold (or penalty) it used; none for barbic and for a
/// count of segments.
struct Temporal_result {
  temporal::Temporal_segmentation segmentation;
  std::optional<temporal::Segmentation_threshold> threshold;
};

/// The segmentation of the frames whose distances are `distances`, as `request` asks.
Temporal_result segment(const Eigen::MatrixXf& distances, const Temporal_request& request);

/// The distances' request of a segmentation's.
Frame_distance_request distance_request(const Temporal_request& request);

/// A segmentation as a report: {"frames", "method", "metric", "threshold" ({"value", "relative"} or
/// null), "segments": [{"first", "last", "cost"}]}.
nlohmann::json temporal_record(const Temporal_result& result, const Temporal_request& request);

}  // namespace deformseg::frontend
