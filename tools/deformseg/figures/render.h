// Pictures of an animation's frames, for `strain --png`: an orthographic view of the mesh, each
// triangle flat in a colour of its own, shaded by how squarely it faces the viewer.
#pragma once

#include "figure.h"

#include <deformseg/mesh/default_mesh.h>

#include <Eigen/Core>

#include <span>

namespace deformseg::tool {

/// Where an animation is seen from: along the axis in which the box around all its frames is
/// thinnest, so that the motion shows broadside; up is +y, or +z when the view is along y.
struct View {
  Eigen::Vector3d right, up, toward_viewer;
  Eigen::Vector3d low, high;  ///< the box around every frame, which every picture frames
};

/// The view of `animation`. O(T V).
View view_of(const mesh::Surface_mesh_animation& animation);

/// Frame `t` seen from `view` in an image whose longer side is `size` pixels, triangle j painted
/// `colors[j]` (one colour a triangle) with a depth buffer. O(V + pixels covered).
Image render_frame(const mesh::Surface_mesh_animation& animation, std::size_t t, const View& view,
                   std::span<const color::Rgb> colors, int size);

}  // namespace deformseg::tool
