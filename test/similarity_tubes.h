// Tubes shared by the similarity tests: a bend, hold and unbend on a thin tube, other timings and
// another tube, cyclic bends, and animations cut or reordered from another's frames.
#pragma once

#include "test_support.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/mesh/synthetic.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <utility>
#include <vector>

namespace deformseg::test {

/// Bend 90 degrees, hold, unbend (39 frames).
inline const std::vector<mesh::Tube_phase> bend_hold_unbend{
    {5, {0.0}}, {10, {right_angle}}, {8, {}}, {10, {0.0}}, {5, {}}};
/// The same bend, quick, then a long hold.
inline const std::vector<mesh::Tube_phase> other_timing{{5, {0.0}}, {3, {right_angle}}, {22, {}}, {3, {0.0}}, {5, {}}};
/// A thicker, longer, coarser tube without caps.
inline const mesh::Tube_shape other_tube{.radius = 0.16, .length = 1.5, .sectors = 12, .rings = 30, .caps = false};

/// A tube of `shape`, placed, bending its `joints` on `schedule`.
inline mesh::Surface_mesh_animation tube(const std::vector<mesh::Tube_phase>& schedule,
                                         const mesh::Tube_shape& shape = {}, const mesh::Placement& placement = {},
                                         std::vector<mesh::Tube_joint> joints = {mesh::Tube_joint{}}) {
  mesh::Bending_tube spec;
  spec.shape = shape;
  spec.joints = std::move(joints);
  spec.schedule = schedule;
  spec.placement = placement;
  return mesh::make_bending_tube(spec).animation;
}

/// The frames of `a` in the order `frames` gives (a frame may repeat).
inline mesh::Surface_mesh_animation frames_of(const mesh::Surface_mesh_animation& a,
                                              const std::vector<std::size_t>& frames) {
  std::vector<double> positions;
  for (std::size_t t : frames) {
    const auto xyz = a.frame_positions(t);
    positions.insert(positions.end(), xyz.begin(), xyz.end());
  }
  return mesh::Surface_mesh_animation(a.face_graph(), std::move(positions));
}

/// One cycle (bend, unbend) of `period` frames, repeated: frame t is the cycle's frame
/// (t + shift) mod period.
inline mesh::Surface_mesh_animation cycles(std::size_t period, std::size_t frames, std::size_t shift) {
  const auto cycle = tube({{period / 2, {right_angle}}, {period - period / 2, {0.0}}});
  std::vector<std::size_t> order;
  for (std::size_t t = 0; t < frames; ++t) order.push_back((t + shift) % period);
  return frames_of(cycle, order);
}

/// Two rigid halves of a point set (`points` points, `frames` frames, `T x 3V` coordinates), the
/// upper one turning about the joint at mid-height by a right angle in all: a robot's limb, with
/// no strain anywhere.
inline std::vector<double> jointed_points(std::size_t frames, std::size_t points) {
  std::vector<double> positions;
  for (std::size_t t = 0; t < frames; ++t) {
    const Eigen::AngleAxisd bend(right_angle * double(t) / double(frames - 1), Eigen::Vector3d::UnitX());
    for (std::size_t v = 0; v < points; ++v) {
      Eigen::Vector3d p(0.1 * double(v % 2), 0.1 * double(v % 3), double(v) / double(points));
      if (p.z() > 0.5) p = bend * (p - Eigen::Vector3d(0, 0, 0.5)) + Eigen::Vector3d(0, 0, 0.5);
      positions.insert(positions.end(), {p.x(), p.y(), p.z()});
    }
  }
  return positions;
}

/// Checks that `policy` gives exactly 1 for a tube against itself, and 1 to rounding against a
/// moved, scaled copy rotated about `turn_axis`, aligned frame to frame; returns the tube and its
/// copy.
template <class Policy>
std::pair<mesh::Surface_mesh_animation, mesh::Surface_mesh_animation> check_moved_copy_is_one(
    const Policy& policy, const Eigen::Vector3d& turn_axis = Eigen::Vector3d(1, 2, 3)) {
  auto a = tube(bend_hold_unbend);
  const mesh::Placement moved{.scale = 2.5,
                        .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, turn_axis.normalized())),
                        .translation = Eigen::Vector3d(3, -1, 4)};
  auto b = tube(bend_hold_unbend, {}, moved);
  CHECK(similarity::motion_similarity(a, a, policy).value == 1.0);
  const similarity::Similarity copy = similarity::motion_similarity(a, b, policy);
  CHECK(copy.value == Approx(1.0).margin(1e-9));
  REQUIRE(copy.alignment.size() == a.num_frames());
  for (std::size_t t = 0; t < a.num_frames(); ++t) CHECK(copy.alignment[t] == std::pair(t, t));
  return {std::move(a), std::move(b)};
}

}  // namespace deformseg::test
