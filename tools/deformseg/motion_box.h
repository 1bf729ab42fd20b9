// The box around every frame of an animation, which info reports and the pictures and the viewer
// page frame.
#pragma once

#include <deformseg/mesh/default_mesh.h>

#include <Eigen/Core>

#include <limits>

namespace deformseg::tool {

/// The smallest and largest x, y, z over all vertices of all frames (empty: +inf and -inf).
struct Motion_box {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
};

/// The box of `animation`. O(T V).
inline Motion_box motion_box(const mesh::Surface_mesh_animation& animation) {
  Motion_box box;
  for (std::size_t t = 0; t < animation.num_frames(); ++t) {
    box.low = box.low.cwiseMin(animation.frame_matrix(t).rowwise().minCoeff());
    box.high = box.high.cwiseMax(animation.frame_matrix(t).rowwise().maxCoeff());
  }
  return box;
}

}  // namespace deformseg::tool
