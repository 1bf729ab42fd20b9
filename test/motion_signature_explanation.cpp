// Motion_signature_similarity::explain and explain_signatures: the channels' shares and mean
// differences equal a sum by hand over the alignment `compare` returns; identical motions differ
// nowhere; where a faster motion's speeds differ most they say it is faster; what is refused.
#include "test_support.h"

#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/motion_signature_explanation.h>
#include <deformseg/similarity/motion_signature_similarity.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace {

namespace ds = deformseg;
using ds::similarity::Signature_channel;
using Catch::Matchers::Contains;

// A tube bending a right angle in `frames` frames, after 5 still ones and before 5 more.
ds::mesh::Surface_mesh_animation bending(std::size_t frames) {
  ds::mesh::Bending_tube spec;
  spec.shape = {.radius = 0.1, .length = 1.0, .sectors = 8, .rings = 16, .caps = true};
  spec.schedule = {{5, {0.0}}, {frames, {ds::test::right_angle}}, {5, {}}};
  return ds::mesh::make_bending_tube(spec).animation;
}

ds::similarity::Motion_signature_similarity<> policy_with(std::size_t bands, std::size_t quantiles,
                                                          bool sides = false) {
  ds::similarity::Motion_signature_similarity<> policy;
  policy.signatures.up = Eigen::Vector3d::UnitZ();
  policy.signatures.bands = bands;
  policy.signatures.quantiles = quantiles;
  if (sides) policy.signatures.sides = Eigen::Vector3d::UnitX();
  return policy;
}

}  // namespace

TEST_CASE("explain: each channel's share and mean difference summed by hand along compare's alignment",
          "[similarity]") {
  for (const auto& [bands, quantiles, sides] :
       {std::tuple<std::size_t, std::size_t, bool>{1, 8, false}, {3, 4, false}, {2, 3, false}, {2, 4, true}}) {
    INFO(bands << " bands of " << quantiles << " quantiles" << (sides ? ", sides" : ""));
    const auto policy = policy_with(bands, quantiles, sides);
    const auto a = policy.describe(bending(8)), b = policy.describe(bending(20));
    const auto why = policy.explain(a, b);
    // At 30 fps a row is a frame: compare's pairs of frames are the rows aligned.
    const auto pairs = policy.compare(a, b).alignment;
    REQUIRE(why.pairs == pairs.size());
    // By hand: column c is kind, lag, band and side by its block of `quantiles`, then its half by its
    // quantile.
    using Key = std::tuple<int, double, std::size_t, int, bool>;
    std::map<Key, std::pair<double, double>> sums;  // squares, differences
    std::map<Key, double> columns;
    double total = 0;
    const std::size_t lags = policy.signatures.lags.size(), halves = sides ? 2 : 1, regions = bands * halves;
    for (Eigen::Index c = 0; c < a.signatures.cols(); ++c) {
      const std::size_t block = std::size_t(c) / quantiles, q = std::size_t(c) % quantiles;
      const std::size_t region = block % regions;
      const int side = sides ? (region % 2 == 0 ? -1 : 1) : 0;
      const Key key{int(block / (lags * regions)), policy.signatures.lags[block / regions % lags], region / halves,
                    side, 2 * q + 1 > quantiles};
      columns[key] += 1;
      for (const auto& [i, j] : pairs) {
        const double d = double(a.signatures(Eigen::Index(i), c)) - double(b.signatures(Eigen::Index(j), c));
        sums[key].first += d * d;
        sums[key].second += d;
        total += d * d;
      }
    }
    REQUIRE(why.channels.size() == sums.size());
    double shares = 0;
    for (const Signature_channel& channel : why.channels) {
      const Key key{channel.kind == Signature_channel::Kind::speed ? 0 : 1, channel.lag, channel.band, channel.side,
                    channel.upper_half};
      REQUIRE(sums.count(key) == 1);
      CHECK(std::abs(channel.share - sums[key].first / total) < 1e-12);
      CHECK(std::abs(channel.mean_difference - sums[key].second / (double(pairs.size()) * columns[key])) < 1e-12);
      shares += channel.share;
    }
    CHECK(std::abs(shares - 1) < 1e-12);
    // Where the speeds differ most, they say that the faster bend is the faster.
    std::vector<Signature_channel> speeds;
    std::ranges::copy_if(why.channels, std::back_inserter(speeds),
                         [](const Signature_channel& c) { return c.kind == Signature_channel::Kind::speed; });
    const auto most = std::ranges::max_element(speeds, {}, &Signature_channel::share);
    CHECK(most->share > 0.05);
    CHECK(most->mean_difference > 0);
  }
}

TEST_CASE("explain: a motion and itself differ nowhere", "[similarity]") {
  const auto policy = policy_with(2, 8);
  const auto a = policy.describe(bending(12));
  const auto why = policy.explain(a, a);
  CHECK(why.pairs == std::size_t(a.signatures.rows()));  // the diagonal
  REQUIRE(why.channels.size() == 2 * 4 * 2 * 2);
  for (const Signature_channel& channel : why.channels) {
    CHECK(channel.share == 0);
    CHECK(channel.mean_difference == 0);
  }
}

TEST_CASE("explain_signatures: signatures of another width and pairs beyond the rows refused", "[similarity]") {
  const auto policy = policy_with(1, 8);
  const auto a = policy.describe(bending(12));
  ds::signatures::Motion_signature_options three_bands = policy.signatures;
  three_bands.bands = 3;
  const std::vector<std::pair<std::size_t, std::size_t>> pairs{{0, 0}};
  CHECK_THROWS_WITH(ds::similarity::explain_signatures(a.signatures, a.signatures, pairs, three_bands),
                    Contains("signatures of 64 and 64 columns, where the options make 192"));
  const std::vector<std::pair<std::size_t, std::size_t>> beyond{{0, std::size_t(a.signatures.rows())}};
  CHECK_THROWS_WITH(ds::similarity::explain_signatures(a.signatures, a.signatures, beyond, policy.signatures),
                    Contains("beyond signatures of"));
}
