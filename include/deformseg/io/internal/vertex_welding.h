/// @file io/internal/vertex_welding.h
/// @brief Details of `io::repair_triangles`: the welding of vertices that coincide in every frame.
#pragma once

#include <deformseg/exceptions.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace deformseg::io::internal {

/// Union-find over [0, n) whose sets are represented by their smallest element, so that the
/// result does not depend on the order of the unions.
class Smallest_union_find {
public:
  explicit Smallest_union_find(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }

  std::uint32_t find(std::uint32_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];  // path halving
      i = parent_[i];
    }
    return i;
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a < b) parent_[b] = a;
    if (b < a) parent_[a] = b;
  }

  /// The set of each element, numbered 0, 1, ... in the order of their smallest element.
  std::vector<std::uint32_t> numbered_sets() {
    std::vector<std::uint32_t> set(parent_.size());
    std::uint32_t count = 0;
    for (std::uint32_t i = 0; i < parent_.size(); ++i) set[i] = find(i) == i ? count++ : set[find(i)];
    return set;
  }

private:
  std::vector<std::uint32_t> parent_;
};

/// Throws unless every coordinate is finite, naming the frame and the vertex as `Deforming_mesh` does.
template <std::floating_point T>
void check_finite_positions(std::span<const T> positions, std::size_t num_vertices) {
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!std::isfinite(positions[i]))
      throw invalid_input("vertex " + std::to_string(i / 3 % num_vertices) + " has a non-finite coordinate",
                          {.frame = i / (3 * num_vertices)});
}

/// The bounding box of a set of `x, y, z` coordinates.
struct Bounding_box {
  std::array<double, 3> low{}, high{};
  double diagonal() const { return std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]); }
};

template <std::floating_point T>
Bounding_box bounding_box(std::span<const T> xyz) {
  Bounding_box box;
  box.low.fill(std::numeric_limits<double>::infinity());
  box.high.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    box.low[i % 3] = std::min(box.low[i % 3], double(xyz[i]));
    box.high[i % 3] = std::max(box.high[i % 3], double(xyz[i]));
  }
  if (xyz.empty()) box = {};
  return box;
}

/// A cell of the hash grid on frame 0.
struct Grid_cell {
  std::array<std::int64_t, 3> index{};
  bool operator==(const Grid_cell&) const = default;
};

struct Grid_cell_hash {
  std::size_t operator()(const Grid_cell& c) const noexcept {
    const auto mix = [](std::uint64_t h, std::int64_t x) {
      return (h ^ static_cast<std::uint64_t>(x)) * 0x100000001b3ull;  // FNV-1a step per coordinate
    };
    return static_cast<std::size_t>(mix(mix(mix(0xcbf29ce484222325ull, c.index[0]), c.index[1]), c.index[2]));
  }
};

/// Vertices `i` and `j` coincide: in every frame, no coordinate differs by more than `distance`.
template <std::floating_point T>
bool coincide_in_every_frame(std::span<const T> positions, std::size_t num_vertices, std::size_t i,
                             std::size_t j, double distance) {
  for (std::size_t frame = 0; frame < positions.size(); frame += 3 * num_vertices)
    for (std::size_t k = 0; k < 3; ++k)
      if (!(std::abs(double(positions[frame + 3 * i + k]) - double(positions[frame + 3 * j + k])) <= distance))
        return false;
  return true;
}

/// A hash of each vertex's trajectory (its coordinates in every frame, 0 and -0 alike), computed
/// frame after frame so that the positions are read in order.
template <std::floating_point T>
std::vector<std::uint64_t> trajectory_hashes(std::span<const T> positions, std::size_t num_vertices) {
  std::vector<std::uint64_t> hashes(num_vertices, 0xcbf29ce484222325ull);
  for (std::size_t frame = 0; frame < positions.size(); frame += 3 * num_vertices)
    for (std::size_t v = 0; v < num_vertices; ++v)
      for (std::size_t k = 0; k < 3; ++k) {
        const double x = double(positions[frame + 3 * v + k]);
        hashes[v] = (hashes[v] ^ std::bit_cast<std::uint64_t>(x == 0 ? 0.0 : x)) * 0x100000001b3ull;  // FNV-1a
      }
  for (std::uint64_t& h : hashes) h ^= h >> 29;
  return hashes;
}

/// Hashes vertices by their trajectory's hash and compares their trajectories, equal as numbers.
template <std::floating_point T>
struct Same_trajectory {
  std::span<const T> positions;
  std::size_t num_vertices;
  std::span<const std::uint64_t> hashes;

  std::size_t operator()(std::uint32_t v) const noexcept { return static_cast<std::size_t>(hashes[v]); }

  bool operator()(std::uint32_t a, std::uint32_t b) const noexcept {
    for (std::size_t frame = 0; frame < positions.size(); frame += 3 * num_vertices)
      for (std::size_t k = 0; k < 3; ++k)
        if (positions[frame + 3 * a + k] != positions[frame + 3 * b + k]) return false;
    return true;
  }
};

/// Unites the vertices that `same` finds equal (it hashes a vertex and compares two), and returns
/// the smallest vertex of each class in increasing order: the only ones the grid then compares.
/// Without this, a point shared by many vertices (an unwelded mesh, a part scaled to nothing on
/// its bone, an accessor of zeros) would cost a comparison per pair of them. O(V) expected.
template <class Same>
std::vector<std::uint32_t> unite_same_vertices(std::size_t num_vertices, const Same& same,
                                               Smallest_union_find& welded) {
  std::unordered_set<std::uint32_t, Same, Same> first_of_class(num_vertices, same, same);
  std::vector<std::uint32_t> distinct;
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    const auto [first, inserted] = first_of_class.insert(v);
    if (inserted) distinct.push_back(v);
    else welded.unite(*first, v);
  }
  return distinct;
}

/// Welds vertices: first those `same` finds equal (see `unite_same_vertices`); then, among the
/// first of each class, every pair that `coincide` accepts of the vertices whose `points` (3
/// finite coordinates per vertex) lie in the same or neighbouring cells of a hash grid of `cell`-sized
/// cells; then the transitive closure.
/// @return the welded vertex of each input vertex, numbered in the order of their smallest input vertex.
/// @pre `coincide` accepts only vertices whose points are less than `cell` apart in each coordinate.
/// O(V) expected, unless many vertices `same` tells apart lie within a cell of each other.
template <class Same, class Coincide>
std::vector<std::uint32_t> weld_on_grid(std::span<const double> points, double cell, const Same& same,
                                        const Coincide& coincide) {
  const std::size_t num_vertices = points.size() / 3;
  const Bounding_box box = bounding_box(points);
  const auto cell_of = [&](std::size_t v) {  // indices from the corner of the box
    Grid_cell c;
    for (std::size_t k = 0; k < 3; ++k)
      c.index[k] = static_cast<std::int64_t>(std::floor((points[3 * v + k] - box.low[k]) / cell));
    return c;
  };
  Smallest_union_find welded(num_vertices);
  const std::vector<std::uint32_t> distinct = unite_same_vertices(num_vertices, same, welded);
  std::unordered_map<Grid_cell, std::vector<std::uint32_t>, Grid_cell_hash> grid;
  grid.reserve(distinct.size());
  for (const std::uint32_t v : distinct) grid[cell_of(v)].push_back(v);

  for (const std::uint32_t v : distinct) {
    const Grid_cell home = cell_of(v);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto found = grid.find({{home.index[0] + dx, home.index[1] + dy, home.index[2] + dz}});
          if (found == grid.end()) continue;
          for (const std::uint32_t w : found->second)
            if (w < v && welded.find(w) != welded.find(v) && coincide(v, w)) welded.unite(v, w);
        }
  }
  return welded.numbered_sets();
}

/// The cell of a welding grid for vertices at most `distance` apart in a box of diagonal
/// `extent`: no smaller than `distance`, but not so small that a cell index overflows (a distance
/// of 0 still welds vertices in the same place).
inline double welding_cell(double distance, double extent) {
  return extent == 0 ? 1.0 : std::max(distance, extent * 0x1p-40);
}

/// Welds the vertices of an animation (`T x 3V` positions, T >= 1) that coincide in every frame
/// within `tolerance` times the diagonal of the bounding box of all frames, and the vertices that
/// coincide with those (the transitive closure).
/// @return the welded vertex of each input vertex, numbered in the order of their smallest input vertex.
/// Vertices of the same trajectory are united first; among the others, candidates come from a
/// hash grid of cells no smaller than `distance` on frame 0: the vertices in the 27 cells around
/// a vertex, each checked over all frames. O(T V) expected, unless many vertices of different
/// trajectories lie within `distance` of each other in frame 0.
template <std::floating_point T>
std::vector<std::uint32_t> weld_vertices(std::span<const T> positions, std::size_t num_vertices, double tolerance) {
  const double extent = bounding_box(positions).diagonal();
  const double distance = tolerance * extent;
  const std::vector<double> first_frame(positions.begin(), positions.begin() + std::ptrdiff_t(3 * num_vertices));
  const std::vector<std::uint64_t> hashes = trajectory_hashes(positions, num_vertices);
  return weld_on_grid(std::span<const double>(first_frame), welding_cell(distance, extent),
                      Same_trajectory<T>{positions, num_vertices, hashes}, [&](std::uint32_t v, std::uint32_t w) {
                        return coincide_in_every_frame(positions, num_vertices, v, w, distance);
                      });
}

}  // namespace deformseg::io::internal
