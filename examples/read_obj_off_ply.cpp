// The format-specific readers read_obj, read_off and read_ply, and points_of, which hands a
// Triangle_soup to make_face_graph to build a CGAL mesh.
//
//   read_obj_off_ply [FILE.obj|.off|.ply]
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/off.h>
#include <deformseg/io/ply.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/ply.h>
#include <deformseg/mesh/synthetic.h>

#include <fstream>
#include <iostream>

using namespace deformseg;

void build_and_print(const std::string& name, const io::Triangle_soup& soup) {
  const mesh::Surface_mesh mesh = mesh::make_face_graph<mesh::Surface_mesh>(io::points_of(soup), soup.triangles);
  std::cout << name << ": " << soup.num_vertices() << " vertices, " << soup.triangles.size()
            << " triangles; as a Surface_mesh, " << mesh.number_of_edges() << " edges, closed: "
            << std::boolalpha << CGAL::is_closed(mesh) << '\n';
}

int main(int argc, char** argv) {
  if (argc > 1) {
    const std::string path = argv[1];
    const auto soup = path.ends_with(".obj")   ? io::read_obj(path)
                      : path.ends_with(".off") ? io::read_off(path)
                                               : io::read_ply(path);
    build_and_print(path, soup);
    return 0;
  }
  // One frame of a small tube in each format.
  mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 8, .rings = 6, .caps = true};
  const auto tube = mesh::make_bending_tube(spec);
  io::write_obj(tube.animation, 0, "tube.obj");
  io::write_ply(tube.animation, 0, "tube.ply");
  {
    std::ofstream off("tube.off");
    off << "OFF\n" << tube.animation.num_vertices() << ' ' << tube.animation.num_faces() << " 0\n";
    const auto xyz = tube.animation.frame_positions(0);
    for (std::size_t i = 0; i < tube.animation.num_vertices(); ++i)
      off << xyz[3 * i] << ' ' << xyz[3 * i + 1] << ' ' << xyz[3 * i + 2] << '\n';
    for (const auto& t : tube.animation.triangles()) off << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  build_and_print("tube.obj", io::read_obj("tube.obj"));
  build_and_print("tube.off", io::read_off("tube.off"));
  build_and_print("tube.ply", io::read_ply("tube.ply"));
  return 0;
}
