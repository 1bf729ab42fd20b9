/// @file temporal/segment_cost.h
/// @brief The within-segment dissimilarity `Ds(m, n)` of a frame distance matrix in O(1) per
/// query: `Segment_cost`.
#pragma once

#include <deformseg/exceptions.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace deformseg::temporal {

/// @brief Answers, for any frame interval [m, n], the within-segment dissimilarity
/// `Ds(m, n) = sum_{i, j in [m, n]} D(i, j) / (n - m + 1)^2` of a frame distance matrix D: the
/// average distance over all ordered pairs of frames of the interval, each frame with itself
/// included (@ref method_temporal), so that one frame has `Ds = 0`.
///
/// It owns a 2-D prefix sum (summed-area table) of D in double, `(T + 1)^2` values, from which
/// any block sum is four lookups.
class Segment_cost {
public:
  /// @brief The prefix sums of `distances`.
  /// @param distances a square matrix of finite, non-negative frame distances (any Eigen
  /// expression of float or double), as `frame_distances` gives.
  /// @throws invalid_input when it is empty, not square, or has a negative or non-finite entry
  /// (naming its row and column).
  /// @par Complexity O(T^2) time and memory (8 (T + 1)^2 bytes: 800 MB for T = 10000).
  template <class Derived>
  explicit Segment_cost(const Eigen::MatrixBase<Derived>& distances)
      : frames_(std::size_t(distances.rows())), prefix_((frames_ + 1) * (frames_ + 1), 0.0) {
    if (distances.rows() == 0 || distances.rows() != distances.cols())
      throw invalid_input("Segment_cost: the frame distance matrix must be square and not empty, not " +
                          std::to_string(distances.rows()) + " x " + std::to_string(distances.cols()));
    for (std::size_t i = 0; i < frames_; ++i) {
      double row = 0;
      for (std::size_t j = 0; j < frames_; ++j) {
        const double d = double(distances(Eigen::Index(i), Eigen::Index(j)));
        if (!(d >= 0 && std::isfinite(d)))
          throw invalid_input("Segment_cost: frame distance (" + std::to_string(i) + ", " + std::to_string(j) +
                              ") is " + std::to_string(d) + ", not a finite number >= 0");
        row += d;
        at(i + 1, j + 1) = at(i, j + 1) + row;
      }
    }
  }

  /// @brief The number of frames T.
  std::size_t num_frames() const noexcept { return frames_; }

  /// @brief `sum_{i, j in [m, n]} D(i, j)`.
  /// @pre `m <= n < num_frames()` (unchecked).
  /// @par Complexity O(1).
  double block_sum(std::size_t m, std::size_t n) const noexcept {
    return at(n + 1, n + 1) - at(m, n + 1) - at(n + 1, m) + at(m, m);
  }

  /// @brief The frame distance `D(i, j)`, recovered from the prefix sums (to a rounding error
  /// of about 1e-16 times the sum of all distances).
  /// @pre `i, j < num_frames()` (unchecked).
  /// @par Complexity O(1).
  double distance(std::size_t i, std::size_t j) const noexcept {
    return clamp_rounding(at(i + 1, j + 1) - at(i, j + 1) - at(i + 1, j) + at(i, j));
  }

  /// @brief `Ds(m, n)`, the average distance between the frames of [m, n] (0 for one frame).
  /// @pre `m <= n < num_frames()` (unchecked).
  /// @par Complexity O(1).
  double operator()(std::size_t m, std::size_t n) const noexcept {
    const double length = double(n - m + 1);
    return clamp_rounding(block_sum(m, n)) / (length * length);
  }

  /// @brief `(n - m + 1) Ds(m, n)`: the cost of segment [m, n] in a partition, weighted by its
  /// length (see `Optimal_partition` for why the weight).
  /// @pre `m <= n < num_frames()` (unchecked).
  /// @par Complexity O(1).
  double weighted(std::size_t m, std::size_t n) const noexcept {
    return clamp_rounding(block_sum(m, n)) / double(n - m + 1);
  }

  /// @brief The mean distance between two different frames, the scale of relative thresholds
  /// (0 for one frame).
  /// @par Complexity O(1).
  double mean_distance() const noexcept {
    return frames_ < 2 ? 0.0 : at(frames_, frames_) / (double(frames_) * double(frames_ - 1));
  }

private:
  double& at(std::size_t i, std::size_t j) { return prefix_[i * (frames_ + 1) + j]; }
  double at(std::size_t i, std::size_t j) const { return prefix_[i * (frames_ + 1) + j]; }
  // A block of zeros can come out a hair below 0 from the differences of large prefix sums.
  static double clamp_rounding(double sum) { return sum > 0 ? sum : 0.0; }

  std::size_t frames_;
  std::vector<double> prefix_;
};

}  // namespace deformseg::temporal
