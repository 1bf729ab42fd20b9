// The faces that share an edge with each face, from a face-vertex index table, and those linked
// to it, in compressed rows: face f's neighbours are neighbours[offsets[f], offsets[f + 1]),
// ascending.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

namespace deformseg::spatiotemporal::internal {

struct Face_adjacency {
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> neighbours;

  std::span<const std::uint32_t> of(std::size_t face) const {
    return std::span<const std::uint32_t>(neighbours).subspan(offsets[face], offsets[face + 1] - offsets[face]);
  }
};

// Edges are found by sorting (smaller vertex, larger vertex, face) triples: O(F log F), no hash
// table; faces around a non-manifold edge are all neighbours of each other. Each link (f, g)
// makes f and g neighbours both ways.
inline Face_adjacency face_adjacency(std::span<const std::array<std::uint32_t, 3>> triangles,
                                     std::span<const std::pair<std::uint32_t, std::uint32_t>> links = {}) {
  using Edge = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
  std::vector<Edge> edges;
  edges.reserve(3 * triangles.size());
  for (std::uint32_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[f][std::size_t(k)], b = triangles[f][std::size_t((k + 1) % 3)];
      edges.emplace_back(std::min(a, b), std::max(a, b), f);
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
           std::get<1>(edges[j]) == std::get<1>(edges[i]))
      ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = i; b < j; ++b)
        if (a != b) pairs.emplace_back(std::get<2>(edges[a]), std::get<2>(edges[b]));
    i = j;
  }
  for (const auto& [f, g] : links)
    if (f != g) pairs.emplace_back(f, g), pairs.emplace_back(g, f);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  Face_adjacency adjacency{std::vector<std::uint32_t>(triangles.size() + 1, 0), {}};
  adjacency.neighbours.reserve(pairs.size());
  for (const auto& [f, g] : pairs) {
    ++adjacency.offsets[f + 1];
    adjacency.neighbours.push_back(g);
  }
  for (std::size_t f = 0; f < triangles.size(); ++f) adjacency.offsets[f + 1] += adjacency.offsets[f];
  return adjacency;
}

}  // namespace deformseg::spatiotemporal::internal
