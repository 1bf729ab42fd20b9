// Tests of spatiotemporal_segments.h: the union-find against a flood fill, the clean-up steps on
// label volumes made by hand, a bending tube, invariance and determinism, real data.
#include "test_support.h"
#include "mesh_types.h"

#include <deformseg/io/frame_sequence.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>
#include <deformseg/mesh/synthetic.h>

#include <Eigen/Geometry>

#include <numbers>
#include <random>
#include <vector>

using namespace deformseg;

namespace {

using test::grid;
using test::Triangles;

// A "strain field" of 0 and 1 from labels: deformed where `deformed` says.
strain::Strain_field<float> field_of(const std::vector<std::uint8_t>& deformed, std::size_t faces) {
  strain::Strain_field<float>::Storage values(deformed.size());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = deformed[i] ? 1.0f : 0.0f;
  return strain::Strain_field<float>(faces, deformed.size() / faces, std::move(values), {}, std::nullopt, 0);
}

// Components of deformed cells by breadth-first flood fill over (shared edge, same frame) and
// (same triangle, next or previous frame), numbered in order of first cell.
std::vector<std::int32_t> flood_fill(const std::vector<std::uint8_t>& deformed, const Triangles& triangles) {
  const std::size_t faces = triangles.size(), frames = deformed.size() / faces;
  const auto shares_edge = [&](std::size_t f, std::size_t g) {
    int shared = 0;
    for (auto v : triangles[f]) shared += std::count(triangles[g].begin(), triangles[g].end(), v) ? 1 : 0;
    return f != g && shared == 2;
  };
  std::vector<std::int32_t> labels(deformed.size(), -1);
  std::int32_t next = 0;
  for (std::size_t start = 0; start < deformed.size(); ++start) {
    if (!deformed[start] || labels[start] != -1) continue;
    std::vector<std::size_t> queue{start};
    labels[start] = next;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::size_t t = queue[q] / faces, f = queue[q] % faces;
      std::vector<std::size_t> around;
      for (std::size_t g = 0; g < faces; ++g)
        if (shares_edge(f, g)) around.push_back(t * faces + g);
      if (t > 0) around.push_back(queue[q] - faces);
      if (t + 1 < frames) around.push_back(queue[q] + faces);
      for (std::size_t c : around)
        if (deformed[c] && labels[c] == -1) labels[c] = next, queue.push_back(c);
    }
    ++next;
  }
  return labels;
}

std::vector<std::int32_t> labels_of(const spatiotemporal::Spatiotemporal_segmentation& s) {
  std::vector<std::int32_t> labels;
  for (std::size_t t = 0; t < s.num_frames(); ++t)
    for (std::int32_t k : s.frame_labels(t)) labels.push_back(k);
  return labels;
}

const spatiotemporal::Spatiotemporal_options no_clean_up{.min_triangles = 1, .min_frames = 1, .max_island = 0};

}  // namespace

TEST_CASE("spatio-temporal segments: the union-find equals a flood fill on random label volumes", "[spatiotemporal]") {
  std::mt19937 random(7);
  for (int trial = 0; trial < 40; ++trial) {
    const Triangles triangles = grid(2 + std::uint32_t(trial % 5));
    const std::size_t frames = 1 + std::size_t(trial % 6);
    const double density = 0.2 + 0.15 * double(trial % 5);
    std::bernoulli_distribution coin(density);
    std::vector<std::uint8_t> deformed(triangles.size() * frames);
    for (auto& d : deformed) d = coin(random);
    const auto s =
        spatiotemporal::spatiotemporal_segmentation(field_of(deformed, triangles.size()), triangles, no_clean_up);
    CHECK(labels_of(s) == flood_fill(deformed, triangles));
  }
}

TEST_CASE("spatio-temporal segments: extents, and small or short segments become rigid", "[spatiotemporal]") {
  // A 4 x 4 grid, 32 triangles, 4 frames: a square of 4 triangles lasting frames 0-2 (segment 0),
  // one triangle at frame 3 (segment 1).
  const Triangles triangles = grid(4);
  std::vector<std::uint8_t> deformed(32 * 4, 0);
  for (std::size_t t = 0; t < 3; ++t)
    for (std::size_t f : {0, 1, 2, 3}) deformed[t * 32 + f] = 1;
  deformed[3 * 32 + 20] = 1;
  const auto field = field_of(deformed, 32);
  const auto all = spatiotemporal::spatiotemporal_segmentation(field, triangles, no_clean_up);
  REQUIRE(all.num_segments() == 2);
  CHECK(all.extent(0).first_frame == 0);
  CHECK(all.extent(0).last_frame == 2);
  CHECK(all.extent(0).cells == 12);
  CHECK(all.extent(0).largest_slice == 4);
  CHECK(all.extent(1).first_frame == 3);
  CHECK(all.label(20, 3) == 1);
  CHECK(all.label(20, 2) == spatiotemporal::Spatiotemporal_segmentation::rigid);

  auto options = no_clean_up;
  options.min_frames = 2;
  CHECK(spatiotemporal::spatiotemporal_segmentation(field, triangles, options).num_segments() == 1);
  options.min_frames = 4;
  CHECK(spatiotemporal::spatiotemporal_segmentation(field, triangles, options).num_segments() == 0);
  options.min_frames = 1, options.min_triangles = 2;
  const auto large = spatiotemporal::spatiotemporal_segmentation(field, triangles, options);
  CHECK(large.num_segments() == 1);
  CHECK(large.label(20, 3) == spatiotemporal::Spatiotemporal_segmentation::rigid);
}

TEST_CASE("spatio-temporal segments: rigid islands enclosed by one segment are absorbed", "[spatiotemporal]") {
  // A 6 x 6 grid, one frame: every triangle deformed but the 2 of square (4, 3) and the 4 of the
  // squares (1, 3) and (1, 4), which sit inside; and a deformed column 0 cut off from the rest by
  // a rigid column 1, so that column 1 touches two segments.
  const Triangles triangles = grid(6);
  std::vector<std::uint8_t> deformed(72, 1);
  const auto square = [](std::size_t i, std::size_t j) {
    return std::array<std::size_t, 2>{2 * (i * 6 + j), 2 * (i * 6 + j) + 1};
  };
  for (const auto& [i, j] : {std::pair{4, 3}, {1, 3}, {1, 4}})
    for (std::size_t f : square(std::size_t(i), std::size_t(j))) deformed[f] = 0;
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t f : square(i, 1)) deformed[f] = 0;
  const auto field = field_of(deformed, 72);
  auto options = no_clean_up;
  REQUIRE(spatiotemporal::spatiotemporal_segmentation(field, triangles, options).num_segments() == 2);

  options.max_island = 2;  // the 2-triangle island only
  const auto small = spatiotemporal::spatiotemporal_segmentation(field, triangles, options);
  CHECK(small.label(square(4, 3)[0], 0) == small.label(square(2, 5)[0], 0));
  CHECK(small.label(square(1, 3)[0], 0) == spatiotemporal::Spatiotemporal_segmentation::rigid);
  options.max_island = 4;
  const auto both = spatiotemporal::spatiotemporal_segmentation(field, triangles, options);
  CHECK(both.label(square(1, 4)[1], 0) == both.label(square(2, 5)[0], 0));
  // Column 1 (12 triangles) touches both segments: it stays rigid, however large the limit.
  options.max_island = 100;
  const auto column = spatiotemporal::spatiotemporal_segmentation(field, triangles, options);
  CHECK(column.label(square(0, 1)[0], 0) == spatiotemporal::Spatiotemporal_segmentation::rigid);
  CHECK(column.num_segments() == 2);
}

TEST_CASE("spatio-temporal segments: a tube bending once deforms in its blend zone while it moves",
          "[spatiotemporal]") {
  mesh::Bending_tube spec;
  spec.schedule = {{10, {}}, {10, {std::numbers::pi / 2}}, {10, {}}, {10, {0.0}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto s = spatiotemporal::spatiotemporal_segmentation(tube.animation);
  // Previous-pose strain: the bend (frames 11-20) and the unbend (31-40) are two segments.
  REQUIRE(s.num_segments() == 2);
  CHECK(s.extent(0).first_frame >= 11);
  CHECK(s.extent(0).last_frame <= 20);
  CHECK(s.extent(1).first_frame >= 31);
  for (std::size_t t = 0; t < s.num_frames(); ++t)
    for (std::size_t f = 0; f < s.num_faces(); ++f)
      if (s.label(f, t) != spatiotemporal::Spatiotemporal_segmentation::rigid) CHECK(tube.face_joint[f] == 0);

  // Moved, turned and scaled, the same labels; and the same twice.
  mesh::Bending_tube placed = spec;
  placed.placement = {.scale = 4.0,
                      .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(2.0, Eigen::Vector3d(3, 1, -1).normalized())),
                      .translation = Eigen::Vector3d(50, 20, -30)};
  CHECK(labels_of(spatiotemporal::spatiotemporal_segmentation(mesh::make_bending_tube(placed).animation)) ==
        labels_of(s));
  CHECK(labels_of(spatiotemporal::spatiotemporal_segmentation(tube.animation)) == labels_of(s));
}

TEMPLATE_LIST_TEST_CASE("spatio-temporal segments: every mesh type gives the default model's segments",
                        "[spatiotemporal][mesh_types]", test::Mesh_types) {
  mesh::Bending_tube spec;
  spec.shape = {.sectors = 8, .rings = 24};
  spec.schedule = {{5, {}}, {8, {std::numbers::pi / 2}}, {5, {}}, {8, {0.0}}};
  const auto tube = mesh::make_bending_tube(spec);
  const TestType on(tube.animation);
  for (const auto& options :
       {spatiotemporal::Spatiotemporal_options{.threshold = 0.01}, no_clean_up,
        spatiotemporal::Spatiotemporal_options{.reference = strain::Strain_reference::rest_pose, .threshold = 0.01}}) {
    const auto expected = spatiotemporal::spatiotemporal_segmentation(tube.animation, options);
    const auto s = spatiotemporal::spatiotemporal_segmentation(on.model(), options);
    REQUIRE(expected.num_segments() > 0);
    CHECK(labels_of(s) == labels_of(expected));
    REQUIRE(s.num_segments() == expected.num_segments());
    for (std::size_t k = 0; k < s.num_segments(); ++k) {
      CHECK(s.extent(k).first_frame == expected.extent(k).first_frame);
      CHECK(s.extent(k).last_frame == expected.extent(k).last_frame);
      CHECK(s.extent(k).cells == expected.extent(k).cells);
      CHECK(s.extent(k).largest_slice == expected.extent(k).largest_slice);
    }
  }
}

TEST_CASE("spatio-temporal segments: bad input is named", "[spatiotemporal]") {
  const Triangles triangles = grid(2);
  const auto field = field_of(std::vector<std::uint8_t>(8, 0), 8);
  CHECK_THROWS_WITH(spatiotemporal::spatiotemporal_segmentation(field, Triangles(grid(3))),
                    Catch::Contains("18 triangles"));
  CHECK_THROWS_WITH(spatiotemporal::spatiotemporal_segmentation(field, triangles, {.threshold = std::nan("")}),
                    Catch::Contains("threshold"));
  CHECK_THROWS_WITH(spatiotemporal::Spatiotemporal_segmentation(2, 1, {1, 0}), Catch::Contains("label 1"));
}

TEST_CASE("spatio-temporal segments: the horse gallop and the samba, deterministic", "[spatiotemporal][data]") {
  for (const char* name : {"horse-gallop", "samba"}) {
    const auto folder = test::unpacked(std::string(name) + "/" + name + ".tar.xz") / name;
    const auto animation = io::read_frame_sequence(folder.string());
    const auto a = spatiotemporal::spatiotemporal_segmentation(animation);
    const auto b = spatiotemporal::spatiotemporal_segmentation(animation);
    INFO(name << ": " << a.num_segments() << " segments");
    CHECK(labels_of(a) == labels_of(b));
    CHECK(a.num_segments() >= 10);
    CHECK(a.num_segments() < 200);
    for (std::size_t k = 0; k < a.num_segments(); ++k) {
      CHECK(a.extent(k).largest_slice >= 10);
      CHECK(a.extent(k).last_frame >= a.extent(k).first_frame + 5);  // 6 frames at least
    }
  }
}
