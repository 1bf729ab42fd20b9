// deformseg::compiled, the temporal module: temporal_segmentation with its default policy
// (Optimal_partition), of the default animation and of its float strain field. The headers declare
// these instantiations `extern template` (end of temporal/temporal_segmentation.h).
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/temporal/temporal_segmentation.h>

namespace deformseg::temporal {
template Temporal_segmentation segment_frames<Optimal_partition>(const Segment_cost&, const Optimal_partition&);
template Temporal_segmentation temporal_segmentation<float, Optimal_partition>(const strain::Strain_field<float>&,
                                                                               const Optimal_partition&,
                                                                               const strain::Frame_distance_options&);
template Temporal_segmentation temporal_segmentation<mesh::Surface_mesh_animation, Optimal_partition>(
    const mesh::Surface_mesh_animation&, const Optimal_partition&, const strain::Frame_distance_options&);
}  // namespace deformseg::temporal
