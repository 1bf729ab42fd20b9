/// @file strain/frame_distances.h
/// @brief The distance between every two frames of a strain field, the input of temporal
/// segmentation: `frame_distances`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/strain/strain.h>
#include <deformseg/threads.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::strain {

/// @brief How two frame descriptors (the strain vectors x, y of two frames) are compared.
enum class Frame_metric {
  /// @brief `|x - y|`, the default (@ref method_temporal).
  euclidean,
  /// @brief `sum_j |x_j - y_j|`: less dominated by the few most strained triangles.
  l1,
  /// @brief `1 - x.y / (|x| |y|)`, in [0, 2]: compares where the strain lies, not how much there
  /// is. A frame without strain is at distance 0 from another such frame and 1 from any other.
  cosine,
};

/// @brief The options of `frame_distances`.
struct Frame_distance_options {
  /// @brief The metric. Default: `Frame_metric::euclidean`.
  Frame_metric metric = Frame_metric::euclidean;
  /// @brief Threads (0: all the hardware's threads, `thread_count`), at most `max_threads`. The
  /// result is bit-identical
  /// for any number.
  int threads = 0;
};

namespace internal {

// Frames per tile of the distance matrix: a tile's Gram block is one Eigen product, run by one
// thread, so that the result does not depend on how tiles are shared among threads.
inline constexpr std::size_t distance_tile = 128;

template <class Work>
void for_each_tile_pair(std::size_t frames, int threads, const Work& work) {
  const std::size_t tiles = (frames + distance_tile - 1) / distance_tile;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < tiles; ++i)
    for (std::size_t j = i; j < tiles; ++j) pairs.emplace_back(i, j);
  deformseg::internal::parallel_for(pairs.size(), threads, [&](std::size_t p) {
    work(pairs[p].first * distance_tile, pairs[p].second * distance_tile);
  });
}

// sum_j (x_j - y_j)^2 in double, the exact way, for pairs where the Gram formula cancels.
template <class Value>
double squared_difference(const Value* x, const Value* y, std::size_t n) {
  double sum = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double d = double(x[j]) - double(y[j]);
    sum += d * d;
  }
  return sum;
}

template <class Value>
double absolute_difference(const Value* x, const Value* y, std::size_t n) {
  double sum = 0;
  for (std::size_t j = 0; j < n; ++j) sum += std::abs(double(x[j]) - double(y[j]));
  return sum;
}

// Euclidean or cosine distances from the Gram matrix G = X^T X, tile by tile (upper tiles only,
// mirrored). Where |x|^2 + |y|^2 - 2 x.y is below `cancellation` times |x|^2 + |y|^2 (near
// identical frames), rounding would dominate it: that distance is computed directly instead.
template <class Result, class Value>
void gram_distances(const Strain_field<Value>& field, Frame_metric metric, int threads,
                    Eigen::Matrix<Result, Eigen::Dynamic, Eigen::Dynamic>& out) {
  using Matrix = Eigen::Matrix<Value, Eigen::Dynamic, Eigen::Dynamic>;
  const auto x = field.matrix();
  const std::size_t frames = field.num_frames(), faces = field.num_faces();
  const Eigen::Matrix<double, Eigen::Dynamic, 1> norms = x.template cast<double>().colwise().squaredNorm().transpose();
  const double cancellation = 64 * double(std::numeric_limits<Value>::epsilon()) * std::sqrt(double(faces));
  for_each_tile_pair(frames, threads, [&](std::size_t i0, std::size_t j0) {
    const auto ni = Eigen::Index(std::min(distance_tile, frames - i0));
    const auto nj = Eigen::Index(std::min(distance_tile, frames - j0));
    Matrix gram(ni, nj);
    gram.noalias() = x.middleCols(Eigen::Index(i0), ni).transpose() * x.middleCols(Eigen::Index(j0), nj);
    for (Eigen::Index b = 0; b < nj; ++b)
      for (Eigen::Index a = 0; a < ni; ++a) {
        const std::size_t i = i0 + std::size_t(a), j = j0 + std::size_t(b);
        if (i >= j) continue;  // the diagonal is 0, the lower half a mirror
        const double sum = norms[Eigen::Index(i)] + norms[Eigen::Index(j)];
        double d = 0;
        if (metric == Frame_metric::cosine) {
          const double product = std::sqrt(norms[Eigen::Index(i)] * norms[Eigen::Index(j)]);
          d = product > 0 ? std::clamp(1 - double(gram(a, b)) / product, 0.0, 2.0) : (sum > 0 ? 1.0 : 0.0);
        } else {
          double squared = sum - 2 * double(gram(a, b));
          if (squared <= cancellation * sum)
            squared = squared_difference(x.col(Eigen::Index(i)).data(), x.col(Eigen::Index(j)).data(), faces);
          d = std::sqrt(std::max(squared, 0.0));
        }
        out(Eigen::Index(i), Eigen::Index(j)) = out(Eigen::Index(j), Eigen::Index(i)) = Result(d);
      }
  });
}

template <class Result, class Value>
void l1_distances(const Strain_field<Value>& field, int threads,
                  Eigen::Matrix<Result, Eigen::Dynamic, Eigen::Dynamic>& out) {
  const std::size_t frames = field.num_frames(), faces = field.num_faces();
  for_each_tile_pair(frames, threads, [&](std::size_t i0, std::size_t j0) {
    for (std::size_t i = i0; i < std::min(frames, i0 + distance_tile); ++i)
      for (std::size_t j = std::max(j0, i + 1); j < std::min(frames, j0 + distance_tile); ++j)
        out(Eigen::Index(i), Eigen::Index(j)) = out(Eigen::Index(j), Eigen::Index(i)) =
            Result(absolute_difference(field.frame(i).data(), field.frame(j).data(), faces));
  });
}

}  // namespace internal

/// @brief The `T x T` matrix of distances between the frames of a strain field, each frame the
/// vector of its F strains (@ref method_temporal; the frame descriptor is the normalised
/// rest-pose strain).
///
/// Euclidean and cosine distances come from the Gram matrix `X^T X` of the `F x T` field, an
/// Eigen matrix product computed in tiles of 128 frames, the upper ones only (the matrix is
/// symmetric); L1 distances are computed pair by pair. Where the Gram formula
/// `|x|^2 + |y|^2 - 2 x.y` would cancel (near-identical frames), the distance is computed
/// directly in double. The diagonal is exactly 0 and no distance is negative.
/// @tparam Result the matrix's scalar, `float` or `double`; default (`void`): the field's.
/// @param field the strain field (`F x T`).
/// @param options the metric (default Euclidean) and threads.
/// @return the symmetric `T x T` matrix.
/// @throws invalid_input when the field is empty, or for `threads` out of [0, `max_threads`].
/// @par Complexity
/// O(T^2 F): `T^2 F` multiply-adds for Euclidean and cosine (half a full product, by symmetry),
/// `1.5 T^2 F` operations for L1; O(T^2) memory.
template <class Result = void, std::floating_point Value>
  requires std::is_void_v<Result> || std::floating_point<Result>
auto frame_distances(const Strain_field<Value>& field, const Frame_distance_options& options = {}) {
  using Scalar = std::conditional_t<std::is_void_v<Result>, Value, Result>;
  if (field.num_frames() == 0 || field.num_faces() == 0)
    throw invalid_input("frame_distances: the strain field is empty (" + std::to_string(field.num_faces()) +
                        " triangles, " + std::to_string(field.num_frames()) + " frames)");
  thread_count(options.threads, "frame_distances");
  const auto frames = Eigen::Index(field.num_frames());
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> distances =
      Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>::Zero(frames, frames);
  if (options.metric == Frame_metric::l1)
    internal::l1_distances(field, options.threads, distances);
  else
    internal::gram_distances(field, options.metric, options.threads, distances);
  return distances;
}

}  // namespace deformseg::strain
