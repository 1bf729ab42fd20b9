/// @file similarity/segment_costs.h
/// @brief `Segment_costs`, the graph edit costs of segment graphs (`Segment_graph`) that see the
/// nodes' kinds and area shares.
#pragma once

#include <deformseg/spatiotemporal/frame_segments.h>

#include <cmath>

namespace deformseg::similarity {

/// @brief Edit costs of segment graphs (a `ged::GedCostModel` for `Segment_node` labels):
/// inserting or deleting a node costs 1 plus `area_weight` times its area share; substituting a
/// node costs 1 when the kinds differ, plus `area_weight` times the difference of the area
/// shares; inserting or deleting an edge costs 1, keeping one 0.
///
/// With `area_weight = 0` these are the unit costs of @ref method_similarity on the node kinds
/// alone, which see only the shape of the graphs: a thick leg closes a deformed band into a ring
/// and a thin one does not, so the shape depends on the mesh. The area shares tell a large
/// deformed region from a small one and are the same for the same motion on another shape.
struct Segment_costs {
  /// @brief How much a difference of area share (in [0, 1]) costs, next to the 1 of a kind.
  /// Default: 1.
  double area_weight = 1.0;

  /// @brief `[kinds differ] + area_weight |a.area - b.area|`.
  double node_substitution(const spatiotemporal::Segment_node& a, const spatiotemporal::Segment_node& b) const {
    return (a.kind != b.kind ? 1.0 : 0.0) + area_weight * std::abs(a.area - b.area);
  }
  /// @brief `1 + area_weight a.area`.
  double node_insertion(const spatiotemporal::Segment_node& a) const { return 1.0 + area_weight * a.area; }
  /// @brief `1 + area_weight a.area`.
  double node_deletion(const spatiotemporal::Segment_node& a) const { return 1.0 + area_weight * a.area; }
  /// @brief 1.
  double edge_insertion() const { return 1.0; }
  /// @brief 1.
  double edge_deletion() const { return 1.0; }
  /// @brief 0.
  double edge_substitution() const { return 0.0; }
};

}  // namespace deformseg::similarity
