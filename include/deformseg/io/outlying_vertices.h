/// @file io/outlying_vertices.h
/// @brief `Outlier_check`: vertices absurdly far for their mesh's own scale, as corrupt data
/// gives them (a coordinate of 1e20 in a mesh a metre across), found frame by frame.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace deformseg::io {

/// @brief A vertex of a frame that lies farther from the frame's middle than the check allows.
struct Outlying_vertex {
  std::size_t frame = 0;   ///< the frame, as the caller numbers it
  std::size_t vertex = 0;  ///< the vertex
  double distance = 0;     ///< from the frame's middle (the median of each coordinate)
  double scale = 0;        ///< the mesh's median radius in its first frame

  /// @brief "frame 12 vertex 40 lies 1e+20 from the frame's middle, 3.7e+20 times the mesh's
  /// median radius (0.269)".
  std::string text() const {
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, " lies %.3g from the frame's middle, %.2g times the mesh's median radius (%.3g)",
                  distance, distance / scale, scale);
    return "frame " + std::to_string(frame) + " vertex " + std::to_string(vertex) + numbers;
  }
};

/// @brief Finds, frame by frame, vertices farther from their frame's middle than `ratio` times
/// the mesh's median radius in its first frame: coordinates no modelling tool makes, which
/// corrupt data does (a bit flipped in an exponent, a misread buffer).
///
/// The scale is robust: the median distance of the first frame's vertices from the median of each
/// coordinate, so that a few corrupt vertices do not hide themselves; a frame is measured from its
/// own middle, so that root motion does not count. A frame whose bounding box spans less than the
/// allowed distance is passed at the cost of one pass; only the others are searched.
/// @par Example
/// @include outlier_check.cpp
class Outlier_check {
public:
  /// @brief The default `ratio`: 10^5, far above any character's extent over its median radius
  /// (a 10 km ground under a 1 m body is 10^4).
  static constexpr double default_ratio = 1e5;

  /// @brief The check of a mesh whose first frame is `first_frame` (3V coordinates).
  /// @pre every coordinate is finite; `ratio` > 0. A mesh whose first frame has no spread (its
  /// vertices mostly at one point) is never refused: it has no scale to judge by.
  /// @par Complexity O(V) expected.
  template <std::floating_point T>
  explicit Outlier_check(std::span<const T> first_frame, double ratio = default_ratio) {
    const std::array<double, 3> middle = middle_of(first_frame);
    std::vector<double> distances(first_frame.size() / 3);
    for (std::size_t v = 0; v < distances.size(); ++v) distances[v] = distance(first_frame, v, middle);
    if (distances.empty()) return;
    const auto median = distances.begin() + std::ptrdiff_t(distances.size() / 2);
    std::nth_element(distances.begin(), median, distances.end());
    scale_ = *median, allowed_ = ratio * scale_;
  }

  /// @brief The mesh's median radius in its first frame (0 without spread).
  double scale() const { return scale_; }

  /// @brief The farthest vertex of `frame` (3V coordinates, numbered `index` in reports) beyond the
  /// allowed distance, if any.
  /// @par Complexity O(V): one pass, and an expected O(V) search in a frame that fails it.
  template <std::floating_point T>
  std::optional<Outlying_vertex> operator()(std::span<const T> frame, std::size_t index) const {
    if (scale_ <= 0 || frame.empty() || spans_less(frame)) return std::nullopt;
    const std::array<double, 3> middle = middle_of(frame);
    std::optional<Outlying_vertex> farthest;
    for (std::size_t v = 0; v < frame.size() / 3; ++v) {
      const double d = distance(frame, v, middle);
      if (d > allowed_ && (!farthest || d > farthest->distance))
        farthest = Outlying_vertex{.frame = index, .vertex = v, .distance = d, .scale = scale_};
    }
    return farthest;
  }

private:
  // The median of each coordinate.
  template <class T>
  static std::array<double, 3> middle_of(std::span<const T> frame) {
    std::array<double, 3> middle{};
    std::vector<double> values(frame.size() / 3);
    for (std::size_t k = 0; k < 3 && !values.empty(); ++k) {
      for (std::size_t v = 0; v < values.size(); ++v) values[v] = double(frame[3 * v + k]);
      const auto median = values.begin() + std::ptrdiff_t(values.size() / 2);
      std::nth_element(values.begin(), median, values.end());
      middle[k] = *median;
    }
    return middle;
  }

  template <class T>
  static double distance(std::span<const T> frame, std::size_t v, const std::array<double, 3>& point) {
    const double x = double(frame[3 * v]) - point[0], y = double(frame[3 * v + 1]) - point[1],
                 z = double(frame[3 * v + 2]) - point[2];
    return std::sqrt(x * x + y * y + z * z);
  }

  // True when the frame's bounding box is within the allowed distance of every point in it, so
  // that no vertex can be that far from the frame's middle.
  template <class T>
  bool spans_less(std::span<const T> frame) const {
    std::array<T, 3> low{frame[0], frame[1], frame[2]}, high = low;
    for (std::size_t i = 3; i + 2 < frame.size(); i += 3)
      for (std::size_t k = 0; k < 3; ++k) low[k] = std::min(low[k], frame[i + k]), high[k] = std::max(high[k], frame[i + k]);
    double squared = 0;
    for (std::size_t k = 0; k < 3; ++k) squared += (double(high[k]) - double(low[k])) * (double(high[k]) - double(low[k]));
    return std::sqrt(squared) <= allowed_;
  }

  double scale_ = 0;
  double allowed_ = 0;
};

}  // namespace deformseg::io
