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
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/mesh/synthetic.h>

#include <benchmark/benchmark.h>

#include <numbers>

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

void strain(benchmark::State& state) {
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

}  // namespace

BENCHMARK(strain)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(labels_and_segments)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(evolving_graph_of_segments)->Name("evolving_graph")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(all)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
