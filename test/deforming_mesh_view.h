// A model of DeformingMesh that is not a Deforming_mesh, for the tests that check an algorithm
// takes any model: a view of a Deforming_mesh through its point maps.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>

#include <cstddef>

namespace deformseg::test {

template <class Graph>
struct Deforming_mesh_view {
  using Face_graph = Graph;
  const mesh::Deforming_mesh<Graph>* animation;
  const Face_graph& face_graph() const { return animation->face_graph(); }
  std::size_t num_frames() const { return animation->num_frames(); }
  auto frame_point_map(std::size_t t) const { return animation->frame_point_map(t); }
};

}  // namespace deformseg::test
