// Frames compared as sets of points, for two readings of one clip that split and order their
// vertices differently (an FBX file and its glTF original, deformseg's reading and the FBX SDK's).
#pragma once

#include <deformseg/io/gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace deformseg::test {

using Point = std::array<double, 3>;

/// The distinct positions of frame `t`, each scaled by `scale`, sorted.
inline std::vector<Point> distinct_positions(const io::Sampled_gltf& sampled, std::size_t t,
                                             const Point& scale = {1, 1, 1}) {
  std::vector<Point> points;
  for (std::size_t v = 0; v < sampled.num_vertices; ++v) {
    const double* p = sampled.positions.data() + 3 * (t * sampled.num_vertices + v);
    points.push_back({scale[0] * p[0], scale[1] * p[1], scale[2] * p[2]});
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

/// The largest distance from a point of `from` to the nearest of `to`, both sorted (by x first:
/// the search stops beyond the nearest).
inline double farthest_from(const std::vector<Point>& from, const std::vector<Point>& to) {
  const auto distance = [](const Point& p, const Point& q) { return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]); };
  double gap = 0;
  for (const Point& p : from) {
    double nearest = INFINITY;
    const auto at = std::lower_bound(to.begin(), to.end(), p);
    for (auto q = at; q != to.end() && (*q)[0] - p[0] < nearest; ++q) nearest = std::min(nearest, distance(p, *q));
    for (auto q = at; q != to.begin() && p[0] - (*std::prev(q))[0] < nearest;)
      --q, nearest = std::min(nearest, distance(p, *q));
    gap = std::max(gap, nearest);
  }
  return gap;
}

}  // namespace deformseg::test
