/// @file signatures/procrustes_distances.h
/// @brief The frame x frame self-dissimilarity matrix of one animation: the weighted Procrustes
/// distance between every two frames (each frame centred, the animation scaled to unit size,
/// frames rotated onto each other), and the per-vertex weights it uses.
#pragma once

#include <deformseg/exceptions.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace deformseg::signatures {

/// Each vertex's share of the surface at frame `positions[0 .. 3V)`: a third of the area of every
/// triangle it belongs to, normalised to sum 1 (uniform when the surface has no area, so that a
/// point cloud still works). Vertices in no triangle weigh 0.
template <class Triangle>
std::vector<double> vertex_area_weights(std::span<const double> frame, std::span<const Triangle> triangles,
                                        std::size_t num_vertices) {
  std::vector<double> weights(num_vertices, 0.0);
  double total = 0;
  for (const auto& tri : triangles) {
    const auto point = [&](std::size_t k) { return Eigen::Vector3d(frame.data() + 3 * std::size_t(tri[k])); };
    const double area = 0.5 * (point(1) - point(0)).cross(point(2) - point(0)).norm();
    if (!std::isfinite(area)) continue;
    for (std::size_t k = 0; k < 3; ++k) weights[std::size_t(tri[k])] += area / 3;
    total += area;
  }
  if (!(total > 0)) std::fill(weights.begin(), weights.end(), 1.0);
  double sum = 0;
  for (double w : weights) sum += w;
  for (double& w : weights) w /= sum;
  return weights;
}

/// Frames as the rows of a `3T x V` matrix: frame t's x, y, z in rows 3t..3t+2, each centred on
/// its weighted centroid and multiplied by sqrt(weight); all divided by the animation's weighted
/// RMS radius (mean over frames), so that the result does not depend on position or scale.
/// @par Example
/// @include procrustes_distance.cpp
inline Eigen::MatrixXd centred_weighted_frames(std::span<const double> positions, std::span<const double> weights,
                                               std::size_t frames) {
  const std::size_t vertices = weights.size();
  Eigen::MatrixXd rows(3 * Eigen::Index(frames), Eigen::Index(vertices));
  const Eigen::Map<const Eigen::VectorXd> w(weights.data(), Eigen::Index(vertices));
  const Eigen::VectorXd root_w = w.cwiseSqrt();
  for (std::size_t t = 0; t < frames; ++t) {
    const Eigen::Map<const Eigen::MatrixXd> xyz(positions.data() + 3 * vertices * t, 3, Eigen::Index(vertices));
    const Eigen::Vector3d centroid = xyz * w;
    rows.middleRows(3 * Eigen::Index(t), 3) = (xyz.colwise() - centroid) * root_w.asDiagonal();
  }
  const double mean_square = rows.squaredNorm() / double(std::max<std::size_t>(frames, 1));
  if (mean_square > 0) rows /= std::sqrt(mean_square);
  return rows;
}

/// The smallest |R X - Y| over rotations R, from the cross-covariance `C = X Y^T` and the squared
/// sizes: |X|^2 + |Y|^2 - 2 (s1 + s2 +- s3), the sign of the smallest singular value being that of
/// det(C), so that reflections are not allowed (Kabsch).
/// @par Example
/// @include procrustes_distance.cpp
inline double procrustes_distance(const Eigen::Matrix3d& cross, double square_x, double square_y) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cross);
  const Eigen::Vector3d s = svd.singularValues();
  const double trace = s(0) + s(1) + (cross.determinant() < 0 ? -s(2) : s(2));
  return std::sqrt(std::max(0.0, square_x + square_y - 2 * trace));
}

/// The `T x T` matrix of weighted Procrustes distances between the frames of one animation,
/// `positions` being `T x 3V` coordinates: symmetric, 0 on the diagonal, in units of the
/// animation's RMS radius (so in [0, 2] for frames of that size). Invariant to translating,
/// rotating and scaling the animation, and to rotating any single frame.
/// @par Complexity O(T^2 V) for the cross-covariances (one `3T x V` by `V x 3T` product, the
/// upper half), O(T^2) 3 x 3 SVDs; O(T^2 + T V) memory.
inline Eigen::MatrixXd procrustes_distances(std::span<const double> positions, std::span<const double> weights) {
  const std::size_t vertices = weights.size();
  if (vertices == 0 || positions.size() % (3 * vertices) != 0)
    throw invalid_input("procrustes_distances: positions are not T x 3V for the weights' V");
  const std::size_t frames = positions.size() / (3 * vertices);
  const Eigen::MatrixXd rows = centred_weighted_frames(positions, weights, frames);
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(rows.rows(), rows.rows());
  gram.selfadjointView<Eigen::Upper>().rankUpdate(rows);
  Eigen::MatrixXd distances = Eigen::MatrixXd::Zero(Eigen::Index(frames), Eigen::Index(frames));
  for (Eigen::Index i = 0; i < Eigen::Index(frames); ++i) {
    const double square_i = gram.block<3, 3>(3 * i, 3 * i).trace();
    for (Eigen::Index j = i + 1; j < Eigen::Index(frames); ++j) {
      const double square_j = gram.block<3, 3>(3 * j, 3 * j).trace();
      distances(i, j) = distances(j, i) = procrustes_distance(gram.block<3, 3>(3 * i, 3 * j), square_i, square_j);
    }
  }
  return distances;
}

}  // namespace deformseg::signatures
