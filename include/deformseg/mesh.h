/// @file mesh.h
/// @brief Every public header of module `mesh`, the mesh model: `Deforming_mesh`, the `FaceGraph` and
/// `DeformingMesh` concepts, the default Surface_mesh types, face areas and the synthetic bending tubes.
#pragma once

#include <deformseg/mesh/concepts.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/mesh/make_face_graph.h>
#include <deformseg/mesh/synthetic.h>
