/// @file mesh.h
/// @brief Every public header of module `mesh`, the mesh model: `Deforming_mesh` and the `DeformingMesh`
/// concept, the default Surface_mesh types, face areas and the synthetic bending tubes.
#pragma once

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/mesh/synthetic.h>
