#include "strain.h"

#include "inputs.h"


namespace deformseg::frontend {

void check(const Strain_request& r, Front front) {
  check_choice("reference", r.reference, strain_reference_choices, front);
  check_choice("measure", r.measure, strain_measure_choices, front);
  check_choice("normalize", r.normalize, strain_normalization_choices, front);
  const auto name = [&](const char* parameter) { return spelled(parameter, front); };
  constexpr auto rest = strain::Strain_reference::rest_pose, previous = strain::Strain_reference::previous_pose;
  if (r.sigma && !entry_named(strain_normalizations, r.normalize).value)
    refuse(name("sigma") + " asks for " + spelled("normalize", name_of(strain_normalizations, true), front));
  const bool against_previous = entry_named(strain_references, r.reference).value == previous;
  if (against_previous && r.rest_frame != 0)
    refuse(name("rest_frame") + " asks for " + spelled("reference", name_of(strain_references, rest), front));
  if (!r.reference_mesh.empty() && (against_previous || r.rest_frame != 0))
    refuse(name("reference_mesh") + " takes the place of the rest frame: it excludes " +
           spelled("reference", name_of(strain_references, previous), front) + " and " + name("rest_frame"));
}

strain::Strain_options strain_options(const Strain_request& r, int threads) {
  return {.reference = entry_named(strain_references, r.reference).value,
          .rest_frame = r.rest_frame,
          .measure = entry_named(strain_measures, r.measure).value,
          .normalization = entry_named(strain_normalizations, r.normalize).value
                               ? strain::Strain_normalization_choice(strain::Gaussian_normalization{.sigma = r.sigma})
                               : strain::No_normalization{},
          .degenerate_tolerance = r.degenerate_tolerance,
          .threads = threads};
}

strain::Strain_field<float> strain_against(const mesh::Surface_mesh_animation& animation, const std::string& path,
                                           const strain::Strain_options& options) {
  if (path.empty()) return strain::compute_strain(animation, options);
  const mesh::Surface_mesh reference = read_reference_mesh(path);
  try {
    return strain::compute_strain(animation, reference, options);
  } catch (const invalid_input& error) {
    throw invalid_input(std::string(error.what()) + " (the reference mesh must have the connectivity of the "
                        "animation as read: its counts of vertices and triangles)", {.file = path});
  }
}

strain::Strain_field<float> strain_field(const mesh::Surface_mesh_animation& animation, const Strain_request& request,
                                         int threads) {
  return strain_against(animation, request.reference_mesh, strain_options(request, threads));
}

}  // namespace deformseg::frontend
