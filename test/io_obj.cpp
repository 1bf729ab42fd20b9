// Tests of io/obj.h (read_obj, write_obj) and of the OBJ path of read_mesh_points, on small files
// made here and, tagged [data], on the shared real animations against CGAL's reader; with
// write_ply, the writers' refusals.
#include "tetrahedron.h"
#include "writer_support.h"

#include <deformseg/exceptions.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/ply.h>
#include <deformseg/io/read_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

using deformseg::invalid_input;
using deformseg::io::read_mesh_points;
using deformseg::io::read_obj;
using deformseg::io::Triangle_soup;
using Catch::Matchers::Message;
namespace fs = std::filesystem;

namespace {

// The tetrahedron as an OBJ file.
const std::string tetrahedron_obj =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 0 1 0\n"
    "v 0 0 1\n"
    "f 1 3 2\n"
    "f 1 2 4\n"
    "f 2 3 4\n"
    "f 1 4 3\n";
using deformseg::test::Triangles;
using deformseg::test::tetrahedron_points;
using deformseg::test::tetrahedron_triangles;

fs::path obj_file(const std::string& name, const std::string& text) {
  return deformseg::test::write_file("io_obj/" + name, text);
}

using deformseg::test::at;

}  // namespace

TEST_CASE("read_obj: vertices and triangles in the order of the file", "[io][obj]") {
  const Triangle_soup soup = read_obj(obj_file("tetrahedron.obj", tetrahedron_obj));
  CHECK(soup.num_vertices() == 4);
  CHECK(soup.points == tetrahedron_points);
  CHECK(soup.triangles == tetrahedron_triangles);
}

TEST_CASE("read_obj: numbers are read exactly, in every decimal notation", "[io][obj]") {
  const Triangle_soup soup = read_obj(obj_file("numbers.obj",
                                               "v 0.1 -2.5e-3 +7\n"
                                               "v 1E2 .5 -0\n"
                                               "v -0.022739015899999999 0.97907069999999996 4.9406564584124654e-324\n"
                                               "f 1 2 3\n"));
  const std::vector<double> expected{0.1, -2.5e-3, 7, 100, 0.5, -0.0, -0.022739015899999999, 0.97907069999999996,
                                     4.9406564584124654e-324};
  REQUIRE(soup.points.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    CHECK(std::bit_cast<std::uint64_t>(soup.points[i]) == std::bit_cast<std::uint64_t>(expected[i]));
}

TEST_CASE("read_obj: every face corner form, relative indices, and the statements it skips", "[io][obj]") {
  const Triangle_soup soup = read_obj(obj_file("forms.obj",
                                               "# a comment\n"
                                               "mtllib tetra.mtl\n"
                                               "o tetra\n"
                                               "\n"
                                               "   \t\n"
                                               "v 0 0 0 1\n"             // with w
                                               "v 1 0 0 0.5 0.5 0.5\n"   // with a colour
                                               "v\t0 1 0 # a comment\n"
                                               "v 0 0 1\n"
                                               "vn 0 0 1\n"
                                               "vt 0.5 0.5\n"
                                               "vp 0.1\n"
                                               "g side\n"
                                               "usemtl red\n"
                                               "s off\n"
                                               "f 1/1 3/1 2/1\n"
                                               "f 1//1 2//1 4//1\n"
                                               "f 2/1/1 3/1/1 4/1/1\n"
                                               "f -4 -1 -2 # relative: 1 4 3\n"
                                               "l 1 2\n"));
  CHECK(soup.points == tetrahedron_points);
  CHECK(soup.triangles == tetrahedron_triangles);
}

TEST_CASE("read_obj: CRLF endings, a last line without newline, indices before their vertices", "[io][obj]") {
  SECTION("CRLF") {
    std::string crlf;
    for (const char c : tetrahedron_obj) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const Triangle_soup soup = read_obj(obj_file("crlf.obj", crlf));
    CHECK(soup.points == tetrahedron_points);
    CHECK(soup.triangles == tetrahedron_triangles);
  }
  SECTION("no newline at the end") {
    const Triangle_soup soup = read_obj(obj_file("no-newline.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3"));
    CHECK(soup.triangles == Triangles{{0, 1, 2}});
    const Triangle_soup last_vertex = read_obj(obj_file("no-newline-v.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0.25"));
    CHECK(last_vertex.points.back() == 0.25);
  }
  SECTION("a face before its vertices, as CGAL also reads") {
    const Triangle_soup soup = read_obj(obj_file("forward.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"));
    CHECK(soup.triangles == Triangles{{0, 1, 2}});
  }
}

TEST_CASE("read_obj: polygons are rejected, or fan-triangulated on request", "[io][obj]") {
  const fs::path quad = obj_file("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3\n");
  CHECK_THROWS_MATCHES(read_obj(quad), invalid_input,
                       Message(at(quad, 6, "a face with 4 vertices, not a triangle: set the option `triangulate` "
                                           "to fan-triangulate polygons")));
  const Triangle_soup soup = read_obj(quad, {.triangulate = true});
  CHECK(soup.triangles == Triangles{{0, 1, 2}, {0, 2, 3}, {1, 4, 2}});

  const fs::path segment = obj_file("segment.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  CHECK_THROWS_MATCHES(read_obj(segment, {.triangulate = true}), invalid_input,
                       Message(at(segment, 3, "a face with 2 vertices: a face needs 3")));
}

TEST_CASE("read_obj: each error names the file and the line", "[io][obj][errors]") {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

  SECTION("a missing file") {
    const fs::path missing = deformseg::test::scratch_dir() / "io_obj" / "missing.obj";
    CHECK_THROWS_MATCHES(read_obj(missing), invalid_input, Message(missing.string() + ": cannot open: no such file"));
  }
  SECTION("a folder") {
    const fs::path folder = deformseg::test::fresh_dir("io_obj/folder.obj");
    CHECK_THROWS_MATCHES(read_obj(folder), invalid_input,
                         Message(folder.string() + ": cannot open: it is a folder, not a file"));
  }
  SECTION("a malformed number") {
    const fs::path bad = obj_file("malformed.obj", "v 0 0 0\nv 1 0.5.1 0\n");
    CHECK_THROWS_MATCHES(read_obj(bad), invalid_input, Message(at(bad, 2, "malformed number \"0.5.1\"")));
    const fs::path word = obj_file("word.obj", "v 0 zero 0\n");
    CHECK_THROWS_MATCHES(read_obj(word), invalid_input, Message(at(word, 1, "malformed number \"zero\"")));
  }
  SECTION("a NaN or infinite coordinate") {
    const fs::path nan = obj_file("nan.obj", three + "v 0 nan 0\n");
    CHECK_THROWS_MATCHES(read_obj(nan), invalid_input, Message(at(nan, 4, "non-finite coordinate \"nan\"")));
    const fs::path inf = obj_file("inf.obj", "v -inf 0 0\n");
    CHECK_THROWS_MATCHES(read_obj(inf), invalid_input, Message(at(inf, 1, "non-finite coordinate \"-inf\"")));
    const fs::path huge = obj_file("huge.obj", "v 1e400 0 0\n");
    CHECK_THROWS_MATCHES(read_obj(huge), invalid_input,
                         Message(at(huge, 1, "number \"1e400\" is out of the range of double")));
  }
  SECTION("fewer than 3 coordinates") {
    const fs::path short_v = obj_file("short.obj", "v 0 0 0\nv 1 2\n");
    CHECK_THROWS_MATCHES(read_obj(short_v), invalid_input,
                         Message(at(short_v, 2, "a v line needs 3 coordinates, it has 2")));
    const fs::path bare_v = obj_file("bare.obj", "v 0 0 0\nv\n");
    CHECK_THROWS_MATCHES(read_obj(bare_v), invalid_input,
                         Message(at(bare_v, 2, "a v line needs 3 coordinates, it has 0")));
  }
  SECTION("an index 0") {
    const fs::path zero = obj_file("zero.obj", three + "f 0 1 2\n");
    CHECK_THROWS_MATCHES(read_obj(zero), invalid_input,
                         Message(at(zero, 4, "vertex index 0: OBJ indices start at 1")));
  }
  SECTION("an index out of range, on the first line that has one") {
    const fs::path beyond = obj_file("beyond.obj", three + "f 1 2 3\nf 1 2 4\nf 1 2 9\n");
    CHECK_THROWS_MATCHES(read_obj(beyond), invalid_input,
                         Message(at(beyond, 5, "vertex index 4 out of range: the file has 3 vertices")));
    const fs::path relative = obj_file("relative.obj", three + "f -1 -2 -4\n");
    CHECK_THROWS_MATCHES(read_obj(relative), invalid_input,
                         Message(at(relative, 4, "relative vertex index -4 out of range: 3 vertices before it")));
  }
  SECTION("a malformed face") {
    const fs::path letters = obj_file("letters.obj", three + "f 1 2 x\n");
    CHECK_THROWS_MATCHES(read_obj(letters), invalid_input,
                         Message(at(letters, 4, "expected a vertex index, found \"x\"")));
    const fs::path corner = obj_file("corner.obj", three + "f 1/a 2 3\n");
    CHECK_THROWS_MATCHES(read_obj(corner), invalid_input, Message(at(corner, 4, "malformed face corner \"1/a\"")));
    const fs::path dash = obj_file("dash.obj", three + "f 1 2-3 3\n");
    CHECK_THROWS_MATCHES(read_obj(dash), invalid_input, Message(at(dash, 4, "malformed face corner \"2-3\"")));
    const fs::path slashes = obj_file("slashes.obj", three + "f 1 2 3/1/1/1\n");
    CHECK_THROWS_MATCHES(read_obj(slashes), invalid_input,
                         Message(at(slashes, 4, "malformed face corner \"3/1/1/1\"")));
  }
  SECTION("an index of 19 or more digits, refused before it overflows int64") {
    // Fuzzing found the overflow (undefined behaviour, seen under -fsanitize=undefined and in
    // test/fuzz/regressions/obj/ub-index-19-digits.obj): the digits were summed before counted.
    const fs::path nineteen = obj_file("19-digits.obj", three + "f 1 2 9999999999999999999\n");
    CHECK_THROWS_MATCHES(read_obj(nineteen), invalid_input,
                         Message(at(nineteen, 4, "a vertex index \"9999999999999999999\" is out of range")));
    const fs::path relative = obj_file("19-digits-relative.obj", three + "f 1 -99999999999999999999999999/1 3\n");
    CHECK_THROWS_MATCHES(read_obj(relative), invalid_input,
                         Message(at(relative, 4, "a vertex index \"-99999999999999999999999999/1\" is out of range")));
    const fs::path eighteen = obj_file("18-digits.obj", three + "f 1 2 999999999999999999\n");
    CHECK_THROWS_MATCHES(
        read_obj(eighteen), invalid_input,
        Message(at(eighteen, 4, "vertex index 999999999999999999 out of range: the file has fewer vertices")));
  }
  SECTION("an unknown statement") {
    const fs::path unknown = obj_file("unknown.obj", three + "vx 1 2 3\n");
    CHECK_THROWS_MATCHES(read_obj(unknown), invalid_input, Message(at(unknown, 4, "unknown OBJ statement \"vx\"")));
  }
  SECTION("an empty mesh") {
    const fs::path empty = obj_file("empty.obj", "");
    CHECK_THROWS_MATCHES(read_obj(empty), invalid_input, Message(empty.string() + ": no vertex: the mesh is empty"));
    const fs::path comments = obj_file("comments.obj", "# nothing\n\ng group\n");
    CHECK_THROWS_MATCHES(read_obj(comments), invalid_input,
                         Message(comments.string() + ": no vertex: the mesh is empty"));
  }
  SECTION("the line is counted over CRLF endings and comments") {
    const fs::path crlf = obj_file("crlf-error.obj", "# one\r\nv 0 0 0\r\n\r\nv 1 0 x\r\n");
    CHECK_THROWS_MATCHES(read_obj(crlf), invalid_input, Message(at(crlf, 4, "malformed number \"x\"")));
  }
}

// A damaged file's bytes reach the message escaped, so that a terminal shows them and acts on none.
TEST_CASE("read_obj: a message quotes a damaged file's bytes as \\xHH, never raw", "[io][obj][errors]") {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const auto message_of = [](const fs::path& path) {
    try {
      static_cast<void>(read_obj(path));
    } catch (const invalid_input& e) {
      return std::string(e.what());
    }
    FAIL("read " << path);
    return std::string();
  };
  SECTION("a statement of Latin-1 and control bytes") {
    // v, E9 (Latin-1 e acute, not UTF-8), ESC [2J (a terminal's clear-screen), DEL.
    const fs::path latin = obj_file("latin1.obj", three + "v\xE9\x1B[2J\x7F 1 2 3\n");
    const std::string message = message_of(latin);
    CHECK(message == at(latin, 4, "unknown OBJ statement \"v\\xE9\\x1B[2J\\x7F\""));
    CHECK(message.find('\xE9') == std::string::npos);
    CHECK(message.find('\x1B') == std::string::npos);
  }
  SECTION("a number cut inside a UTF-8 sequence, and a backslash") {
    // 40 bytes kept: the 2-byte e acute (C3 A9) at bytes 40 and 41 is cut after its first byte.
    const fs::path cut = obj_file("cut.obj", three + "v 1 2 " + std::string(39, '7') + "\xC3\xA9\\9\n");
    CHECK(message_of(cut) == at(cut, 4, "malformed number \"" + std::string(39, '7') + "\\xC3...\""));
    const fs::path slash = obj_file("slash.obj", three + "v 1 2 a\\b\n");
    CHECK(message_of(slash) == at(slash, 4, "malformed number \"a\\\\b\""));
  }
  SECTION("valid UTF-8 stays as it is") {
    const fs::path utf8 = obj_file("utf8.obj", three + "caf\xC3\xA9 1\n");
    CHECK(message_of(utf8) == at(utf8, 4, "unknown OBJ statement \"caf\xC3\xA9\""));
  }
}

TEST_CASE("read_mesh_points (OBJ): positions only, in double or float", "[io][obj]") {
  const fs::path path = obj_file("points.obj", "vn 0 0 1\nv 0.1 0.2 0.3\nf 1 2 3 4 5\nv 1 2 3\nv 4 5 6 7\n");
  std::vector<double> xyz(9);
  read_mesh_points(path, xyz);
  CHECK(xyz == std::vector<double>{0.1, 0.2, 0.3, 1, 2, 3, 4, 5, 6});

  std::vector<float> xyz_float(9);
  read_mesh_points(path, xyz_float);
  CHECK(xyz_float == std::vector<float>{0.1f, 0.2f, 0.3f, 1, 2, 3, 4, 5, 6});

  SECTION("another vertex count") {
    std::vector<double> four(12);
    CHECK_THROWS_MATCHES(read_mesh_points(path, four), invalid_input,
                         Message(path.string() + ": has 3 vertices instead of 4"));
    std::vector<double> two(6);
    CHECK_THROWS_MATCHES(read_mesh_points(path, two), invalid_input,
                         Message(path.string() + ": has 3 vertices instead of 2"));
  }
  SECTION("a bad number names its line") {
    const fs::path bad = obj_file("points-bad.obj", "v 0 0 0\nf 1 2 3\nv 0 inf 0\n");
    std::vector<double> two(6);
    CHECK_THROWS_MATCHES(read_mesh_points(bad, two), invalid_input,
                         Message(at(bad, 3, "non-finite coordinate \"inf\"")));
    const fs::path big = obj_file("points-big.obj", "v 0 0 0\nv 0 1e39 0\n");
    std::vector<float> as_float(6);
    CHECK_THROWS_MATCHES(read_mesh_points(big, as_float), invalid_input,
                         Message(at(big, 2, "number \"1e39\" is out of the range of float")));
  }
  SECTION("room for a number of coordinates that is not a multiple of 3") {
    std::vector<double> eight(8);
    CHECK_THROWS_MATCHES(read_mesh_points(path, eight), invalid_input,
                         Message(path.string() + ": room for 8 coordinates given, not a multiple of 3"));
  }
}

namespace {

using Cgal_point = CGAL::Simple_cartesian<double>::Point_3;

// CGAL's reading of a mesh file, as a soup.
void read_with_cgal(const fs::path& path, std::vector<Cgal_point>& points,
                    std::vector<std::vector<std::size_t>>& faces) {
  REQUIRE(CGAL::IO::read_polygon_soup(path.string(), points, faces, CGAL::parameters::verbose(false)));
}

// Checks that `soup` is CGAL's reading of `path`, to the last bit of every coordinate.
void check_same_as_cgal(const Triangle_soup& soup, const fs::path& path) {
  std::vector<Cgal_point> points;
  std::vector<std::vector<std::size_t>> faces;
  read_with_cgal(path, points, faces);
  REQUIRE(soup.num_vertices() == points.size());
  std::size_t differing_bits = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      differing_bits +=
          std::bit_cast<std::uint64_t>(soup.points[3 * i + k]) != std::bit_cast<std::uint64_t>(points[i][k]);
  CHECK(differing_bits == 0);
  REQUIRE(soup.triangles.size() == faces.size());
  std::size_t differing_faces = 0;
  for (std::size_t j = 0; j < faces.size(); ++j)
    differing_faces += faces[j] != std::vector<std::size_t>(soup.triangles[j].begin(), soup.triangles[j].end());
  CHECK(differing_faces == 0);
}

}  // namespace

TEST_CASE("read_obj on the horse gallop and samba frames: CGAL's reading, to the last bit", "[io][obj][data]") {
  const fs::path horse = deformseg::test::unpacked("horse-gallop/horse-gallop.tar.xz");
  const Triangle_soup first = read_obj(horse / "horse-gallop" / "0001.obj");
  CHECK(first.num_vertices() == 8431);
  CHECK(first.triangles.size() == 16843);
  CHECK(first.triangles.front() == std::array<std::uint32_t, 3>{8430, 11, 12});  // "f 8431 12 13"
  check_same_as_cgal(first, horse / "horse-gallop" / "0001.obj");
  check_same_as_cgal(read_obj(horse / "horse-gallop" / "0037.obj"), horse / "horse-gallop" / "0037.obj");
  check_same_as_cgal(read_obj(horse / "horse-gallop.obj"), horse / "horse-gallop.obj");

  const fs::path samba = deformseg::test::unpacked("samba/samba.tar.xz");
  const Triangle_soup dancer = read_obj(samba / "samba" / "mesh_0100.obj");
  CHECK(dancer.num_vertices() == 9971);
  CHECK(dancer.triangles.size() == 19938);
  check_same_as_cgal(dancer, samba / "samba" / "mesh_0100.obj");

  // Positions only: the same numbers.
  std::vector<double> xyz(3 * 9971);
  read_mesh_points(samba / "samba" / "mesh_0100.obj", xyz);
  CHECK(xyz == dancer.points);
}

TEST_CASE("read_obj on the cat poses: faces a//a b//b c//c, vn lines, header comments", "[io][obj][data]") {
  const fs::path cats = deformseg::test::unpacked("cat-lion-poses/cat-poses.tgz") / "cat-poses";
  for (const char* name : {"cat-reference.obj", "cat-01.obj", "cat-09.obj"}) {
    const Triangle_soup soup = read_obj(cats / name);
    CHECK(soup.num_vertices() == 7207);
    CHECK(soup.triangles.size() == 14410);
    CHECK(soup.triangles.front() == std::array<std::uint32_t, 3>{7206, 0, 1});  // "f 7207//7207 1//1 2//2"
    check_same_as_cgal(soup, cats / name);
  }
}

// ---- The writer: write_obj (helpers shared with the other writers' tests: writer_support.h) ----

namespace color = deformseg::color;
namespace io = deformseg::io;
namespace mesh = deformseg::mesh;
namespace test = deformseg::test;

namespace {

using deformseg::test::Polygons;
using deformseg::test::canonical_triangles;
using deformseg::test::check_points;
using deformseg::test::drifting_tetrahedron;
using deformseg::test::face_lines;
using deformseg::test::file_text;
using deformseg::test::graph_name;
using deformseg::test::tetra_polygons;
using deformseg::test::tetrahedron;
using deformseg::test::writer_output;
using Point = deformseg::test::Point_3;
using Polyhedron = CGAL::Polyhedron_3<deformseg::mesh::Kernel>;

}  // namespace

TEST_CASE("write_obj: the vertices as their shortest exact text, the triangles 1-based", "[io][writers][obj]") {
  // Frame 1 holds numbers whose shortest form is decimal, scientific, negative zero, subnormal.
  std::vector<double> xyz(12, 0.0);
  const std::vector<double> frame1{0.1, 1.0 / 3, -2.5, 1e-300, 123456789.125, -0.0, 2.0 / 3, 1e21, 5e-324, 0, 0, 1};
  xyz.insert(xyz.end(), frame1.begin(), frame1.end());
  const mesh::Deforming_mesh<mesh::Surface_mesh> animation(tetrahedron<mesh::Surface_mesh>(), xyz);
  const fs::path file = writer_output("obj_text", "frame1.obj");
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

TEST_CASE("write_obj: a float animation is written in float's shortest form", "[io][writers][obj]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh, float>(2);
  const fs::path file = writer_output("obj_float", "frame1.obj");
  io::write_obj(animation, 1, file);
  // Vertex 0 of frame 1 is (0.1f, 1/3.f, 0): shorter than the double these floats are.
  CHECK(file_text(file).starts_with("# deformseg: frame 1 of 2\nv 0.1 0.33333334 0\n"));
}

TEMPLATE_TEST_CASE("write_obj: CGAL reads back the same points and triangles", "[io][writers][obj]", mesh::Surface_mesh,
                   Polyhedron) {
  const auto animation = drifting_tetrahedron<TestType>(3);
  const fs::path file = writer_output("obj_cgal_" + graph_name<TestType>(), "frame2.obj");
  io::write_obj(animation, 2, file);
  std::vector<Point> points;
  Polygons polygons;
  REQUIRE(CGAL::IO::read_polygon_soup(file.string(), points, polygons));
  check_points(points, animation, 2);
  CHECK(canonical_triangles(polygons) == canonical_triangles(tetra_polygons()));
}

TEST_CASE("write_obj and write_ply reject bad arguments, naming the file", "[io][writers][errors]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh>(3);
  const fs::path folder = test::fresh_dir("writers/errors");

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
