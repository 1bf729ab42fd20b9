// Tests of io/off.h (read_off, write_off), io/ply.h (read_ply, write_ply) and io/read_mesh.h
// (read_mesh, read_mesh_points for OFF and PLY, the choice by extension), on small files made here.
#include "tetrahedron.h"
#include "writer_support.h"

#include <deformseg/exceptions.h>
#include <deformseg/io/off.h>
#include <deformseg/io/ply.h>
#include <deformseg/io/read_mesh.h>

#include <CGAL/Polyhedron_3.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using deformseg::invalid_input;
using deformseg::io::read_mesh;
using deformseg::io::read_mesh_points;
using deformseg::io::read_off;
using deformseg::io::read_ply;
using deformseg::io::Triangle_soup;
using Catch::Matchers::Message;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {

using deformseg::test::Triangles;

using deformseg::test::tetrahedron_points;
using deformseg::test::tetrahedron_triangles;
const std::string tetrahedron_off =
    "OFF\n"
    "4 4 6\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

fs::path file(const std::string& name, const std::string& text) {
  return deformseg::test::write_file("io_off_ply/" + name, text);
}

using deformseg::test::at;

// The bytes of `value` in little-endian order, as binary_little_endian PLY stores it.
template <class T>
std::string little_endian(T value) {
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  return std::string(bytes.data(), bytes.size());
}

// A binary PLY tetrahedron with double coordinates; `points` may replace its vertices.
std::string binary_ply(const std::vector<double>& points = tetrahedron_points) {
  std::string text =
      "ply\nformat binary_little_endian 1.0\ncomment made by deformseg's tests\n"
      "element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  for (const double c : points) text += little_endian(c);
  for (const auto& t : tetrahedron_triangles) {
    text += little_endian(std::uint8_t{3});
    for (const std::uint32_t i : t) text += little_endian(static_cast<std::int32_t>(i));
  }
  return text;
}

const std::string ascii_ply_header =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n";

}  // namespace

TEST_CASE("read_off: vertices and triangles, indices from 0", "[io][off]") {
  const Triangle_soup soup = read_off(file("tetrahedron.off", tetrahedron_off));
  CHECK(soup.points == tetrahedron_points);
  CHECK(soup.triangles == tetrahedron_triangles);
}

TEST_CASE("read_off: COFF colours, counts on the keyword line, comments, CRLF", "[io][off]") {
  const std::string text =
      "COFF 4 4 0 # counts on the keyword line\r\n"
      "# a comment line\r\n"
      "0 0 0 255 0 0 255\r\n1 0 0 0 255 0 255\r\n\r\n0 1 0 0 0 255 255\r\n0 0 1 9 9 9 255\r\n"
      "3 0 2 1 255 0 0\r\n3 0 1 3\r\n3\t1 2 3 # face colours come after the indices\r\n3 0 3 2";
  const Triangle_soup soup = read_off(file("coff.off", text));
  CHECK(soup.points == tetrahedron_points);
  CHECK(soup.triangles == tetrahedron_triangles);
}

TEST_CASE("read_off: polygons are rejected, or fan-triangulated on request", "[io][off]") {
  const fs::path quad = file("quad.off", "OFF\n4 1 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  CHECK_THROWS_MATCHES(read_off(quad), invalid_input,
                       Message(at(quad, 7, "a face with 4 vertices, not a triangle: set the option `triangulate` "
                                           "to fan-triangulate polygons")));
  CHECK(read_off(quad, {.triangulate = true}).triangles == Triangles{{0, 1, 2}, {0, 2, 3}});
}

TEST_CASE("read_off: each error names the file and the line", "[io][off][errors]") {
  SECTION("a missing file") {
    const fs::path missing = deformseg::test::scratch_dir() / "io_off_ply" / "missing.off";
    CHECK_THROWS_MATCHES(read_off(missing), invalid_input, Message(missing.string() + ": cannot open: no such file"));
  }
  SECTION("not an OFF file, or a variant deformseg does not read") {
    const fs::path ply = file("not-off.off", "ply\nformat ascii 1.0\n");
    CHECK_THROWS_MATCHES(read_off(ply), invalid_input,
                         Message(at(ply, 1, "not an OFF file: it starts with \"ply\" instead of OFF")));
    const fs::path four = file("4off.off", "4OFF\n1 0 0\n0 0 0 1\n");
    CHECK_THROWS_MATCHES(
        read_off(four), invalid_input,
        Message(at(four, 1, "unsupported OFF variant \"4OFF\": deformseg reads OFF, COFF, NOFF and CNOFF")));
    const fs::path binary = file("binary.off", "OFF BINARY\n");
    CHECK_THROWS_MATCHES(read_off(binary), invalid_input,
                         Message(at(binary, 1, "binary OFF is not supported: write it as text")));
  }
  SECTION("a malformed or missing count") {
    const fs::path bad = file("bad-count.off", "OFF\n# counts\n4 x 0\n");
    CHECK_THROWS_MATCHES(read_off(bad), invalid_input, Message(at(bad, 3, "expected a face count, found \"x\"")));
    const fs::path none = file("no-count.off", "OFF\n");
    CHECK_THROWS_MATCHES(read_off(none), invalid_input,
                         Message(none.string() + ": the OFF header has no vertex and face counts"));
  }
  SECTION("a malformed or non-finite number") {
    const fs::path bad = file("bad-number.off", "OFF\n3 0 0\n0 0 0\n1 0,5 0\n0 1 0\n");
    CHECK_THROWS_MATCHES(read_off(bad), invalid_input, Message(at(bad, 4, "malformed number \"0,5\"")));
    const fs::path nan = file("nan.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 NaN 0\n");
    CHECK_THROWS_MATCHES(read_off(nan), invalid_input, Message(at(nan, 5, "non-finite coordinate \"NaN\"")));
  }
  SECTION("fewer than 3 coordinates") {
    const fs::path short_line = file("short.off", "OFF\n3 0 0\n0 0 0\n1 0\n0 1 0\n");
    CHECK_THROWS_MATCHES(read_off(short_line), invalid_input,
                         Message(at(short_line, 4, "a vertex line needs 3 coordinates, it has 2")));
  }
  SECTION("an index out of range, or missing") {
    const fs::path beyond = file("beyond.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n");
    CHECK_THROWS_MATCHES(read_off(beyond), invalid_input, Message(at(beyond, 7, "vertex index 3 out of range [0, 3)")));
    const fs::path negative = file("negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n");
    CHECK_THROWS_MATCHES(read_off(negative), invalid_input,
                         Message(at(negative, 6, "expected a vertex index, found \"-1\"")));
    const fs::path missing = file("missing-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n");
    CHECK_THROWS_MATCHES(read_off(missing), invalid_input, Message(at(missing, 6, "the face has 2 of its 3 indices")));
  }
  SECTION("fewer lines than the header announces") {
    const fs::path vertices = file("few-vertices.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    CHECK_THROWS_MATCHES(
        read_off(vertices), invalid_input,
        Message(vertices.string() + ": the file ends after 3 of 4 vertices that its header announces"));
    const fs::path faces = file("few-faces.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# the end\n");
    CHECK_THROWS_MATCHES(read_off(faces), invalid_input,
                         Message(faces.string() + ": the file ends after 1 of 2 faces that its header announces"));
  }
  SECTION("counts more than the file holds: nothing allocated for them, the file ends first") {
    // Fuzzing found these ending in a bare std::bad_alloc (test/fuzz/regressions/off).
    const fs::path huge = file("huge-count.off", "OFF\n4244444444444444 0 0\n");
    CHECK_THROWS_MATCHES(
        read_off(huge), invalid_input,
        Message(huge.string() + ": the file ends after 0 of 4244444444444444 vertices that its header announces"));
    const fs::path vertices = file("3e9-vertices.off", "OFF\n3000000000 1 0\n0 0 0\n");
    CHECK_THROWS_MATCHES(
        read_off(vertices), invalid_input,
        Message(vertices.string() + ": the file ends after 1 of 3000000000 vertices that its header announces"));
    std::vector<double> xyz(9);
    CHECK_THROWS_MATCHES(read_mesh_points(vertices, xyz), invalid_input,
                         Message(vertices.string() + ": has 3000000000 vertices instead of 3"));
    const fs::path faces = file("3e9-faces.off", "OFF\n3 3000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    CHECK_THROWS_MATCHES(
        read_off(faces), invalid_input,
        Message(faces.string() + ": the file ends after 1 of 3000000000 faces that its header announces"));
  }
  SECTION("the shortest lines still fit the counts") {
    const Triangle_soup soup = read_off(file("shortest.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2"));
    CHECK(soup.points.size() == 9);
    CHECK(soup.triangles == Triangles{{0, 1, 2}});
  }
  SECTION("an empty mesh") {
    const fs::path empty = file("empty.off", "OFF\n0 0 0\n");
    CHECK_THROWS_MATCHES(read_off(empty), invalid_input, Message(empty.string() + ": no vertex: the mesh is empty"));
  }
}

TEST_CASE("read_ply: text and binary, float and double coordinates", "[io][ply]") {
  SECTION("ascii, float coordinates and vertex colours") {
    const std::string text = ascii_ply_header +
                             "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0 255 0 0\n1 0 0 255 0 0\n0 1 0 255 0 0\n0 0 1 255 0 0\n"
                             "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
    const Triangle_soup soup = read_ply(file("ascii.ply", text));
    CHECK(soup.points == tetrahedron_points);
    CHECK(soup.triangles == tetrahedron_triangles);
  }
  SECTION("binary little endian, double coordinates") {
    const std::vector<double> points{0.1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1e-300};
    const Triangle_soup soup = read_ply(file("binary.ply", binary_ply(points)));
    CHECK(soup.points == points);
    CHECK(soup.triangles == tetrahedron_triangles);
  }
}

TEST_CASE("read_ply: integer coordinates, other elements and list properties passed over", "[io][ply]") {
  // CGAL's reader dereferenced null on an x of an integer type; deformseg reads any scalar type.
  const std::string text =
      "ply\r\nformat ascii 1.0\r\nobj_info made by hand\r\nelement vertex 4\r\nproperty short x\r\n"
      "property int y\r\nproperty uchar z\r\nproperty float nx\r\nelement face 4\r\n"
      "property list uint8 uint vertex_index\r\nproperty list uchar float texcoord\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
      "0 0 0 nan\r\n1 0 0 0\r\n0 1 0 0\r\n0 0 1 0\r\n"
      "3 0 2 1 2 0.5 0.5\r\n3 0 1 3 0\r\n3 1 2 3 0\r\n3 0 3 2 0\r\n0 1\r\n";
  const Triangle_soup soup = read_ply(file("integers.ply", text));
  CHECK(soup.points == tetrahedron_points);
  CHECK(soup.triangles == tetrahedron_triangles);
}

TEST_CASE("read_ply: polygons are rejected, or fan-triangulated on request", "[io][ply]") {
  const fs::path quad = file("quad.ply",
                             "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                             "property double z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  CHECK_THROWS_MATCHES(read_ply(quad), invalid_input,
                       Message(quad.string() + ": face 0: a face with 4 vertices, not a triangle: set the option "
                                               "`triangulate` to fan-triangulate polygons"));
  CHECK(read_ply(quad, {.triangulate = true}).triangles == Triangles{{0, 1, 2}, {0, 2, 3}});
}

TEST_CASE("read_ply: each error names the file, and the face or vertex", "[io][ply][errors]") {
  SECTION("a missing file") {
    const fs::path missing = deformseg::test::scratch_dir() / "io_off_ply" / "missing.ply";
    CHECK_THROWS_MATCHES(read_ply(missing), invalid_input, Message(missing.string() + ": cannot open: no such file"));
  }
  SECTION("not a PLY file") {
    const fs::path off = file("not-ply.ply", tetrahedron_off);
    CHECK_THROWS_MATCHES(read_ply(off), invalid_input,
                         Message(off.string() + ": not a PLY file: it does not start with the line \"ply\""));
  }
  SECTION("a truncated body") {
    const std::string whole = binary_ply();
    const fs::path truncated = file("truncated.ply", whole.substr(0, whole.size() - 10));
    CHECK_THROWS_MATCHES(read_ply(truncated), invalid_input,
                         Message(truncated.string() + ": the file ends inside face 3 of the 4 the header announces"));
    const fs::path text = file("truncated-ascii.ply", ascii_ply_header + "element face 1\n"
                               "property list uchar int vertex_indices\nend_header\n"
                               "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n0 0 1 1 1 1\n3 0 1\n");
    CHECK_THROWS_MATCHES(read_ply(text), invalid_input,
                         Message(text.string() + ": the file ends inside face 0 of the 1 the header announces"));
  }
  SECTION("a malformed header, refused before the body is read") {
    // Fuzzing found CGAL's reader dereferencing null on the first of these
    // (test/fuzz/regressions/ply/segv-property-before-element.ply): deformseg checks the header.
    const std::string found = "ply\nformat ascii 1.0\nele\xdament vertex 3\nproperty float x\n";
    const fs::path mangled = file("mangled.ply", found);
    CHECK_THROWS_MATCHES(read_ply(mangled), invalid_input,
                         Message(at(mangled, 3, "unknown PLY header line \"ele\\xDAment\"")));  // the byte escaped
    // And this one, the first version of deformseg's reader reading past the end of the buffer
    // (seen under AddressSanitizer; test/fuzz/regressions/ply/heap-overflow-no-newline.ply): a
    // file without a newline, whose header lines ran into the bytes after its end.
    const fs::path no_newline = file("no-newline.ply", std::string("ply\rformat ascii 0.8r`hedrot asci'rtyfl\0me", 42));
    CHECK_THROWS_MATCHES(read_ply(no_newline), invalid_input,
                         Message(at(no_newline, 1, "expected the line \"format ascii 1.0\" (or binary_little_endian, "
                                                   "binary_big_endian) after \"ply\"")));
    const fs::path before = file("property-first.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\n");
    CHECK_THROWS_MATCHES(read_ply(before), invalid_input, Message(at(before, 3, "a property before any element")));
    const fs::path type = file("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty floot x\n");
    CHECK_THROWS_MATCHES(read_ply(type), invalid_input, Message(at(type, 4, "unknown PLY type \"floot\"")));
    const fs::path list =
        file("list.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n");
    CHECK_THROWS_MATCHES(read_ply(list), invalid_input,
                         Message(at(list, 4, "a list's count must be of an integer type, not \"float\"")));
    const fs::path format = file("format.ply", "ply\nformat binary 1.0\n");
    CHECK_THROWS_MATCHES(read_ply(format), invalid_input, Message(at(format, 2, "unknown PLY format \"binary\"")));
    const fs::path no_end = file("no-end.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
    CHECK_THROWS_MATCHES(read_ply(no_end), invalid_input,
                         Message(no_end.string() + ": the PLY header has no end_header line"));
    const fs::path no_z = file("no-z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                               "property float y\nend_header\n0 0\n");
    CHECK_THROWS_MATCHES(read_ply(no_z), invalid_input,
                         Message(no_z.string() + ": the vertex element has no scalar property z"));
    const fs::path no_list =
        file("no-list.ply", ascii_ply_header + "element face 1\nproperty int vertex_indices\nend_header\n");
    CHECK_THROWS_MATCHES(
        read_ply(no_list), invalid_input,
        Message(no_list.string() + ": the face element has no vertex_indices list of an integer type"));
  }
  SECTION("counts more than the file holds, refused before anything is allocated for them") {
    const fs::path vertices = file("huge-count.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                                   "property float x\nproperty float y\nproperty float z\nend_header\n0123456789ab");
    CHECK_THROWS_MATCHES(read_ply(vertices), invalid_input,
                         Message(vertices.string() + ": the header announces 4000000000 vertex items of 12 bytes or "
                                                     "more, more than the 12 bytes of the body hold"));
    // A list's count is read from the body: the items it announces are read one by one, so a
    // count of two billion ends at the end of the file rather than in an allocation.
    const fs::path list =
        file("huge-list.ply", ascii_ply_header +
                                  "element face 1\nproperty list int int vertex_indices\n"
                                  "end_header\n0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n0 0 1 1 1 1\n2000000000 0 1 2\n");
    CHECK_THROWS_MATCHES(read_ply(list), invalid_input,
                         Message(list.string() + ": the file ends inside face 0 of the 1 the header announces"));
    const fs::path header_only = file("header-only.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                      "property float y\nproperty float z\nend_header");
    CHECK_THROWS_MATCHES(read_ply(header_only), invalid_input,
                         Message(header_only.string() + ": the header announces 1 vertex items of 6 bytes or more, "
                                                        "more than the 0 bytes of the body hold"));
    const fs::path empty_element = file("no-property.ply", ascii_ply_header + "element nothing 1000000\nend_header\n");
    CHECK_THROWS_MATCHES(read_ply(empty_element), invalid_input,
                         Message(empty_element.string() + ": element nothing has no property but 1000000 items"));
  }
  SECTION("a malformed or out-of-range value, with its line") {
    const std::string header =
        ascii_ply_header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const fs::path colour =
        file("colour.ply", header + "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 256\n0 0 1 1 1 1\n3 0 1 2\n");
    CHECK_THROWS_MATCHES(read_ply(colour), invalid_input,
                         Message(at(colour, 15, "vertex 2: \"256\" is out of the range of uchar")));
    const fs::path number =
        file("number.ply", header + "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 x 1 1 1\n0 0 1 1 1 1\n3 0 1 2\n");
    CHECK_THROWS_MATCHES(read_ply(number), invalid_input, Message(at(number, 15, "malformed number \"x\"")));
    const fs::path count = file("count.ply", header + "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n0 0 1 1 1 1\n-3 0 1 2\n");
    CHECK_THROWS_MATCHES(read_ply(count), invalid_input,
                         Message(at(count, 17, "face 0: \"-3\" is out of the range of uchar")));
  }
  SECTION("an index out of range") {
    const fs::path beyond =
        file("beyond.ply", ascii_ply_header +
                               "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0 1 1 1\n1 0 0 1 1 1\n0 1 0 1 1 1\n0 0 1 1 1 1\n"
                               "3 0 1 2\n3 0 1 7\n");
    CHECK_THROWS_MATCHES(read_ply(beyond), invalid_input,
                         Message(beyond.string() + ": face 1 has vertex index 7 out of range [0, 4)"));
  }
  SECTION("a non-finite coordinate") {
    std::vector<double> points = tetrahedron_points;
    points[4] = std::numeric_limits<double>::quiet_NaN();
    const fs::path nan = file("nan.ply", binary_ply(points));
    CHECK_THROWS_MATCHES(read_ply(nan), invalid_input,
                         Message(nan.string() + ": vertex 1 has a non-finite coordinate"));
  }
  SECTION("an empty mesh") {
    const fs::path empty =
        file("empty.ply",
             "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
             "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n");
    CHECK_THROWS_MATCHES(read_ply(empty), invalid_input, Message(empty.string() + ": no vertex: the mesh is empty"));
  }
}

TEST_CASE("read_mesh: the reader chosen by the extension, in any case", "[io][read_mesh]") {
  const std::string tetrahedron_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"tetra.obj", tetrahedron_obj}, {"TETRA.OBJ", tetrahedron_obj}, {"tetra.off", tetrahedron_off},
           {"tetra.Off", tetrahedron_off}, {"tetra.ply", binary_ply()}}) {
    INFO(name);
    const Triangle_soup soup = read_mesh(file(name, text));
    CHECK(soup.points == tetrahedron_points);
    CHECK(soup.triangles == tetrahedron_triangles);
  }
  const fs::path stl = file("tetra.stl", "solid tetra\n");
  CHECK_THROWS_MATCHES(
      read_mesh(stl), invalid_input,
      Message(stl.string() + ": unknown mesh format \".stl\": deformseg reads .obj, .off and .ply files"));
  const fs::path none = file("tetra", tetrahedron_off);
  CHECK_THROWS_MATCHES(
      read_mesh(none), invalid_input,
      Message(none.string() + ": unknown mesh format \"\": deformseg reads .obj, .off and .ply files"));
}

TEST_CASE("read_mesh_points: positions only, from OFF and PLY", "[io][read_mesh]") {
  std::vector<double> xyz(12);
  read_mesh_points(file("points.off", tetrahedron_off), xyz);
  CHECK(xyz == tetrahedron_points);

  const std::vector<double> moved{0.5, 0, 0, 1.5, 0, 0, 0.5, 1, 0, 0.5, 0, 1};
  std::vector<float> xyz_float(12);
  read_mesh_points(file("points.ply", binary_ply(moved)), xyz_float);
  CHECK(xyz_float == std::vector<float>(moved.begin(), moved.end()));

  std::vector<double> three(9);
  const fs::path off = file("points-count.off", tetrahedron_off);
  CHECK_THROWS_MATCHES(read_mesh_points(off, three), invalid_input,
                       Message(off.string() + ": has 4 vertices instead of 3"));
  const fs::path ply = file("points-count.ply", binary_ply());
  CHECK_THROWS_MATCHES(read_mesh_points(ply, three), invalid_input,
                       Message(ply.string() + ": has 4 vertices instead of 3"));

  std::vector<double> big = tetrahedron_points;
  big[5] = 1e300;
  const fs::path beyond_float = file("points-big.ply", binary_ply(big));
  CHECK_THROWS_MATCHES(read_mesh_points(beyond_float, xyz_float), invalid_input,
                       Message(beyond_float.string() + ": vertex 1 has a coordinate out of the range of float"));
}

// ---- The writers: write_off and write_ply (helpers shared with the other writers' tests: writer_support.h) ----

namespace io = deformseg::io;
namespace mesh = deformseg::mesh;

namespace {

using deformseg::test::Polygons;
using deformseg::test::canonical_triangles;
using deformseg::test::check_points;
using deformseg::test::drifting_tetrahedron;
using deformseg::test::face_lines;
using deformseg::test::file_text;
using deformseg::test::four_colors;
using deformseg::test::graph_name;
using deformseg::test::read_ply_colored;
using deformseg::test::tetra_polygons;
using deformseg::test::tetrahedron;
using deformseg::test::writer_output;
using Point = deformseg::test::Point_3;
using Polyhedron = CGAL::Polyhedron_3<deformseg::mesh::Kernel>;

}  // namespace

TEST_CASE("write_off: the counts, the vertices as their shortest exact text, the triangles 0-based",
          "[io][writers][off]") {
  std::vector<double> xyz(12, 0.0);
  const std::vector<double> frame1{0.1, 1.0 / 3, -2.5, 1e-300, 123456789.125, -0.0, 2.0 / 3, 1e21, 5e-324, 0, 0, 1};
  xyz.insert(xyz.end(), frame1.begin(), frame1.end());
  const mesh::Deforming_mesh<mesh::Surface_mesh> animation(tetrahedron<mesh::Surface_mesh>(), xyz);
  const fs::path file = writer_output("off_text", "frame1.off");
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

TEST_CASE("write_ply: text PLY, with face colours, exactly", "[io][writers][ply]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh>(2);
  const fs::path file = writer_output("ply_ascii", "frame1.ply");
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
  const fs::path file = writer_output("ply_binary_" + graph_name<TestType>(), "frame2.ply");
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
  CHECK(canonical_triangles(polygons) == canonical_triangles(tetra_polygons()));
  REQUIRE(colors.size() == 4);
  for (std::size_t j = 0; j < 4; ++j)
    CHECK(colors[j] == CGAL::IO::Color(four_colors[j].r, four_colors[j].g, four_colors[j].b));
}

TEST_CASE("write_ply: a float animation, without colours, as float properties", "[io][writers][ply]") {
  const auto animation = drifting_tetrahedron<mesh::Surface_mesh, float>(2);
  const fs::path file = writer_output("ply_float", "frame1.ply");
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
