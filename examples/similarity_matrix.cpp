// The similarity matrix of four animations: two schedules, each on two tubes. Each animation is
// described once; the pairs run in parallel. The same matrix of descriptions made beforehand
// (described_similarity_matrix). Then a pose of one frame among them, which the matrix refuses,
// naming it.
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/mesh/synthetic.h>

#include <iostream>
#include <numbers>
#include <vector>

int main() {
  using namespace deformseg;
  const double right = std::numbers::pi / 2;
  const std::vector<std::vector<mesh::Tube_phase>> schedules{
      {{5, {0.0}}, {10, {right}}, {8, {}}, {10, {0.0}}, {5, {}}},
      {{5, {0.0}}, {5, {right}}, {4, {}}, {5, {0.0}}, {5, {right}}, {4, {}}, {5, {0.0}}, {5, {}}}};
  const std::vector<mesh::Tube_shape> shapes{
      {}, {.radius = 0.16, .length = 1.5, .sectors = 12, .rings = 30, .caps = false}};
  std::vector<mesh::Surface_mesh_animation> animations;
  for (const auto& schedule : schedules)
    for (const auto& shape : shapes) {
      mesh::Bending_tube spec;
      spec.shape = shape;
      spec.schedule = schedule;
      animations.push_back(mesh::make_bending_tube(spec).animation);
    }
  // [matrix]
  const Eigen::MatrixXd m = similarity::similarity_matrix(animations);
  // [matrix]
  std::cout << "one bend (thin, thick), two bends (thin, thick):\n" << m << '\n';

  // [described]
  // Animations described as they come (read one at a time, say, and freed), compared afterwards:
  // the same matrix.
  const similarity::Default_similarity policy;
  std::vector<similarity::Motion_signature_description> descriptions;
  for (const auto& animation : animations) descriptions.push_back(policy.describe(animation));
  const bool same = similarity::described_similarity_matrix(descriptions, policy) == m;
  // [described]
  std::cout << "from the descriptions: " << (same ? "the same matrix" : "another matrix") << '\n';

  // [pose]
  // A pose of one frame has no motion to describe: the matrix names it, so that it can be left out.
  const auto first = animations[0].frame_positions(0);
  animations.emplace_back(animations[0].face_graph(), std::vector<double>(first.begin(), first.end()));
  try {
    similarity::similarity_matrix(animations);
  } catch (const similarity::animation_not_described& e) {
    std::cout << "animation " << e.index() << " not described: " << e.reason() << '\n';
  }
  // [pose]
  return same ? 0 : 1;
}
