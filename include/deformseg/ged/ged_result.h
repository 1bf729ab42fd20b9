/// @file ged/ged_result.h
/// @brief What a graph edit distance policy returns: `Ged_result`. The `GedPolicy` concept is
/// in `ged/ged_policy.h`.
#pragma once

#include <vector>

namespace deformseg::ged {

/// @brief The result of a graph edit distance computation between graphs A and B.
///
/// `lower <= distance <= upper` always. When `exact` is true, `distance == lower == upper` is the
/// graph edit distance; otherwise `distance` is `upper`, the cost of `mapping` (or, for a pure
/// lower-bound policy, `lower`, with an empty mapping).
struct Ged_result {
  double distance = 0;       ///< the distance found (exact or the best upper bound)
  bool exact = false;        ///< whether `distance` is proven to be the graph edit distance
  double lower = 0;          ///< a proven lower bound on the graph edit distance
  double upper = 0;          ///< the cost of `mapping`, an upper bound
  std::vector<int> mapping;  ///< node i of A -> node of B, or -1 when i is deleted
};

}  // namespace deformseg::ged
