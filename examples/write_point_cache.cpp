// Writes an animation as a Blender/Maya PC2 and a LightWave/Blender MDD point cache, reads their
// headers, and reads both back with the animation's connectivity.
#include <deformseg/io/point_cache.h>
#include <deformseg/mesh/synthetic.h>

#include <algorithm>
#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  // A tube bending its middle joint by a right angle over 12 frames, in float: a point cache
  // stores float32, so a float animation comes back exactly.
  mesh::Bending_tube spec;
  spec.schedule = {{12, {std::numbers::pi / 2}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto animation = mesh::make_deforming_mesh<float>(tube.animation);

  // [caches]
  io::write_pc2(animation, "tube.pc2", {.start_frame = 1});  // Blender's first frame is 1
  io::write_mdd(animation, "tube.mdd", 24);                  // 24 frames per second

  const io::Point_cache_info pc2 = io::read_point_cache_info("tube.pc2");
  const io::Point_cache_info mdd = io::read_point_cache_info("tube.mdd");
  std::cout << "tube.pc2: " << pc2.num_frames << " samples of " << pc2.num_vertices << " points from frame "
            << pc2.start_frame << ", every " << pc2.sample_rate << " frame\n";
  std::cout << "tube.mdd: " << mdd.num_frames << " frames of " << mdd.num_vertices << " points, the last at "
            << mdd.frame_times.back() << " s\n";

  // The caches hold no connectivity: vertex i of the cache is vertex index i of the topology.
  const auto from_pc2 = io::read_pc2<mesh::Surface_mesh, float>("tube.pc2", animation.face_graph());
  const auto from_mdd = io::read_mdd<mesh::Surface_mesh, float>("tube.mdd", animation.face_graph());
  // [caches]
  const bool same = std::ranges::equal(from_pc2.all_positions(), animation.all_positions()) &&
                    std::ranges::equal(from_mdd.all_positions(), animation.all_positions());
  std::cout << "read back: " << (same ? "the same positions, to the last bit" : "DIFFERENT positions") << '\n';
  return same ? 0 : 1;
}
