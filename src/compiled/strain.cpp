// deformseg::compiled, the strain module: compute_strain on the default animation with the options'
// built-in measures and normalisations, in float and double. The headers declare these
// instantiations `extern template` (end of strain/strain.h) for the programs that link the library.
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/strain/strain.h>

namespace deformseg::strain {
template Strain_field<float> compute_strain<float, mesh::Surface_mesh_animation>(const mesh::Surface_mesh_animation&,
                                                                                 const Strain_options&);
template Strain_field<double> compute_strain<double, mesh::Surface_mesh_animation>(
    const mesh::Surface_mesh_animation&, const Strain_options&);
}  // namespace deformseg::strain
