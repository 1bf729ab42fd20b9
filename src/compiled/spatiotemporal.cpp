// deformseg::compiled, the spatio-temporal module: spatiotemporal_segmentation and evolving_graph
// of the default animation, and the segmentation of a float strain field. The headers declare
// these instantiations `extern template` (ends of spatiotemporal/spatiotemporal_segments.h and
// spatiotemporal/evolving_graph.h).
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>

namespace deformseg::spatiotemporal {
template Spatiotemporal_segmentation spatiotemporal_segmentation<float>(const strain::Strain_field<float>&,
                                                                       const Body_layout&,
                                                                       const Spatiotemporal_options&);
template Spatiotemporal_segmentation spatiotemporal_segmentation<mesh::Surface_mesh_animation>(
    const mesh::Surface_mesh_animation&, const Spatiotemporal_options&);
template Evolving_graph evolving_graph<mesh::Surface_mesh_animation>(const mesh::Surface_mesh_animation&,
                                                                    const Spatiotemporal_options&);
}  // namespace deformseg::spatiotemporal
