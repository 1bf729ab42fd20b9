// A synthetic tube bending at two joints one after the other, with its ground truth: which
// triangles each joint deforms, and the frames of each phase of the schedule.
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  // [spec]
  mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 12, .rings = 40, .caps = true};
  spec.joints = {{.position = 0.3, .blend_width = 0.1}, {.position = 0.7, .blend_width = 0.1}};
  // rest 5 frames; bend the lower joint; hold; bend the upper one; straighten both.
  spec.schedule = {{5, {0.0, 0.0}}, {8, {right, 0.0}}, {5, {}}, {8, {right, right}}, {8, {0.0, 0.0}}};
  // The same motion elsewhere: three times larger, turned, moved.
  spec.placement = {.scale = 3.0,
                    .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX())),
                    .translation = Eigen::Vector3d(1, 2, 3)};

  const auto tube = mesh::make_bending_tube(spec);
  // [spec]
  std::cout << tube.animation.num_frames() << " frames, " << tube.animation.num_vertices()
            << " vertices, " << tube.animation.num_faces() << " triangles\n";
  for (int joint : {-1, 0, 1})
    std::cout << (joint < 0 ? "rigid" : "joint " + std::to_string(joint)) << ": "
              << std::count(tube.face_joint.begin(), tube.face_joint.end(), joint) << " triangles\n";
  for (std::size_t p = 0; p < tube.phase_frames.size(); ++p)
    std::cout << "phase " << p << ": frames " << tube.phase_frames[p][0] << " to " << tube.phase_frames[p][1]
              << ", angles at its end " << tube.joint_angles[tube.phase_frames[p][1]][0] << ", "
              << tube.joint_angles[tube.phase_frames[p][1]][1] << '\n';
  return 0;
}
