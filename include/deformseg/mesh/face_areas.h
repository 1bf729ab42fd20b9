/// @file mesh/face_areas.h
/// @brief The area of every triangle of one frame of an animation: `face_areas`.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace deformseg::mesh {

/// @brief The area of each triangle of frame `t`, in face index order, in double precision.
/// @pre `t < animation.num_frames()`; otherwise throws `invalid_input`.
/// @return `animation.num_faces()` areas, each >= 0 (0 for a degenerate triangle).
/// @par Complexity O(F).
template <FaceGraph Graph, std::floating_point Coordinate>
std::vector<double> face_areas(const Deforming_mesh<Graph, Coordinate>& animation, std::size_t t) {
  const auto xyz = animation.frame_matrix(t);
  const auto triangles = animation.triangles();
  std::vector<double> areas(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Eigen::Vector3d a = xyz.col(Eigen::Index(triangles[f][0])).template cast<double>();
    const Eigen::Vector3d b = xyz.col(Eigen::Index(triangles[f][1])).template cast<double>();
    const Eigen::Vector3d c = xyz.col(Eigen::Index(triangles[f][2])).template cast<double>();
    areas[f] = 0.5 * (b - a).cross(c - a).norm();
  }
  return areas;
}

}  // namespace deformseg::mesh
