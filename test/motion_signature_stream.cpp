// Streamed motion signatures (signatures/motion_signature_stream.h) and the frame sources of
// io/frame_stream.h: equal to the in-memory description to the last bit, for point caches, frame
// sequences and glTF clips, at frame rates at and below the signature rate, with and without an up
// direction; the ring's bound; the errors of a frame that cannot be read and of a changed source.
#include "gltf_writer.h"
#include "test_support.h"

#include <deformseg/io/frame_stream.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/signatures/motion_signature_stream.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <Eigen/Core>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace ds = deformseg;
using Catch::Matchers::Contains;

// A tube bending back and forth, longer than the ring (273 frames at 30 fps): 361 frames.
ds::mesh::Surface_mesh_animation long_tube() {
  ds::mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 8, .rings = 12, .caps = true};
  for (int k = 0; k < 6; ++k) {
    spec.schedule.push_back({25, {ds::test::right_angle * (k % 2 == 0 ? 1.0 : 0.3)}});
    spec.schedule.push_back({35, {}});
  }
  return ds::mesh::make_bending_tube(spec).animation;
}

ds::signatures::Motion_signature_options options_with(std::optional<Eigen::Vector3d> up) {
  ds::signatures::Motion_signature_options options;
  options.up = up;
  return options;
}

// The description the in-memory path gives (Motion_signature_similarity::describe), in float.
template <class Animation>
Eigen::MatrixXf described(const Animation& animation, const ds::signatures::Motion_signature_options& options) {
  ds::similarity::Motion_signature_similarity<> policy;
  policy.signatures = options;
  return policy.describe(animation).signatures;
}

// The streamed description of the policy (Motion_signature_similarity::describe_stream).
template <class Source>
Eigen::MatrixXf streamed(Source& source, const ds::signatures::Motion_signature_options& options) {
  ds::similarity::Motion_signature_similarity<> policy;
  policy.signatures = options;
  return policy.describe_stream(source).signatures;
}

template <class Scalar>
void require_same_bits(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& a,
                       const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& b) {
  REQUIRE(a.rows() == b.rows());
  REQUIRE(a.cols() == b.cols());
  REQUIRE(a.size() > 0);
  CHECK(std::memcmp(a.data(), b.data(), sizeof(Scalar) * std::size_t(a.size())) == 0);
}

const std::vector<std::optional<Eigen::Vector3d>> ups{Eigen::Vector3d::UnitY(), std::nullopt};

// Writes the tube as a PC2 (or MDD) cache and an OBJ topology; gives the cache.
fs::path write_cache(const ds::mesh::Surface_mesh_animation& tube, const std::string& name) {
  const fs::path folder = ds::test::fresh_dir("stream_" + name);
  ds::io::write_obj(tube, 0, folder / "topology.obj");
  const fs::path cache = folder / name;
  if (cache.extension() == ".pc2")
    ds::io::write_pc2(tube, cache);
  else
    ds::io::write_mdd(tube, cache);
  return cache;
}

// A source that counts the frames read and can replace its file when rewound.
struct Counting_source : ds::io::Point_cache_frame_source {
  using Point_cache_frame_source::Point_cache_frame_source;
  std::size_t read = 0, rewinds = 0;
  std::function<void()> on_second_rewind{};
  void read_frame(std::span<float> out) {
    Point_cache_frame_source::read_frame(out);
    ++read;
  }
  void rewind() {
    if (++rewinds == 2 && on_second_rewind) on_second_rewind();
    Point_cache_frame_source::rewind();
  }
};

// The signatures as the code before the bucket selection computed them (the reference the
// descriptions must equal to the last bit): each row's rates per lag into an array of keyed rates,
// then the radix selection (`weighted_quantiles`), every row computed anew.
Eigen::MatrixXd reference_signatures(std::span<const double> positions, std::span<const double> weights,
                                     const ds::signatures::Motion_signature_options& options, double fps,
                                     std::span<const double> instants) {
  namespace si = ds::signatures::internal;
  const std::size_t vertices = weights.size(), frames = positions.size() / (3 * vertices), k = options.quantiles;
  const si::Signature_rows rows = si::signature_rows(options, fps, frames, si::rms_radius(positions, weights, frames));
  const auto frame_of = [&](std::size_t t) { return positions.data() + 3 * vertices * t; };
  Eigen::MatrixXd out(Eigen::Index(instants.size()), Eigen::Index(rows.columns));
  std::vector<si::Keyed_rate> speeds(vertices), rises(vertices), spare(vertices);
  std::vector<double> row(rows.columns);
  const std::size_t lags = options.lags.size();
  for (std::size_t r = 0; r < instants.size(); ++r) {
    for (std::size_t l = 0; l < lags; ++l) {
      const double lag = options.lags[l];
      const auto before = si::frames_around(frame_of, si::frame_at(instants[r] - lag, fps, frames));
      const auto after = si::frames_around(frame_of, si::frame_at(instants[r] + lag, fps, frames));
      const double unit = 1.0 / (2.0 * lag * rows.radius);
      for (std::size_t v = 0; v < vertices; ++v) {
        const Eigen::Vector3d d = si::point_at(after, v) - si::point_at(before, v);
        speeds[v] = {si::order_key(d.norm() * unit), weights[v]};
        if (rows.up) rises[v] = {si::order_key(d.dot(*rows.up) * unit), weights[v]};
      }
      double* speed_quantiles = row.data() + l * k;
      si::weighted_quantiles(speeds, spare, k, speed_quantiles);
      for (std::size_t q = 0; q < k; ++q) speed_quantiles[q] = std::log(std::max(speed_quantiles[q], options.floor));
      if (!rows.up) continue;
      double* vertical = speed_quantiles + lags * k;
      si::weighted_quantiles(rises, spare, k, vertical);
      for (std::size_t q = 0; q < k; ++q)
        vertical[q] = std::sqrt(options.vertical_weight) * std::asinh(vertical[q] / options.vertical_unit);
    }
    for (std::size_t c = 0; c < rows.columns; ++c) out(Eigen::Index(r), Eigen::Index(c)) = row[c];
  }
  return out;
}

}  // namespace

TEST_CASE("motion_signatures: the bits of the radix selection of every row anew", "[signatures]") {
  const auto tube = long_tube();
  for (const double fps : {30.0, 24.0})
    for (const auto& up : ups) {
      INFO("fps " << fps << (up ? " with up" : " without up"));
      const auto options = options_with(up);
      const auto instants = ds::similarity::internal::signature_instants(tube.num_frames(), fps, 30);
      ds::signatures::with_positions_and_weights(tube, [&](auto positions, std::span<const double> weights) {
        require_same_bits(ds::signatures::motion_signatures_at(positions, weights, options, fps,
                                                               std::span<const double>(instants)),
                          reference_signatures(positions, weights, options, fps, instants));
      });
    }
}

TEST_CASE("motion_signatures_streamed: the library's animals as the radix selection of every row anew",
          "[signatures][gltf][data]") {
  // Each clip of three bodies streamed from its file (the welded vertices posed alone, the file's
  // connectivity shared by its clips), against the reference on the clip read whole.
  const fs::path animals = ds::test::data_dir() / "library" / "animals_pack";
  for (const char* body : {"Alpaca.glb", "Horse.glb", "Wolf.glb"}) {
    REQUIRE(fs::exists(animals / body));  // [data]: run only where the shared data are
    const ds::io::Gltf_file file(animals / body);
    const auto connectivity = std::make_shared<const ds::io::Gltf_connectivity>(file);
    const ds::signatures::Motion_signature_options options;
    for (const std::string& clip : file.clip_names()) {
      INFO(body << "#" << clip);
      const auto animation = file.read({.clip = clip});
      const auto instants = ds::signatures::frame_instants(animation.num_frames(), 30);
      ds::io::Gltf_frame_source source(connectivity, {.clip = clip});
      const Eigen::MatrixXd streamed_rows =
          ds::signatures::motion_signatures_streamed(source, options, std::span<const double>(instants));
      ds::signatures::with_positions_and_weights(animation, [&](auto positions, std::span<const double> weights) {
        require_same_bits(streamed_rows, reference_signatures(positions, weights, options, 30, instants));
      });
    }
  }
}

TEST_CASE("motion_signatures_streamed: positions in memory give motion_signatures_at's bits", "[signatures]") {
  const auto tube = long_tube();
  const auto triangles = tube.triangles();
  for (const double fps : {30.0, 24.0, 12.0, 60.0})
    for (const auto& up : ups) {
      INFO("fps " << fps << (up ? " with up" : " without up"));
      const auto options = options_with(up);
      ds::signatures::Positions_frame_source<double> source(tube.all_positions(), tube.num_vertices(), triangles, fps);
      const std::vector<double> instants =
          ds::similarity::internal::signature_instants(tube.num_frames(), fps, 30);
      const Eigen::MatrixXd expected = ds::signatures::with_positions_and_weights(
          tube, [&](auto positions, std::span<const double> weights) {
            return ds::signatures::motion_signatures_at(positions, weights, options, fps,
                                                        std::span<const double>(instants));
          });
      require_same_bits(ds::signatures::motion_signatures_streamed(source, options, std::span<const double>(instants)),
                        expected);
    }
}

TEST_CASE("streamed_ring_frames: the longest lag's span and a batch, at most the animation", "[signatures]") {
  const ds::signatures::Motion_signature_options options;
  const auto at_30 = ds::signatures::frame_instants(1000, 30);
  // 128 frames either side of a row, both ends included, and 16 more.
  CHECK(ds::signatures::streamed_ring_frames(options, 30, 1000, std::span<const double>(at_30)) == 257 + 16);
  const auto at_60 = ds::signatures::frame_instants(1000, 60);
  CHECK(ds::signatures::streamed_ring_frames(options, 60, 1000, std::span<const double>(at_60)) == 513 + 16);
  const auto short_clip = ds::signatures::frame_instants(40, 30);
  CHECK(ds::signatures::streamed_ring_frames(options, 30, 40, std::span<const double>(short_clip)) == 40);
  const std::vector<double> backwards{0.5, 0.25};
  CHECK_THROWS_WITH(ds::signatures::streamed_ring_frames(options, 30, 40, std::span<const double>(backwards)),
                    Contains("instant 1") && Contains("comes before"));
}

TEST_CASE("Point_cache_frame_source: PC2 and MDD streamed equal read_animation's description", "[signatures][io]") {
  const auto tube = long_tube();
  for (const std::string name : {"tube.pc2", "tube.mdd"}) {
    const fs::path cache = write_cache(tube, name);
    for (const double fps : {30.0, 15.0})
      for (const auto& up : ups) {
        INFO(name << " at " << fps << " fps" << (up ? " with up" : " without up"));
        const auto options = options_with(up);
        const auto whole = ds::io::read_animation(cache.string(), {.topology = cache.parent_path() / "topology.obj",
                                                                   .fps = fps});
        ds::io::Point_cache_frame_source source(cache, {.topology = cache.parent_path() / "topology.obj", .fps = fps});
        CHECK(source.num_frames() == whole.num_frames());
        CHECK(source.num_vertices() == whole.num_vertices());
        require_same_bits(streamed(source, options), described(whole, options));
      }
  }
}

TEST_CASE("Point_cache_frame_source: reads each frame twice and holds the ring only", "[signatures][io]") {
  const auto tube = long_tube();
  const fs::path cache = write_cache(tube, "count.pc2");
  Counting_source source(cache, {.topology = cache.parent_path() / "topology.obj"});
  static_cast<void>(streamed(source, {}));
  CHECK(source.read == 2 * tube.num_frames());
  CHECK(source.rewinds == 2);
}

TEST_CASE("Point_cache_frame_source: a clip no longer than the ring is read once, into it", "[signatures][io]") {
  const auto tube = long_tube();
  const std::vector<double> xyz(tube.all_positions().begin(),
                                tube.all_positions().begin() + std::ptrdiff_t(3 * tube.num_vertices() * 100));
  const ds::mesh::Surface_mesh_animation clip(tube.face_graph(), xyz);
  const fs::path cache = write_cache(clip, "short.pc2");
  const fs::path topology = cache.parent_path() / "topology.obj";
  Counting_source source(cache, {.topology = topology});
  const auto whole = ds::io::read_animation(cache.string(), {.topology = topology});
  for (const auto& up : ups) {
    const auto options = options_with(up);
    source.read = source.rewinds = 0;
    require_same_bits(streamed(source, options), described(whole, options));
    CHECK(source.read == 100);
    CHECK(source.rewinds == 1);
  }
}

TEST_CASE("Frame_sequence_source: OBJ frames streamed equal read_frame_sequence's description", "[signatures][io]") {
  auto tube = long_tube();
  const fs::path folder = ds::test::fresh_dir("stream_sequence");
  ds::io::write_sequence(tube, folder, {.format = ds::io::Mesh_format::obj});
  for (const double fps : {30.0, 20.0})
    for (const auto& up : ups) {
      INFO(fps << " fps" << (up ? " with up" : " without up"));
      const auto options = options_with(up);
      const auto whole = ds::io::read_animation(folder.string(), {.fps = fps});
      ds::io::Frame_sequence_source source(folder.string(), {.fps = fps});
      require_same_bits(streamed(source, options), described(whole, options));
    }
  SECTION("with a topology file") {
    const fs::path topology = folder.parent_path() / "stream_topology.obj";
    ds::io::write_obj(tube, 3, topology);
    const auto whole = ds::io::read_animation(folder.string(), {.topology = topology});
    ds::io::Frame_sequence_source source(folder.string(), {.topology = topology});
    require_same_bits(streamed(source, {}), described(whole, {}));
  }
  SECTION("a frame file that cannot be read names it and its frame") {
    ds::io::Frame_sequence_source source(folder.string(), {});
    const fs::path broken = folder / "frame_0200.obj";
    REQUIRE(fs::exists(broken));
    ds::test::write_file("stream_sequence/frame_0200.obj", "v 0 0 0\nv 1 oops 0\n");
    CHECK_THROWS_WITH(streamed(source, {}), Contains("frame_0200.obj") && Contains("frame 200"));
  }
}

TEST_CASE("Point_cache_frame_source: a truncated frame and a changed length are refused", "[signatures][io]") {
  const auto tube = long_tube();
  SECTION("a frame the file no longer holds names the file and the frame") {
    const fs::path cache = write_cache(tube, "cut.pc2");
    ds::io::Point_cache_frame_source source(cache, {.topology = cache.parent_path() / "topology.obj"});
    fs::resize_file(cache, 32 + 12 * tube.num_vertices() * 100 + 5);  // after the header was read
    std::vector<float> frame(3 * source.num_vertices());
    for (int t = 0; t < 100; ++t) source.read_frame(std::span<float>(frame));
    CHECK_THROWS_WITH(source.read_frame(std::span<float>(frame)), Contains("cut.pc2") && Contains("frame 100"));
  }
  SECTION("a cache rewritten shorter between the two passes") {
    const fs::path cache = write_cache(tube, "changed.pc2");
    Counting_source source(cache, {.topology = cache.parent_path() / "topology.obj"});
    source.on_second_rewind = [&] {
      std::vector<double> positions(tube.all_positions().begin(),
                                    tube.all_positions().begin() + std::ptrdiff_t(3 * tube.num_vertices() * 300));
      ds::io::write_pc2(ds::mesh::Surface_mesh_animation(tube.face_graph(), std::move(positions)), cache);
    };
    CHECK_THROWS_WITH(streamed(source, {}), Contains("changed between its two readings") && Contains("361 frames") &&
                                                 Contains("then 300"));
  }
  SECTION("welding is refused: it compares every frame") {
    const fs::path cache = write_cache(tube, "weld.pc2");
    CHECK_THROWS_WITH(ds::io::Point_cache_frame_source(cache, {.topology = cache.parent_path() / "topology.obj",
                                                                .repair = {.weld = true}}),
                      Contains("not welded") && Contains("topology.obj"));
  }
}

#if DEFORMSEG_HAS_GLTF
TEST_CASE("Gltf_frame_source: a hand-made clip streamed equals Gltf_file::read's description", "[signatures][gltf]") {
  using json = nlohmann::json;
  ds::test::Gltf_writer w;
  // A 4 x 4 grid of triangles on a node that moves and turns for 12 s: 361 frames at 30 fps.
  std::vector<float> points;
  std::vector<std::uint16_t> indices;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) points.insert(points.end(), {float(x), float(y) * 0.5f, float(x * y) * 0.1f});
  for (std::uint16_t y = 0; y < 3; ++y)
    for (std::uint16_t x = 0; x < 3; ++x) {
      const std::uint16_t a = std::uint16_t(4 * y + x);
      indices.insert(indices.end(), {a, std::uint16_t(a + 1), std::uint16_t(a + 4), std::uint16_t(a + 1),
                                     std::uint16_t(a + 5), std::uint16_t(a + 4)});
    }
  const int position = w.floats(points, "VEC3");
  const int index = w.accessor(w.view(indices.data(), 2 * indices.size()), ds::test::Gltf_writer::ushort_type,
                               indices.size(), "SCALAR");
  const int mesh =
      w.push("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", position}}}, {"indices", index}}})}});
  w.push("nodes", {{"mesh", mesh}});
  w.push("scenes", {{"nodes", {0}}});
  json clip = {{"name", "wander"}, {"samplers", json::array()}, {"channels", json::array()}};
  const auto channel = [&](const std::string& path, const std::vector<float>& times, const std::vector<float>& values,
                           const std::string& type) {
    clip["samplers"].push_back({{"input", w.floats(times, "SCALAR")}, {"output", w.floats(values, type)}});
    clip["channels"].push_back({{"sampler", clip["samplers"].size() - 1}, {"target", {{"node", 0}, {"path", path}}}});
  };
  channel("translation", {0, 3, 7, 12}, {0, 0, 0, 2, 1, 0, -1, 3, 2, 0, 0, 1}, "VEC3");
  const float s = std::sqrt(0.5f);
  channel("rotation", {1, 6, 12}, {0, 0, 0, 1, 0, s, 0, s, s, 0, 0, s}, "VEC4");
  channel("scale", {0, 12}, {1, 1, 1, 1, 2, 1}, "VEC3");
  w.push("animations", clip);
  const fs::path path = ds::test::scratch_dir() / "stream_wander.glb";
  w.write_glb(path);

  const ds::io::Gltf_file file(path);
  for (const double fps : {30.0, 24.0})
    for (const auto& up : ups) {
      INFO(fps << " fps" << (up ? " with up" : " without up"));
      const auto options = options_with(up);
      ds::io::Gltf_frame_source source(file, {.fps = fps});
      require_same_bits(streamed(source, options), described(file.read({.fps = fps}), options));
    }
  SECTION("the frame sampler gives sample's frames") {
    const auto sampled = file.sample({.fps = 24});
    auto sampler = file.frame_sampler({.fps = 24});
    REQUIRE(sampler.num_frames() == sampled.report.frames);
    std::vector<double> frame(3 * sampler.num_vertices());
    for (std::size_t t = 0; t < sampler.num_frames(); t += 7) {
      sampler.sample_frame(t, std::span<double>(frame));
      CHECK(std::memcmp(frame.data(), sampled.positions.data() + t * frame.size(), 8 * frame.size()) == 0);
    }
    CHECK_THROWS_WITH(sampler.sample_frame(sampler.num_frames(), std::span<double>(frame)),
                      Contains("stream_wander.glb") && Contains("no frame"));
  }
}

TEST_CASE("with_frame_source: a shared character's clip streamed equals read_animation's description",
          "[signatures][gltf][data]") {
  const fs::path fox = ds::test::data_dir() / "characters" / "Fox.glb";
  REQUIRE(fs::exists(fox));  // [data]: run only where the shared data are
  for (const double fps : {30.0, 15.0})
    for (const auto& up : ups) {
      INFO(fps << " fps" << (up ? " with up" : " without up"));
      const auto options = options_with(up);
      const std::string input = fox.string() + "#Run";
      const Eigen::MatrixXf stream = ds::io::with_frame_source(
          input, {.fps = fps}, [&](auto& source) { return streamed(source, options); });
      require_same_bits(stream, described(ds::io::read_animation(input, {.fps = fps}), options));
    }
}
#endif
