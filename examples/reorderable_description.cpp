// ReorderableDescription: a front end asks it of a policy's description before it computes a
// z-score (similarity_significance shuffles the frames of a description). A description of one's
// own models it with frame_count and reordered_frames in its namespace; one without frames does not.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/motion_signature_similarity.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/similarity/similarity.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numbers>
#include <random>
#include <span>
#include <vector>

namespace own {

using namespace deformseg;

// The mean height of the vertices, frame by frame.
struct Heights {
  std::vector<double> z;
};
std::size_t frame_count(const Heights& h) { return h.z.size(); }
Heights reordered_frames(const Heights& h, std::span<const std::size_t> order) {
  Heights out;
  for (const std::size_t t : order) out.z.push_back(h.z[t]);
  return out;
}

Heights heights(const mesh::Surface_mesh_animation& animation) {
  Heights h;
  for (std::size_t t = 0; t < animation.num_frames(); ++t) {
    const auto xyz = animation.frame_positions(t);
    double sum = 0;
    for (std::size_t i = 2; i < xyz.size(); i += 3) sum += xyz[i];
    h.z.push_back(sum / double(animation.num_vertices()));
  }
  return h;
}

// 1 / (1 + a difference).
similarity::Similarity of_difference(double difference) {
  similarity::Similarity s;
  s.value = 1 / (1 + difference);
  s.score = difference;
  return s;
}

// Frame by frame: 1 / (1 + the mean difference of the heights).
struct Height_similarity {
  using Description = Heights;
  similarity::Similarity compare(const Heights& a, const Heights& b) const {
    double difference = 0;
    for (std::size_t t = 0; t < a.z.size() && t < b.z.size(); ++t) difference += std::abs(a.z[t] - b.z[t]);
    return of_difference(difference / double(a.z.size()));
  }
};

// The height of the last frame alone: nothing to shuffle.
struct Final_height_similarity {
  using Description = double;
  similarity::Similarity compare(double a, double b) const {
    return of_difference(std::abs(a - b));
  }
};

}  // namespace own

namespace {

// What a front end prints: the similarity, and its z-score when the description can be shuffled.
template <class Policy>
bool report(const char* name, const Policy& policy, const typename Policy::Description& a,
            const typename Policy::Description& b) {
  std::printf("%-24s similarity %.3f", name, policy.compare(a, b).value);
  if constexpr (deformseg::similarity::ReorderableDescription<typename Policy::Description>) {
    std::mt19937 random(1);
    std::printf(", z-score %.1f\n", deformseg::similarity::similarity_significance(policy, a, b, 20, random));
    return true;
  } else {
    std::printf(", no z-score (its description has no frames to shuffle)\n");
    return false;
  }
}

}  // namespace

int main() {
  using namespace deformseg;
  static_assert(similarity::ReorderableDescription<similarity::Motion_signature_similarity<>::Description>);
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {10, {std::numbers::pi / 2}}, {5, {}}, {10, {0.0}}};
  const auto thin = mesh::make_bending_tube(spec).animation;
  spec.shape.radius = 0.15;
  const auto thick = mesh::make_bending_tube(spec).animation;
  const own::Heights a = own::heights(thin), b = own::heights(thick);
  const bool shuffled = report("heights frame by frame", own::Height_similarity{}, a, b);
  const bool not_shuffled = report("the last height", own::Final_height_similarity{}, a.z.back(), b.z.back());
  return shuffled && !not_shuffled ? 0 : 1;
}
