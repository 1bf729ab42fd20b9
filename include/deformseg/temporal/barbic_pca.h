/// @file temporal/barbic_pca.h
/// @brief The PCA change detection of Barbič et al. 2004, a baseline policy of temporal
/// segmentation: `Barbic_pca`.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/temporal/segment_cost.h>
#include <deformseg/temporal/segments.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace deformseg::temporal {

/// @brief Temporal segmentation by PCA change detection (J. Barbič, A. Safonova, J.-Y. Pan,
/// C. Faloutsos, J. K. Hodgins, N. S. Pollard: *Segmenting motion capture data into distinct
/// behaviors*, Graphics Interface 2004), the baseline the thesis compares with.
///
/// From a segment's first frame s: the first `window` frames fix the dimension r, the fewest
/// principal components that hold `energy` of their variance. Then for each next frame i, e(i)
/// is the squared error of frames [s, i] projected onto their own best r-dimensional affine
/// subspace, and d(i) = e(i) - e(i - lag) its growth. A new behaviour makes the error grow faster:
/// a segment ends before the first i where d(i) exceeds the mean of the earlier d by `deviations`
/// of their standard deviations (and a noise floor), and the search starts again at i.
///
/// The frames' principal components come from the frame distances alone, by classical
/// multidimensional scaling: the eigenvalues of `-J D^2 J / 2` (J centres) are those of the
/// frames' scatter matrix when D is Euclidean (the default of `frame_distances`; with another
/// metric this is an approximation).
/// @par Complexity O(n^3) per frame of a segment of n frames (an eigen-decomposition of its
/// frames), so O(T n^3) in all: a baseline for animations of hundreds of frames, not thousands.
struct Barbic_pca {
  /// @brief Frames that fix the dimension r (>= 2). Default: 10.
  std::size_t window = 10;
  /// @brief The share of the variance the r components keep, in (0, 1]. Default: 0.9 (the
  /// paper's).
  double energy = 0.9;
  /// @brief Frames over which the error's growth is measured (>= 1). Default: 5.
  std::size_t lag = 5;
  /// @brief How many standard deviations above the mean growth cut. Default: 3 (the paper's).
  double deviations = 3;

  /// @brief The segments of `cost`'s frames.
  /// @throws invalid_input when a parameter is out of range.
  std::vector<Frame_interval> operator()(const Segment_cost& cost) const {
    check();
    const std::size_t frames = cost.num_frames();
    // Errors below this, in squared distance, are rounding (identical frames).
    const double floor = 1e-9 * cost.mean_distance() * cost.mean_distance();
    std::vector<Frame_interval> segments;
    for (std::size_t s = 0; s < frames;) {
      const std::optional<std::size_t> cut = s + window + lag < frames ? find_cut(cost, s, floor) : std::nullopt;
      const std::size_t end = cut.value_or(frames);
      segments.push_back({s, end - 1});
      s = end;
    }
    return segments;
  }

private:
  void check() const {
    if (window < 2 || lag < 1 || !(energy > 0 && energy <= 1) || !(deviations >= 0))
      throw invalid_input("Barbic_pca: window >= 2, lag >= 1, energy in (0, 1] and deviations >= 0 are needed");
  }

  // The eigenvalues of the frames [s, e]' scatter matrix, largest first, from their distances.
  static Eigen::VectorXd scatter_eigenvalues(const Segment_cost& cost, std::size_t s, std::size_t e) {
    const auto n = Eigen::Index(e - s + 1);
    Eigen::MatrixXd b(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) {
        const double d = cost.distance(s + std::size_t(i), s + std::size_t(j));
        b(i, j) = -0.5 * d * d;
      }
    const Eigen::MatrixXd centred = b.rowwise() - b.colwise().mean();
    const Eigen::MatrixXd gram = centred.colwise() - centred.rowwise().mean();
    Eigen::VectorXd values = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(gram, Eigen::EigenvaluesOnly).eigenvalues();
    values = values.reverse().cwiseMax(0.0);
    return values;
  }

  // The fewest leading eigenvalues that hold `energy` of the sum.
  std::size_t dimension(const Eigen::VectorXd& values) const {
    const double total = values.sum();
    double kept = 0;
    for (Eigen::Index r = 0; r < values.size(); ++r) {
      if (kept >= energy * total) return std::size_t(r);
      kept += values[r];
    }
    return std::size_t(values.size());
  }

  // The first frame of the next behaviour after s, if any.
  std::optional<std::size_t> find_cut(const Segment_cost& cost, std::size_t s, double floor) const {
    const std::size_t r = dimension(scatter_eigenvalues(cost, s, s + window - 1));
    std::vector<double> error, growth;
    for (std::size_t i = s + window - 1; i < cost.num_frames(); ++i) {
      const Eigen::VectorXd values = scatter_eigenvalues(cost, s, i);
      error.push_back(
          values.tail(values.size() - Eigen::Index(std::min<std::size_t>(r, std::size_t(values.size())))).sum());
      if (error.size() <= lag) continue;
      const double d = error.back() - error[error.size() - 1 - lag];
      if (growth.size() >= 2 && d > floor && d > mean(growth) + deviations * deviation(growth)) return i;
      growth.push_back(d);
    }
    return std::nullopt;
  }

  static double mean(const std::vector<double>& v) {
    double sum = 0;
    for (double x : v) sum += x;
    return sum / double(v.size());
  }

  static double deviation(const std::vector<double>& v) {
    const double m = mean(v);
    double sum = 0;
    for (double x : v) sum += (x - m) * (x - m);
    return std::sqrt(sum / double(v.size()));
  }
};

}  // namespace deformseg::temporal
