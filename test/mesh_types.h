// The mesh types of the generic tests: each algorithm's core test runs as a template test case
// over `Mesh_types`, and its result on each type must be the default model's
// (Deforming_mesh<Surface_mesh>) to the last bit.
//
// A type of the list holds an animation made from a default-model animation and gives it, through
// `model()`, as one model of DeformingMesh: the default model on another FaceGraph (Polyhedron_3,
// OpenMesh's TriMesh), or a user's own model (Deforming_mesh_view, per-frame point maps) on each of
// the three FaceGraphs. OpenMesh is in the list when the build found it (DEFORMSEG_TEST_OPENMESH).
#pragma once

#include "deforming_mesh_view.h"

#include <deformseg/exceptions.h>
#include <deformseg/mesh/default_mesh.h>

#include <CGAL/Polyhedron_3.h>
#if DEFORMSEG_TEST_OPENMESH
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#endif

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>
#include <vector>

namespace deformseg::test {

/// CGAL's halfedge data structure, the second CGAL FaceGraph.
using Polyhedron = CGAL::Polyhedron_3<mesh::Kernel>;

#if DEFORMSEG_TEST_OPENMESH
/// OpenMesh's traits with double points: its default traits hold floats, which would round every
/// position on the way in.
struct Open_mesh_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
/// OpenMesh's triangle mesh, a FaceGraph through CGAL's graph traits for OpenMesh.
using Open_mesh = OpenMesh::TriMesh_ArrayKernelT<Open_mesh_traits>;
#endif

/// The animation `reference` on the connectivity `Graph`: the same points and triangles in the same
/// order, the same positions and frame rate. Throws when `Graph` gives its faces' corners in
/// another order than `reference`, so that a test never compares unlike meshes.
template <class Graph>
mesh::Deforming_mesh<Graph> on_graph(const mesh::Surface_mesh_animation& reference) {
  const auto first = reference.frame_positions(0);
  std::vector<std::array<double, 3>> points(reference.num_vertices());
  for (std::size_t v = 0; v < points.size(); ++v) points[v] = {first[3 * v], first[3 * v + 1], first[3 * v + 2]};
  const auto all = reference.all_positions();
  mesh::Deforming_mesh<Graph> copy(mesh::make_face_graph<Graph>(points, reference.triangles()),
                                   std::vector<double>(all.begin(), all.end()));
  copy.set_frames_per_second(reference.frames_per_second());
  const auto a = reference.triangles(), b = copy.triangles();
  if (!std::equal(a.begin(), a.end(), b.begin(), b.end()))
    throw invalid_input("on_graph: the graph gives the triangles' corners in another order");
  return copy;
}

/// The default model on `Graph`.
template <class Graph>
struct Default_model_on {
  using Model = mesh::Deforming_mesh<Graph>;  ///< what model() gives
  explicit Default_model_on(const mesh::Surface_mesh_animation& reference) : animation(on_graph<Graph>(reference)) {}
  const Model& model() const { return animation; }
  Model animation;
};

/// A user's own model on `Graph`: per-frame point maps, not a Deforming_mesh, so that every
/// algorithm takes its generic path.
template <class Graph>
struct Own_model_on {
  using Model = Deforming_mesh_view<Graph>;  ///< what model() gives
  explicit Own_model_on(const mesh::Surface_mesh_animation& reference) : animation(on_graph<Graph>(reference)) {}
  Own_model_on(const Own_model_on&) = delete;  // the view points into `animation`
  Own_model_on& operator=(const Own_model_on&) = delete;
  Model model() const { return {&animation}; }
  mesh::Deforming_mesh<Graph> animation;
};

/// The types of the generic template tests (TEMPLATE_LIST_TEST_CASE).
using Mesh_types = std::tuple<Default_model_on<Polyhedron>, Own_model_on<mesh::Surface_mesh>, Own_model_on<Polyhedron>
#if DEFORMSEG_TEST_OPENMESH
                              ,
                              Default_model_on<Open_mesh>, Own_model_on<Open_mesh>
#endif
                              >;

}  // namespace deformseg::test
