/// @file mesh/default_mesh.h
/// @brief The mesh types deformseg's readers and generators produce unless told otherwise.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace deformseg::mesh {

/// @brief The default kernel: CGAL's exact predicates, inexact constructions.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
/// @brief The default connectivity: a `CGAL::Surface_mesh` of `Kernel` points.
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
/// @brief The default animation: `Surface_mesh` connectivity, `double` coordinates.
using Surface_mesh_animation = Deforming_mesh<Surface_mesh>;

}  // namespace deformseg::mesh
