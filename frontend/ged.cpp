#include "ged.h"

namespace deformseg::frontend {

void check(const Ged_request& r, Front front) { check_choice("method", r.method, ged_method_choices, front); }

Any_ged exact_ged(const Ged_request& r) {
  return ged::Exact_ged{.max_expanded = r.max_expanded, .max_seconds = r.max_seconds};
}

Any_ged bipartite_ged(const Ged_request&) { return ged::Bipartite_ged{}; }

Any_ged lower_bound_ged(const Ged_request&) { return ged::Assignment_lower_bound{}; }

Any_ged make_ged(const Ged_request& r) { return entry_named(ged_methods, r.method).make(r); }

}  // namespace deformseg::frontend
