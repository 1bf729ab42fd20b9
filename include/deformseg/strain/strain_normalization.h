/// @file strain/strain_normalization.h
/// @brief How `compute_strain` normalises raw strains: the `StrainNormalization` concept, the
/// Gaussian kernel (default) and no normalisation, and the statistics that choose sigma.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/strain/internal/strain_math.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/strain/internal/strain_statistics.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>

namespace deformseg::strain {

/// @brief The raw strains of a whole animation, as `compute_strain` hands them to a
/// normalisation to transform in place.
///
/// @tparam Value `float` or `double`.
template <std::floating_point Value>
struct Raw_strain_field {
  /// @brief All `F x T` raw strains, column-major (frame `t` is `values[t F, (t + 1) F)`); a
  /// normalisation overwrites them with the normalised strains.
  std::span<Value> values;
  /// @brief The number of triangles F.
  std::size_t num_faces = 0;
  /// @brief The frame whose strains are 0 by definition and say nothing of the motion (the rest
  /// frame of rest-pose strain, frame 0 of previous-pose strain), left out of `samples()`; none
  /// when the reference is a mesh of its own.
  std::optional<std::size_t> zero_frame{};
  /// @brief Threads the normalisation may use (0: all the hardware's threads (`thread_count`)); its result must not
  /// depend on it.
  int threads = 0;

  /// @brief The strains that measure the motion, which statistics are taken over: every value
  /// but those of `zero_frame`, as up to two contiguous runs (before and after it).
  /// @par Complexity O(1).
  std::array<std::span<const Value>, 2> samples() const {
    const std::span<const Value> all = values;
    if (!zero_frame) return {all, {}};
    const std::size_t begin = *zero_frame * num_faces;
    return {all.first(begin), all.subspan(begin + num_faces)};
  }
};

/// @brief A normalisation of raw strains: a copyable object whose `normalize` transforms a
/// `Raw_strain_field<float>` and a `Raw_strain_field<double>` in place and gives the parameter it
/// used (the Gaussian kernel's sigma), or none.
///
/// What it returns is kept in `Strain_field::sigma()`. Its result must not depend on
/// `Raw_strain_field::threads`. Has models: `Gaussian_normalization` (the default),
/// `No_normalization`.
template <class N>
concept StrainNormalization = std::copy_constructible<N> &&
    requires(const N& n, const Raw_strain_field<float>& f, const Raw_strain_field<double>& d) {
      { n.normalize(f) } -> std::same_as<std::optional<double>>;
      { n.normalize(d) } -> std::same_as<std::optional<double>>;
    };

/// @brief No normalisation: `compute_strain` gives the raw strains, and `sigma()` is empty.
struct No_normalization {
  /// @brief Leaves the strains as they are.
  /// @return none.
  template <std::floating_point Value>
  std::optional<double> normalize(const Raw_strain_field<Value>&) const {
    return std::nullopt;
  }
};

/// @brief Which statistic of the raw strains gives the Gaussian kernel's sigma (see
/// `Gaussian_normalization`).
enum class Sigma_statistic {
  /// @brief A percentile of the strain magnitudes, `Gaussian_normalization::percentile` (default
  /// 95): robust to any share of outliers below 100 - percentile %. The default.
  percentile,
  /// @brief The standard deviation of the strain magnitudes, the method's first reading
  /// (@ref method_strain). Not robust: a few sliver triangles multiply it, flattening every other
  /// normalised strain (@ref section_sigma_choice).
  standard_deviation,
  /// @brief The median absolute deviation of the strain magnitudes from their median, times
  /// 1.4826 (the standard deviation of a normal distribution with that MAD). Robust, but a
  /// statistic of the typical triangle, not of the deformed ones.
  scaled_mad,
};

/// @brief The Gaussian kernel of the method (@ref method_strain), the default normalisation:
/// `s' = 1 - exp(-s^2 / (2 sigma^2))`, which maps strains in [0, inf) to [0, 1).
///
/// sigma is `sigma` when given, else a statistic of the raw strains (`sigma_of`): by default
/// their 95th percentile, so that a strain of that size becomes 1 - exp(-1/2) = 0.39, strains well
/// above it (joints bent hard, and sliver triangles) saturate near 1, and the rest keep their
/// order and contrast.
///
/// The statistic is taken over the magnitudes `|s|` of the samples of the field (every frame but
/// the one whose strain is 0 by definition) that exceed `noise_level`: strains below it are the
/// rounding of a rigid motion, and counting them would let a mostly rigid animation choose a
/// sigma of rounding size and blow its noise up to visible strains. sigma is at least
/// `noise_level`.
///
/// The 95th percentile because it is the highest percentile that sliver triangles hardly move,
/// and it keeps the strain of one motion on two different meshes alike (@ref section_sigma_choice).
struct Gaussian_normalization {
  /// @brief sigma, when given (finite, > 0). Default: none, from the data.
  std::optional<double> sigma{};
  /// @brief The statistic that gives sigma when it is not given. Default: `percentile`.
  Sigma_statistic statistic = Sigma_statistic::percentile;
  /// @brief The percentile, in (0, 100], for `Sigma_statistic::percentile`: the nearest-rank
  /// percentile, the smallest sample that at least this share of the samples do not exceed.
  /// Default: 95.
  double percentile = 95;
  /// @brief Strains of magnitude at or below this are left out of the statistic, and sigma is at
  /// least this. Default: 1e-5 (a rigid motion gives about 1e-7 in float, see `compute_strain`).
  double noise_level = 1e-5;

  /// @brief The sigma this normalisation uses for `field`: `sigma` if given, else the statistic
  /// of the samples' magnitudes above `noise_level`, and at least `noise_level`.
  /// @throws invalid_input when a parameter is out of range (given sigma not finite and > 0,
  /// percentile outside (0, 100], noise level negative or not finite).
  /// @par Complexity O(F T): two passes of radix selection per order statistic (four for
  /// `double`), three for the standard deviation; the same result for any number of threads.
  template <std::floating_point Value>
  double sigma_of(const Raw_strain_field<Value>& field) const {
    check();
    if (sigma) return *sigma;
    const auto samples = field.samples();
    const int threads = field.threads;
    const Value noise = Value(noise_level);
    // Magnitudes above the noise level; others become -1, out of every statistic.
    const auto kept = [noise](Value v) { return v > noise || v < -noise ? (v < 0 ? -v : v) : Value(-1); };
    double statistic_value = 0;
    switch (statistic) {
      case Sigma_statistic::percentile:
        statistic_value = double(internal::kept_quantile(samples, percentile / 100, threads, kept).value_or(0));
        break;
      case Sigma_statistic::standard_deviation: {
        const auto sum = [&](const auto& f) {
          return internal::sum_of(samples, threads, [&](double v) {
            const double m = double(kept(Value(v)));
            return m >= 0 ? f(m) : 0.0;
          });
        };
        const double n = sum([](double) { return 1.0; });
        if (n == 0) break;
        const double mean = sum([](double m) { return m; }) / n;
        statistic_value = std::sqrt(sum([mean](double m) { return (m - mean) * (m - mean); }) / n);
        break;
      }
      case Sigma_statistic::scaled_mad: {
        const auto median = internal::kept_quantile(samples, 0.5, threads, kept);
        if (!median) break;
        const auto deviation = internal::kept_quantile(samples, 0.5, threads, [&](Value v) {
          const Value m = kept(v);
          return m >= 0 ? (m > *median ? m - *median : *median - m) : Value(-1);
        });
        statistic_value = 1.4826 * double(*deviation);
        break;
      }
    }
    return std::max(statistic_value, noise_level);
  }

  /// @brief Normalises the strains of `field` in place with `sigma_of(field)`.
  /// @return the sigma used.
  /// @throws invalid_input as `sigma_of`.
  /// @par Complexity O(F T), as `sigma_of`, plus one vectorised pass.
  template <std::floating_point Value>
  std::optional<double> normalize(const Raw_strain_field<Value>& field) const {
    const double used = sigma_of(field);
    // y = (s k)^2 with k = sqrt(1/2) / sigma, k limited to the largest finite Value so that s = 0
    // gives 0 whatever sigma.
    const double k = std::min(std::sqrt(0.5) / used, double(std::numeric_limits<Value>::max()));
    apply(field, Value(k));
    return used;
  }

private:
  void check() const {
    if (sigma && !(std::isfinite(*sigma) && *sigma > 0))
      throw invalid_input("Gaussian normalisation: sigma must be finite and > 0, not " + std::to_string(*sigma));
    if (!(percentile > 0 && percentile <= 100))
      throw invalid_input("Gaussian normalisation: percentile must be in (0, 100], not " + std::to_string(percentile));
    if (!(noise_level >= 0 && std::isfinite(noise_level)))
      throw invalid_input("Gaussian normalisation: noise_level must be finite and >= 0, not " +
                          std::to_string(noise_level));
  }

  // s <- 1 - exp(-(s k)^2), vectorised, in fixed blocks.
  template <std::floating_point Value>
  static void apply(const Raw_strain_field<Value>& field, Value k) {
    Value* values = field.values.data();
    const std::size_t n = field.values.size();
    const std::size_t blocks = (n + internal::statistics_block - 1) / internal::statistics_block;
    deformseg::internal::parallel_for(blocks, field.threads, [&](std::size_t b) {
      Value* first = values + b * internal::statistics_block;
      const std::size_t count = std::min(internal::statistics_block, n - b * internal::statistics_block);
      for (std::size_t i = 0; i < count; ++i) {
        const Value scaled = first[i] * k;
        first[i] = internal::one_minus_exp_neg(scaled * scaled);
      }
    });
  }
};

}  // namespace deformseg::strain
