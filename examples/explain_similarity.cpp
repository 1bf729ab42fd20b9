// explain: where two motions' signatures differ along their alignment. A tube bends in 10 frames,
// another the same way in 30: the speeds differ most (the first moves faster), and the shares of all
// channels sum to 1. The signatures here cut the surface into 2 height bands
// (Motion_signature_options::bands), so that the explanation also says which band differs.
#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

int main() {
  using namespace deformseg;
  const auto bending = [](std::size_t frames) {
    mesh::Bending_tube spec;
    spec.schedule = {{5, {0.0}}, {frames, {std::numbers::pi / 2}}, {5, {}}};
    return mesh::make_bending_tube(spec).animation;
  };
  similarity::Motion_signature_similarity<> policy{};
  policy.signatures.bands = 2;
  const auto fast = policy.describe(bending(10)), slow = policy.describe(bending(30));
  const similarity::Motion_signature_explanation why = policy.explain(fast, slow);

  double total = 0;
  for (const similarity::Signature_channel& c : why.channels) total += c.share;
  const auto most = std::ranges::max_element(why.channels, {}, &similarity::Signature_channel::share);
  std::printf("%zu channels over %zu aligned pairs, shares summing to %.6f\n", why.channels.size(), why.pairs, total);
  std::printf("most: %s at lag %.3f s, band %zu, %s half: %.0f%% of the difference, A %.2fx as fast as B\n",
              most->kind == similarity::Signature_channel::Kind::speed ? "speeds" : "vertical rates", most->lag,
              most->band, most->upper_half ? "upper" : "lower", 100 * most->share, std::exp(most->mean_difference));
  const bool speeds_differ = most->kind == similarity::Signature_channel::Kind::speed && most->mean_difference > 0;
  return std::abs(total - 1) < 1e-9 && speeds_differ ? 0 : 1;
}
