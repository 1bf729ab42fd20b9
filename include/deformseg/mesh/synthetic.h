/// @file mesh/synthetic.h
/// @brief Synthetic animations with known ground truth: a tube that bends at joints on a schedule.
///
/// The tube is skinned on a chain of bones along its axis with linear blend skinning. Outside the
/// blend zone of a joint a vertex follows one bone rigidly, so a triangle deforms if and only if
/// one of its vertices lies strictly inside a blend zone; that is the ground truth the tests of
/// strain and segmentation check against. The same schedule on tubes of other radius, length,
/// resolution, position, orientation and scale gives "the same motion on another shape".
#pragma once

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

namespace deformseg::mesh {

/// @brief The shape of a tube along the z axis, from z = 0 to z = `length`, before placement.
struct Tube_shape {
  double radius = 0.1;       ///< radius of the tube
  double length = 1.0;       ///< length along the axis
  std::size_t sectors = 16;  ///< vertices around the axis, at least 3
  std::size_t rings = 48;    ///< segments along the axis, at least 1 (rings + 1 vertex rings)
  bool caps = true;          ///< close both ends with a fan around a centre vertex
};

/// @brief A joint of the tube: where it bends, over how long a zone, towards which side.
struct Tube_joint {
  double position = 0.5;      ///< height of the joint as a fraction of the length, in (0, 1)
  double blend_width = 0.15;  ///< length of the blend zone centred on the joint, as a fraction of the length
  double direction = 0.0;     ///< side it bends towards, an angle around the axis (0: towards +x)
};

/// @brief How the joint angles move during a phase of a schedule.
enum class Easing {
  smooth,  ///< a smooth step: starting and stopping softly, fastest in the middle (the default)
  linear   ///< at constant speed, starting and stopping at once
};

/// @brief One phase of a schedule: during `frames` frames the joint angles move from their values
/// at the start of the phase to `angles`, as `easing` says.
struct Tube_phase {
  std::size_t frames = 1;          ///< frames the phase adds to the animation, at least 1
  std::vector<double> angles;      ///< target angle of each joint in radians; empty: hold the pose
  Easing easing = Easing::smooth;  ///< how the angles move. Default: `Easing::smooth`
};

/// @brief A similarity transform applied to every frame: scale, then rotate, then translate.
struct Placement {
  double scale = 1.0;                                           ///< uniform scale, > 0
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< rotation (normalised on use)
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();        ///< translation
};

/// @brief Everything that defines a bending tube animation.
struct Bending_tube {
  Tube_shape shape{};                          ///< the tube's shape
  std::vector<Tube_joint> joints{Tube_joint{}};  ///< joints from the bottom up (default: one, in the middle)
  std::vector<Tube_phase> schedule{};          ///< phases one after the other, from all angles 0
  Placement placement{};                       ///< where the whole animation stands
};

/// @brief A synthetic animation and its ground truth.
template <class Graph = Surface_mesh>
struct Synthetic_animation {
  Deforming_mesh<Graph> animation;  ///< the frames; frame 0 has every joint angle 0
  /// @brief Per triangle: the joint in whose blend zone it lies (it deforms when that joint
  /// bends), or -1 for a triangle that only ever moves rigidly.
  std::vector<int> face_joint;
  /// @brief Per frame, the angle of each joint in radians.
  std::vector<std::vector<double>> joint_angles;
  /// @brief Per phase, its first and last frame.
  std::vector<std::array<std::size_t, 2>> phase_frames;
};

namespace internal {

// Smooth step on [0, 1] with zero slope at both ends, so that motion and blending start softly.
inline double smooth_step(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

/// The most coordinates a tube's frames may hold: 2^29 (4 GiB of doubles), the glTF reader's bound.
inline constexpr double max_tube_coordinates = double(std::size_t(1) << 29);

// Refuses a tube whose frames would not fit in memory, before any is made.
inline void check_tube_size(const Bending_tube& spec) {
  const auto& s = spec.shape;
  double frames = 1;
  for (const auto& phase : spec.schedule) frames += double(phase.frames);
  const double vertices = (double(s.rings) + 1) * double(s.sectors) + 2;
  if (3 * vertices * frames > max_tube_coordinates)
    throw invalid_input("a tube of " + std::to_string(std::llround(vertices)) + " vertices over " +
                        std::to_string(std::llround(frames)) + " frames holds more than the 2^29 coordinates "
                        "deformseg makes: fewer sectors, rings or frames");
}

inline void check_bending_tube(const Bending_tube& spec) {
  const auto& s = spec.shape;
  if (!(s.radius > 0) || !(s.length > 0) || s.sectors < 3 || s.rings < 1)
    throw invalid_input("tube shape needs radius > 0, length > 0, sectors >= 3 and rings >= 1");
  check_tube_size(spec);
  if (!(spec.placement.scale > 0)) throw invalid_input("placement scale must be > 0");
  double previous_top = 0.0;
  for (std::size_t j = 0; j < spec.joints.size(); ++j) {
    const auto& joint = spec.joints[j];
    const double bottom = joint.position - joint.blend_width / 2;
    if (!(joint.blend_width > 0) || bottom < previous_top || joint.position + joint.blend_width / 2 > 1)
      throw invalid_input("joint " + std::to_string(j) +
                          ": blend zones must have a width > 0, lie inside the tube and not "
                          "overlap, from the bottom up");
    previous_top = joint.position + joint.blend_width / 2;
  }
  for (std::size_t p = 0; p < spec.schedule.size(); ++p) {
    const auto& phase = spec.schedule[p];
    if (phase.frames == 0 || !(phase.angles.empty() || phase.angles.size() == spec.joints.size()))
      throw invalid_input("phase " + std::to_string(p) + ": needs at least 1 frame and either no "
                          "angle (hold) or one angle per joint (" +
                          std::to_string(spec.joints.size()) + ")");
  }
}

// The tube's rest vertices (rings from the bottom up, then the cap centres) and triangles,
// oriented outwards.
inline void tube_rest_mesh(const Tube_shape& s, std::vector<Eigen::Vector3d>& points,
                           std::vector<std::array<std::size_t, 3>>& triangles) {
  const auto at = [&](std::size_t ring, std::size_t sector) { return ring * s.sectors + sector % s.sectors; };
  for (std::size_t i = 0; i <= s.rings; ++i)
    for (std::size_t k = 0; k < s.sectors; ++k) {
      const double a = 2 * std::numbers::pi * double(k) / double(s.sectors);
      points.emplace_back(s.radius * std::cos(a), s.radius * std::sin(a),
                          s.length * double(i) / double(s.rings));
    }
  for (std::size_t i = 0; i < s.rings; ++i)
    for (std::size_t k = 0; k < s.sectors; ++k) {
      triangles.push_back({at(i, k), at(i, k + 1), at(i + 1, k + 1)});
      triangles.push_back({at(i, k), at(i + 1, k + 1), at(i + 1, k)});
    }
  if (!s.caps) return;
  const std::size_t bottom = points.size(), top = bottom + 1;
  points.emplace_back(0, 0, 0);
  points.emplace_back(0, 0, s.length);
  for (std::size_t k = 0; k < s.sectors; ++k) {
    triangles.push_back({bottom, at(0, k + 1), at(0, k)});
    triangles.push_back({top, at(s.rings, k), at(s.rings, k + 1)});
  }
}

// The joint angles of every frame: frame 0 all zero, then each phase's frames in turn.
inline std::vector<std::vector<double>> schedule_angles(const Bending_tube& spec,
                                                        std::vector<std::array<std::size_t, 2>>& phase_frames) {
  std::vector<std::vector<double>> angles{std::vector<double>(spec.joints.size(), 0.0)};
  for (const auto& phase : spec.schedule) {
    const std::vector<double> from = angles.back();
    const std::vector<double>& to = phase.angles.empty() ? from : phase.angles;
    phase_frames.push_back({angles.size(), angles.size() + phase.frames - 1});
    for (std::size_t f = 1; f <= phase.frames; ++f) {
      const double progress = double(f) / double(phase.frames);
      const double u = phase.easing == Easing::smooth ? smooth_step(progress) : progress;
      std::vector<double> pose(from.size());
      for (std::size_t j = 0; j < pose.size(); ++j) pose[j] = from[j] + u * (to[j] - from[j]);
      angles.push_back(std::move(pose));
    }
  }
  return angles;
}

// Where joint j's blend zone puts a vertex at height z: its weight on the bone above the joint.
// A ring lying on the zone's edge must follow one bone exactly, not get a weight of 1e-16 from
// rounding, so weights this close to 0 or 1 are snapped.
inline double blend_weight(const Tube_joint& joint, double length, double z) {
  constexpr double snap = 1e-9;
  const double bottom = (joint.position - joint.blend_width / 2) * length;
  const double w = smooth_step((z - bottom) / (joint.blend_width * length));
  return w < snap ? 0.0 : w > 1 - snap ? 1.0 : w;
}

// Whether joint j deforms a triangle when it bends: unless its three vertices follow the same
// bone (all weights 0, or all 1), the blended transform is not a rigid motion of the triangle.
inline bool bends_with(const Bending_tube& spec, std::size_t j, const std::vector<Eigen::Vector3d>& rest,
                       const std::array<std::size_t, 3>& triangle) {
  std::array<double, 3> w;
  for (int k = 0; k < 3; ++k) w[k] = blend_weight(spec.joints[j], spec.shape.length, rest[triangle[k]].z());
  const bool all_below = w[0] == 0.0 && w[1] == 0.0 && w[2] == 0.0;
  const bool all_above = w[0] == 1.0 && w[1] == 1.0 && w[2] == 1.0;
  return !all_below && !all_above;
}

// Linear blend skinning of one rest point on the bone chain. Bones are separated by the joints;
// joint j turns everything above it about the point (0, 0, z_j). A point between joints j-1 and j
// blends the transform of the bone below joint j with the one above it.
inline Eigen::Vector3d skin(const Bending_tube& spec, const std::vector<double>& angles,
                            const Eigen::Vector3d& rest) {
  Eigen::Vector3d p = rest;
  // Apply the joints from the top down: a joint's rotation carries everything above it,
  // including the already-bent part, so the chain composes as parent after child.
  for (std::size_t j = spec.joints.size(); j-- > 0;) {
    const auto& joint = spec.joints[j];
    const double w = blend_weight(joint, spec.shape.length, rest.z());
    if (w == 0.0) continue;
    const Eigen::Vector3d pivot(0, 0, joint.position * spec.shape.length);
    const Eigen::Vector3d axis(-std::sin(joint.direction), std::cos(joint.direction), 0);
    const Eigen::Vector3d turned = pivot + Eigen::AngleAxisd(angles[j], axis) * (p - pivot);
    p = (1 - w) * p + w * turned;
  }
  return p;
}

}  // namespace internal

/// @brief A tube bending at its joints on a schedule, by linear blend skinning.
///
/// Frame 0 has every joint angle 0 (a straight tube); each phase of `spec.schedule` then adds its
/// frames, the angles moving from their value at the start of the phase to its targets with a
/// smooth step or at constant speed, as the phase's `easing` says, so the last frame of a phase
/// reaches them. Placement is applied to every frame.
///
/// Example, a tube bending once by 90 degrees in the middle: rest 10 frames, bend 10, hold 10,
/// unbend 10:
/// @code
/// Bending_tube spec;
/// const double right = std::numbers::pi / 2;
/// spec.schedule = {{10, {0.0}}, {10, {right}}, {10, {}}, {10, {0.0}}};
/// auto tube = make_bending_tube(spec);  // 41 frames
/// @endcode
///
/// @tparam Graph the connectivity type, a `FaceGraph` (default `Surface_mesh`).
/// @pre radius, length and scale > 0; sectors >= 3, rings >= 1; joint blend zones inside (0, 1),
/// not overlapping, from the bottom up; every phase has at least one frame and either no angle
/// or one per joint; the frames hold at most 2^29 coordinates (3 V T). Otherwise throws
/// `invalid_input`, before any frame is made.
/// @return the animation, its per-triangle ground truth and its frame schedule.
/// @par Complexity O(T V J) for T frames, V vertices, J joints.
template <FaceGraph Graph = Surface_mesh>
Synthetic_animation<Graph> make_bending_tube(const Bending_tube& spec) {
  internal::check_bending_tube(spec);
  std::vector<Eigen::Vector3d> rest;
  std::vector<std::array<std::size_t, 3>> triangles;
  internal::tube_rest_mesh(spec.shape, rest, triangles);

  const Eigen::Quaterniond rotation = spec.placement.rotation.normalized();
  const auto place = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return rotation * (spec.placement.scale * p) + spec.placement.translation;
  };

  std::vector<std::array<std::size_t, 2>> phase_frames;
  auto angles = internal::schedule_angles(spec, phase_frames);
  Coordinate_buffer<double> positions;
  positions.reserve(angles.size() * rest.size() * 3);
  for (const auto& pose : angles)
    for (const auto& r : rest) {
      const Eigen::Vector3d p = place(internal::skin(spec, pose, r));
      positions.insert(positions.end(), {p.x(), p.y(), p.z()});
    }

  std::vector<std::array<double, 3>> first_frame(rest.size());
  for (std::size_t i = 0; i < rest.size(); ++i)
    for (int k = 0; k < 3; ++k) first_frame[i][k] = positions[3 * i + k];

  Synthetic_animation<Graph> result{
      Deforming_mesh<Graph>(make_face_graph<Graph>(first_frame, triangles), std::move(positions)),
      std::vector<int>(triangles.size(), -1), std::move(angles), std::move(phase_frames)};
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (std::size_t j = 0; j < spec.joints.size(); ++j)
      if (internal::bends_with(spec, j, rest, triangles[f])) result.face_joint[f] = int(j);
  return result;
}

}  // namespace deformseg::mesh

#if DEFORMSEG_COMPILED
// deformseg::compiled holds this instantiation (src/compiled/mesh.cpp): a program that links it
// compiles against its declaration. Any other connectivity instantiates where it is used.
namespace deformseg::mesh {
extern template Synthetic_animation<Surface_mesh> make_bending_tube<Surface_mesh>(const Bending_tube&);
}  // namespace deformseg::mesh
#endif
