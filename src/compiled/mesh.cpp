// deformseg::compiled, the mesh module: the synthetic bending tube on the default connectivity. The
// header declares this instantiation `extern template` (end of mesh/synthetic.h).
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/synthetic.h>

namespace deformseg::mesh {
template Synthetic_animation<Surface_mesh> make_bending_tube<Surface_mesh>(const Bending_tube&);
}  // namespace deformseg::mesh
