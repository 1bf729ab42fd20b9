// Tests of the writers of io/obj.h, io/off.h, io/ply.h and io/frame_sequence.h: exact text, numbers that read
// back identically, PLY face colours read back by CGAL, file names that sort in frame order, and
// the errors.
#include "tetrahedron.h"

#include <deformseg/color/color.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/off.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/off.h>
#include <deformseg/io/ply.h>
#include <deformseg/io/frame_sequence.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

using namespace deformseg;
using Catch::Matchers::Message;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {

using Polyhedron = CGAL::Polyhedron_3<mesh::Kernel>;
using Point = CGAL::Simple_cartesian<double>::Point_3;
using Polygons = std::vector<std::vector<std::size_t>>;

using deformseg::test::graph_name;
using deformseg::test::tetra_points;
using deformseg::test::tetra_triangles;
using deformseg::test::tetrahedron;

// Frame t moves vertex i by (t / 10, t / 3, -t i / 7): values with long decimal expansions.
template <class Coordinate>
std::vector<Coordinate> drifting_positions(std::size_t frames) {
  std::vector<Coordinate> xyz;
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t i = 0; i < 4; ++i) {
      const double d = double(t);
      xyz.push_back(Coordinate(tetra_points[i][0] + d / 10));
      xyz.push_back(Coordinate(tetra_points[i][1] + d / 3));
      xyz.push_back(Coordinate(tetra_points[i][2] - d * double(i) / 7));
    }
  return xyz;
}

template <class Graph, class Coordinate = double>
mesh::Deforming_mesh<Graph, Coordinate> drifting_tetrahedron(std::size_t frames) {
  return mesh::Deforming_mesh<Graph, Coordinate>(tetrahedron<Graph>(), drifting_positions<Coordinate>(frames));
}

// A path for a file a test writes, in a folder of its own, emptied first.
fs::path output(const std::string& test, const std::string& name) {
  return test::fresh_dir("io_writers/" + test) / name;
}

using deformseg::test::file_text;

// The triangles of a polygon soup, each rotated to start at its smallest index, as the
// animation's triangle table may start each cycle anywhere.
std::vector<std::array<std::size_t, 3>> canonical(const Polygons& polygons) {
  std::vector<std::array<std::size_t, 3>> triangles;
  for (const auto& polygon : polygons) {
    REQUIRE(polygon.size() == 3);
    std::array<std::size_t, 3> triangle{polygon[0], polygon[1], polygon[2]};
    std::rotate(triangle.begin(), std::min_element(triangle.begin(), triangle.end()), triangle.end());
    triangles.push_back(triangle);
  }
  return triangles;
}

Polygons tetra_polygons() {
  Polygons polygons;
  for (const auto& t : tetra_triangles) polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  return polygons;
}

template <class Animation>
void check_points(const std::vector<Point>& points, const Animation& animation, std::size_t frame) {
  REQUIRE(points.size() == animation.num_vertices());
  const auto xyz = animation.frame_positions(frame);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(points[i][k] == double(xyz[3 * i + k]));
}

// The face lines the animation's triangle table gives, with a suffix each (colours).
template <class Animation>
std::string face_lines(const Animation& animation, const char* prefix, int base,
                       const std::vector<std::string>& suffixes) {
  std::string lines;
  for (std::size_t j = 0; j < animation.num_faces(); ++j) {
    lines += prefix;
    for (const auto v : animation.triangles()[j]) lines.append(" ").append(std::to_string(v + base));
    if (!suffixes.empty()) lines.append(suffixes[j]);
    lines.append("\n");
  }
  return lines;
}

// Reads a PLY file with CGAL, face colours included (CGAL wants both colour iterators of one type).
bool read_ply_colored(const fs::path& file, std::vector<Point>& points, Polygons& polygons,
                      std::vector<CGAL::IO::Color>& face_colors) {
  std::vector<CGAL::IO::Color> vertex_colors;
  return CGAL::IO::read_PLY(file.string(), points, polygons,
                            CGAL::parameters::face_color_output_iterator(std::back_inserter(face_colors))
                                .vertex_color_output_iterator(std::back_inserter(vertex_colors)));
}

const std::vector<color::Rgb> four_colors{{255, 0, 0}, {0, 128, 0}, {0, 0, 255}, {12, 34, 56}};

}  // namespace

TEST_CASE("write_obj: the vertices as their shortest exact text, the triangles 1-based", "[io][writers][obj]") {
  // Frame 1 holds numbers whose shortest form is decimal, scientific, negative zero, subnormal.
  std::vector<double> xyz(12, 0.0);
  const std::vector<double> frame1{0.1, 1.0 / 3, -2.5, 1e-300, 123456789.125, -0.0, 2.0 / 3, 1e21, 5e-324, 0, 0, 1};
  xyz.insert(xyz.end(), frame1.begin(), frame1.end());
  const mesh::Deforming_mesh<mesh::Surface_mesh> animation(tetrahedron<mesh::Surface_mesh>(), xyz);
  const fs::path file = output("obj_text", "frame1.obj");
  io::write_obj(animation, 1, file);

  const std::string text = file_text(file);
  const std::string vertex_lines = "# deformseg: frame 1 of 2\n"
                                   "v 0.1 0.3333333333333333 -2.5\n"
                                   "v 1e-300 123456789.125 -0\n"
                                   "v 0.6666666666666666 1e+21 5e-324\n"
                                   "v 0 0 1\n";
  CHECK(text == vertex_lines + face_lines(animation, "f", 1, {}));

  // Each number reads back to the same bits.
  std::istringstream lines(text.substr(text.find('\n') + 1));
  for (std::size_t i = 0; i < 4; ++i) {
    std::string v, number;
    lines >> v;
    for (int k = 0; k < 3; ++k) {
      lines >> number;
      double value = 42;
      std::from_chars(number.data(), number.data() + number.size(), value);
      CHECK(std::bit_cast<std::uint64_t>(value) == std::bit_cast<std::uint64_t>(frame1[3 * i + k]));
    }
  }
}

TEST_CASE("write_off: the counts, the vertices as their shortest exact text, the triangles 0-based",
          "[io][writers][off]") {
  std::vector<double> xyz(12, 0.0);
  const std::vector<double> frame1{0.1, 1.0 / 3, -2.5, 1e-300, 123456789.125, -0.0, 2.0 / 3, 1e21, 5e-324, 0, 0, 1};
  xyz.insert(xyz.end(), frame1.begin(), frame1.end());
  const mesh::Deforming_mesh<mesh::Surface_mesh> animation(tetrahedron<mesh::Surface_mesh>(), xyz);
  const fs::path file = output("off_text", "frame1.off");
  io::write_off(animation, 1, file);
  CHECK(file_text(file) == "OFF\n# deformseg: frame 1 of 2\n4 4 0\n"
                           "0.1 0.3333333333333333 -2.5\n"
                           "1e-300 123456789.125 -0\n"
                           "0.6666666666666666 1e+21 5e-324\n"
                           "0 0 1\n" +
                               face_lines(animation, "3", 0, {}));
  const io::Triangle_soup soup = io::read_off(file);
  CHECK(std::ranges::equal(soup.points, frame1));
  CHECK(std::ranges::equal(soup.triangles, animation.triangles()));
  CHECK_THROWS_WITH(io::write_off(animation, 2, file), StartsWith(file.string() + ": "));
}

TEST_CASE("write_obj: a float animation is written in float's shortest form", "[io][writers][obj]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh, float>(2);
  const fs::path file = output("obj_float", "frame1.obj");
  io::write_obj(animation, 1, file);
  // Vertex 0 of frame 1 is (0.1f, 1/3.f, 0): shorter than the double these floats are.
  CHECK(file_text(file).starts_with("# deformseg: frame 1 of 2\nv 0.1 0.33333334 0\n"));
}

TEMPLATE_TEST_CASE("write_obj: CGAL reads back the same points and triangles", "[io][writers][obj]", mesh::Surface_mesh,
                   Polyhedron) {
  const auto animation = drifting_tetrahedron<TestType>(3);
  const fs::path file = output("obj_cgal_" + graph_name<TestType>(), "frame2.obj");
  io::write_obj(animation, 2, file);
  std::vector<Point> points;
  Polygons polygons;
  REQUIRE(CGAL::IO::read_polygon_soup(file.string(), points, polygons));
  check_points(points, animation, 2);
  CHECK(canonical(polygons) == canonical(tetra_polygons()));
}

TEST_CASE("write_ply: text PLY, with face colours, exactly", "[io][writers][ply]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh>(2);
  const fs::path file = output("ply_ascii", "frame1.ply");
  io::write_ply(animation, 1, file, four_colors, {.encoding = io::Ply_encoding::ascii});
  const std::string expected = "ply\n"
                               "format ascii 1.0\n"
                               "comment deformseg: frame 1 of 2\n"
                               "element vertex 4\n"
                               "property double x\n"
                               "property double y\n"
                               "property double z\n"
                               "element face 4\n"
                               "property list uchar int vertex_indices\n"
                               "property uchar red\n"
                               "property uchar green\n"
                               "property uchar blue\n"
                               "end_header\n"
                               "0.1 0.3333333333333333 0\n"
                               "1.1 0.3333333333333333 -0.14285714285714285\n"
                               "0.1 1.3333333333333333 -0.2857142857142857\n"
                               "0.1 0.3333333333333333 0.5714285714285714\n";
  CHECK(file_text(file) == expected + face_lines(animation, "3", 0, {" 255 0 0", " 0 128 0", " 0 0 255", " 12 34 56"}));
}

TEMPLATE_TEST_CASE("write_ply: binary PLY with face colours, read back by CGAL", "[io][writers][ply]",
                   mesh::Surface_mesh, Polyhedron) {
  const auto animation = drifting_tetrahedron<TestType>(3);
  const fs::path file = output("ply_binary_" + graph_name<TestType>(), "frame2.ply");
  io::write_ply(animation, 2, file, four_colors);

  const std::string header = "ply\n"
                             "format binary_little_endian 1.0\n"
                             "comment deformseg: frame 2 of 3\n"
                             "element vertex 4\n"
                             "property double x\n"
                             "property double y\n"
                             "property double z\n"
                             "element face 4\n"
                             "property list uchar int vertex_indices\n"
                             "property uchar red\n"
                             "property uchar green\n"
                             "property uchar blue\n"
                             "end_header\n";
  const std::string bytes = file_text(file);
  CHECK(bytes.substr(0, header.size()) == header);
  CHECK(bytes.size() == header.size() + 4 * 3 * 8 + 4 * (1 + 3 * 4 + 3));
  // The first face: its count, then its first index little-endian.
  const std::size_t first_face = header.size() + 4 * 3 * 8;
  CHECK(bytes[first_face] == 3);
  CHECK(bytes.substr(first_face + 1, 4) == std::string{char(animation.triangles()[0][0]), 0, 0, 0});

  std::vector<Point> points;
  Polygons polygons;
  std::vector<CGAL::IO::Color> colors;
  REQUIRE(read_ply_colored(file, points, polygons, colors));
  check_points(points, animation, 2);
  CHECK(canonical(polygons) == canonical(tetra_polygons()));
  REQUIRE(colors.size() == 4);
  for (std::size_t j = 0; j < 4; ++j)
    CHECK(colors[j] == CGAL::IO::Color(four_colors[j].r, four_colors[j].g, four_colors[j].b));
}

TEST_CASE("write_ply: a float animation, without colours, as float properties", "[io][writers][ply]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh, float>(2);
  const fs::path file = output("ply_float", "frame1.ply");
  io::write_ply(animation, 1, file);
  const std::string bytes = file_text(file);
  const std::string header_end =
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  REQUIRE(bytes.find(header_end) != std::string::npos);
  const std::size_t body = bytes.find(header_end) + header_end.size();
  CHECK(bytes.size() == body + 4 * 3 * 4 + 4 * (1 + 3 * 4));
  // Vertex 0, y = 1/3.f = 0x3EAAAAAB, little-endian.
  CHECK(bytes.substr(body + 4, 4) == "\xAB\xAA\xAA\x3E");

  std::vector<Point> points;
  Polygons polygons;
  REQUIRE(CGAL::IO::read_PLY(file.string(), points, polygons));
  check_points(points, animation, 1);
}

TEST_CASE("write_obj and write_ply reject bad arguments, naming the file", "[io][writers][errors]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh>(3);
  const fs::path folder = test::fresh_dir("io_writers/errors");

  SECTION("a frame out of range") {
    const fs::path obj = folder / "frame3.obj";
    CHECK_THROWS_MATCHES(io::write_obj(animation, 3, obj), invalid_input,
                         Message(obj.string() + ": cannot write frame 3 of an animation of 3 frames"));
    const fs::path ply = folder / "frame3.ply";
    CHECK_THROWS_MATCHES(io::write_ply(animation, 3, ply), invalid_input,
                         Message(ply.string() + ": cannot write frame 3 of an animation of 3 frames"));
    CHECK_FALSE(fs::exists(obj));
  }
  SECTION("a colour count other than the face count") {
    const fs::path ply = folder / "colors.ply";
    const std::vector<color::Rgb> three(3);
    CHECK_THROWS_MATCHES(io::write_ply(animation, 0, ply, three), invalid_input,
                         Message(ply.string() + ": 3 face colours for 4 faces"));
  }
  SECTION("a path in a folder that does not exist") {
    const fs::path obj = folder / "missing" / "frame.obj";
    CHECK_THROWS_MATCHES(io::write_obj(animation, 0, obj), invalid_input,
                         Message(obj.string() + ": cannot write: " + std::generic_category().message(ENOENT)));
  }
  SECTION("a device that is full") {
    if (fs::exists("/dev/full"))
      CHECK_THROWS_MATCHES(io::write_obj(animation, 0, "/dev/full"), invalid_input,
                           Message("/dev/full: cannot write: " + std::generic_category().message(ENOSPC)));
  }
  SECTION("a path that is a folder") {
    CHECK_THROWS_MATCHES(io::write_ply(animation, 0, folder), invalid_input,
                         Message(folder.string() + ": cannot write: it is a folder, not a file"));
  }
}

TEST_CASE("sequence_file_name: zero-padded to the width of the last frame", "[io][writers][sequence]") {
  CHECK(io::sequence_file_name(7, 10) == "frame_0007.ply");
  CHECK(io::sequence_file_name(7, 100001) == "frame_000007.ply");
  CHECK(io::sequence_file_name(99999, 100000) == "frame_99999.ply");
  CHECK(io::sequence_file_name(3, 12, {.format = io::Mesh_format::obj, .prefix = "m", .min_digits = 1}) == "m03.obj");
  CHECK(io::sequence_file_name(0, 1, {.min_digits = 0}) == "frame_0.ply");
  CHECK(io::sequence_file_name(2, 3, {.format = io::Mesh_format::off}) == "frame_0002.off");
}

TEST_CASE("write_sequence: names that sort the same plainly and naturally", "[io][writers][sequence]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh>(12);
  const fs::path folder = test::fresh_dir("io_writers/names") / "new" / "folder";
  const auto files = io::write_sequence(animation, folder, {.min_digits = 1});
  REQUIRE(files.size() == 12);
  CHECK(files.front().filename() == "frame_00.ply");
  CHECK(files[9].filename() == "frame_09.ply");
  CHECK(files.back().filename() == "frame_11.ply");
  auto sorted = files;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted == files);
  CHECK(io::list_frame_files(folder.string()) == files);
}

TEMPLATE_TEST_CASE("write_sequence then read_frame_sequence: the same positions", "[io][writers][sequence]", float,
                   double) {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh, TestType>(5);
  for (const auto format : {io::Mesh_format::obj, io::Mesh_format::off, io::Mesh_format::ply}) {
    const std::string extension = deformseg::io::internal::file_extension(format);
    const fs::path folder = test::fresh_dir(std::string("io_writers/round_trip_") +
                                            (sizeof(TestType) == 4 ? "float" : "double") + extension);
    const auto files = io::write_sequence(animation, folder, {.format = format});
    REQUIRE(files.size() == 5);
    CHECK(files[4].filename() == "frame_0004" + extension);
    const auto read = io::read_frame_sequence<mesh::Surface_mesh, TestType>(folder.string());
    REQUIRE(read.num_frames() == 5);
    CHECK(std::ranges::equal(read.all_positions(), animation.all_positions()));
  }
}

TEST_CASE("write_sequence: per-frame face colours through a callback", "[io][writers][sequence]") {
  const auto animation = drifting_tetrahedron<Polyhedron>(3);
  const auto colors_of = [](std::size_t t) {
    std::vector<color::Rgb> colors;
    for (std::uint8_t j = 0; j < 4; ++j)
      colors.push_back({std::uint8_t(10 * t), std::uint8_t(50 * j), std::uint8_t(255 - j)});
    return colors;
  };
  const fs::path folder = test::fresh_dir("io_writers/colors");
  const auto files = io::write_sequence(animation, folder, {.face_colors = colors_of});
  REQUIRE(files.size() == 3);
  for (std::size_t t = 0; t < 3; ++t) {
    std::vector<Point> points;
    Polygons polygons;
    std::vector<CGAL::IO::Color> colors;
    REQUIRE(read_ply_colored(files[t], points, polygons, colors));
    check_points(points, animation, t);
    REQUIRE(colors.size() == 4);
    for (std::size_t j = 0; j < 4; ++j) {
      const color::Rgb expected = colors_of(t)[j];
      CHECK(colors[j] == CGAL::IO::Color(expected.r, expected.g, expected.b));
    }
  }
}

TEST_CASE("write_sequence rejects bad options, naming the folder or the file", "[io][writers][sequence][errors]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh>(3);
  const fs::path folder = test::fresh_dir("io_writers/sequence_errors");

  SECTION("colours asked of OBJ") {
    const auto none = [](std::size_t) { return std::vector<color::Rgb>{}; };
    CHECK_THROWS_MATCHES(io::write_sequence(animation, folder, {.format = io::Mesh_format::obj, .face_colors = none}),
                         invalid_input,
                         Message(folder.string() + ": face colours need the PLY format: OBJ and OFF files have none"));
  }
  SECTION("a frame with a wrong number of colours") {
    const auto colors = [](std::size_t t) {
      return t == 1 ? std::vector<color::Rgb>(four_colors.begin(), four_colors.begin() + 2) : four_colors;
    };
    const fs::path second = folder / "frame_0001.ply";
    CHECK_THROWS_MATCHES(io::write_sequence(animation, folder, {.face_colors = colors}), invalid_input,
                         Message(second.string() + ": frame 1: 2 face colours for 4 faces"));
    CHECK(fs::exists(folder / "frame_0000.ply"));
    CHECK_FALSE(fs::exists(second));
  }
  SECTION("a prefix with a folder in it") {
    CHECK_THROWS_MATCHES(io::write_sequence(animation, folder, {.prefix = "sub/frame_"}), invalid_input,
                         Message(folder.string() + ": the prefix \"sub/frame_\" holds a folder separator"));
  }
  SECTION("a folder that is a file") {
    const fs::path file = test::write_file("io_writers/sequence_errors/a_file", "not a folder");
    CHECK_THROWS_MATCHES(io::write_sequence(animation, file), invalid_input,
                         Message(file.string() + ": cannot write into it: it is not a folder"));
    CHECK_THROWS_MATCHES(io::write_sequence(animation, file / "sub"), invalid_input,
                         Message((file / "sub").string() + ": cannot create the folder: " +
                                 std::generic_category().message(ENOTDIR)));
  }
  SECTION("an animation without frames writes nothing") {
    const mesh::Deforming_mesh<mesh::Surface_mesh> empty(tetrahedron<mesh::Surface_mesh>());
    CHECK(io::write_sequence(empty, folder / "empty").empty());
    CHECK(fs::is_empty(folder / "empty"));
  }
}
