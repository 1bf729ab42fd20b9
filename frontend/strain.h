// The strain as a command and a Python function ask for it: measures, normalisations and
// references by name, against a frame or a reference mesh read from a file.
#pragma once

#include "parameters.h"
#include "registry.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/strain/strain.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <tuple>

namespace deformseg::frontend {

/// A strain as the user asks for it.
struct Strain_request {
  std::string reference{strain_references[0].name};
  std::size_t rest_frame = 0;
  std::string reference_mesh{};  ///< a mesh file in the place of the rest frame; empty: none
  std::string measure{strain_measures[0].name};
  std::string normalize{strain_normalizations[0].name};
  std::optional<double> sigma{};
  double degenerate_tolerance = 1e-12;
};

/// The reference-mesh parameter, which the strain, the temporal and the spatio-temporal
/// segmentation share.
template <class Request>
constexpr Parameter<Request, std::string> reference_mesh_parameter() {
  return {"reference_mesh", &Request::reference_mesh,
          "A mesh file (.obj, .off, .ply) with the animation's connectivity in another pose: a rest pose kept "
          "apart from the frames, in the place of the rest frame",
          Parameter_kind::file};
}

/// The strain request's table.
inline constexpr std::tuple strain_parameters{
    choice_parameter("reference", &Strain_request::reference, "What the strain is measured against",
                     strain_reference_choices),
    numeric_parameter("rest_frame", &Strain_request::rest_frame, "The rest frame, with reference rest. Default: 0",
                      counts()),
    reference_mesh_parameter<Strain_request>(),
    choice_parameter("measure", &Strain_request::measure, "The strain measure", strain_measure_choices),
    choice_parameter("normalize", &Strain_request::normalize, "The normalisation", strain_normalization_choices),
    numeric_parameter("sigma", &Strain_request::sigma,
                      "The Gaussian normalisation's sigma. Default: the 95th percentile", positive),
    numeric_parameter("degenerate_tolerance", &Strain_request::degenerate_tolerance,
                      "Reference triangles thinner than this have strain 0. Default: 1e-12", non_negative),
};

/// Checks a request's choices and combinations before any input is read; its numbers' ranges are
/// the table's, refused where the values come in (the tool's options, Python's keywords).
/// @throws invalid_input naming the parameter as `front` spells it.
void check(const Strain_request& request, Front front);

/// The library's options of a checked request.
strain::Strain_options strain_options(const Strain_request& request, int threads);

/// The strain field of `animation` as `request` asks, against its reference mesh when it names
/// one (read from its file; an error of connectivity then names that file).
strain::Strain_field<float> strain_field(const mesh::Surface_mesh_animation& animation,
                                         const Strain_request& request, int threads);

/// The strain field of `animation` with `options`, against `reference_mesh` (read from the file
/// `path`) when `path` is not empty; an error of connectivity then names that file.
strain::Strain_field<float> strain_against(const mesh::Surface_mesh_animation& animation, const std::string& path,
                                           const strain::Strain_options& options);

}  // namespace deformseg::frontend
