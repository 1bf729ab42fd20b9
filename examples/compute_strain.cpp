// Per-triangle strain of a bending tube: against the rest pose (the pose), against the previous
// frame (the motion), with another measure, without normalisation, and against a reference mesh.
#include <deformseg/strain/strain.h>
#include <deformseg/mesh/synthetic.h>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  // A tube that rests, bends by 90 degrees in the middle, holds, and straightens: 31 frames.
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}, {5, {}}, {10, {0.0}}};
  const auto tube = mesh::make_bending_tube(spec);
  const auto& animation = tube.animation;

  // The defaults: rest pose = frame 0, maximal absolute principal strain, Gaussian normalisation
  // with sigma = the 95th percentile of the raw strains.
  // [defaults]
  const strain::Strain_field<float> pose = strain::compute_strain(animation);
  const auto frame_20 = pose.frame(20);  // bent and held: one contiguous vector of F strains
  std::cout << pose.num_faces() << " triangles x " << pose.num_frames() << " frames, sigma " << *pose.sigma()
            << ", degenerate " << pose.degenerate_count() << '\n';
  // [defaults]
  std::cout << "frame 20: largest normalised strain " << *std::max_element(frame_20.begin(), frame_20.end())
            << ", triangles above 0.5: "
            << std::count_if(frame_20.begin(), frame_20.end(), [](float s) { return s > 0.5f; }) << '\n';

  // The sigma the default normalisation chose, found again from the raw strains (frame 0, the
  // rest frame, is 0 by definition and left out).
  const auto raw =
      strain::compute_strain(animation, strain::Strain_options{.normalization = strain::No_normalization{}});
  std::vector<float> values(raw.values().begin(), raw.values().end());
  const double sigma =
      strain::Gaussian_normalization{}.sigma_of(strain::Raw_strain_field<float>{values, raw.num_faces(), 0});
  std::cout << "sigma from the raw strains: " << sigma << '\n';

  // Motion: strain of each frame against the one before; it is 0 while the tube holds still.
  // [motion]
  const auto motion = strain::compute_strain(animation, {.reference = strain::Strain_reference::previous_pose});
  // [motion]
  for (std::size_t t : {10, 18, 25}) {
    const auto frame = motion.frame(t);
    std::cout << "motion, frame " << t << ": largest " << *std::max_element(frame.begin(), frame.end()) << '\n';
  }

  // Raw Green-Lagrange strain in double, with principal directions.
  // [measure]
  const auto green = strain::compute_strain<double>(
      animation, {.measure = strain::Green_lagrange_strain{}, .normalization = strain::No_normalization{},
                  .principal_directions = true});
  // [measure]
  const std::size_t bent = std::size_t(std::max_element(green.frame(20).begin(), green.frame(20).end()) -
                                       green.frame(20).begin());
  std::cout << "most strained triangle at frame 20: " << bent << ", Green-Lagrange " << green(bent, 20)
            << ", stretched along " << green.principal_directions(20).row(Eigen::Index(bent)) << '\n';

  // A reference mesh of its own (here the straight tube, as a Surface_mesh) in place of a frame.
  // [reference_mesh]
  const mesh::Surface_mesh straight = animation.face_graph();
  const auto against_mesh =
      strain::compute_strain(animation, straight, {.normalization = strain::Gaussian_normalization{.sigma = 0.1}});
  // [reference_mesh]
  std::cout << "against the straight mesh, sigma given " << *against_mesh.sigma() << ", frame 20 triangle " << bent
            << ": " << against_mesh(bent, 20) << '\n';
  return 0;
}
