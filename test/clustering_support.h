// Synthetic data for the clustering tests: points in far-apart blobs of the plane, and their
// Euclidean distance matrix.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

namespace deformseg_clustering_test {

// Points of the plane and the group each was drawn around.
struct Blobs {
  Eigen::MatrixXd distances;
  std::vector<std::size_t> truth;  // canonical: numbered by first appearance
  std::vector<Eigen::Vector2d> points;
};

inline Eigen::MatrixXd euclidean_distances(const std::vector<Eigen::Vector2d>& points) {
  const auto n = Eigen::Index(points.size());
  Eigen::MatrixXd d(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) d(i, j) = (points[std::size_t(i)] - points[std::size_t(j)]).norm();
  return d;
}

// sizes[g] points in a disc of radius 1 around centre g, the centres at least `separation`
// apart; items in a shuffled order so that the groups interleave.
inline Blobs make_blobs(const std::vector<std::size_t>& sizes, unsigned seed, double separation = 20.0) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::pair<Eigen::Vector2d, std::size_t>> items;
  for (std::size_t g = 0; g < sizes.size(); ++g) {
    const Eigen::Vector2d centre(separation * double(g % 4), separation * double(g / 4));
    for (std::size_t k = 0; k < sizes[g];) {
      const Eigen::Vector2d offset(unit(random), unit(random));
      if (offset.norm() > 1.0) continue;
      items.push_back({centre + offset, g});
      ++k;
    }
  }
  std::shuffle(items.begin(), items.end(), random);
  Blobs b;
  std::vector<std::size_t> renumber(sizes.size(), sizes.size());
  std::size_t next = 0;
  for (const auto& [point, group] : items) {
    if (renumber[group] == sizes.size()) renumber[group] = next++;
    b.points.push_back(point);
    b.truth.push_back(renumber[group]);
  }
  b.distances = euclidean_distances(b.points);
  return b;
}

// Random points with integer coordinates in [0, range): with range small, many equal distances.
inline Eigen::MatrixXd random_distances(std::size_t n, std::mt19937& random, int range = 100) {
  std::uniform_int_distribution<int> coordinate(0, range - 1);
  std::vector<Eigen::Vector2d> points(n);
  for (auto& p : points) p = Eigen::Vector2d(coordinate(random), coordinate(random));
  return euclidean_distances(points);
}

// Points on a line, with their distances |x - y|.
inline Eigen::MatrixXd on_a_line(const std::vector<double>& x) {
  const auto n = Eigen::Index(x.size());
  Eigen::MatrixXd d(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) d(i, j) = std::abs(x[std::size_t(i)] - x[std::size_t(j)]);
  return d;
}

}  // namespace deformseg_clustering_test
