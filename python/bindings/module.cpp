// deformseg._deformseg: the compiled half of the Python module, over the library's default types
// (Surface_mesh_animation, float strains). The pure-Python half (python/deformseg/) re-exports these
// names and adds the evolving graph's classes, networkx conversions and `ged` on networkx graphs.
//
// One file per topic adds its part (bindings.h lists them); what they share is in common.h (long
// calls, JSON reports as Python values), arrays.h (NumPy arrays in and out), inputs.h (animations)
// and pickling.h. The functions that do what the tool's commands do are made from the front end's
// tables (frontend/, through parameters.h): the same names, defaults, checks, messages and
// dispatch as the tool's. Every call that can take long releases the GIL and can be interrupted by
// Ctrl-C; the arguments it reads stay referenced by Python objects held for the call.
#include "bindings.h"
#include "store.h"

#include "frontend/similarity.h"
#include "frontend/spatiotemporal.h"
#include "frontend/strain.h"
#include "frontend/temporal.h"

#include <span>
#include <utility>

namespace {

// The front end's choices by parameter, for the stub's test (python/tests/test_stub.py), which
// checks every Literal[...] of the stub against them.
pybind11::dict choices() {
  using namespace deformseg::frontend;
  const std::pair<const char*, std::span<const Choice>> tables[] = {
      {"measure", strain_measure_choices},
      {"normalize", strain_normalization_choices},
      {"reference", strain_reference_choices},
      {"method", temporal_method_choices},
      {"metric", frame_metric_choices},
      {"policy", policy_choices},
      {"alignment", alignment_choices},
      {"up", up_direction_choices},
      {"sides", side_direction_choices},
      {"segmentation_reference", segmentation_reference_choices},
      {"verify", deformseg::python::store_verifications}};
  pybind11::dict out;
  for (const auto& [parameter, table] : tables) {
    pybind11::list names;
    for (const Choice& choice : table) names.append(pybind11::str(choice.name.data(), choice.name.size()));
    out[parameter] = names;
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_deformseg, m) {
  m.doc() = "The compiled half of deformseg; import `deformseg`, which re-exports it.";
  using namespace deformseg::python;
  bind_errors(m);
  bind_animation(m);
  bind_store(m);
  bind_store_describe(m);
  bind_strain(m);
  bind_temporal(m);
  bind_spatiotemporal(m);
  bind_similarity(m);
  bind_find_motion(m);
  bind_evaluation(m);
  bind_ged(m);
  m.attr("_choices") = choices();
  m.attr("__version__") = DEFORMSEG_VERSION;
}
