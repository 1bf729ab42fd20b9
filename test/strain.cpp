// Tests of strain.h, strain_measures.h and strain_normalization.h: compute_strain on animations
// whose strains are known in closed form, against an independent long double computation, on the
// bending tube's ground truth, across mesh types and thread counts, and on bad input.
#include "test_support.h"
#include "mesh_types.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/strain/internal/strain_math.h>
#include <deformseg/strain/strain.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/threads.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <vector>

using namespace deformseg;
using deformseg::strain::internal::one_minus_exp_neg;
using deformseg::strain::internal::sqrt_nonnegative;
using deformseg::strain::internal::statistics_block;
using deformseg::strain::internal::strain_chunk;

namespace {

using test::Polyhedron;
using Vector3 = Eigen::Vector3d;
using Map = std::function<Vector3(const Vector3&)>;
using deformseg::test::right_angle;

// A flat grid of n x n squares (two triangles each) in the plane z = 0, centred on the origin.
struct Grid {
  std::vector<Vector3> points;
  std::vector<std::array<int, 3>> triangles;
};

Grid flat_grid(int n) {
  Grid g;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) g.points.emplace_back(double(j) / n - 0.5, double(i) / n - 0.5, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
      g.triangles.push_back({a, b, d});
      g.triangles.push_back({a, d, c});
    }
  return g;
}

// The rest shape of the default bending tube, as a grid-like point set.
Grid tube_shape() {
  mesh::Bending_tube spec;
  const auto tube = mesh::make_bending_tube(spec);
  Grid g;
  const auto frame = tube.animation.frame_matrix(0);
  for (Eigen::Index i = 0; i < frame.cols(); ++i) g.points.emplace_back(frame.col(i));
  for (const auto& t : tube.animation.triangles()) g.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
  return g;
}

// An animation of `shape` with one frame per map, each frame the map applied to every point.
template <class Graph = mesh::Surface_mesh>
mesh::Deforming_mesh<Graph> animate(const Grid& shape, const std::vector<Map>& frames) {
  std::vector<std::array<double, 3>> points;
  for (const auto& p : shape.points) points.push_back({p.x(), p.y(), p.z()});
  std::vector<double> positions;
  for (const auto& map : frames)
    for (const auto& p : shape.points) {
      const Vector3 q = map(p);
      positions.insert(positions.end(), {q.x(), q.y(), q.z()});
    }
  return mesh::Deforming_mesh<Graph>(mesh::make_face_graph<Graph>(points, shape.triangles), std::move(positions));
}

Map identity() {
  return [](const Vector3& p) { return p; };
}

// A rigid motion: rotation by `angle` about `axis`, then translation.
Map rigid(double angle, const Vector3& axis, const Vector3& translation) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return [r, translation](const Vector3& p) { return Vector3(r * p + translation); };
}

// A linear map, then a rigid motion.
Map linear_map(const Eigen::Matrix3d& m, const Map& then = identity()) {
  return [m, then](const Vector3& p) { return then(m * p); };
}

using Gaussian = strain::Gaussian_normalization;

strain::Strain_options raw() { return {.normalization = strain::No_normalization{}}; }

strain::Strain_options raw_with(strain::Strain_measure_choice measure) {
  return {.measure = measure, .normalization = strain::No_normalization{}};
}

// The largest strain magnitude of a field over all triangles and frames.
template <class Value>
double largest(const strain::Strain_field<Value>& field) {
  double m = 0;
  for (Value v : field.values()) m = std::max(m, double(std::abs(v)));
  return m;
}

// The largest |a - b| / max(|b|, floor) over two fields: their relative difference, where strains
// below `floor` (the rounding of rigid triangles) count as that large.
template <class A, class B>
double largest_relative_difference(const strain::Strain_field<A>& a, const strain::Strain_field<B>& b,
                                   double floor = 1e-9) {
  double m = 0;
  for (std::size_t t = 0; t < a.num_frames(); ++t)
    for (std::size_t j = 0; j < a.num_faces(); ++j)
      m = std::max(m, std::abs(double(a(j, t)) - double(b(j, t))) / std::max(floor, std::abs(double(b(j, t)))));
  return m;
}

// Principal stretches l1 >= l2 of the affine map between two triangles, computed the way
// METHOD.md describes it, independently of the library: each triangle in a 2-D frame of its own
// (e1 along its first edge), F = Ds Dm^-1, and the closed-form singular values of a 2x2 matrix,
// all in long double.
using Real = long double;
using Vector3r = Eigen::Matrix<Real, 3, 1>;
using Matrix2r = Eigen::Matrix<Real, 2, 2>;

Matrix2r edge_matrix(const Vector3r& x0, const Vector3r& x1, const Vector3r& x2) {
  const Vector3r e1 = x1 - x0, e2 = x2 - x0;
  const Vector3r a = e1.normalized();
  const Vector3r b = (e2 - e2.dot(a) * a).normalized();
  Matrix2r d;
  d << e1.dot(a), e2.dot(a), 0, e2.dot(b);
  return d;
}

std::array<Real, 2> principal_stretches(const std::array<Vector3r, 3>& x, const std::array<Vector3r, 3>& y) {
  const Matrix2r f = edge_matrix(y[0], y[1], y[2]) * edge_matrix(x[0], x[1], x[2]).inverse();
  const Real a = f(0, 0), b = f(0, 1), c = f(1, 0), d = f(1, 1);
  const Real p = std::sqrt((a + d) * (a + d) + (c - b) * (c - b));
  const Real q = std::sqrt((a - d) * (a - d) + (c + b) * (c + b));
  return {(p + q) / 2, (p - q) / 2};
}

}  // namespace

static_assert(strain::StrainMeasure<strain::Max_principal_strain>);
static_assert(strain::StrainMeasure<strain::Green_lagrange_strain>);
static_assert(strain::StrainMeasure<strain::Frobenius_strain>);
static_assert(strain::StrainMeasure<strain::Area_ratio_strain>);
static_assert(!strain::StrainMeasure<int>);
static_assert(strain::StrainNormalization<strain::Gaussian_normalization>);
static_assert(strain::StrainNormalization<strain::No_normalization>);
static_assert(!strain::StrainNormalization<strain::Max_principal_strain>);

namespace {
// A measure that answers in double for float stretches does not model StrainMeasure.
struct Double_only_measure {
  template <class T>
  double operator()(const strain::Principal_stretches<T>&) const {
    return 0;
  }
};
// A user's measure: the signed largest stretch.
struct Largest_stretch {
  template <std::floating_point T>
  T operator()(const strain::Principal_stretches<T>& p) const {
    return p.strain1;
  }
};
// A user's normalisation: divide by the largest sample.
struct Divide_by_largest {
  template <std::floating_point Value>
  std::optional<double> normalize(const strain::Raw_strain_field<Value>& field) const {
    double largest = 0;
    for (const auto& run : field.samples())
      for (Value v : run) largest = std::max(largest, double(v));
    for (Value& v : field.values) v = Value(double(v) / largest);
    return largest;
  }
};
}  // namespace

static_assert(!strain::StrainMeasure<Double_only_measure>);
static_assert(strain::StrainMeasure<Largest_stretch>);
static_assert(strain::StrainNormalization<Divide_by_largest>);

TEST_CASE("strain math: vectorisable sqrt and 1 - exp(-y) within 2 ulp", "[strain][math]") {
  const auto ulps = [](auto value, auto exact) {
    using T = decltype(exact);
    const T step = std::nextafter(std::abs(exact), std::numeric_limits<T>::infinity()) - std::abs(exact);
    return std::abs(double(value) - double(exact)) / double(step);
  };
  double worst_sqrt = 0, worst_exp = 0;
  for (std::uint32_t bits = 0x00800000u; bits < 0x7f800000u; bits += 4099) {
    const float x = std::bit_cast<float>(bits);
    worst_sqrt = std::max(worst_sqrt, ulps(sqrt_nonnegative(x), std::sqrt(x)));
  }
  for (std::uint32_t bits = 0; bits < std::bit_cast<std::uint32_t>(100.0f); bits += 4099) {
    const float y = std::bit_cast<float>(bits);
    worst_exp =
        std::max(worst_exp, ulps(one_minus_exp_neg(y), float(-std::expm1(-double(y)))));
  }
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(1, 2);
  for (int i = 0; i < 200000; ++i) {
    const double x = std::ldexp(mantissa(random), int(random() % 1200) - 600);
    worst_sqrt = std::max(worst_sqrt, ulps(sqrt_nonnegative(x), std::sqrt(x)));
    const double y = std::ldexp(mantissa(random), int(random() % 70) - 62);
    worst_exp = std::max(worst_exp, ulps(one_minus_exp_neg(y), -std::expm1(-y)));
  }
  CHECK(worst_sqrt <= 1);
  CHECK(worst_exp <= 2);
  CHECK(sqrt_nonnegative(0.0f) == 0.0f);
  CHECK(sqrt_nonnegative(0.0) == 0.0);
  CHECK(one_minus_exp_neg(0.0f) == 0.0f);
  CHECK(one_minus_exp_neg(1e30f) == 1.0f);
  CHECK(one_minus_exp_neg(std::numeric_limits<double>::infinity()) == 1.0);
}

TEST_CASE("strain: a rigid motion of every frame gives 0 for every measure", "[strain]") {
  const Grid shape = tube_shape();
  const auto animation = animate(shape, {identity(), rigid(0.7, {1, 2, 3}, {0.1, -0.2, 0.3}),
                                         rigid(2.5, {-1, 0, 1}, {1000, 2000, -3000}),
                                         rigid(-1.2, {0, 1, 0}, {1e-3, 0, 5})});
  // Rounding of the rotated positions (1e-16 of coordinates up to 3000) over edges of 0.01.
  constexpr double tolerance = 1e-9;
  CHECK(largest(strain::compute_strain(animation, raw())) < tolerance);
  CHECK(largest(strain::compute_strain(animation, raw_with(strain::Green_lagrange_strain{}))) < tolerance);
  CHECK(largest(strain::compute_strain(animation, raw_with(strain::Frobenius_strain{}))) < tolerance);
  CHECK(largest(strain::compute_strain(animation, raw_with(strain::Area_ratio_strain{}))) < tolerance);
  CHECK(largest(strain::compute_strain<double>(animation, raw())) < tolerance);
  CHECK(largest(strain::compute_strain(animation, {.reference = strain::Strain_reference::previous_pose,
                                           .normalization = Gaussian{.sigma = 0.1}})) < 1e-12);
}

TEST_CASE("strain: a uniform scale of the whole sequence gives the same field", "[strain]") {
  mesh::Bending_tube spec;
  spec.schedule = {{6, {right_angle}}, {6, {-0.4}}};
  const auto plain = mesh::make_bending_tube(spec);
  spec.placement.scale = 37.5;
  const auto scaled = mesh::make_bending_tube(spec);
  for (auto reference : {strain::Strain_reference::rest_pose, strain::Strain_reference::previous_pose}) {
    const auto a = strain::compute_strain(plain.animation, {.reference = reference});
    const auto b = strain::compute_strain(scaled.animation, {.reference = reference});
    CHECK(*a.sigma() == Approx(*b.sigma()).epsilon(1e-6));
    CHECK(largest_relative_difference(a, b) < 1e-5);
    const auto c = strain::compute_strain(
        plain.animation, strain::Strain_options{.reference = reference, .measure = strain::Area_ratio_strain{}});
    const auto d = strain::compute_strain(
        scaled.animation, strain::Strain_options{.reference = reference, .measure = strain::Area_ratio_strain{}});
    CHECK(largest_relative_difference(c, d) < 1e-5);
  }
}

TEST_CASE("strain: a uniform stretch by a gives |a - 1|, and each measure its formula", "[strain]") {
  const std::array<double, 6> factors{0.25, 0.9, 0.999, 1.0001, 1.5, 4.0};
  std::vector<Map> frames{identity()};
  const Map place = rigid(0.4, {1, 1, 0}, {3, -4, 5});
  for (double a : factors) frames.push_back(linear_map(a * Eigen::Matrix3d::Identity(), place));
  // The tube (a closed surface: a uniform scale of space stretches every triangle by a in every
  // direction) and a flat grid in a tilted plane.
  for (const Grid& shape : {tube_shape(), flat_grid(6)}) {
    const auto animation = animate(shape, frames);
    const auto max_principal = strain::compute_strain(animation, raw());
    const auto green = strain::compute_strain(animation, raw_with(strain::Green_lagrange_strain{}));
    const auto frobenius = strain::compute_strain(animation, raw_with(strain::Frobenius_strain{}));
    const auto area = strain::compute_strain(animation, raw_with(strain::Area_ratio_strain{}));
    const auto exact = strain::compute_strain<double>(animation, raw());
    for (std::size_t t = 1; t < animation.num_frames(); ++t) {
      const double a = factors[t - 1];
      for (std::size_t j = 0; j < animation.num_faces(); ++j) {
        CHECK(max_principal(j, t) == Approx(std::abs(a - 1)).epsilon(1e-6));
        CHECK(exact(j, t) == Approx(std::abs(a - 1)).epsilon(1e-9));
        CHECK(green(j, t) == Approx(std::abs(a * a - 1) / 2).epsilon(1e-6));
        CHECK(frobenius(j, t) == Approx(std::sqrt(2.0) * std::abs(a - 1)).epsilon(1e-6));
        CHECK(area(j, t) == Approx(std::abs(a * a - 1)).epsilon(1e-6));
      }
    }
  }
}

TEST_CASE("strain: shears give their known principal stretches", "[strain]") {
  // A flat grid in z = 0 under the in-plane linear map M has F = M (restricted to the plane) for
  // every triangle. A simple shear M = [1 g; 0 1] has C = [1 g; g 1 + g^2], whose eigenvalues
  // l^2 = 1 + g^2/2 +- g sqrt(1 + g^2/4) give l1,2 = sqrt(1 + g^2/4) +- g/2 (l1 l2 = 1: area kept).
  // A pure shear M = diag(k, 1/k) has l1 = k, l2 = 1/k.
  const double g = 0.5, k = 1.25;
  Eigen::Matrix3d simple = Eigen::Matrix3d::Identity();
  simple(0, 1) = g;
  const Eigen::Matrix3d pure = Eigen::Vector3d(k, 1 / k, 1).asDiagonal();
  const Map place = rigid(1.1, {0.3, -1, 2}, {-7, 8, 9});
  const auto animation = animate(flat_grid(5), {place, linear_map(simple, place), linear_map(pure, place)});

  const double s1 = std::sqrt(1 + g * g / 4) + g / 2, s2 = std::sqrt(1 + g * g / 4) - g / 2;
  const std::array<std::array<double, 2>, 2> stretches{{{s1, s2}, {k, 1 / k}}};
  const auto max_principal = strain::compute_strain(animation, raw());
  const auto green = strain::compute_strain(animation, raw_with(strain::Green_lagrange_strain{}));
  const auto frobenius = strain::compute_strain(animation, raw_with(strain::Frobenius_strain{}));
  const auto area = strain::compute_strain(animation, raw_with(strain::Area_ratio_strain{}));
  for (std::size_t t = 1; t <= 2; ++t) {
    const auto [l1, l2] = stretches[t - 1];
    for (std::size_t j = 0; j < animation.num_faces(); ++j) {
      CHECK(max_principal(j, t) == Approx(std::max(l1 - 1, 1 - l2)).epsilon(1e-6));
      CHECK(green(j, t) == Approx(std::max(l1 * l1 - 1, 1 - l2 * l2) / 2).epsilon(1e-6));
      CHECK(frobenius(j, t) == Approx(std::hypot(l1 - 1, l2 - 1)).epsilon(1e-6));
      CHECK(area(j, t) < 1e-6);
    }
  }
  CHECK(max_principal(0, 1) == Approx(0.2807764064).epsilon(1e-6));  // (sqrt(17) + 1) / 4 - 1
}

TEST_CASE("strain: float strains are relatively exact against long double, slivers and small strains included",
          "[strain]") {
  // Random triangles, a tenth of them slivers of aspect 1e-4, each deformed by a random affine
  // map close to identity or not, moved far from the origin.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  Grid shape;
  std::vector<Map> frames{identity()};
  constexpr int count = 600;
  for (int i = 0; i < count; ++i) {
    const Vector3 x0(unit(random), unit(random), unit(random));
    const Vector3 e1 = 0.01 * Vector3(unit(random), unit(random), unit(random));
    Vector3 e2 = 0.01 * Vector3(unit(random), unit(random), unit(random));
    if (i % 10 == 0) e2 = 0.37 * e1 + 1e-4 * e1.norm() * e1.cross(e2).cross(e1).normalized();
    shape.points.insert(shape.points.end(), {x0, x0 + e1, x0 + e2});
    shape.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  for (double size : {1e-5, 1e-3, 0.3}) {
    Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) += size * unit(random);
    frames.push_back(linear_map(m, rigid(unit(random) * 3, {1, 2, 3}, {100, -200, 50})));
  }
  const auto animation = animate(shape, frames);
  const auto field = strain::compute_strain(animation, raw());
  const auto exact = strain::compute_strain<double>(animation, raw());
  double worst = 0, worst_exact = 0;
  for (std::size_t t = 1; t < animation.num_frames(); ++t)
    for (std::size_t j = 0; j < animation.num_faces(); ++j) {
      std::array<Vector3r, 3> x, y;
      for (int k = 0; k < 3; ++k) {
        const auto v = animation.triangles()[j][std::size_t(k)];
        x[std::size_t(k)] = animation.frame_matrix(0).col(v).cast<Real>();
        y[std::size_t(k)] = animation.frame_matrix(t).col(v).cast<Real>();
      }
      const auto [l1, l2] = principal_stretches(x, y);
      const double expected = double(std::max(l1 - 1, 1 - l2));
      worst = std::max(worst, std::abs(field(j, t) - expected) / expected);
      worst_exact = std::max(worst_exact, std::abs(exact(j, t) - expected) / expected);
    }
  // Strains from 1e-5 to 0.5. Both are limited by the slivers: their height vector cancels terms
  // L/h = 1e4 times larger, leaving 1e-16 L/h = 1e-12 absolute on strains of 1e-5 (float adds its
  // own rounding, a few 6e-8 relative).
  CHECK(worst < 1e-6);
  CHECK(worst_exact < 1e-6);
}

TEST_CASE("strain: principal directions follow the stretch, in the deformed plane", "[strain]") {
  const double theta = 0.6;
  const Vector3 along(std::cos(theta), std::sin(theta), 0);
  const Eigen::Matrix3d stretch = Eigen::Matrix3d::Identity() + 0.5 * along * along.transpose();
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.9, Vector3(1, -2, 0.5).normalized()).toRotationMatrix();
  const Map place = [turn](const Vector3& p) { return Vector3(turn * p + Vector3(4, 5, 6)); };
  const Grid grid = flat_grid(4);
  const auto animation = animate(grid, {identity(), linear_map(stretch, place), place});
  const auto field = strain::compute_strain(animation, {.principal_directions = true});
  REQUIRE(field.has_principal_directions());
  const auto stretched = field.principal_directions(1);
  const auto rigid_frame = field.principal_directions(2);
  const auto rest_frame = field.principal_directions(0);
  for (std::size_t j = 0; j < animation.num_faces(); ++j) {
    const Eigen::Index row = Eigen::Index(j);
    const Vector3 d = stretched.row(row).cast<double>().transpose();
    CHECK(d.norm() == Approx(1).epsilon(1e-6));
    CHECK(std::abs(d.dot(turn * along)) == Approx(1).epsilon(1e-6));
    // No preferred direction: the first edge's, at the frame's position.
    const auto& tri = animation.triangles()[j];
    const Vector3 edge = (animation.frame_matrix(2).col(tri[1]) - animation.frame_matrix(2).col(tri[0])).normalized();
    CHECK((rigid_frame.row(row).cast<double>().transpose() - edge).norm() < 1e-6);
    const Vector3 rest_edge = (grid.points[std::size_t(tri[1])] - grid.points[std::size_t(tri[0])]).normalized();
    CHECK((rest_frame.row(row).cast<double>().transpose() - rest_edge).norm() < 1e-6);
  }
  // Directions do not change the strains.
  const auto without = strain::compute_strain(animation);
  CHECK(std::equal(without.values().begin(), without.values().end(), field.values().begin()));
}

TEST_CASE("strain: on the bending tube, exactly the blend-zone triangles deform", "[strain]") {
  mesh::Bending_tube spec;
  spec.schedule = {{10, {0.0}}, {10, {right_angle}}, {10, {}}, {10, {0.0}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& a = tube.animation;
  const auto rest = strain::compute_strain(a, raw());
  const auto normalised = strain::compute_strain(a);
  const auto motion = strain::compute_strain(a, {.reference = strain::Strain_reference::previous_pose});
  const auto frame = a.frame_matrix(0);
  std::size_t middle_of_zone = 0;
  for (std::size_t j = 0; j < a.num_faces(); ++j) {
    double rigid_strain = 0;
    for (std::size_t t = 0; t < a.num_frames(); ++t) rigid_strain = std::max(rigid_strain, double(rest(j, t)));
    if (tube.face_joint[j] < 0) {
      CHECK(rigid_strain < 1e-9);
      for (std::size_t t = 0; t < a.num_frames(); ++t) CHECK(normalised(j, t) < 1e-9f);
    } else if (std::abs(frame.col(a.triangles()[j][0]).z() - 0.5) < 0.03) {
      ++middle_of_zone;
      CHECK(rest(j, 25) > 1e-2);      // bent and held
      CHECK(rest(j, 5) < 1e-9);       // not yet bent
      CHECK(normalised(j, 25) > 1e-3f);
      CHECK(motion(j, 15) > 1e-4f);   // bending
      CHECK(motion(j, 25) < 1e-9f);   // held still
    }
  }
  CHECK(middle_of_zone > 0);
  CHECK(rest.degenerate_count() == 0);
}

TEMPLATE_LIST_TEST_CASE("strain: every mesh type gives the default model's field, to the last bit", "[strain][mesh_types]",
                        test::Mesh_types) {
  mesh::Bending_tube spec;
  spec.schedule = {{4, {right_angle}}, {4, {0.2}}};
  const auto tube = mesh::make_bending_tube(spec);
  const TestType on(tube.animation);
  static_assert(mesh::DeformingMesh<typename TestType::Model>);

  const auto same = [](const auto& a, const auto& b) {
    if (!std::ranges::equal(a.values(), b.values()) || a.sigma() != b.sigma() ||
        a.degenerate_count() != b.degenerate_count())
      return false;
    for (std::size_t t = 0; t < a.num_frames(); ++t)
      if (a.principal_directions(t) != b.principal_directions(t)) return false;
    return true;
  };
  for (auto reference : {strain::Strain_reference::rest_pose, strain::Strain_reference::previous_pose}) {
    const strain::Strain_options options{.reference = reference, .principal_directions = true};
    CHECK(same(strain::compute_strain(on.model(), options), strain::compute_strain(tube.animation, options)));
  }
  // Against a reference mesh: the type's own graph (its points are the rest frame's), for the type's
  // model and for the default model, against the default model's Surface_mesh.
  const strain::Strain_options options{.principal_directions = true};
  const auto& graph = on.model().face_graph();
  const auto expected = strain::compute_strain(tube.animation, tube.animation.face_graph(), options);
  CHECK(same(strain::compute_strain(on.model(), graph, options), expected));
  CHECK(same(strain::compute_strain(tube.animation, graph, options), expected));
  CHECK(std::ranges::equal(strain::compute_strain<double>(on.model(), graph).values(),
                           strain::compute_strain<double>(tube.animation, tube.animation.face_graph()).values()));
}

TEST_CASE("strain: one thread and all threads give bit-identical fields", "[strain][threads]") {
  mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 40, .rings = 120, .caps = true};
  spec.joints = {{.position = 0.3, .blend_width = 0.2}, {.position = 0.7, .blend_width = 0.1}};
  spec.schedule = {{9, {right_angle, 0.0}}, {9, {0.3, -right_angle}}, {5, {}}};
  const auto tube = mesh::make_bending_tube(spec);
  REQUIRE(tube.animation.num_faces() > 3 * strain_chunk);
  REQUIRE(tube.animation.num_faces() * tube.animation.num_frames() > 3 * statistics_block);

  const auto same = [](const auto& a, const auto& b) {
    return a.values().size() == b.values().size() &&
           std::memcmp(a.values().data(), b.values().data(), a.values().size_bytes()) == 0 &&
           a.sigma() == b.sigma() && a.degenerate_count() == b.degenerate_count();
  };
  for (auto reference : {strain::Strain_reference::rest_pose, strain::Strain_reference::previous_pose})
    for (auto statistic : {strain::Sigma_statistic::percentile, strain::Sigma_statistic::standard_deviation,
                           strain::Sigma_statistic::scaled_mad}) {
      const auto one = strain::compute_strain(tube.animation, {.reference = reference,
                                                        .normalization = Gaussian{.statistic = statistic},
                                                        .principal_directions = true,
                                                        .threads = 1});
      for (int threads : {2, 3, 0}) {
        const auto many = strain::compute_strain(tube.animation, {.reference = reference,
                                                           .normalization = Gaussian{.statistic = statistic},
                                                           .principal_directions = true,
                                                           .threads = threads});
        CHECK(same(one, many));
        for (std::size_t t = 0; t < one.num_frames(); t += 7)
          CHECK(one.principal_directions(t) == many.principal_directions(t));
      }
      const auto exact_one = strain::compute_strain<double>(tube.animation, {.reference = reference, .threads = 1});
      const auto exact_two = strain::compute_strain<double>(tube.animation, {.reference = reference, .threads = 2});
      CHECK(same(exact_one, exact_two));
    }
  // The default, 0 (all the hardware's threads), gives the serial field.
  const auto serial = strain::compute_strain(tube.animation, {.threads = 1});
  const auto parallel = strain::compute_strain(tube.animation);
  CHECK(same(serial, parallel));
}

TEST_CASE("strain: previous-pose strain of a sequence that holds still is 0", "[strain]") {
  const auto animation = animate(tube_shape(), std::vector<Map>(5, rigid(0.3, {1, 0, 0}, {10, 20, 30})));
  const auto raw_field =
      strain::compute_strain(animation, strain::Strain_options{.reference = strain::Strain_reference::previous_pose,
                                                               .normalization = strain::No_normalization{}});
  CHECK(largest(raw_field) < 1e-12);
  const auto field = strain::compute_strain(animation, {.reference = strain::Strain_reference::previous_pose});
  CHECK(largest(field) < 1e-12);
  // No sample above the noise level: sigma is the noise level.
  CHECK(field.sigma() == strain::Gaussian_normalization{}.noise_level);
  for (float v : field.frame(0)) CHECK(v == 0.0f);
}

TEST_CASE("strain: a degenerate reference triangle gives 0, never NaN, and is counted", "[strain]") {
  // Two triangles sharing the edge 0-2; at rest, vertex 3 lies on that edge's line, so triangle
  // 1 (0 2 3) has zero area, and it opens up later.
  Grid shape;
  shape.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 2, 0}};
  shape.triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto animation =
      animate(shape, {identity(), [](const Vector3& p) { return Vector3(p + Vector3(0, p.x() == 2 ? -1.5 : 0, 0)); },
                      [](const Vector3& p) { return Vector3(2 * p); }});
  for (const auto& field :
       {strain::compute_strain(animation, {.principal_directions = true}),
        strain::compute_strain(
            animation, strain::Strain_options{.measure = strain::Area_ratio_strain{}, .principal_directions = true})}) {
    CHECK(field.degenerate_count() == 2);  // triangle 1 in frames 1 and 2 (frame 0 is the rest)
    for (std::size_t t = 0; t < 3; ++t) {
      CHECK(field(1, t) == 0.0f);
      CHECK(field.principal_directions(t).row(1).norm() == 0.0f);
      for (float v : field.frame(t)) CHECK(std::isfinite(v));
    }
    CHECK(field(0, 2) > 0.1f);  // the other triangle is measured
  }
  // Against the previous pose, triangle 1 is degenerate only as a reference, in frame 0 -> 1.
  const auto motion = strain::compute_strain(animation, {.reference = strain::Strain_reference::previous_pose});
  CHECK(motion.degenerate_count() == 1);
  CHECK(motion(1, 1) == 0.0f);
  CHECK(motion(1, 2) > 0.1f);
  // A tolerance of 0.9 makes every triangle degenerate.
  const auto all = strain::compute_strain(animation, {.degenerate_tolerance = 0.9});
  CHECK(all.degenerate_count() == 2 * 2);
  CHECK(largest(all) == 0);
}

TEST_CASE("strain: a triangle collapsed onto a segment or a point has l2 = 0", "[strain]") {
  // The right triangle (0 0 0) (1 0 0) (0 1 0); frame 1 moves its third vertex onto the first
  // (u = e1, v = 0: l1 = 1, l2 = 0), frame 2 puts all three on one point (l1 = l2 = 0).
  Grid shape;
  shape.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  shape.triangles = {{0, 1, 2}};
  const auto animation = animate(shape, {identity(), [](const Vector3& p) { return Vector3(p.x(), 0, 0); },
                                         [](const Vector3&) { return Vector3(5, 6, 7); }});
  const auto max_principal = strain::compute_strain(
      animation, strain::Strain_options{.normalization = strain::No_normalization{}, .principal_directions = true});
  const auto green = strain::compute_strain(animation, raw_with(strain::Green_lagrange_strain{}));
  const auto frobenius = strain::compute_strain<double>(animation, raw_with(strain::Frobenius_strain{}));
  const auto area = strain::compute_strain(animation, raw_with(strain::Area_ratio_strain{}));
  for (std::size_t t : {1, 2}) {
    CHECK(max_principal(0, t) == Approx(1).epsilon(1e-6));  // max(l1 - 1, 1 - 0)
    CHECK(green(0, t) == Approx(0.5).epsilon(1e-6));         // (1 - 0^2) / 2
    CHECK(area(0, t) == Approx(1).epsilon(1e-6));            // |0 - 1|
  }
  CHECK(frobenius(0, 1) == Approx(1).epsilon(1e-12));             // sqrt(0^2 + 1^2)
  CHECK(frobenius(0, 2) == Approx(std::sqrt(2.0)).epsilon(1e-12));  // sqrt(1 + 1)
  // Stretched along the segment; a point has no direction.
  CHECK((max_principal.principal_directions(1).row(0).cast<double>() - Eigen::RowVector3d(1, 0, 0)).norm() < 1e-6);
  CHECK(max_principal.principal_directions(2).row(0).norm() == 0.0f);
}

TEST_CASE("strain: absurd coordinates saturate, never NaN or inf", "[strain]") {
  Grid shape;
  shape.points = {{0, 0, 0}, {1e-150, 0, 0}, {0, 1e-150, 0}, {1, 1, 1}};
  shape.triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto animation = animate(
      shape, {identity(), [](const Vector3& p) { return Vector3(1e150 * p); },
              [](const Vector3& p) { return Vector3(p + Vector3(1e300, -1e300, 0) * (p.x() > 0 ? 1.0 : 0.0)); }});
  for (bool directions : {false, true}) {
    const auto field = strain::compute_strain(
        animation,
        strain::Strain_options{.normalization = strain::No_normalization{}, .principal_directions = directions});
    for (float v : field.values()) CHECK(std::isfinite(v));
    const auto normalised = strain::compute_strain(animation, {.principal_directions = directions});
    for (float v : normalised.values()) CHECK((v >= 0 && v <= 1));
    const auto exact = strain::compute_strain<double>(animation, {.reference = strain::Strain_reference::previous_pose,
                                                          .principal_directions = directions});
    for (double v : exact.values()) CHECK((v >= 0 && v <= 1));
    if (directions)
      for (std::size_t t = 0; t < 3; ++t) CHECK(field.principal_directions(t).allFinite());
  }
}

TEST_CASE("strain: the Gaussian normalisation and its sigma statistics", "[strain][normalization]") {
  mesh::Bending_tube spec;
  spec.schedule = {{5, {right_angle}}, {5, {-0.5}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto raw_field = strain::compute_strain(tube.animation, raw());
  std::vector<float> samples;  // every frame but the rest frame, above the noise level
  for (std::size_t t = 1; t < raw_field.num_frames(); ++t)
    for (float v : raw_field.frame(t))
      if (v > 1e-5f) samples.push_back(v);
  std::sort(samples.begin(), samples.end());
  const auto nearest_rank = [&](double percent) {
    return double(samples[std::size_t(std::ceil(percent / 100 * double(samples.size()))) - 1]);
  };

  SECTION("default: the 95th percentile, nearest rank") {
    const auto field = strain::compute_strain(tube.animation);
    CHECK(*field.sigma() == nearest_rank(95));
    CHECK(*strain::compute_strain(tube.animation, {.normalization = Gaussian{.percentile = 50}}).sigma() ==
          nearest_rank(50));
    CHECK(*strain::compute_strain(tube.animation, {.normalization = Gaussian{.percentile = 100}}).sigma() ==
          samples.back());
    const double sigma = *field.sigma();
    for (std::size_t t = 0; t < field.num_frames(); ++t)
      for (std::size_t j = 0; j < field.num_faces(); ++j) {
        const double s = raw_field(j, t);
        CHECK(field(j, t) == Approx(-std::expm1(-s * s / (2 * sigma * sigma))).margin(1e-7).epsilon(1e-6));
      }
  }
  SECTION("the standard deviation and the scaled MAD") {
    double mean = 0, square = 0;
    for (float v : samples) mean += v;
    mean /= double(samples.size());
    for (float v : samples) square += (v - mean) * (v - mean);
    const auto std_field = strain::compute_strain(
        tube.animation, {.normalization = Gaussian{.statistic = strain::Sigma_statistic::standard_deviation}});
    CHECK(*std_field.sigma() == Approx(std::sqrt(square / double(samples.size()))).epsilon(1e-12));
    const double median = nearest_rank(50);
    std::vector<double> deviations;
    for (float v : samples) deviations.push_back(std::abs(double(v) - median));
    std::sort(deviations.begin(), deviations.end());
    const auto mad_field = strain::compute_strain(
        tube.animation, {.normalization = Gaussian{.statistic = strain::Sigma_statistic::scaled_mad}});
    CHECK(*mad_field.sigma() == Approx(1.4826 * deviations[(deviations.size() + 1) / 2 - 1]).epsilon(1e-6));
  }
  SECTION("a given sigma, and none") {
    const auto given = strain::compute_strain(tube.animation, {.normalization = Gaussian{.sigma = 0.05}});
    CHECK(*given.sigma() == 0.05);
    CHECK(given(100, 8) ==
          Approx(-std::expm1(-double(raw_field(100, 8)) * raw_field(100, 8) / (2 * 0.05 * 0.05))).epsilon(1e-6));
    const auto none = strain::compute_strain(tube.animation, raw());
    CHECK(!none.sigma());
  }
  SECTION("a user's measure and normalisation") {
    const auto field = strain::compute_strain(tube.animation, {}, Largest_stretch{}, Divide_by_largest{});
    CHECK(*field.sigma() > 0.1);
    CHECK(largest(field) == Approx(1));
  }
  SECTION("the statistic on a hand-made field, float and double") {
    // Frame 1 is the zero frame and is left out; so are the values at or below the noise level.
    std::vector<double> values{0.3, 0.0, 1e-7, 0.1, 9.0, 9.0, 9.0, 9.0, 0.2, 0.5, -0.4, 0.6};
    std::vector<float> floats(values.begin(), values.end());
    const strain::Raw_strain_field<double> exact{values, 4, 1, 0};
    const strain::Raw_strain_field<float> single{floats, 4, 1, 0};
    // Samples: 0.3 0.1 0.2 0.5 0.4 0.6 (magnitudes), sorted 0.1 0.2 0.3 0.4 0.5 0.6.
    CHECK(strain::Gaussian_normalization{.percentile = 50}.sigma_of(exact) == 0.3);
    CHECK(strain::Gaussian_normalization{.percentile = 51}.sigma_of(exact) == 0.4);
    CHECK(strain::Gaussian_normalization{}.sigma_of(exact) == 0.6);
    CHECK(strain::Gaussian_normalization{.percentile = 50}.sigma_of(single) == 0.3f);
    CHECK(strain::Gaussian_normalization{.statistic = strain::Sigma_statistic::scaled_mad}.sigma_of(exact) ==
          Approx(1.4826 * 0.1));
    CHECK(strain::Gaussian_normalization{.statistic = strain::Sigma_statistic::standard_deviation}.sigma_of(exact) ==
          Approx(std::sqrt(17.5 / 600)));
  }
}

TEST_CASE("strain: a reference mesh of its own", "[strain]") {
  mesh::Bending_tube spec;
  spec.schedule = {{4, {right_angle}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& a = tube.animation;
  // The rest frame as a mesh of its own gives the rest-pose field, every frame a sample.
  const mesh::Surface_mesh rest = a.face_graph();
  // Frame 0 is then measured (rounding, ~1e-16) rather than 0 by definition.
  const auto with_mesh = strain::compute_strain(a, rest, {.normalization = Gaussian{.sigma = 0.1}});
  const auto with_frame = strain::compute_strain(a, {.normalization = Gaussian{.sigma = 0.1}});
  const auto after_frame_0 = [](const auto& field) { return field.values().subspan(field.num_faces()); };
  CHECK(std::ranges::equal(after_frame_0(with_mesh), after_frame_0(with_frame)));
  CHECK(largest(with_mesh) == largest(with_frame));
  // A Polyhedron_3 reference for a Surface_mesh animation.
  std::vector<std::array<double, 3>> points;
  for (std::size_t i = 0; i < a.num_vertices(); ++i)
    points.push_back({a.frame_positions(0)[3 * i], a.frame_positions(0)[3 * i + 1], a.frame_positions(0)[3 * i + 2]});
  const auto polyhedron = mesh::make_face_graph<Polyhedron>(points, a.triangles());
  const auto with_polyhedron = strain::compute_strain(a, polyhedron, {.normalization = Gaussian{.sigma = 0.1}});
  CHECK(std::ranges::equal(with_polyhedron.values(), with_mesh.values()));
}

TEST_CASE("strain: policy objects in place of the options' measure and normalisation", "[strain]") {
  mesh::Bending_tube spec;
  spec.schedule = {{4, {right_angle}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& a = tube.animation;
  const mesh::Surface_mesh rest = a.face_graph();
  // The options' measure and normalisation, which the policies replace, differ from them.
  const strain::Strain_options ignored{.reference = strain::Strain_reference::previous_pose,
                                       .measure = strain::Area_ratio_strain{},
                                       .normalization = strain::No_normalization{}};
  const auto chosen = strain::compute_strain(a, {.reference = strain::Strain_reference::previous_pose,
                                                 .measure = strain::Green_lagrange_strain{},
                                                 .normalization = Gaussian{.percentile = 50}});
  const auto given = strain::compute_strain(a, ignored, strain::Green_lagrange_strain{}, Gaussian{.percentile = 50});
  CHECK(largest(given) > 0.1);
  CHECK(std::ranges::equal(given.values(), chosen.values()));
  CHECK(given.sigma() == chosen.sigma());
  const auto against_rest = strain::compute_strain(a, rest, {.measure = strain::Frobenius_strain{}});
  const auto against_rest_given =
      strain::compute_strain(a, rest, {.measure = strain::Area_ratio_strain{}}, strain::Frobenius_strain{}, Gaussian{});
  CHECK(largest(against_rest) > 0.1);
  CHECK(std::ranges::equal(against_rest_given.values(), against_rest.values()));
  CHECK_THROWS_WITH(strain::compute_strain(a, rest, ignored, strain::Max_principal_strain{}, Gaussian{}),
                    Catch::Contains("a reference mesh takes the place of the rest pose"));
}

TEST_CASE("strain: one frame into face property maps", "[strain]") {
  mesh::Bending_tube spec;
  spec.schedule = {{4, {right_angle}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto field = strain::compute_strain(tube.animation, {.principal_directions = true});

  mesh::Surface_mesh mesh = tube.animation.face_graph();
  auto strain = mesh.add_property_map<mesh::Surface_mesh::Face_index, float>("f:strain", -1.0f).first;
  auto direction = mesh.add_property_map<mesh::Surface_mesh::Face_index, mesh::Kernel::Vector_3>("f:direction").first;
  strain::put_strain_frame(field, 4, mesh, strain);
  strain::put_principal_directions(field, 4, mesh, direction);
  for (std::size_t j = 0; j < field.num_faces(); ++j) {
    const auto f = tube.animation.face_descriptors()[j];
    CHECK(strain[f] == field(j, 4));
    CHECK(direction[f].x() == double(field.principal_directions(4)(Eigen::Index(j), 0)));
    CHECK(direction[f].z() == double(field.principal_directions(4)(Eigen::Index(j), 2)));
  }

  const auto polyhedron_tube = mesh::make_bending_tube<Polyhedron>(spec);
  using Face = boost::graph_traits<Polyhedron>::face_descriptor;
  std::map<Face, double> values;
  strain::put_strain_frame(field, 3, polyhedron_tube.animation.face_graph(), boost::make_assoc_property_map(values));
  REQUIRE(values.size() == field.num_faces());
  for (std::size_t j = 0; j < field.num_faces(); ++j)
    CHECK(values.at(polyhedron_tube.animation.face_descriptors()[j]) == double(field(j, 3)));
}

TEST_CASE("strain: bad input throws invalid_input with a clear message", "[strain][errors]") {
  mesh::Bending_tube spec;
  spec.schedule = {{3, {right_angle}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& a = tube.animation;
  using Catch::Contains;

  CHECK_THROWS_WITH(strain::compute_strain(mesh::Deforming_mesh<mesh::Surface_mesh>(a.face_graph())),
                    Contains("has no frame"));
  CHECK_THROWS_WITH(strain::compute_strain(a, {.rest_frame = 4}),
                    Contains("rest frame 4 out of range") && Contains("4 frames"));
  CHECK_THROWS_WITH(strain::compute_strain(a, {.threads = -1}), Contains("threads must be"));
  CHECK_THROWS_WITH(strain::compute_strain(a, {.degenerate_tolerance = 1.5}), Contains("degenerate_tolerance"));
  CHECK_THROWS_WITH(strain::compute_strain(a, {.normalization = Gaussian{.sigma = 0.0}}),
                    Contains("sigma must be finite and > 0"));
  CHECK_THROWS_WITH(strain::compute_strain(a, {.normalization = Gaussian{.sigma = std::nan("")}}),
                    Contains("sigma must be"));
  CHECK_THROWS_WITH(strain::compute_strain(a, {.normalization = Gaussian{.percentile = 0}}),
                    Contains("percentile must be in (0, 100]"));
  CHECK_THROWS_WITH(strain::compute_strain(a, {.normalization = Gaussian{.noise_level = -1}}), Contains("noise_level"));

  SECTION("a reference mesh that does not match") {
    mesh::Bending_tube other = spec;
    other.shape.sectors = 12;
    const auto smaller = mesh::make_bending_tube(other);
    CHECK_THROWS_WITH(strain::compute_strain(a, smaller.animation.face_graph()),
                      Contains("the reference mesh has 590 vertices and 1176 faces, the animation 786 and 1568"));
    // The same counts, other triangles: the first face turned around.
    auto triangles = std::vector<std::array<std::uint32_t, 3>>(a.triangles().begin(), a.triangles().end());
    std::vector<std::array<double, 3>> points(a.num_vertices());
    for (std::size_t i = 0; i < points.size(); ++i)
      points[i] = {a.frame_positions(0)[3 * i], a.frame_positions(0)[3 * i + 1], a.frame_positions(0)[3 * i + 2]};
    std::swap(triangles[0], triangles[1]);
    CHECK_THROWS_WITH(strain::compute_strain(a, mesh::make_face_graph<mesh::Surface_mesh>(points, triangles)),
                      Contains("face 0 of the reference mesh has vertices"));
    CHECK_THROWS_WITH(strain::compute_strain(a, a.face_graph(), {.reference = strain::Strain_reference::previous_pose}),
                      Contains("a reference mesh takes the place of the rest pose"));
  }
  SECTION("a field asked for what it does not have") {
    const auto field = strain::compute_strain(a);
    CHECK_THROWS_WITH(field.frame(4), "strain of frame 4 asked of a field of 4 frames");
    CHECK_THROWS_WITH(field.principal_directions(0), Contains("principal directions were not computed"));
    mesh::Surface_mesh smaller = a.face_graph();
    CGAL::Euler::remove_face(halfedge(*faces(smaller).begin(), smaller), smaller);
    smaller.collect_garbage();
    auto map = smaller.add_property_map<mesh::Surface_mesh::Face_index, float>("f:strain").first;
    CHECK_THROWS_WITH(strain::put_strain_frame(field, 0, smaller, map),
                      Contains("the graph has 1567 faces, the strain field 1568"));
    CHECK_THROWS_AS(strain::Strain_field<float>(3, 2, strain::Strain_field<float>::Storage(5), {}, {}, 0),
                    invalid_input);
  }
}
