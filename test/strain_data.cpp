// Tests of compute_strain on the shared real animations (tagged [data]): invariance on the horse
// gallop moved far from the origin, robustness of sigma to its sliver triangles, and shape
// independence on the cat and lion poses.
#include "test_support.h"

#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/read_mesh.h>
#include <deformseg/strain/strain.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace deformseg;

namespace {

mesh::Surface_mesh_animation horse_gallop() {
  return io::read_frame_sequence((test::unpacked("horse-gallop/horse-gallop.tar.xz") / "horse-gallop").string());
}

// The same animation scaled, turned and moved far from the origin, every frame in double.
mesh::Surface_mesh_animation placed(const mesh::Surface_mesh_animation& a, double scale,
                                    const Eigen::Vector3d& translation) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.2, Eigen::Vector3d(1, -3, 2).normalized()).toRotationMatrix();
  std::vector<double> positions(a.all_positions().begin(), a.all_positions().end());
  for (std::size_t i = 0; i < positions.size(); i += 3) {
    const Eigen::Vector3d p =
        scale * (turn * Eigen::Vector3d(positions[i], positions[i + 1], positions[i + 2])) + translation;
    for (int k = 0; k < 3; ++k) positions[i + std::size_t(k)] = p[k];
  }
  return mesh::Surface_mesh_animation(a.face_graph(), std::move(positions));
}

// The frame distance matrix: Euclidean distances between the frames' strain vectors.
std::vector<double> distance_matrix(const strain::Strain_field<float>& field, std::size_t frames) {
  std::vector<double> d(frames * frames);
  for (std::size_t i = 0; i < frames; ++i)
    for (std::size_t j = 0; j < frames; ++j) {
      double sum = 0;
      for (std::size_t f = 0; f < field.num_faces(); ++f) {
        const double x = double(field(f, i)) - double(field(f, j));
        sum += x * x;
      }
      d[i * frames + j] = std::sqrt(sum);
    }
  return d;
}

// Pearson's correlation between the upper triangles of two distance matrices.
double upper_triangle_correlation(const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
  std::vector<double> x, y;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      x.push_back(a[i * n + j]);
      y.push_back(b[i * n + j]);
    }
  const auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double e : v) s += e;
    return s / double(v.size());
  };
  const double mx = mean(x), my = mean(y);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxy / std::sqrt(sxx * syy);
}

}  // namespace

TEST_CASE("strain data: the horse gallop scaled, turned and moved far away keeps its strains", "[strain][data]") {
  const auto horse = horse_gallop();
  REQUIRE(horse.num_faces() == 16843);
  REQUIRE(horse.num_frames() == 48);
  const auto moved = placed(horse, 2.5, {120, -80, 100});

  const auto raw = strain::Strain_options{.normalization = strain::No_normalization{}};
  const auto a = strain::compute_strain(horse, raw);
  const auto b = strain::compute_strain(moved, raw);
  CHECK(a.degenerate_count() == 0);
  // Relative differences, strains below 1e-9 counting as 1e-9: 2 % of the triangle-frames are
  // rigid in the data, with strains of 1e-16 that are rounding on both sides.
  std::size_t within = 0, measured = 0;
  double worst = 0;
  for (std::size_t t = 1; t < a.num_frames(); ++t)
    for (std::size_t f = 0; f < a.num_faces(); ++f) {
      const double x = a(f, t), y = b(f, t);
      const double relative = std::abs(x - y) / std::max(std::abs(x), 1e-9);
      within += relative <= 1e-5 ? 1 : 0;
      ++measured;
      worst = std::max(worst, relative);
    }
  INFO("share within 1e-5: " << double(within) / double(measured) << ", largest relative difference " << worst);
  CHECK(double(within) >= 0.999 * double(measured));
  CHECK(worst < 0.01);  // slivers included

  // Normalised, the same: sigma is a statistic of the same strains.
  const auto c = strain::compute_strain(horse);
  const auto d = strain::compute_strain(moved);
  CHECK(*c.sigma() == Approx(*d.sigma()).epsilon(1e-5));
  double largest_difference = 0;
  for (std::size_t i = 0; i < c.values().size(); ++i)
    largest_difference = std::max(largest_difference, double(std::abs(c.values()[i] - d.values()[i])));
  CHECK(largest_difference < 1e-5);
}

TEST_CASE("strain data: the default sigma is robust to the horse's sliver triangles", "[strain][data]") {
  const auto horse = horse_gallop();
  const auto field = strain::compute_strain(horse, strain::Strain_options{.normalization = strain::No_normalization{}});
  // The triangles by shape: smallest height over longest edge at rest.
  std::vector<std::pair<double, std::size_t>> shape;
  const auto rest = horse.frame_matrix(0);
  for (std::size_t f = 0; f < horse.num_faces(); ++f) {
    const auto& t = horse.triangles()[f];
    const Eigen::Vector3d e1 = rest.col(t[1]) - rest.col(t[0]), e2 = rest.col(t[2]) - rest.col(t[0]);
    const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
    shape.emplace_back(e1.cross(e2).norm() / longest, f);
  }
  std::sort(shape.begin(), shape.end());
  // sigma of the strains of all triangles, and of all but the worst-shaped 17 (0.1 %).
  const auto sigma_without_worst = [&](std::size_t dropped, strain::Sigma_statistic statistic) {
    std::vector<bool> keep(horse.num_faces(), true);
    for (std::size_t i = 0; i < dropped; ++i) keep[shape[i].second] = false;
    std::vector<float> values;
    for (std::size_t t = 0; t < field.num_frames(); ++t)
      for (std::size_t f = 0; f < field.num_faces(); ++f)
        if (keep[f]) values.push_back(field(f, t));
    const strain::Raw_strain_field<float> samples{values, values.size() / field.num_frames(), 0, 0};
    return strain::Gaussian_normalization{.statistic = statistic}.sigma_of(samples);
  };
  const double percentile_all = sigma_without_worst(0, strain::Sigma_statistic::percentile);
  const double percentile_kept = sigma_without_worst(17, strain::Sigma_statistic::percentile);
  const double deviation_all = sigma_without_worst(0, strain::Sigma_statistic::standard_deviation);
  const double deviation_kept = sigma_without_worst(17, strain::Sigma_statistic::standard_deviation);
  INFO("95th percentile " << percentile_all << " -> " << percentile_kept << ", standard deviation "
                          << deviation_all << " -> " << deviation_kept);
  CHECK(std::abs(percentile_all - percentile_kept) < 0.01 * percentile_all);
  CHECK(deviation_all > 3 * deviation_kept);
  CHECK(shape[0].first < 0.01);  // there are slivers: a height below 1 % of the longest edge
}

TEST_CASE("strain data: the same poses on a cat and a lion give alike frame distances", "[strain][data]") {
  const auto cat_dir = test::unpacked("cat-lion-poses/cat-poses.tgz") / "cat-poses";
  const auto lion_dir = test::unpacked("cat-lion-poses/lion-poses.tgz") / "lion-poses";
  // Each folder: the reference, then poses 01 to 09; in natural order the reference comes last.
  REQUIRE(io::list_frame_files(cat_dir.string()).back().filename() == "cat-reference.obj");
  REQUIRE(io::list_frame_files(lion_dir.string()).back().filename() == "lion-reference.obj");
  const auto cat = io::read_frame_sequence(cat_dir.string());
  const auto lion = io::read_frame_sequence(lion_dir.string());
  REQUIRE(cat.num_frames() == 10);
  REQUIRE(lion.num_frames() == 10);
  CHECK(cat.num_faces() == 14410);
  CHECK(lion.num_faces() == 9996);

  // 10 x 10 with the reference as rest frame 9 (its row: each pose's distance to rest).
  const auto correlation = [&](const auto& options, std::size_t frames) {
    const auto a = strain::compute_strain(cat, options);
    const auto b = strain::compute_strain(lion, options);
    return upper_triangle_correlation(distance_matrix(a, frames), distance_matrix(b, frames), frames);
  };
  const double normalised = correlation(strain::Strain_options{.rest_frame = 9}, 10);
  const double poses_only = correlation(strain::Strain_options{.rest_frame = 9}, 9);
  const double raw =
      correlation(strain::Strain_options{.rest_frame = 9, .normalization = strain::No_normalization{}}, 10);
  const double deviation = correlation(
      strain::Strain_options{.rest_frame = 9, .normalization = strain::Gaussian_normalization{
                                                  .statistic = strain::Sigma_statistic::standard_deviation}},
      10);
  INFO("correlation: default " << normalised << " (9 x 9: " << poses_only << "), no normalisation " << raw
                               << ", sigma = standard deviation " << deviation);
  CHECK(normalised >= 0.95);
  CHECK(poses_only >= 0.95);
  CHECK(normalised > raw);
  CHECK(normalised > deviation + 0.05);

  // The reference given as a mesh of its own gives the same fields for the poses.
  const auto reference = io::read_mesh(cat_dir / "cat-reference.obj");
  const auto reference_mesh = mesh::make_face_graph<mesh::Surface_mesh>(io::points_of(reference), reference.triangles);
  const auto poses = io::read_frame_sequence((cat_dir / "cat-0?.obj").string());
  const auto with_mesh = strain::compute_strain(poses, reference_mesh);
  const auto with_frame = strain::compute_strain(cat, {.rest_frame = 9});
  CHECK(with_mesh.sigma() == with_frame.sigma());
  CHECK(std::ranges::equal(with_mesh.values(), with_frame.values().first(9 * cat.num_faces())));
}
