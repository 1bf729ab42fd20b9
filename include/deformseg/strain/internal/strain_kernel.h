// The per-triangle strain kernel behind compute_strain (strain/strain.h).
//
// For a reference triangle x0 x1 x2 with edges E1 = x1 - x0, E2 = x2 - x0, take the orthonormal
// basis of its plane e1 = E1 / |E1|, e2 = H / |H| with H = E2 - mu E1, mu = E1.E2 / |E1|^2, the
// height vector. The affine map onto the deformed triangle y0 y1 y2 (edges d1, d2) sends e1 and e2
// to
//     u = alpha d1,   v = beta d2 + gamma d1,   alpha = 1/|E1|, beta = 1/|H|, gamma = -mu/|H|,
// the columns of the 3x2 deformation gradient F = Ds Dm^-1 (the manual's chapter 11) in that basis, so
// C = F^T F = [u.u u.v; u.v v.v]: the brief's C = A^T G A (A = Dm^-1, G the Gram matrix of the
// deformed edges) with A applied to the edges before the dot products. For a sliver (height h,
// length L) the entries of A are ~L/h: A^T G A cancels terms ~(L/h)^2, beta d2 + gamma d1 terms
// ~L/h, and in double. The kernel runs a block of triangles at a time through three loops:
//  1. gather (scalar): the edges d1, d2 of each triangle, in double, from the frame's positions;
//  2. transform (double, vectorised): u, v, then a = |u|^2 - 1, b = |v|^2 - 1, c = u.v (the
//     entries of C - I, without the cancellation float would suffer for small strains) and
//     det C = |u|^2 |v|^2 - (u.v)^2, rounded once to the kernel's Value type;
//  3. measure (Value, vectorised): the eigenvalues of C as 1 + m with
//     m1,2 = (a + b +- sqrt((a - b)^2 + 4 c^2)) / 2, l1 = sqrt(1 + m1), l2 = sqrt(det C) / l1,
//     l - 1 = m / (l + 1), then the measure and, if asked, the principal direction.
// Every step after the transform is well conditioned, so a float strain is within a few float
// rounding errors of the exact strain of the double positions, relatively, slivers and small
// strains included.
#pragma once

#include <deformseg/internal/parallel_for.h>
#include <deformseg/strain/internal/strain_math.h>
#include <deformseg/strain/strain_measures.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::strain::internal {

using Triangle_indices = std::array<std::uint32_t, 3>;

// The triangles, each rotated to start at its smallest vertex index: the strain does not depend on
// where a face's halfedge cycle starts, and its rounding then does not either, so that graphs
// whose cycles start elsewhere (Surface_mesh, Polyhedron_3) give bit-identical fields.
inline std::vector<Triangle_indices> canonical_triangles(std::span<const Triangle_indices> triangles) {
  std::vector<Triangle_indices> canonical(triangles.begin(), triangles.end());
  for (auto& t : canonical)
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return canonical;
}

// Triangles per block of the kernel: the block's deformed bases fit in L1 (6 x 256 values).
inline constexpr std::size_t strain_block = 256;
// Triangles per work item handed to a thread: a few blocks, to amortise scheduling.
inline constexpr std::size_t strain_chunk = 8 * strain_block;

// Bounds on |a|, |b|, |c| (entries of C - I), and det C <= bound^2, under which nothing in the
// measure stage overflows ((a - b)^2 + 4 c^2 <= 8 bound^2, m1 m2 <= 4 bound^2 stay finite).
// Stretches this large (1e9 for float, 1e75 for double) have no meaning; they saturate, and inf
// or NaN from absurd input (coordinates near the end of the double range) become the bound.
template <std::floating_point Value>
inline constexpr Value saturation_bound = sizeof(Value) == 4 ? Value(0x1p60) : Value(0x1p500);

struct Vector3 {
  double x, y, z;
};

inline Vector3 operator-(const Vector3& a, const Vector3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline double dot(const Vector3& a, const Vector3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class Coordinate>
inline Vector3 point(const Coordinate* xyz, std::uint32_t vertex) {
  const Coordinate* p = xyz + 3 * std::size_t(vertex);
  return {double(p[0]), double(p[1]), double(p[2])};
}

// The edges E1 = x1 - x0 and E2 = x2 - x0 of a triangle, in double.
template <class Coordinate>
inline std::array<Vector3, 2> edges(const Coordinate* xyz, const Triangle_indices& t) {
  const Vector3 x0 = point(xyz, t[0]);
  return {point(xyz, t[1]) - x0, point(xyz, t[2]) - x0};
}

// What stage A needs of a reference triangle (see the top of this file).
struct Reference_basis {
  double alpha = 0, beta = 0, gamma = 0;
  bool degenerate = true;
};

// The reference basis of a triangle with edges e1, e2; degenerate when twice its area
// |E1 x E2| is at most `tolerance` times its longest edge squared (then all coefficients are 0).
inline Reference_basis reference_basis(const Vector3& e1, const Vector3& e2, double tolerance) {
  const double e1_squared = dot(e1, e1);
  const double e2_squared = dot(e2, e2);
  const Vector3 e3 = e2 - e1;
  const double longest_squared = std::max({e1_squared, e2_squared, dot(e3, e3)});
  const Vector3 normal = cross(e1, e2);
  const double twice_area = std::sqrt(dot(normal, normal));
  if (!(twice_area > tolerance * longest_squared)) return {};
  const double e1_length = std::sqrt(e1_squared);
  const double height = twice_area / e1_length;
  const double mu = dot(e1, e2) / e1_squared;
  return {1 / e1_length, 1 / height, -mu / height, false};
}

// The reference bases of all triangles of one pose, structure of arrays.
struct Reference_bases {
  std::vector<double> alpha, beta, gamma;
  std::vector<std::uint32_t> degenerate;  // indices of the degenerate triangles, ascending
};

// Stage 1's output: the deformed edges of a block of triangles, structure of arrays.
struct Edge_block {
  alignas(64) std::array<double, strain_block> d1x, d1y, d1z, d2x, d2y, d2z;
};

// Stage 2's output: C - I and det C (and u, v, for the principal directions) of a block.
template <std::floating_point Value>
struct Cauchy_green_block {
  alignas(64) std::array<Value, strain_block> a, b, c, det;
  alignas(64) std::array<Value, strain_block> ux, uy, uz, vx, vy, vz;
};

// Stage 1: the edges y1 - y0 and y2 - y0 of triangles [0, count), from positions `xyz`.
template <class Coordinate>
void gather_edges(const Coordinate* xyz, const Triangle_indices* triangles, std::size_t count, Edge_block& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const auto [d1, d2] = edges(xyz, triangles[k]);
    out.d1x[k] = d1.x;
    out.d1y[k] = d1.y;
    out.d1z[k] = d1.z;
    out.d2x[k] = d2.x;
    out.d2y[k] = d2.y;
    out.d2z[k] = d2.z;
  }
}

// Stage 2: u = alpha d1, v = beta d2 + gamma d1, then C - I and det C, in double, rounded to Value.
template <bool with_directions, std::floating_point Value>
void cauchy_green(const Edge_block& e, const double* __restrict alpha, const double* __restrict beta,
                  const double* __restrict gamma, std::size_t count, Cauchy_green_block<Value>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const double ux = alpha[k] * e.d1x[k];
    const double uy = alpha[k] * e.d1y[k];
    const double uz = alpha[k] * e.d1z[k];
    const double vx = beta[k] * e.d2x[k] + gamma[k] * e.d1x[k];
    const double vy = beta[k] * e.d2y[k] + gamma[k] * e.d1y[k];
    const double vz = beta[k] * e.d2z[k] + gamma[k] * e.d1z[k];
    const double uu = ux * ux + uy * uy + uz * uz;
    const double vv = vx * vx + vy * vy + vz * vz;
    const double uv = ux * vx + uy * vy + uz * vz;
    out.a[k] = Value(uu - 1);
    out.b[k] = Value(vv - 1);
    out.c[k] = Value(uv);
    // |u x v|^2 by Lagrange's identity: in double, its cancellation costs float precision only
    // for a triangle squashed to a 1e-4 of its width, whose strain it hardly changes.
    out.det[k] = Value(uu * vv - uv * uv);
    if constexpr (with_directions) {
      out.ux[k] = Value(ux);
      out.uy[k] = Value(uy);
      out.uz[k] = Value(uz);
      out.vx[k] = Value(vx);
      out.vy[k] = Value(vy);
      out.vz[k] = Value(vz);
    }
  }
}

// 1 when |x| > bound or x is NaN, else 0, by the bits: an integer OR-reduction of these
// vectorises, where a floating-point clamp in the loop would not.
template <std::floating_point Value>
inline Float_bits<Value> beyond(Value x, Value bound) {
  using Bits = Float_bits<Value>;
  constexpr Bits magnitude = ~Bits(0) >> 1;
  return (std::bit_cast<Bits>(x) & magnitude) > std::bit_cast<Bits>(bound) ? Bits(1) : Bits(0);
}

// x limited to [-bound, bound], NaN to bound.
template <std::floating_point Value>
inline Value saturate(Value x, Value bound) {
  return x >= -bound ? (x <= bound ? x : bound) : (x < -bound ? -bound : bound);
}

// Saturates a block's C - I, det C and u, v when any is out of bounds (a rare, scalar path).
template <bool with_directions, std::floating_point Value>
void saturate_block(Cauchy_green_block<Value>& g, std::size_t count) {
  constexpr Value bound = saturation_bound<Value>;
  constexpr Value det_bound = bound * bound;
  const Value stretch_bound = sqrt_nonnegative(bound);
  Float_bits<Value> out_of_bounds = 0;
  for (std::size_t k = 0; k < count; ++k)
    out_of_bounds |= beyond(g.a[k], bound) | beyond(g.b[k], bound) | beyond(g.c[k], bound) |
                     beyond(g.det[k], det_bound);
  if constexpr (with_directions)
    for (std::size_t k = 0; k < count; ++k)
      out_of_bounds |= beyond(g.ux[k], stretch_bound) | beyond(g.uy[k], stretch_bound) |
                       beyond(g.uz[k], stretch_bound) | beyond(g.vx[k], stretch_bound) |
                       beyond(g.vy[k], stretch_bound) | beyond(g.vz[k], stretch_bound);
  if (!out_of_bounds) return;
  for (std::size_t k = 0; k < count; ++k) {
    g.a[k] = saturate(g.a[k], bound);
    g.b[k] = saturate(g.b[k], bound);
    g.c[k] = saturate(g.c[k], bound);
    g.det[k] = saturate(g.det[k], det_bound);
    if constexpr (with_directions)
      for (auto* component : {&g.ux, &g.uy, &g.uz, &g.vx, &g.vy, &g.vz})
        (*component)[k] = saturate((*component)[k], stretch_bound);
  }
}

// Where a per-frame result goes: the strain of each triangle and, optionally, its principal
// direction as three arrays (x, y, z), all indexed like the block's triangles.
template <std::floating_point Value>
struct Frame_output {
  Value* strain;
  Value* direction_x = nullptr;
  Value* direction_y = nullptr;
  Value* direction_z = nullptr;

  Frame_output advanced(std::size_t k) const {
    if (!direction_x) return {strain + k};
    return {strain + k, direction_x + k, direction_y + k, direction_z + k};
  }
};

// The principal stretches of one triangle from C - I = [a c; c b] and det C, and what the
// principal direction needs.
template <std::floating_point T>
struct Stretch {
  Principal_stretches<T> principal;
  T a_minus_b, c, disc;
};

template <std::floating_point T>
inline Stretch<T> stretch(T a, T b, T c, T det) {
  const T d = a - b;
  const T t = a + b;
  const T disc = sqrt_nonnegative(d * d + T(4) * c * c);
  const T m1 = T(0.5) * (t + disc);  // lambda1 - 1, no cancellation
  const T m2 = T(0.5) * (t - disc);  // lambda2 - 1, cancels only where m1 dominates the strain
  // Rounding may take a 0 (a triangle collapsed to a point or a segment) a hair below 0.
  const T lambda1 = max_zero(T(1) + m1);
  const T r1 = rsqrt_nonnegative(lambda1);  // finite for lambda1 = 0, when det = 0 too
  const T l1 = lambda1 * r1;
  const T area_ratio = sqrt_nonnegative(max_zero(det));
  const T l2 = std::min(area_ratio * r1, l1);  // det C / l1, relatively exact even near 0
  // l - 1 = m / (l + 1), one division for both; J - 1 = (J^2 - 1) / (J + 1) with
  // J^2 - 1 = m1 + m2 + m1 m2, its own division (dropped, like every unused field, when the measure
  // does not read it).
  const T p1 = l1 + T(1), p2 = l2 + T(1);
  const T q = T(1) / (p1 * p2);
  return {{.stretch1 = l1,
           .stretch2 = l2,
           .strain1 = m1 * p2 * q,
           .strain2 = m2 * p1 * q,
           .lambda1 = lambda1,
           .lambda2 = l2 * l2,
           .green1 = T(0.5) * m1,
           .green2 = T(0.5) * m2,
           .area_ratio = area_ratio,
           .area_change = (t + m1 * m2) / (area_ratio + T(1))},
          d, c, disc};
}

// Below this relative difference (l1^2 - l2^2) / l1^2, a triangle has no principal direction: its
// direction would be rounding noise (a rigid or uniformly scaled triangle).
template <std::floating_point T>
inline constexpr T isotropy_tolerance = T(1e-6);

// The unit vector along which the triangle is stretched most, in its deformed plane: F n1 with n1
// the eigenvector of C for lambda1, taken from whichever column of C - lambda2 I has no
// cancellation. Where l1 ~ l2 there is no such direction: the first edge's, or 0 when collapsed.
template <std::floating_point T>
inline std::array<T, 3> principal_direction(const Stretch<T>& s, T ux, T uy, T uz, T vx, T vy, T vz) {
  const bool first_column = s.a_minus_b >= T(0);
  const T a0 = first_column ? s.a_minus_b + s.disc : T(2) * s.c;
  const T b0 = first_column ? T(2) * s.c : s.disc - s.a_minus_b;
  const T unit = rsqrt_nonnegative(a0 * a0 + b0 * b0);  // (a, b) of length 1 or 0, for range
  const bool isotropic = s.disc <= isotropy_tolerance<T> * s.principal.lambda1;
  const T a = isotropic ? T(1) : a0 * unit;
  const T b = isotropic ? T(0) : b0 * unit;
  const T wx = a * ux + b * vx, wy = a * uy + b * vy, wz = a * uz + b * vz;
  const T length = rsqrt_nonnegative(wx * wx + wy * wy + wz * wz);  // finite for w = 0: then 0
  return {wx * length, wy * length, wz * length};
}

// Stage 3: the strain (and direction) of the `count` triangles of a block. The loop is what
// vectorises; keep it free of branches and of calls that are not inlined.
template <bool with_directions, std::floating_point Value, StrainMeasure Measure>
void measure_block(const Cauchy_green_block<Value>& g, std::size_t count, const Measure& measure,
                   const Frame_output<Value>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const Stretch<Value> s = stretch(g.a[k], g.b[k], g.c[k], g.det[k]);
    out.strain[k] = measure(s.principal);
    if constexpr (with_directions) {
      const auto w = principal_direction(s, g.ux[k], g.uy[k], g.uz[k], g.vx[k], g.vy[k], g.vz[k]);
      out.direction_x[k] = w[0];
      out.direction_y[k] = w[1];
      out.direction_z[k] = w[2];
    }
  }
}

// Strain 0 and direction 0 for the triangles in `indices` that fall in [first, first + count).
template <std::floating_point Value>
void zero_degenerate(std::span<const std::uint32_t> indices, std::size_t first, std::size_t count,
                     const Frame_output<Value>& out) {
  auto it = std::lower_bound(indices.begin(), indices.end(), first);
  for (; it != indices.end() && *it < first + count; ++it) {
    const std::size_t k = *it - first;
    out.strain[k] = 0;
    if (out.direction_x) out.direction_x[k] = out.direction_y[k] = out.direction_z[k] = 0;
  }
}

// A frame whose strain is 0 by definition (the reference frame itself, frame 0 of previous-pose
// strain): strain 0, direction along the first edge (0 for a degenerate triangle).
template <std::floating_point Value, class Coordinate>
void zero_frame(const Coordinate* xyz, const Triangle_indices* triangles, std::size_t count,
                const Frame_output<Value>& out) {
  std::fill(out.strain, out.strain + count, Value(0));
  if (!out.direction_x) return;
  for (std::size_t k = 0; k < count; ++k) {
    const Vector3 e = edges(xyz, triangles[k])[0];
    const double length = std::sqrt(dot(e, e));
    const double scale = length > 0 ? 1 / length : 0;
    out.direction_x[k] = Value(e.x * scale);
    out.direction_y[k] = Value(e.y * scale);
    out.direction_z[k] = Value(e.z * scale);
  }
}

// One frame's triangles [first, first + count) against the reference `bases`, block by block.
template <bool with_directions, std::floating_point Value, class Coordinate, StrainMeasure Measure>
void strains_against(const Coordinate* xyz, std::span<const Triangle_indices> triangles,
                     const Reference_bases& bases, std::size_t first, std::size_t count,
                     const Measure& measure, const Frame_output<Value>& out) {
  Edge_block edge_block;
  Cauchy_green_block<Value> green;
  for (std::size_t done = 0; done < count; done += strain_block) {
    const std::size_t j = first + done;
    const std::size_t n = std::min(strain_block, count - done);
    gather_edges(xyz, triangles.data() + j, n, edge_block);
    cauchy_green<with_directions>(edge_block, bases.alpha.data() + j, bases.beta.data() + j, bases.gamma.data() + j,
                                  n, green);
    saturate_block<with_directions>(green, n);
    measure_block<with_directions>(green, n, measure, out.advanced(done));
  }
  zero_degenerate<Value>(bases.degenerate, first, count, out);
}

template <std::floating_point Value, class Coordinate, StrainMeasure Measure>
void strains_against(const Coordinate* xyz, std::span<const Triangle_indices> triangles,
                     const Reference_bases& bases, std::size_t first, std::size_t count,
                     const Measure& measure, const Frame_output<Value>& out) {
  if (out.direction_x)
    strains_against<true>(xyz, triangles, bases, first, count, measure, out);
  else
    strains_against<false>(xyz, triangles, bases, first, count, measure, out);
}

// Runs `work(item)` for item in [0, items) on `threads` threads (0: the default), and gives the
// sum of what the calls return (an integer sum, so the same for any number of threads).
template <class Work>
std::size_t parallel_sum(std::size_t items, int threads, const Work& work) {
  const auto sums = deformseg::internal::parallel_for_with_locals(items, threads, 1, [] { return std::size_t(0); },
                                             [&](std::size_t& sum, std::size_t item) { sum += work(item); });
  std::size_t sum = 0;
  for (const std::size_t s : sums) sum += s;
  return sum;
}

// The frame and the first triangle of work item `item`, the items of (frame, chunk of triangles)
// taken chunk after chunk: the items a thread takes one after another then share a chunk, whose
// triangles, reference bases and (for previous-pose strain) positions at the frame before stay in
// its cache, and memory traffic is the positions of each frame, once.
inline std::pair<std::size_t, std::size_t> work_item(std::size_t item, std::size_t frames) {
  return {item % frames, item / frames * strain_chunk};
}

// The reference bases of `triangles` at the positions `xyz`, on `threads` threads.
template <class Coordinate>
Reference_bases reference_bases(const Coordinate* xyz, std::span<const Triangle_indices> triangles,
                                double tolerance, int threads) {
  const std::size_t count = triangles.size();
  Reference_bases bases{std::vector<double>(count), std::vector<double>(count), std::vector<double>(count), {}};
  std::vector<std::uint8_t> degenerate(count);
  const auto fill = [&](std::size_t first, std::size_t last) {
    for (std::size_t j = first; j < last; ++j) {
      const auto [e1, e2] = edges(xyz, triangles[j]);
      const Reference_basis b = reference_basis(e1, e2, tolerance);
      bases.alpha[j] = b.alpha;
      bases.beta[j] = b.beta;
      bases.gamma[j] = b.gamma;
      degenerate[j] = b.degenerate;
    }
  };
  if (threads == 1) {
    fill(0, count);
  } else {
    const std::size_t chunks = (count + strain_chunk - 1) / strain_chunk;
    parallel_sum(chunks, threads, [&](std::size_t c) -> std::size_t {
      fill(c * strain_chunk, std::min(count, (c + 1) * strain_chunk));
      return 0;
    });
  }
  for (std::size_t j = 0; j < count; ++j)
    if (degenerate[j]) bases.degenerate.push_back(std::uint32_t(j));
  return bases;
}

// Where the field's frame t goes, in arrays of F x T strains and T blocks of 3 F direction
// components (x of every triangle, then y, then z).
template <std::floating_point Value>
Frame_output<Value> frame_output(Value* strain, Value* directions, std::size_t faces, std::size_t t) {
  if (!directions) return {strain + t * faces};
  Value* d = directions + 3 * t * faces;
  return {strain + t * faces, d, d + faces, d + 2 * faces};
}

// Strain of every frame against one fixed reference (rest pose or a given mesh). `zero` is the
// frame whose strain is 0 by definition, if any. Returns the number of degenerate triangle-frames.
template <std::floating_point Value, class Coordinate, StrainMeasure Measure>
std::size_t fixed_reference_strains(std::span<const Coordinate> positions, std::size_t frames,
                                    std::span<const Triangle_indices> triangles, const Reference_bases& bases,
                                    std::optional<std::size_t> zero, const Measure& measure, int threads,
                                    Value* strain, Value* directions) {
  const std::size_t faces = triangles.size();
  const std::size_t block = positions.size() / frames;
  const std::size_t chunks = (faces + strain_chunk - 1) / strain_chunk;
  parallel_sum(frames * chunks, threads, [&](std::size_t item) -> std::size_t {
    const auto [t, first] = work_item(item, frames);
    const std::size_t count = std::min(strain_chunk, faces - first);
    const Coordinate* xyz = positions.data() + t * block;
    const Frame_output<Value> out = frame_output(strain, directions, faces, t).advanced(first);
    if (t == zero) {
      zero_frame(xyz, triangles.data() + first, count, out);
      zero_degenerate<Value>(bases.degenerate, first, count, out);
    } else
      strains_against(xyz, triangles, bases, first, count, measure, out);
    return 0;
  });
  return bases.degenerate.size() * (zero ? frames - 1 : frames);
}

// Strain of every frame t >= 1 against frame t - 1 (frame 0 is 0 by definition). Returns the
// number of degenerate triangle-frames.
template <std::floating_point Value, class Coordinate, StrainMeasure Measure>
std::size_t previous_pose_strains(std::span<const Coordinate> positions, std::size_t frames,
                                  std::span<const Triangle_indices> triangles, double tolerance,
                                  const Measure& measure, int threads, Value* strain, Value* directions) {
  const std::size_t faces = triangles.size();
  const std::size_t block = positions.size() / frames;
  const std::size_t chunks = (faces + strain_chunk - 1) / strain_chunk;
  return parallel_sum(frames * chunks, threads, [&](std::size_t item) -> std::size_t {
    const auto [t, first] = work_item(item, frames);
    const std::size_t count = std::min(strain_chunk, faces - first);
    const Coordinate* xyz = positions.data() + t * block;
    const Frame_output<Value> out = frame_output(strain, directions, faces, t).advanced(first);
    if (t == 0) {
      zero_frame(xyz, triangles.data() + first, count, out);
      return 0;
    }
    // The reference of this chunk: its triangles at frame t - 1, indexed from `first`.
    const auto chunk_triangles = triangles.subspan(first, count);
    Reference_bases bases = reference_bases(xyz - block, chunk_triangles, tolerance, 1);
    strains_against(xyz, chunk_triangles, bases, 0, count, measure, out);
    return bases.degenerate.size();
  });
}

}  // namespace deformseg::strain::internal
