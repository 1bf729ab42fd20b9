// Tests of io/point_cache.h: PC2 and MDD round trips, header fields, files made byte by byte
// here (so that the byte order is checked against the formats, not only against the writers),
// and every error with its message.
#include "tetrahedron.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/point_cache.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/io/off.h>

#include <CGAL/Polyhedron_3.h>

#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

using namespace deformseg;
using deformseg::io::Point_cache_format;
using deformseg::io::Point_cache_info;
using Catch::Matchers::Message;
namespace fs = std::filesystem;

namespace {

using Polyhedron = CGAL::Polyhedron_3<mesh::Kernel>;

// The tetrahedron: V = 4, so a frame is 48 bytes.
using deformseg::test::graph_name;
using deformseg::test::tetrahedron;

// Frame t, vertex i, axis k at (i + 1) * (k + 1) / 10 + t / 3: values no float holds exactly.
template <class Coordinate>
std::vector<Coordinate> moving_positions(std::size_t frames) {
  std::vector<Coordinate> xyz;
  for (std::size_t t = 0; t < frames; ++t)
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) xyz.push_back(Coordinate((i + 1) * (k + 1) / 10.0 + double(t) / 3.0));
  return xyz;
}

template <class Graph, class Coordinate>
mesh::Deforming_mesh<Graph, Coordinate> moving_tetrahedron(std::size_t frames) {
  return mesh::Deforming_mesh<Graph, Coordinate>(tetrahedron<Graph>(), moving_positions<Coordinate>(frames));
}

// A file built byte by byte, in either byte order, written by the test's own code.
class Bytes {
public:
  explicit Bytes(std::endian order) : order_(order) {}
  Bytes& text(std::string_view s) { data_.append(s); return *this; }
  Bytes& i32(std::int32_t v) { return word(std::bit_cast<std::uint32_t>(v)); }
  Bytes& f32(float v) { return word(std::bit_cast<std::uint32_t>(v)); }
  Bytes& floats(std::size_t n, float v) { for (std::size_t i = 0; i < n; ++i) f32(v); return *this; }
  Bytes& zeros(std::size_t n) { data_.append(n, '\0'); return *this; }
  fs::path save(const std::string& name) const { return test::write_file("io_point_cache/" + name, data_); }

private:
  Bytes& word(std::uint32_t bits) {
    for (int k = 0; k < 4; ++k) {
      const int shift = order_ == std::endian::little ? 8 * k : 8 * (3 - k);
      data_.push_back(static_cast<char>((bits >> shift) & 0xFF));
    }
    return *this;
  }
  std::endian order_;
  std::string data_;
};

// A PC2 header as Blender writes it, for `points` points and `samples` samples.
Bytes pc2_header(std::int32_t points, std::int32_t samples, std::int32_t version = 1) {
  Bytes bytes(std::endian::little);
  bytes.text(std::string_view("POINTCACHE2\0", 12)).i32(version).i32(points).f32(1.0f).f32(1.0f).i32(samples);
  return bytes;
}

// An MDD header: counts, then frame t at time t / 10.
Bytes mdd_header(std::int32_t frames, std::int32_t points) {
  Bytes bytes(std::endian::big);
  bytes.i32(frames).i32(points);
  for (std::int32_t t = 0; t < frames; ++t) bytes.f32(float(t) / 10.0f);
  return bytes;
}

// The error message for `path`, optionally at `frame`.
std::string in_file(const fs::path& path, const std::string& message) { return path.string() + ": " + message; }
std::string in_frame(const fs::path& path, std::size_t frame, const std::string& message) {
  return path.string() + ": frame " + std::to_string(frame) + ": " + message;
}

// A path for a file a test writes; each test uses names of its own, so that tests can run in
// parallel. Any earlier file of that name is removed.
fs::path scratch(const std::string& name) {
  const fs::path dir = test::scratch_dir() / "io_point_cache_out";
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

}  // namespace

TEMPLATE_TEST_CASE("write_pc2 then read_pc2: float coordinates come back exactly", "[io][pc2]", mesh::Surface_mesh,
                   Polyhedron) {
  const auto animation = moving_tetrahedron<TestType, float>(3);
  const fs::path cache = scratch("tetra_" + graph_name<TestType>() + ".pc2");
  io::write_pc2(animation, cache);
  const auto read = io::read_pc2<TestType, float>(cache, tetrahedron<TestType>());
  REQUIRE(read.num_frames() == 3);
  REQUIRE(read.num_vertices() == 4);
  CHECK(std::ranges::equal(read.all_positions(), animation.all_positions()));
}

TEMPLATE_TEST_CASE("write_mdd then read_mdd: float coordinates come back exactly", "[io][mdd]", mesh::Surface_mesh,
                   Polyhedron) {
  const auto animation = moving_tetrahedron<TestType, float>(3);
  const fs::path cache = scratch("tetra_" + graph_name<TestType>() + ".mdd");
  io::write_mdd(animation, cache);
  const auto read = io::read_mdd<TestType, float>(cache, tetrahedron<TestType>());
  REQUIRE(read.num_frames() == 3);
  CHECK(std::ranges::equal(read.all_positions(), animation.all_positions()));
}

TEST_CASE("read_pc2, read_mdd and read_animation: the frame rate is an input, 30 by default", "[io][pc2][mdd]") {
  const auto animation = moving_tetrahedron<mesh::Surface_mesh, float>(3);
  const fs::path pc2 = scratch("tetra_rate.pc2"), mdd = scratch("tetra_rate.mdd");
  io::write_pc2(animation, pc2);
  io::write_mdd(animation, mdd);
  CHECK(io::read_pc2(pc2, tetrahedron<mesh::Surface_mesh>()).frames_per_second() == 30);
  CHECK(io::read_pc2(pc2, tetrahedron<mesh::Surface_mesh>(), 24).frames_per_second() == 24);
  CHECK(io::read_mdd(mdd, tetrahedron<mesh::Surface_mesh>(), 60).frames_per_second() == 60);
  const fs::path topology = scratch("tetra_rate.off");
  io::write_off(animation, 0, topology);
  CHECK(io::read_animation(pc2.string(), {.topology = topology, .fps = 15}).frames_per_second() == 15);
  CHECK_THROWS_WITH(io::read_animation(mdd.string(), {.topology = topology, .fps = -1}),
                    Catch::Contains("fps must be positive"));
}

TEST_CASE("point caches of a double animation hold its coordinates rounded to float", "[io][pc2][mdd]") {
  const auto animation = moving_tetrahedron<mesh::Surface_mesh, double>(2);
  for (const char* name : {"double.pc2", "double.mdd"}) {
    const fs::path cache = scratch(name);
    const bool pc2 = std::string_view(name).ends_with(".pc2");
    if (pc2)
      io::write_pc2(animation, cache);
    else
      io::write_mdd(animation, cache);
    const auto read = pc2 ? io::read_pc2(cache, tetrahedron<mesh::Surface_mesh>())
                          : io::read_mdd(cache, tetrahedron<mesh::Surface_mesh>());
    REQUIRE(read.all_positions().size() == 24);
    for (std::size_t i = 0; i < 24; ++i)
      CHECK(read.all_positions()[i] == double(static_cast<float>(animation.all_positions()[i])));
    CHECK(read.all_positions()[1] != animation.all_positions()[1]);  // 0.2 is no float
  }
}

TEST_CASE("write_pc2: the bytes of the format, and the header read back", "[io][pc2]") {
  const auto animation = moving_tetrahedron<mesh::Surface_mesh, float>(3);
  const fs::path cache = scratch("header.pc2");
  io::write_pc2(animation, cache, {.start_frame = 10, .sample_rate = 0.5});

  const std::string bytes = test::file_text(cache);
  REQUIRE(bytes.size() == 32 + 3 * 4 * 12);
  CHECK(bytes.substr(0, 32) == std::string("POINTCACHE2\0"
                                           "\x01\0\0\0"          // version 1
                                           "\x04\0\0\0"          // 4 points
                                           "\0\0\x20\x41"        // start frame 10.0f
                                           "\0\0\0\x3f"          // sample rate 0.5f
                                           "\x03\0\0\0",         // 3 samples
                                           32));
  // Frame 0, vertex 0, y = 0.2f = 0x3E4CCCCD, little-endian.
  CHECK(bytes.substr(36, 4) == "\xCD\xCC\x4C\x3E");

  const Point_cache_info info = io::read_point_cache_info(cache);
  CHECK(info.format == Point_cache_format::pc2);
  CHECK(info.num_vertices == 4);
  CHECK(info.num_frames == 3);
  CHECK(info.start_frame == 10.0);
  CHECK(info.sample_rate == 0.5);
  CHECK(info.frame_times.empty());
}

TEST_CASE("write_mdd: the bytes of the format, and the frame times read back", "[io][mdd]") {
  const auto animation = moving_tetrahedron<mesh::Surface_mesh, float>(3);
  const fs::path cache = scratch("header.MDD");
  io::write_mdd(animation, cache, 4.0);

  const std::string bytes = test::file_text(cache);
  REQUIRE(bytes.size() == 8 + 3 * 4 + 3 * 4 * 12);
  CHECK(bytes.substr(0, 20) == std::string("\0\0\0\x03"    // 3 frames
                                           "\0\0\0\x04"    // 4 points
                                           "\0\0\0\0"      // time 0
                                           "\x3e\x80\0\0"  // time 0.25f
                                           "\x3f\0\0\0",   // time 0.5f
                                           20));
  // Frame 0, vertex 0, y = 0.2f = 0x3E4CCCCD, big-endian.
  CHECK(bytes.substr(24, 4) == "\x3E\x4C\xCC\xCD");

  const Point_cache_info info = io::read_point_cache_info(cache);
  CHECK(info.format == Point_cache_format::mdd);
  CHECK(info.num_vertices == 4);
  CHECK(info.num_frames == 3);
  CHECK(info.frame_times == std::vector<double>{0.0, 0.25, 0.5});
}

TEST_CASE("read_pc2 and read_mdd decode files made byte by byte", "[io][pc2][mdd]") {
  // Two frames: every coordinate of frame t is -1.5 + t.
  Bytes pc2 = pc2_header(4, 2);
  pc2.floats(12, -1.5f).floats(12, -0.5f);
  Bytes mdd = mdd_header(2, 4);
  mdd.floats(12, -1.5f).floats(12, -0.5f);
  const auto from_pc2 = io::read_pc2(pc2.save("by_hand.pc2"), tetrahedron<mesh::Surface_mesh>());
  const auto from_mdd = io::read_mdd<Polyhedron, float>(mdd.save("by_hand.mdd"), tetrahedron<Polyhedron>());
  REQUIRE(from_pc2.num_frames() == 2);
  REQUIRE(from_mdd.num_frames() == 2);
  for (std::size_t i = 0; i < 24; ++i) {
    CHECK(from_pc2.all_positions()[i] == (i < 12 ? -1.5 : -0.5));
    CHECK(from_mdd.all_positions()[i] == (i < 12 ? -1.5f : -0.5f));
  }
  CHECK(io::read_point_cache_info(mdd.save("by_hand.mdd")).frame_times == std::vector<double>{0.0, double(0.1f)});
}

TEST_CASE("read_pc2 rejects a bad file with a message naming the problem", "[io][pc2][errors]") {
  const auto read = [](const fs::path& path) { return io::read_pc2(path, tetrahedron<mesh::Surface_mesh>()); };

  SECTION("a missing file") {
    const fs::path path = test::scratch_dir() / "io_point_cache" / "missing.pc2";
    CHECK_THROWS_MATCHES(read(path), invalid_input, Message(in_file(path, "cannot open: no such file")));
  }
  SECTION("a wrong signature") {
    Bytes bytes(std::endian::little);
    bytes.text("POINTCACHE3").zeros(21 + 48);
    const fs::path path = bytes.save("signature.pc2");
    CHECK_THROWS_MATCHES(
        read(path), invalid_input,
        Message(in_file(path, "not a PC2 point cache: it does not start with the signature \"POINTCACHE2\"")));
    CHECK_THROWS_MATCHES(
        io::read_point_cache_info(path), invalid_input,
        Message(in_file(path, "not a PC2 point cache: it does not start with the signature \"POINTCACHE2\"")));
  }
  SECTION("a wrong version") {
    const fs::path path = pc2_header(4, 1, 2).floats(12, 0).save("version.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "PC2 file version 2; deformseg reads version 1")));
  }
  SECTION("a header cut short") {
    Bytes bytes(std::endian::little);
    bytes.text(std::string_view("POINTCACHE2\0", 12)).i32(1);
    const fs::path path = bytes.save("short_header.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "truncated header: the file has 16 bytes, a PC2 header 32")));
  }
  SECTION("another vertex count than the topology's") {
    const fs::path path = pc2_header(5, 1).floats(15, 0).save("five_points.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input, Message(in_file(path, "the cache has 5 vertices, the topology 4")));
  }
  SECTION("no frame") {
    const fs::path path = pc2_header(4, 0).save("empty.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "the header gives 0 frames: the cache is empty")));
  }
  SECTION("a truncated file names the incomplete frame and the bytes missing") {
    const fs::path path = pc2_header(4, 3).floats(12 + 5, 0).save("truncated.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_frame(path, 1,
                                          "truncated: the frame has 20 of its 48 bytes; 76 bytes are "
                                          "missing for the 3 frames the header gives")));
    CHECK_THROWS_MATCHES(io::read_point_cache_info(path), invalid_input,
                         Message(in_frame(path, 1,
                                          "truncated: the frame has 20 of its 48 bytes; "
                                          "76 bytes are missing for the 3 frames the header gives")));
  }
  SECTION("trailing bytes after the last frame") {
    const fs::path path = pc2_header(4, 2).floats(24, 0).zeros(5).save("trailing.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "5 trailing bytes after the last of the 2 frames the header gives")));
  }
  SECTION("exactly one frame more than the header gives") {
    const fs::path path = pc2_header(4, 1).floats(24, 0).save("one_more.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path,
                                         "48 trailing bytes after the last of the 1 frames the header gives "
                                         "(exactly one frame more)")));
  }
  SECTION("a NaN coordinate names its frame and vertex") {
    Bytes bytes = pc2_header(4, 3);
    bytes.floats(12 + 12 + 3 + 2, 0).f32(std::numeric_limits<float>::quiet_NaN()).floats(6, 0);
    const fs::path path = bytes.save("nan.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input, Message(in_frame(path, 2, "vertex 1 has a non-finite coordinate")));
  }
  SECTION("an infinite coordinate names its frame and vertex") {
    const fs::path path =
        pc2_header(4, 1).floats(9, 0).f32(-std::numeric_limits<float>::infinity()).floats(2, 0).save("inf.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input, Message(in_frame(path, 0, "vertex 3 has a non-finite coordinate")));
  }
  SECTION("negative counts") {
    const fs::path points = pc2_header(-4, 1).save("negative_points.pc2");
    CHECK_THROWS_MATCHES(read(points), invalid_input,
                         Message(in_file(points, "the header gives a negative number of vertices: -4")));
    const fs::path samples = pc2_header(4, -1).save("negative_samples.pc2");
    CHECK_THROWS_MATCHES(read(samples), invalid_input,
                         Message(in_file(samples, "the header gives a negative number of frames: -1")));
  }
  SECTION("absurd counts are reported, not allocated") {
    constexpr std::int32_t most = std::numeric_limits<std::int32_t>::max();
    const fs::path frames = pc2_header(4, most).floats(12, 0).save("absurd_frames.pc2");
    CHECK_THROWS_MATCHES(read(frames), invalid_input,
                         Message(in_frame(frames, 1,
                                          "truncated: the frame has 0 of its 48 bytes; 103079215008 "
                                          "bytes are missing for the 2147483647 frames the header gives")));
    const fs::path points = pc2_header(most, 1).floats(12, 0).save("absurd_points.pc2");
    CHECK_THROWS_MATCHES(read(points), invalid_input,
                         Message(in_file(points, "the cache has 2147483647 vertices, the topology 4")));
    CHECK_THROWS_MATCHES(io::read_point_cache_info(points), invalid_input,
                         Message(in_frame(points, 0,
                                          "truncated: the frame has 48 of its 25769803764 bytes; 25769803716 bytes "
                                          "are missing for the 1 frames the header gives")));
    const fs::path both = pc2_header(most, most).save("absurd_both.pc2");
    CHECK_THROWS_MATCHES(
        io::read_point_cache_info(both), invalid_input,
        Message(in_file(both,
                        "the header gives 2147483647 frames of 2147483647 vertices: more bytes than any "
                        "file holds")));
  }
  SECTION("a non-finite sample rate") {
    Bytes bytes(std::endian::little);
    bytes.text(std::string_view("POINTCACHE2\0", 12))
        .i32(1)
        .i32(4)
        .f32(0)
        .f32(std::numeric_limits<float>::infinity())
        .i32(1)
        .floats(12, 0);
    const fs::path path = bytes.save("rate.pc2");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "the header's sample rate is not a finite positive number: inf")));
  }
}

TEST_CASE("read_mdd rejects a bad file with a message naming the problem", "[io][mdd][errors]") {
  const auto read = [](const fs::path& path) { return io::read_mdd(path, tetrahedron<mesh::Surface_mesh>()); };

  SECTION("a missing file") {
    const fs::path path = test::scratch_dir() / "io_point_cache" / "missing.mdd";
    CHECK_THROWS_MATCHES(read(path), invalid_input, Message(in_file(path, "cannot open: no such file")));
    CHECK_THROWS_MATCHES(io::read_point_cache_info(path), invalid_input,
                         Message(in_file(path, "cannot open: no such file")));
  }
  SECTION("a header cut short") {
    const fs::path path = Bytes(std::endian::big).i32(3).save("short_header.mdd");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "truncated header: the file has 4 bytes, an MDD header at least 8")));
  }
  SECTION("frame times the file does not hold") {
    const fs::path path = Bytes(std::endian::big).i32(1000).i32(4).zeros(12).save("times.mdd");
    CHECK_THROWS_MATCHES(
        read(path), invalid_input,
        Message(in_file(path, "truncated header: its 1000 frame times need 4008 bytes, the file has 20")));
    CHECK_THROWS_MATCHES(
        io::read_point_cache_info(path), invalid_input,
        Message(in_file(path, "truncated header: its 1000 frame times need 4008 bytes, the file has 20")));
  }
  SECTION("a little-endian file: absurd counts, reported") {
    Bytes bytes(std::endian::little);
    bytes.i32(2).i32(4).f32(0).f32(0.1f).floats(24, 0);
    const fs::path path = bytes.save("little_endian.mdd");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path,
                                         "truncated header: its 33554432 frame times need 134217736 bytes, "
                                         "the file has 112")));
  }
  SECTION("another vertex count than the topology's") {
    const fs::path path = mdd_header(1, 3).floats(9, 0).save("three_points.mdd");
    CHECK_THROWS_MATCHES(read(path), invalid_input, Message(in_file(path, "the cache has 3 vertices, the topology 4")));
  }
  SECTION("no frame") {
    const fs::path path = mdd_header(0, 4).save("empty.mdd");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "the header gives 0 frames: the cache is empty")));
  }
  SECTION("a truncated file") {
    const fs::path path = mdd_header(2, 4).floats(12 + 11, 0).save("truncated.mdd");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_frame(path, 1,
                                          "truncated: the frame has 44 of its 48 bytes; 4 bytes are "
                                          "missing for the 2 frames the header gives")));
  }
  SECTION("trailing bytes") {
    const fs::path path = mdd_header(1, 4).floats(12, 0).zeros(1).save("trailing.mdd");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "1 trailing bytes after the last of the 1 frames the header gives")));
  }
  SECTION("a NaN coordinate and a NaN time") {
    const fs::path coordinate = mdd_header(2, 4).floats(12 + 4, 1).f32(std::nanf("")).floats(7, 1).save("nan.mdd");
    CHECK_THROWS_MATCHES(read(coordinate), invalid_input,
                         Message(in_frame(coordinate, 1, "vertex 1 has a non-finite coordinate")));
    Bytes bytes(std::endian::big);
    bytes.i32(2).i32(4).f32(0).f32(std::nanf("")).floats(24, 0);
    const fs::path time = bytes.save("nan_time.mdd");
    CHECK_THROWS_MATCHES(read(time), invalid_input, Message(in_frame(time, 1, "the frame's time is not finite: nan")));
  }
  SECTION("negative counts") {
    const fs::path path = Bytes(std::endian::big).i32(-2).i32(4).save("negative.mdd");
    CHECK_THROWS_MATCHES(read(path), invalid_input,
                         Message(in_file(path, "the header gives a negative number of frames: -2")));
  }
}

TEST_CASE("read_point_cache_info needs a .pc2 or .mdd extension", "[io][pc2][mdd][errors]") {
  const fs::path path = pc2_header(4, 1).floats(12, 0).save("cache.bin");
  CHECK_THROWS_MATCHES(io::read_point_cache_info(path), invalid_input,
                       Message(in_file(path, "not a point cache: the extension is neither .pc2 nor .mdd")));
  CHECK(io::read_point_cache_info(pc2_header(4, 1).floats(12, 0).save("upper.PC2")).num_frames == 1);
}

TEST_CASE("write_pc2 and write_mdd reject what a point cache cannot hold", "[io][pc2][mdd][errors]") {
  const fs::path pc2 = scratch("unwritten.pc2");
  const fs::path mdd = scratch("unwritten.mdd");

  SECTION("an animation without frames") {
    const mesh::Deforming_mesh<mesh::Surface_mesh> empty(tetrahedron<mesh::Surface_mesh>());
    CHECK_THROWS_MATCHES(io::write_pc2(empty, pc2), invalid_input,
                         Message(in_file(pc2, "the animation has no frame: a point cache needs at least one")));
    CHECK_THROWS_MATCHES(io::write_mdd(empty, mdd), invalid_input,
                         Message(in_file(mdd, "the animation has no frame: a point cache needs at least one")));
  }
  SECTION("a coordinate beyond the range of float") {
    auto xyz = moving_positions<double>(2);
    xyz[12 + 3 * 2 + 1] = -1e300;
    const mesh::Deforming_mesh<mesh::Surface_mesh> huge(tetrahedron<mesh::Surface_mesh>(), xyz);
    CHECK_THROWS_MATCHES(
        io::write_pc2(huge, pc2), invalid_input,
        Message(in_frame(pc2, 1, "vertex 2 has the coordinate -1e+300, beyond the range of a float32")));
    CHECK_THROWS_MATCHES(
        io::write_mdd(huge, mdd), invalid_input,
        Message(in_frame(mdd, 1, "vertex 2 has the coordinate -1e+300, beyond the range of a float32")));
    CHECK_FALSE(fs::exists(pc2));
  }
  SECTION("timing that is not finite or not positive") {
    const auto animation = moving_tetrahedron<mesh::Surface_mesh, double>(1);
    CHECK_THROWS_MATCHES(io::write_pc2(animation, pc2, {.sample_rate = 0}), invalid_input,
                         Message(in_file(pc2, "sample_rate must be a positive finite float32, not 0")));
    CHECK_THROWS_MATCHES(io::write_pc2(animation, pc2, {.start_frame = std::numeric_limits<double>::infinity()}),
                         invalid_input, Message(in_file(pc2, "start_frame must be a finite float32, not inf")));
    CHECK_THROWS_MATCHES(io::write_mdd(animation, mdd, -25.0), invalid_input,
                         Message(in_file(mdd, "frames_per_second must be finite and positive, not -25")));
  }
  SECTION("a folder that does not exist") {
    const fs::path nowhere = test::scratch_dir() / "io_point_cache" / "no_such_folder" / "a.pc2";
    CHECK_THROWS_MATCHES(io::write_pc2(moving_tetrahedron<mesh::Surface_mesh, double>(1), nowhere), invalid_input,
                         Message(in_file(nowhere, "cannot write: " + std::generic_category().message(ENOENT))));
  }
}
