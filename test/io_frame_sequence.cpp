// Tests of io/frame_sequence.h: list_frame_files (folders, patterns, natural order) and
// read_frame_sequence (connectivity from the first frame or a topology file, positions of every
// frame, threads, errors), on small sequences made here and, tagged [data], on the shared ones;
// sequence_file_name and write_sequence (names, formats, colours, errors, read back).
#include "test_support.h"
#include "writer_support.h"

#include <deformseg/mesh/default_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/read_animation.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

using deformseg::invalid_input;
using deformseg::io::list_frame_files;
using deformseg::io::read_frame_sequence;
using Catch::Matchers::Message;
namespace fs = std::filesystem;

namespace {

// The file names of `paths`, in order.
std::vector<std::string> names(const std::vector<fs::path>& paths) {
  std::vector<std::string> result;
  for (const fs::path& p : paths) result.push_back(p.filename().string());
  return result;
}

void touch(const fs::path& path) { std::ofstream(path) << "v 0 0 0\n"; }

// Frame t of a tetrahedron moved by (t, 2t, 3t), with its faces.
std::string tetrahedron_frame(int t, const std::string& extra_vertex = "") {
  std::string text;
  const int corner[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& c : corner)
    text += "v " + std::to_string(c[0] + t) + " " + std::to_string(c[1] + 2 * t) + " " + std::to_string(c[2] + 3 * t) +
            "\n";
  return text + extra_vertex + "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
}

// A folder of `frames` tetrahedron frames named frame_1.obj ... frame_N.obj (not zero-padded).
fs::path tetrahedron_sequence(const std::string& name, int frames) {
  const fs::path folder = deformseg::test::fresh_dir("io_frame_sequence/" + name);
  for (int t = 0; t < frames; ++t)
    std::ofstream(folder / ("frame_" + std::to_string(t + 1) + ".obj")) << tetrahedron_frame(t);
  return folder;
}

}  // namespace

TEST_CASE("list_frame_files: natural order", "[io][frame_sequence]") {
  const fs::path folder = deformseg::test::fresh_dir("io_frame_sequence/natural");
  for (const char* name : {"10.obj", "2.obj", "1.obj", "mesh_0010.obj", "mesh_0009.obj", "mesh_10.obj", "b.obj",
                           "a2b10.obj", "a2b9.obj", "readme.txt", ".hidden.obj"})
    touch(folder / name);
  fs::create_directory(folder / "sub.obj");  // a folder, not a frame
  CHECK(names(list_frame_files(folder.string())) ==
        std::vector<std::string>{"1.obj", "2.obj", "10.obj", "a2b9.obj", "a2b10.obj", "b.obj", "mesh_0009.obj",
                                 "mesh_0010.obj", "mesh_10.obj"});
}

TEST_CASE("list_frame_files: patterns with * and ?", "[io][frame_sequence]") {
  const fs::path folder = deformseg::test::fresh_dir("io_frame_sequence/glob");
  for (const char* name : {"pose_1.obj", "pose_2.obj", "pose_12.obj", "pose_3.off", "rest.obj", "pose_1.obj.bak"})
    touch(folder / name);
  CHECK(names(list_frame_files((folder / "pose_*.obj").string())) ==
        std::vector<std::string>{"pose_1.obj", "pose_2.obj", "pose_12.obj"});
  CHECK(names(list_frame_files((folder / "pose_?.*").string())) ==
        std::vector<std::string>{"pose_1.obj", "pose_1.obj.bak", "pose_2.obj", "pose_3.off"});
  CHECK(names(list_frame_files((folder / "*").string())).size() == 6);
  CHECK(names(list_frame_files((folder / "rest.obj").string())) == std::vector<std::string>{"rest.obj"});
  // The files keep the folder of the pattern.
  CHECK(list_frame_files((folder / "pose_1.*").string()) ==
        std::vector<fs::path>{folder / "pose_1.obj", folder / "pose_1.obj.bak"});
}

TEST_CASE("list_frame_files: nothing to read names the input", "[io][frame_sequence][errors]") {
  const fs::path folder = deformseg::test::fresh_dir("io_frame_sequence/empty");
  touch(folder / "notes.txt");
  CHECK_THROWS_MATCHES(list_frame_files(folder.string()), invalid_input,
                       Message(folder.string() + ": no frame file (.obj, .off or .ply) in the folder"));
  const std::string pattern = (folder / "*.obj").string();
  CHECK_THROWS_MATCHES(list_frame_files(pattern), invalid_input, Message(pattern + ": no file matches the pattern"));
  const std::string missing = (folder / "missing").string();
  CHECK_THROWS_MATCHES(list_frame_files(missing), invalid_input, Message(missing + ": cannot open: no such folder or file"));
  const std::string missing_folder = (folder / "missing" / "*.obj").string();
  CHECK_THROWS_MATCHES(list_frame_files(missing_folder), invalid_input,
                       Message(missing_folder + ": no such folder: \"" + (folder / "missing").string() + "\""));
  const std::string wild_folder = (folder / "*" / "*.obj").string();
  CHECK_THROWS_MATCHES(list_frame_files(wild_folder), invalid_input,
                       Message(wild_folder + ": wildcards (* and ?) are only read in the file name, not in the "
                                             "folders above it"));

  touch(folder / "1.obj");
  touch(folder / "2.ply");
  CHECK_THROWS_MATCHES(list_frame_files(folder.string()), invalid_input,
                       Message(folder.string() +
                               ": the folder holds frames of several formats (.obj and .ply): give "
                               "a pattern such as \"" +
                               (folder / "*").string() + ".obj\" to choose"));
}

TEST_CASE("read_frame_sequence: connectivity of the first frame, positions of all", "[io][frame_sequence]") {
  const fs::path folder = tetrahedron_sequence("tetrahedron", 12);
  const auto animation = read_frame_sequence(folder.string());
  REQUIRE(animation.num_frames() == 12);
  REQUIRE(animation.num_vertices() == 4);
  REQUIRE(animation.num_faces() == 4);
  // frame_10.obj is frame 9 (natural order), moved by (9, 18, 27).
  const auto frame = animation.frame_positions(9);
  CHECK(std::vector<double>(frame.begin(), frame.end()) ==
        std::vector<double>{9, 18, 27, 10, 18, 27, 9, 19, 27, 9, 18, 28});

  SECTION("the same with any number of threads, as float, or in a Polyhedron_3") {
    for (const int threads : {1, 2, 3}) {
      const auto again = read_frame_sequence(folder.string(), {.threads = threads});
      CHECK(std::ranges::equal(again.all_positions(), animation.all_positions()));
    }
    const auto as_float = read_frame_sequence<deformseg::mesh::Surface_mesh, float>(folder.string(), {.threads = 2});
    CHECK(std::ranges::equal(as_float.all_positions(), animation.all_positions()));
    using Polyhedron = CGAL::Polyhedron_3<deformseg::mesh::Kernel>;
    const auto polyhedron = read_frame_sequence<Polyhedron>((folder / "frame_*.obj").string());
    CHECK(std::ranges::equal(polyhedron.all_positions(), animation.all_positions()));
    CHECK(polyhedron.num_faces() == 4);
  }
}

TEST_CASE("read_frame_sequence and read_animation: the frame rate is an input, 30 by default",
          "[io][frame_sequence]") {
  const fs::path folder = tetrahedron_sequence("tetrahedron_rate", 3);
  CHECK(read_frame_sequence(folder.string()).frames_per_second() == 30);
  CHECK(read_frame_sequence(folder.string(), {.fps = 24}).frames_per_second() == 24);
  CHECK(deformseg::io::read_animation(folder.string(), {.fps = 12.5}).frames_per_second() == 12.5);
  CHECK_THROWS_WITH(read_frame_sequence(folder.string(), {.fps = 0}), Catch::Contains("fps must be positive"));
}

TEST_CASE("read_frame_sequence: the connectivity of a topology file, in another format", "[io][frame_sequence]") {
  const fs::path folder = tetrahedron_sequence("with-topology", 3);
  // The topology's vertices are elsewhere: only its faces count.
  const fs::path topology = deformseg::test::write_file(
      "io_frame_sequence/topology.off", "OFF\n4 4 0\n5 5 5\n6 5 5\n5 6 5\n5 5 6\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  const auto animation = read_frame_sequence(folder.string(), {.topology = topology});
  REQUIRE(animation.num_frames() == 3);
  CHECK(animation.frame_positions(0)[3] == 1.0);
  CHECK(animation.frame_positions(2)[11] == 7.0);
}

TEST_CASE("read_frame_sequence: polygons need triangulate", "[io][frame_sequence]") {
  const fs::path folder = deformseg::test::fresh_dir("io_frame_sequence/quads");
  for (int t = 0; t < 2; ++t)
    std::ofstream(folder / ("q" + std::to_string(t) + ".obj"))
        << "v 0 0 " << t << "\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  CHECK_THROWS_MATCHES(
      read_frame_sequence(folder.string()), invalid_input,
      Message((folder / "q0.obj").string() + ":5: frame 0: a face with 4 vertices, not a triangle: "
                                             "set the option `triangulate` to fan-triangulate polygons"));
  const auto animation = read_frame_sequence(folder.string(), {.triangulate = true});
  CHECK(animation.num_faces() == 2);
  CHECK(animation.frame_positions(1)[2] == 1.0);
}

TEST_CASE("read_frame_sequence: errors name the file and the frame, the lowest frame first",
          "[io][frame_sequence][errors]") {
  const fs::path folder = tetrahedron_sequence("bad", 6);

  SECTION("a frame with another vertex count") {
    std::ofstream(folder / "frame_4.obj") << tetrahedron_frame(3, "v 9 9 9\n");
    CHECK_THROWS_MATCHES(read_frame_sequence(folder.string()), invalid_input,
                         Message((folder / "frame_4.obj").string() + ": frame 3: has 5 vertices instead of 4"));
  }
  SECTION("two bad frames: the lower one is reported whatever the number of threads") {
    std::ofstream(folder / "frame_5.obj") << "v 0 0 x\n";
    std::ofstream(folder / "frame_3.obj") << "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\n";
    for (const int threads : {1, 2, 4})
      CHECK_THROWS_MATCHES(read_frame_sequence(folder.string(), {.threads = threads}), invalid_input,
                           Message((folder / "frame_3.obj").string() + ":3: frame 2: non-finite coordinate \"nan\""));
  }
  SECTION("a bad first frame: a defect refused, named at its file") {
    std::ofstream(folder / "frame_1.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n";
    CHECK_THROWS_MATCHES(
        read_frame_sequence(folder.string(), {.repair = {.defects = deformseg::io::Defect_policy::refuse}}),
        invalid_input,
        Message((folder / "frame_1.obj").string() + ": frame 0: triangles 0 and 1 have the same vertices"));
    // Repaired by default, which does not hide that the other frames have another vertex count.
    CHECK_THROWS_MATCHES(read_frame_sequence(folder.string()), invalid_input,
                         Message((folder / "frame_2.obj").string() + ": frame 1: has 4 vertices instead of 3"));
  }
  SECTION("a defect refused in a topology file") {
    const fs::path topology = folder.parent_path() / "bad-topology.off";
    std::ofstream(topology) << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n";
    CHECK_THROWS_MATCHES(
        read_frame_sequence(folder.string(),
                            {.topology = topology, .repair = {.defects = deformseg::io::Defect_policy::refuse}}),
        invalid_input,
        Message(topology.string() + ": triangles 0 and 1 are inconsistently oriented: both go from "
                                    "vertex 0 to vertex 1 on their shared edge"));
    deformseg::io::Repair_report report;
    CHECK(read_frame_sequence(folder.string(), {.topology = topology}, &report).num_faces() == 2);
    CHECK(report.reoriented_triangles == 1);
  }
  SECTION("a missing topology file") {
    const fs::path missing = folder / "missing.off";
    CHECK_THROWS_MATCHES(read_frame_sequence(folder.string(), {.topology = missing}), invalid_input,
                         Message(missing.string() + ": cannot open: no such file"));
  }
  SECTION("an empty sequence") {
    const fs::path empty = deformseg::test::fresh_dir("io_frame_sequence/no-frame");
    CHECK_THROWS_MATCHES(read_frame_sequence(empty.string()), invalid_input,
                         Message(empty.string() + ": no frame file (.obj, .off or .ply) in the folder"));
  }
  SECTION("a negative thread count") {
    CHECK_THROWS_MATCHES(read_frame_sequence(folder.string(), {.threads = -1}), invalid_input,
                         Message("threads must be 0 (the default) to 1024, not -1"));
  }
}

namespace {

// Checks that frame `t` of `animation` holds CGAL's reading of `path`, to the last bit.
template <class Animation>
void check_frame_as_cgal(const Animation& animation, std::size_t t, const fs::path& path) {
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  std::vector<std::vector<std::size_t>> faces;
  REQUIRE(CGAL::IO::read_polygon_soup(path.string(), points, faces, CGAL::parameters::verbose(false)));
  const auto frame = animation.frame_positions(t);
  REQUIRE(frame.size() == 3 * points.size());
  std::size_t differing_bits = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      differing_bits += std::bit_cast<std::uint64_t>(frame[3 * i + k]) != std::bit_cast<std::uint64_t>(points[i][k]);
  INFO("frame " << t << ": " << path);
  CHECK(differing_bits == 0);
}

}  // namespace

TEST_CASE("read_frame_sequence: the horse gallop", "[io][frame_sequence][data]") {
  const fs::path folder = deformseg::test::unpacked("horse-gallop/horse-gallop.tar.xz") / "horse-gallop";
  const auto files = list_frame_files(folder.string());
  REQUIRE(files.size() == 48);
  CHECK(files.front().filename() == "0001.obj");
  CHECK(files.back().filename() == "0048.obj");

  const auto one_thread = read_frame_sequence(folder.string(), {.threads = 1});
  CHECK(one_thread.num_frames() == 48);
  CHECK(one_thread.num_vertices() == 8431);
  CHECK(one_thread.num_faces() == 16843);
  for (std::size_t t = 0; t < 48; ++t) check_frame_as_cgal(one_thread, t, files[t]);

  const auto two_threads = read_frame_sequence(folder.string(), {.threads = 2});
  CHECK(std::ranges::equal(two_threads.all_positions(), one_thread.all_positions()));

  // Frames 24 and 48 are the same file, byte for byte.
  CHECK(std::ranges::equal(one_thread.frame_positions(23), one_thread.frame_positions(47)));

  const auto nine = read_frame_sequence((folder / "000?.obj").string());
  CHECK(nine.num_frames() == 9);
  CHECK(std::ranges::equal(nine.frame_positions(8), one_thread.frame_positions(8)));
  CHECK(read_frame_sequence((folder / "00*.obj").string()).num_frames() == 48);
}

TEST_CASE("read_frame_sequence: the samba dancer", "[io][frame_sequence][data]") {
  const fs::path folder = deformseg::test::unpacked("samba/samba.tar.xz") / "samba";
  const auto files = list_frame_files((folder / "mesh_*.obj").string());
  REQUIRE(files.size() == 175);
  for (std::size_t t = 0; t < files.size(); ++t) {
    char expected[32];
    std::snprintf(expected, sizeof expected, "mesh_%04zu.obj", t);
    CHECK(files[t].filename().string() == expected);
  }
  const auto animation = read_frame_sequence(folder.string(), {.threads = 2});
  CHECK(animation.num_frames() == 175);
  CHECK(animation.num_vertices() == 9971);
  CHECK(animation.num_faces() == 19938);
  for (const std::size_t t : {0, 1, 87, 174}) check_frame_as_cgal(animation, t, files[t]);
  const auto one_thread = read_frame_sequence(folder.string(), {.threads = 1});
  CHECK(std::ranges::equal(one_thread.all_positions(), animation.all_positions()));
}

TEST_CASE("read_frame_sequence: the cat poses, with normals in their files", "[io][frame_sequence][data]") {
  const fs::path folder = deformseg::test::unpacked("cat-lion-poses/cat-poses.tgz") / "cat-poses";
  const auto poses = read_frame_sequence((folder / "cat-0?.obj").string(),
                                         {.topology = folder / "cat-reference.obj"});
  CHECK(poses.num_frames() == 9);
  CHECK(poses.num_vertices() == 7207);
  CHECK(poses.num_faces() == 14410);
  check_frame_as_cgal(poses, 0, folder / "cat-01.obj");
  check_frame_as_cgal(poses, 8, folder / "cat-09.obj");
  // The folder: the nine poses, then the reference (natural order: digits before letters).
  const auto all = read_frame_sequence(folder.string());
  CHECK(all.num_frames() == 10);
  check_frame_as_cgal(all, 9, folder / "cat-reference.obj");
}

// ---- The writer: write_sequence (helpers shared with the other writers' tests: writer_support.h) ----

namespace color = deformseg::color;
namespace io = deformseg::io;
namespace mesh = deformseg::mesh;
namespace test = deformseg::test;

namespace {

using deformseg::test::Polygons;
using deformseg::test::check_points;
using deformseg::test::drifting_tetrahedron;
using deformseg::test::file_text;
using deformseg::test::four_colors;
using deformseg::test::read_ply_colored;
using deformseg::test::tetrahedron;
using deformseg::test::writer_output;
using Point = deformseg::test::Point_3;
using Polyhedron = CGAL::Polyhedron_3<deformseg::mesh::Kernel>;

}  // namespace

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
  const fs::path folder = test::fresh_dir("writers/names") / "new" / "folder";
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
    const fs::path folder = test::fresh_dir(std::string("writers/round_trip_") +
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
  const fs::path folder = test::fresh_dir("writers/colors");
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
  const fs::path folder = test::fresh_dir("writers/sequence_errors");

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
    const fs::path file = test::write_file("writers/sequence_errors/a_file", "not a folder");
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
