// repair_triangles and make_repaired_animation: a small soup as real assets come (an unwelded
// square, a triangle that repeats a vertex, a duplicate, a reversed triangle, three triangles on
// one edge), welded and repaired into an animation, with the report of what changed; and the
// same soup refused, with the defect named.
//
//   repair_triangles
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/io/mesh_repair.h>

#include <array>
#include <cstdint>
#include <iostream>
#include <vector>

using namespace deformseg;

void print(const io::Repair_report& r) {
  std::cout << r.input_vertices << " vertices and " << r.input_triangles << " triangles read\n"
            << "  welded vertices:       " << r.welded_vertices << '\n'
            << "  degenerate triangles:  " << r.degenerate_triangles << " (dropped)\n"
            << "  duplicate triangles:   " << r.duplicate_triangles << " (dropped)\n"
            << "  non-manifold edges:    " << r.non_manifold_edges << '\n'
            << "  non-manifold vertices: " << r.non_manifold_vertices << '\n'
            << "  duplicated vertices:   " << r.duplicated_vertices << '\n'
            << "  reoriented triangles:  " << r.reoriented_triangles << '\n'
            << "  unrepairable:          " << r.unrepairable_triangles << " (dropped)\n"
            << r.vertices << " vertices and " << r.triangles << " triangles after the repair\n";
}

int main() {
  // Two frames of 10 vertices: a unit square whose two triangles have their own vertices (0-2
  // and 3-5, coinciding along the diagonal), and a fin of three triangles on the edge (6, 7).
  const std::vector<std::array<double, 3>> corners = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0},  // triangle 0
      {0, 0, 0}, {1, 1, 0}, {0, 1, 0},  // triangle 1, welded to triangle 0 along the diagonal
      {3, 0, 0}, {3, 1, 0}, {4, 0, 0}, {2, 0, 1}};
  std::vector<double> positions;
  for (int frame = 0; frame < 2; ++frame)
    for (const auto& p : corners) positions.insert(positions.end(), {p[0] * (1 + 0.5 * frame), p[1], p[2]});
  const std::vector<std::array<std::uint32_t, 3>> triangles = {
      {0, 1, 2}, {3, 4, 5},  // the square
      {5, 4, 3},             // the same vertices as triangle 1: a duplicate
      {1, 2, 2},             // repeats vertex 2
      {6, 7, 8}, {6, 7, 9}, {7, 6, 2}};  // three triangles on the edge (6, 7)

  // [repair]
  io::Repair_report report;
  const auto animation = io::make_repaired_animation(std::span<const double>(positions), corners.size(),
                                                     std::span(triangles), {.weld = true}, &report);
  print(report);
  // The same counts by name, as a writer of reports (JSON, a dict) takes them: those not zero.
  std::cout << "counts not zero:";
  for (const auto& [name, count] : report.counts())
    if (count != 0) std::cout << ' ' << name << '=' << count;
  std::cout << '\n';
  std::cout << "the animation: " << animation.num_vertices() << " vertices, " << animation.num_faces()
            << " triangles, " << animation.num_frames() << " frames\n";
  // [repair]

  try {
    io::repair_triangles(std::span<const double>(positions), corners.size(), std::span(triangles),
                         {.weld = true, .defects = io::Defect_policy::refuse});
  } catch (const invalid_input& e) {
    std::cout << "refused: " << e.what() << '\n';
  }
  return 0;
}
