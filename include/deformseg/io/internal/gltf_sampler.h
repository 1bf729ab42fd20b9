// glTF animation samplers: LINEAR (rotations by shortest-path slerp), STEP and CUBICSPLINE (cubic
// Hermite with tangents scaled by the key interval), clamped outside their keys, as the glTF 2.0
// specification's appendix on interpolation says.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/io/internal/gltf_accessor.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace deformseg::io::internal::gltf {

enum class Interpolation { linear, step, cubic_spline };

/// One sampler: key times, and per key `width` values (for CUBICSPLINE three groups per key:
/// in-tangent, value, out-tangent).
struct Sampler {
  std::vector<double> times{};
  std::vector<double> values{};
  std::size_t width = 0;
  Interpolation interpolation = Interpolation::linear;
  bool rotation = false;  // unit quaternions (x, y, z, w): slerp, and normalised results

  double start() const { return times.front(); }
  double end() const { return times.back(); }

  // The value (not a tangent) of key k.
  const double* value(std::size_t k) const {
    return values.data() + (interpolation == Interpolation::cubic_spline ? (3 * k + 1) : k) * width;
  }

  /// Writes the value at time `t` to `out[0, width)`.
  void sample(double t, double* out) const {
    if (t <= times.front() || times.size() == 1) return copy_key(0, out);
    if (t >= times.back()) return copy_key(times.size() - 1, out);
    const std::size_t k = std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const double interval = times[k + 1] - times[k];
    const double u = (t - times[k]) / interval;
    switch (interpolation) {
      case Interpolation::step: return copy_key(k, out);
      case Interpolation::linear:
        if (rotation) return slerp(value(k), value(k + 1), u, out);
        for (std::size_t i = 0; i < width; ++i) out[i] = value(k)[i] + u * (value(k + 1)[i] - value(k)[i]);
        return;
      case Interpolation::cubic_spline: return hermite(k, u, interval, out);
    }
  }

private:
  void copy_key(std::size_t k, double* out) const {
    std::copy_n(value(k), width, out);
    if (rotation) normalize(out);
  }

  // p(u) = (2u^3 - 3u^2 + 1) v_k + (u^3 - 2u^2 + u) d b_k + (-2u^3 + 3u^2) v_k+1 + (u^3 - u^2) d a_k+1,
  // with b_k the out-tangent of key k, a_k+1 the in-tangent of key k+1 and d the key interval.
  void hermite(std::size_t k, double u, double interval, double* out) const {
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = (u3 - 2 * u2 + u) * interval;
    const double h01 = -2 * u3 + 3 * u2, h11 = (u3 - u2) * interval;
    const double* v0 = value(k);
    const double* b0 = v0 + width;
    const double* v1 = value(k + 1);
    const double* a1 = v1 - width;
    for (std::size_t i = 0; i < width; ++i) out[i] = h00 * v0[i] + h10 * b0[i] + h01 * v1[i] + h11 * a1[i];
    if (rotation) normalize(out);
  }

  // Spherical interpolation along the shorter arc (q and -q are the same rotation).
  static void slerp(const double* a, const double* b, double u, double* out) {
    double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const double sign = dot < 0 ? -1.0 : 1.0;
    dot *= sign;
    double wa = 1 - u, wb = u;
    if (dot < 1 - 1e-12) {  // otherwise the arc is too short for sin(): lerp is exact to rounding
      const double angle = std::acos(std::min(dot, 1.0));
      const double s = std::sin(angle);
      wa = std::sin((1 - u) * angle) / s;
      wb = std::sin(u * angle) / s;
    }
    for (int i = 0; i < 4; ++i) out[i] = wa * a[i] + sign * wb * b[i];
    normalize(out);
  }

  static void normalize(double* q) {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (n > 0)
      for (int i = 0; i < 4; ++i) q[i] /= n;
  }
};

inline Interpolation interpolation_named(const std::string& name, const std::string& user) {
  if (name == "LINEAR" || name.empty()) return Interpolation::linear;
  if (name == "STEP") return Interpolation::step;
  if (name == "CUBICSPLINE") return Interpolation::cubic_spline;
  throw invalid_input(user + " has interpolation '" + name + "'; glTF has LINEAR, STEP and CUBICSPLINE");
}

/// Reads sampler `index` of `animation`, whose values have `width` components per key (0: derive
/// it from the counts, for morph target weights).
/// @throws invalid_input when the times are not finite and increasing, or the counts disagree.
inline Sampler read_sampler(const tinygltf::Model& model, const tinygltf::Animation& animation, int index,
                            std::size_t width, bool rotation, const std::string& user) {
  if (index < 0 || std::size_t(index) >= animation.samplers.size())
    throw invalid_input(user + " refers to sampler " + std::to_string(index) + ", which does not exist");
  const tinygltf::AnimationSampler& source = animation.samplers[std::size_t(index)];
  const std::string name = user + " sampler " + std::to_string(index);
  Sampler sampler;
  sampler.interpolation = interpolation_named(source.interpolation, name);
  sampler.rotation = rotation;
  sampler.times = read_accessor(model, source.input, name + " input", 1).values;
  if (sampler.times.empty()) throw invalid_input(name + " has no key");
  for (std::size_t k = 0; k < sampler.times.size(); ++k)
    if (!std::isfinite(sampler.times[k]) || (k > 0 && sampler.times[k] < sampler.times[k - 1]))
      throw invalid_input(name + ": key time " + std::to_string(k) + " is not finite or decreases");
  Accessor_values output = read_accessor(model, source.output, name + " output");
  const std::size_t groups = sampler.interpolation == Interpolation::cubic_spline ? 3 : 1;
  const std::size_t keys = sampler.times.size();
  if (width == 0) {  // weights: one scalar per morph target per key
    if (output.components != 1 || output.count % (groups * keys) != 0)
      throw invalid_input(name + " has " + std::to_string(output.count) + " weights for " + std::to_string(keys) +
                          " keys");
    width = output.count / (groups * keys);
  } else if (output.components != width || output.count != groups * keys) {
    throw invalid_input(name + " has " + std::to_string(output.count) + " outputs of " +
                        std::to_string(output.components) + " components for " + std::to_string(keys) +
                        " keys; expected " + std::to_string(groups * keys) + " of " + std::to_string(width));
  }
  for (double v : output.values)
    if (!std::isfinite(v)) throw invalid_input(name + " has a non-finite output value");
  sampler.width = width;
  sampler.values = std::move(output.values);
  return sampler;
}

}  // namespace deformseg::io::internal::gltf
