// How fast the spatio-temporal segmentation and the evolving graph are, in cells (triangle-frames)
// per second, against the strain kernel that feeds them, measured in the same run:
//
//   build/test/bench/spatiotemporal [--benchmark_filter=...]
//
// The animation: 100 frames of a tube of 100,500 triangles bending at two joints, one after the
// other and then both back, made here. `strain` is compute_strain (previous pose, normalised) on
// two threads; `labels_and_segments` the labelling, union-find and clean-up from that field;
// `evolving_graph` the frame graphs and key frames from the segments; `all` the three together,
// as `evolving_graph(animation)` runs them.
//
// `part_links` finds the contacts of a cylinder cut into bands of 10 rings that share no vertex
// (each band a part touching the next), in triangles per second, at three sizes, against
// `face_adjacency`, the shared edges of the same mesh, measured in the same run.
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/part_links.h>
#include <deformseg/mesh/synthetic.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

using namespace deformseg;

namespace {

const mesh::Surface_mesh_animation& tube() {
  static const mesh::Surface_mesh_animation animation = [] {
    mesh::Bending_tube spec;
    spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 250, .rings = 200, .caps = true};
    spec.joints = {{.position = 0.3, .blend_width = 0.2}, {.position = 0.7, .blend_width = 0.2}};
    const double right = std::numbers::pi / 2;
    spec.schedule = {{30, {right, 0.0}}, {30, {right, right}}, {39, {0.0, 0.0}}};
    return mesh::make_bending_tube(spec).animation;  // 100,500 triangles, 100 frames
  }();
  return animation;
}

const strain::Strain_field<float>& field() {
  static const strain::Strain_field<float> strain =
      strain::compute_strain(tube(), {.reference = strain::Strain_reference::previous_pose});
  return strain;
}

const spatiotemporal::Spatiotemporal_segmentation& segments() {
  static const spatiotemporal::Spatiotemporal_segmentation s =
      spatiotemporal::spatiotemporal_segmentation(field(), tube().triangles());
  return s;
}

void report(benchmark::State& state) {
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(tube().num_faces() * tube().num_frames()));
}

void previous_pose_strain(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(strain::compute_strain(tube(), {.reference = strain::Strain_reference::previous_pose}));
  report(state);
}

void labels_and_segments(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(spatiotemporal::spatiotemporal_segmentation(field(), tube().triangles()));
  report(state);
}

void evolving_graph_of_segments(benchmark::State& state) {
  const std::vector<double> areas = mesh::face_areas(tube(), 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        spatiotemporal::evolving_graph(spatiotemporal::Frame_segments(segments(), tube().triangles(), areas)));
  state.counters["key_frames"] = double(
      spatiotemporal::evolving_graph(spatiotemporal::Frame_segments(segments(), tube().triangles(), areas)).size());
  report(state);
}

void all(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(spatiotemporal::evolving_graph(tube()));
  report(state);
}

// A cylinder of `rings` x `sectors` quads, two triangles each, in bands of 10 rings with vertices
// of their own, standing still for 2 frames.
mesh::Surface_mesh_animation banded_cylinder(std::uint32_t rings, std::uint32_t sectors) {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::uint32_t band = 0; band * 10 < rings; ++band) {
    const auto first = std::uint32_t(points.size());
    const std::uint32_t band_rings = std::min<std::uint32_t>(10, rings - band * 10);
    for (std::uint32_t r = 0; r <= band_rings; ++r)
      for (std::uint32_t s = 0; s < sectors; ++s) {
        const double angle = 2 * std::numbers::pi * double(s) / double(sectors);
        points.push_back({std::cos(angle), std::sin(angle), 0.01 * double(band * 10 + r)});
      }
    for (std::uint32_t r = 0; r < band_rings; ++r)
      for (std::uint32_t s = 0; s < sectors; ++s) {
        const std::uint32_t a = first + r * sectors + s, b = first + r * sectors + (s + 1) % sectors;
        triangles.push_back({a, b, b + sectors});
        triangles.push_back({a, b + sectors, a + sectors});
      }
  }
  std::vector<double> positions;
  for (int frame = 0; frame < 2; ++frame)
    for (const auto& p : points) positions.insert(positions.end(), p.begin(), p.end());
  return {mesh::make_face_graph<mesh::Surface_mesh>(points, triangles), std::move(positions)};
}

void part_links(benchmark::State& state) {
  const auto rings = std::uint32_t(state.range(0));
  const mesh::Surface_mesh_animation cylinder = banded_cylinder(rings, 5 * rings);
  for (auto _ : state) benchmark::DoNotOptimize(spatiotemporal::part_links(cylinder));
  state.counters["links"] = double(spatiotemporal::part_links(cylinder).size());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(cylinder.num_faces()));
}

void face_adjacency(benchmark::State& state) {
  const auto rings = std::uint32_t(state.range(0));
  const mesh::Surface_mesh_animation cylinder = banded_cylinder(rings, 5 * rings);
  for (auto _ : state) benchmark::DoNotOptimize(spatiotemporal::Body_layout(cylinder.triangles()));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(cylinder.num_faces()));
}

}  // namespace

BENCHMARK(part_links)->Arg(40)->Arg(80)->Arg(160)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(face_adjacency)->Arg(40)->Arg(80)->Arg(160)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(previous_pose_strain)->Name("strain")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(labels_and_segments)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(evolving_graph_of_segments)->Name("evolving_graph")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(all)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
