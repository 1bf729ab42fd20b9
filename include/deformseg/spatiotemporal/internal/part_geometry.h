// The geometry behind part_links: the parts of a mesh, a sparse grid of triangles, the distance
// from a point to a triangle, whether a segment crosses a triangle, and the rigid motion that fits
// a part's vertices best.
#pragma once

#include <Eigen/Core>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <unordered_map>
#include <vector>

namespace deformseg::spatiotemporal::internal {

// The part of each triangle: triangles joined by a shared vertex, transitively; parts numbered in
// order of their first triangle. Vertices of no triangle belong to no part.
inline std::vector<std::uint32_t> triangle_parts(std::span<const std::array<std::uint32_t, 3>> triangles,
                                                 std::size_t vertices) {
  std::vector<std::uint32_t> root(vertices);
  std::iota(root.begin(), root.end(), 0u);
  const auto find = [&](std::uint32_t v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  for (const auto& t : triangles)
    for (int k = 1; k < 3; ++k) {
      const std::uint32_t a = find(t[0]), b = find(t[std::size_t(k)]);
      root[std::max(a, b)] = std::min(a, b);
    }
  constexpr std::uint32_t unset = ~0u;
  std::vector<std::uint32_t> part_of_root(vertices, unset), parts(triangles.size());
  std::uint32_t next = 0;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    std::uint32_t& p = part_of_root[find(triangles[f][0])];
    if (p == unset) p = next++;
    parts[f] = p;
  }
  return parts;
}

// The squared distance from p to the triangle (a, b, c): the closest point by the triangle's
// Voronoi regions (vertex, edge, face), as in Ericson's Real-Time Collision Detection, 5.1.5.
inline double squared_distance_to_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).squaredNorm();
  const double sum = va + vb + vc;
  if (!(sum > 0)) return std::min({ap.squaredNorm(), bp.squaredNorm(), cp.squaredNorm()});  // degenerate
  return (p - (a + ab * (vb / sum) + ac * (vc / sum))).squaredNorm();
}

// Whether the segment [p, q] crosses the triangle (a, b, c), touching included (Möller–Trumbore
// on the segment's line, the parameter in [0, 1]). False for a segment in the triangle's plane.
inline bool segment_crosses_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d direction = q - p, ab = b - a, ac = c - a;
  const Eigen::Vector3d h = direction.cross(ac);
  const double det = ab.dot(h);
  const double scale = ab.norm() * ac.norm() * direction.norm();
  if (!(std::abs(det) > 1e-12 * scale)) return false;
  const Eigen::Vector3d s = p - a;
  const double u = s.dot(h) / det;
  if (u < 0 || u > 1) return false;
  const Eigen::Vector3d qv = s.cross(ab);
  const double v = direction.dot(qv) / det;
  if (v < 0 || u + v > 1) return false;
  const double t = ac.dot(qv) / det;
  return t >= 0 && t <= 1;
}

// Triangles binned into the cubic cells their boxes (grown by a margin against rounding) overlap;
// cells hashed, so that memory follows the surface, not the volume. A cell knows whether its
// triangles are all of one part, which no contact test needs to look into.
class Triangle_grid {
public:
  struct Cell {
    std::vector<std::uint32_t> triangles;
    std::uint32_t only_part = ~0u;  // the part of all its triangles, or ~0u when they are of several
  };

  Triangle_grid(const Eigen::Matrix3Xd& points, std::span<const std::array<std::uint32_t, 3>> triangles,
                const std::vector<std::uint32_t>& parts, const Eigen::Vector3d& origin, double cell, double margin)
      : origin_(origin), cell_(cell) {
    for (std::uint32_t f = 0; f < triangles.size(); ++f) {
      Eigen::Vector3d low = points.col(triangles[f][0]), high = low;
      for (int k = 1; k < 3; ++k) {
        low = low.cwiseMin(points.col(triangles[f][std::size_t(k)]));
        high = high.cwiseMax(points.col(triangles[f][std::size_t(k)]));
      }
      for_cells(low.array() - margin, high.array() + margin, [&](std::uint64_t key) {
        Cell& c = cells_[key];
        c.only_part = c.triangles.empty() || c.only_part == parts[f] ? parts[f] : mixed;
        c.triangles.push_back(f);
      });
    }
  }

  // The triangles of the cell of `key` that a triangle of `part` may touch: none when they are
  // all of that part.
  std::span<const std::uint32_t> others(std::uint64_t key, std::uint32_t part) const {
    const auto found = cells_.find(key);
    if (found == cells_.end() || found->second.only_part == part) return {};
    return found->second.triangles;
  }

  // Calls visit(key) for every cell the box [low, high] overlaps.
  template <class Visit>
  void for_cells(const Eigen::Array3d& low, const Eigen::Array3d& high, Visit&& visit) const {
    const std::array<std::int64_t, 3> a = index(low), b = index(high);
    for (std::int64_t x = a[0]; x <= b[0]; ++x)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t z = a[2]; z <= b[2]; ++z) visit(key({x, y, z}));
  }

  // Calls visit(key) for every cell the segment [p, q] passes through, in order (a 3D DDA, as in
  // Amanatides and Woo's traversal of voxels), so that a long edge costs its length in cells, not
  // the volume of its box. A segment that floating point turns off its last cell still ends there.
  template <class Visit>
  void for_cells_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& q, Visit&& visit) const {
    std::array<std::int64_t, 3> at = index(p);
    const std::array<std::int64_t, 3> end = index(q);
    const Eigen::Vector3d direction = q - p;
    std::array<std::int64_t, 3> step{};
    Eigen::Vector3d next_boundary, delta;  // in units of the segment's length
    std::int64_t steps = 0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = std::size_t(k);
      step[a] = direction(k) > 0 ? 1 : direction(k) < 0 ? -1 : 0;
      steps += std::abs(end[a] - at[a]);
      const double boundary = origin_(k) + cell_ * double(at[a] + (step[a] > 0 ? 1 : 0));
      next_boundary(k) = step[a] == 0 ? std::numeric_limits<double>::infinity() : (boundary - p(k)) / direction(k);
      delta(k) = step[a] == 0 ? std::numeric_limits<double>::infinity() : cell_ / std::abs(direction(k));
    }
    visit(key(at));
    for (std::int64_t s = 0; s < steps && at != end; ++s) {
      Eigen::Index axis = 0;
      next_boundary.minCoeff(&axis);
      at[std::size_t(axis)] = std::clamp<std::int64_t>(at[std::size_t(axis)] + step[std::size_t(axis)], 0, mask);
      next_boundary(axis) += delta(axis);
      visit(key(at));
    }
    if (at != end) visit(key(end));
  }

private:
  static constexpr std::uint32_t mixed = ~0u;

  std::array<std::int64_t, 3> index(const Eigen::Array3d& p) const {
    std::array<std::int64_t, 3> i{};
    for (int k = 0; k < 3; ++k)
      i[std::size_t(k)] = std::clamp<std::int64_t>(std::int64_t(std::floor((p(k) - origin_(k)) / cell_)), 0, mask);
    return i;
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& i) {
    return std::uint64_t(i[0]) << 42 | std::uint64_t(i[1]) << 21 | std::uint64_t(i[2]);
  }

  static constexpr std::int64_t mask = (std::int64_t(1) << 21) - 1;
  Eigen::Vector3d origin_;
  double cell_;
  std::unordered_map<std::uint64_t, Cell> cells_;
};

// A rigid motion x -> rotation x + translation.
struct Rigid_motion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return rotation * x + translation; }
};

// The rigid motion taking `from` closest to `to` in the least-squares sense, reflections excluded
// (Kabsch): the columns are corresponding points.
inline Rigid_motion best_rigid_motion(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to) {
  const Eigen::Vector3d from_centre = from.rowwise().mean(), to_centre = to.rowwise().mean();
  const Eigen::Matrix3d cross = (to.colwise() - to_centre) * (from.colwise() - from_centre).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cross, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d sign = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) sign(2, 2) = -1;
  Rigid_motion motion;
  motion.rotation = svd.matrixU() * sign * svd.matrixV().transpose();
  motion.translation = to_centre - motion.rotation * from_centre;
  return motion;
}

}  // namespace deformseg::spatiotemporal::internal
