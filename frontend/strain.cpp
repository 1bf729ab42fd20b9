#include "strain.h"

#include "inputs.h"


namespace deformseg::frontend {

void check(const Strain_request& r, Front front) {
  check_choice("reference", r.reference, strain_references, front);
  check_choice("measure", r.measure, strain_measures, front);
  check_choice("normalize", r.normalize, strain_normalizations, front);
  const auto name = [&](const char* parameter) { return spelled(parameter, front); };
  if (r.sigma && r.normalize != "gaussian")
    refuse(name("sigma") + " asks for " + spelled("normalize", "gaussian", front));
  if (r.reference == "previous" && r.rest_frame != 0)
    refuse(name("rest_frame") + " asks for " + spelled("reference", "rest", front));
  if (!r.reference_mesh.empty() && (r.reference == "previous" || r.rest_frame != 0))
    refuse(name("reference_mesh") + " takes the place of the rest frame: it excludes " +
           spelled("reference", "previous", front) + " and " + name("rest_frame"));
}

namespace {

strain::Strain_measure_choice measure_of(const std::string& name) {
  if (name == "green-lagrange") return strain::Green_lagrange_strain{};
  if (name == "frobenius") return strain::Frobenius_strain{};
  if (name == "area-ratio") return strain::Area_ratio_strain{};
  return strain::Max_principal_strain{};
}

}  // namespace

strain::Strain_options strain_options(const Strain_request& r, int threads) {
  return {.reference = r.reference == "previous" ? strain::Strain_reference::previous_pose
                                                 : strain::Strain_reference::rest_pose,
          .rest_frame = r.rest_frame,
          .measure = measure_of(r.measure),
          .normalization = r.normalize == "none"
                               ? strain::Strain_normalization_choice(strain::No_normalization{})
                               : strain::Gaussian_normalization{.sigma = r.sigma},
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
