// deformseg._deformseg: the compiled half of the Python module, over the library's default types
// (Surface_mesh_animation, float strains). The pure-Python half (python/deformseg/) re-exports these
// names and adds the evolving graph's classes, networkx conversions and `ged` on networkx graphs.
//
// One file per topic adds its part (bindings.h lists them); what they share is in common.h (long
// calls), arrays.h (NumPy arrays in and out), inputs.h (animations and strain references) and
// pickling.h. Every call that can take long releases the GIL and can be interrupted by Ctrl-C; the
// arguments it reads stay referenced by Python objects held for the call. Option names, defaults
// and checks are those of the C++ options and of the `deformseg` tool, whose names the string
// options take.
#include "bindings.h"

PYBIND11_MODULE(_deformseg, m) {
  m.doc() = "The compiled half of deformseg; import `deformseg`, which re-exports it.";
  using namespace deformseg::python;
  bind_errors(m);
  bind_animation(m);
  bind_strain(m);
  bind_temporal(m);
  bind_spatiotemporal(m);
  bind_similarity(m);
  bind_find_motion(m);
  bind_evaluation(m);
  bind_ged(m);
  m.attr("__version__") = DEFORMSEG_VERSION;
}
