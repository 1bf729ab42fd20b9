// The spatio-temporal segmentation and its evolving graph as a command and a Python function ask
// for them.
#pragma once

#include "parameters.h"
#include "strain.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/spatiotemporal/evolving_graph.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

namespace deformseg::frontend {

/// What a cell's strain is measured against, for the spatio-temporal segmentation.
inline constexpr std::array segmentation_references{
    Choice{"previous", "deformed while it moves (default without a reference mesh)"},
    Choice{"rest", "deformed while away from frame 0, or from the reference mesh (the default with one)"},
};

/// A spatio-temporal segmentation as the user asks for it.
struct Spatiotemporal_request {
  double threshold = spatiotemporal::Spatiotemporal_options{}.threshold;
  std::string reference{};  ///< empty: previous, or rest with a reference mesh
  std::string reference_mesh{};
  std::optional<double> sigma{};
  std::size_t min_triangles = spatiotemporal::Spatiotemporal_options{}.min_triangles;
  std::size_t min_frames = spatiotemporal::Spatiotemporal_options{}.min_frames;
  std::size_t max_island = spatiotemporal::Spatiotemporal_options{}.max_island;
  double min_area = spatiotemporal::Spatiotemporal_options{}.min_area;
  double hysteresis = spatiotemporal::Spatiotemporal_options{}.hysteresis;
  double contact_distance = spatiotemporal::Part_link_options{}.contact_distance;
  double rigid_tolerance = spatiotemporal::Part_link_options{}.rigid_tolerance;
};

/// The spatio-temporal request's table.
inline constexpr std::tuple spatiotemporal_parameters{
    numeric_parameter("threshold", &Spatiotemporal_request::threshold,
                      "A cell is deformed above this normalised strain. Default: 0.5", shares),
    choice_parameter("reference", &Spatiotemporal_request::reference, "What the strain is measured against",
                     segmentation_references),
    reference_mesh_parameter<Spatiotemporal_request>(),
    numeric_parameter("sigma", &Spatiotemporal_request::sigma,
                      "The strain's Gaussian normalisation sigma, fixed for every animation. Default: each "
                      "animation's 95th percentile",
                      positive),
    numeric_parameter("min_triangles", &Spatiotemporal_request::min_triangles,
                      "Segments whose largest slice has fewer triangles become rigid. Default: 10", counts()),
    numeric_parameter("min_frames", &Spatiotemporal_request::min_frames,
                      "Segments lasting fewer frames become rigid. Default: 6", counts()),
    numeric_parameter("max_island", &Spatiotemporal_request::max_island,
                      "Rigid islands of at most this many triangles inside one segment join it (0: none). "
                      "Default: 30",
                      counts()),
    numeric_parameter("min_area", &Spatiotemporal_request::min_area,
                      "Segments whose largest slice covers less than this share of the area become rigid. Default: 0",
                      shares),
    numeric_parameter("hysteresis", &Spatiotemporal_request::hysteresis,
                      "Cells above threshold x (1 - this) joined to a cell above the threshold are deformed too. "
                      "Default: 0",
                      Range{.min = 0, .max = 1, .max_open = true}),
    numeric_parameter("contact_distance", &Spatiotemporal_request::contact_distance,
                      "Separate parts within this share of the rest pose's diagonal are neighbours (0: shared edges "
                      "only, the thesis). Default: 0.01",
                      shares),
    numeric_parameter("rigid_tolerance", &Spatiotemporal_request::rigid_tolerance,
                      "Separate parts moving as one rigid body, within this share of the diagonal, make one rigid "
                      "node (0: never). Default: 0.002",
                      shares),
};

/// Checks a request's choices and combinations before any input is read; its numbers' ranges are
/// the table's, refused where the values come in (the tool's options, Python's keywords).
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Spatiotemporal_request& request, Front front);

/// The segments of every frame and the evolving graph of their key frames.
struct Spatiotemporal_result {
  std::unique_ptr<const spatiotemporal::Spatiotemporal_segmentation> segmentation;  ///< what `frames` refers to
  spatiotemporal::Frame_segments frames;
  spatiotemporal::Evolving_graph graph;
};

/// The spatio-temporal segmentation of `animation` as `request` asks.
Spatiotemporal_result spatiotemporal_segments(const mesh::Surface_mesh_animation& animation,
                                              const Spatiotemporal_request& request, int threads);

/// An evolving graph as a report: {"frames", "segments", "key_frames": [{"first", "last", "nodes":
/// [{"id", "kind", "segment" (null for rigid), "triangles", "area"}], "edges": [[u, v], ...]}]}.
nlohmann::json evolving_graph_record(const spatiotemporal::Evolving_graph& graph);

}  // namespace deformseg::frontend
