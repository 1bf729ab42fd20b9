// The weighted quantiles of motion signatures (signatures/internal/weighted_quantiles.h): the radix
// selection (weighted_quantiles) and one round of its buckets checked against rounding
// (Bucket_quantiles) against a sort and a walk, on small adversarial sets whose sums are exact
// (ties, zeros of both signs, equal values, levels on a cumulative weight, k above 64), and against
// each other, to the last bit, on large sets of rates of many magnitudes, from call to call as a
// stream of frames gives them.
#include <deformseg/signatures/internal/weighted_quantiles.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

namespace {

namespace si = deformseg::signatures::internal;

// The rates of one call: values and weights.
struct Rates {
  std::vector<double> value;
  std::vector<double> weight;
};

// The brute force: the rates sorted (-0 before +0), walked one by one up to each level; the largest
// rate for a level beyond the total.
std::vector<double> sort_and_walk(const Rates& rates, std::size_t k) {
  std::vector<std::size_t> order(rates.value.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return si::order_key(rates.value[a]) < si::order_key(rates.value[b]);
  });
  std::vector<double> out(k);
  std::size_t at = 0;
  double cumulative = rates.weight[order[0]];
  for (std::size_t q = 0; q < k; ++q) {
    while (cumulative < si::quantile_level(q, k) && at + 1 < order.size()) cumulative += rates.weight[order[++at]];
    out[q] = rates.value[order[at]];
  }
  return out;
}

std::vector<double> radix(const Rates& rates, std::size_t k) {
  std::vector<si::Keyed_rate> keyed(rates.value.size()), spare(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) keyed[i] = {si::order_key(rates.value[i]), rates.weight[i]};
  std::vector<double> out(k);
  si::weighted_quantiles(keyed, spare, k, out.data());
  return out;
}

// Bucket_quantiles, its memory and bucket span kept by the caller from call to call.
struct Bucketed {
  si::Bucket_quantiles selection;
  si::Bucket_quantiles::Bucket_span span;

  std::vector<double> operator()(const Rates& rates, std::size_t k) {
    std::vector<std::uint64_t> keys(rates.value.size());
    for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = si::order_key(rates.value[i]);
    const auto [low, high] = std::minmax_element(keys.begin(), keys.end());
    std::vector<si::Keyed_rate> keyed(keys.size()), spare(keys.size());
    std::vector<double> out(k);
    selection.quantiles(keys, *low, *high, rates.weight, k, out.data(), span, keyed, spare);
    return out;
  }
};

void require_same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t q = 0; q < a.size(); ++q) {
    INFO("quantile " << q << " of " << a.size() << ": " << a[q] << " and " << b[q]);
    CHECK(std::bit_cast<std::uint64_t>(a[q]) == std::bit_cast<std::uint64_t>(b[q]));
  }
}

// Weights that are multiples of 2^-20 summing to 1 exactly, so that every sum of them, in any
// order, is exact: the sort and walk is then the definition itself. Equal weights (as equal as
// 2^-20 allows) put levels on cumulative weights (1/16 is the weight of 2 of 32 rates).
std::vector<double> dyadic_weights(std::size_t n, std::mt19937& random, bool equal) {
  const std::uint32_t total = 1u << 20;
  std::vector<std::uint32_t> units(n, 1);
  if (!equal) {
    std::uniform_int_distribution<std::uint32_t> draw(1, 1000);
    std::uint64_t drawn = 0;
    for (std::uint32_t& u : units) drawn += (u = draw(random));
    for (std::uint32_t& u : units) u = std::max<std::uint32_t>(1, std::uint32_t(std::uint64_t(u) * total / drawn));
  } else {
    for (std::uint32_t& u : units) u = total / std::uint32_t(n);
  }
  std::uint32_t sum = 0;
  for (const std::uint32_t u : units) sum += u;
  for (std::size_t i = 0; sum < total; i = (i + 1) % n) ++units[i], ++sum;  // what rounding left
  std::vector<double> weights(n);
  for (std::size_t i = 0; i < n; ++i) weights[i] = std::ldexp(double(units[i]), -20);
  return weights;
}

}  // namespace

TEST_CASE("weighted quantiles: small adversarial sets, as the sort and walk give them", "[motion_signature]") {
  std::mt19937 random(11);
  // Ties, zeros of both signs, tiny and huge magnitudes of both signs, a value repeated.
  const std::vector<double> values{0.0, -0.0, 1.5, -1.5, 1e-300, -1e-300, 3.0, 2.0, 0.25, 1e300, -7.0, 1.5};
  std::uniform_int_distribution<std::size_t> value(0, values.size() - 1);
  std::uniform_int_distribution<std::size_t> size(1, 140);
  Bucketed bucketed;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = trial < 20 ? std::size_t(trial + 1) : size(random);
    const std::size_t k = std::vector<std::size_t>{1, 2, 3, 8, 16, 17, 65, 150}[std::size_t(trial) % 8];
    Rates rates;
    // Some sets of zeros only, of both signs (a part the radix selection's buckets cannot split),
    // some of two values only.
    const std::size_t kinds = trial % 5 == 0 ? 2 : trial % 7 == 0 ? 3 : values.size();
    for (std::size_t i = 0; i < n; ++i) rates.value.push_back(values[value(random) % kinds]);
    // Equal weights put levels on cumulative weights (1/16 of 32 rates is 2 of them).
    rates.weight = dyadic_weights(n, random, trial % 3 == 0);
    INFO("trial " << trial << ": " << n << " rates, " << k << " quantiles");
    const std::vector<double> expected = sort_and_walk(rates, k);
    require_same_bits(radix(rates, k), expected);
    require_same_bits(bucketed(rates, k), expected);
  }
}

TEST_CASE("weighted quantiles: zeros of both signs beyond a sorted part, -0 up to its weight", "[motion_signature]") {
  // 100 rates of -0 then +0: the radix selection's buckets lump them (once, all -0).
  Rates rates;
  for (int i = 0; i < 100; ++i) rates.value.push_back(i < 30 ? -0.0 : 0.0), rates.weight.push_back(1.0 / 128);
  rates.value.push_back(1.0), rates.weight.push_back(1 - 100.0 / 128);
  const std::vector<double> out = radix(rates, 4);
  CHECK(std::signbit(out[0]));   // level 1/8: within the 30 / 128 of -0
  CHECK(!std::signbit(out[1]));  // level 3/8: past it
  CHECK(out[3] == 1.0);
  Bucketed bucketed;
  require_same_bits(bucketed(rates, 4), out);
}

TEST_CASE("Bucket_quantiles: the radix selection's bits on rates of many magnitudes, frame after frame",
          "[motion_signature]") {
  // Speeds spread over orders of magnitude (log-normal), signed rates, exact zeros and repeated
  // values, weights of any magnitude; each stream a set of rates that drifts from call to call, as
  // a lag's rates from frame to frame (the bucket span fitted to the last call).
  std::mt19937 random(5);
  std::lognormal_distribution<double> magnitude(-3, 3);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (int stream = 0; stream < 12; ++stream) {
    const std::size_t n = std::vector<std::size_t>{40, 300, 1100, 4500, 20000, 1}[std::size_t(stream) % 6];
    const std::size_t k = stream == 11 ? 150 : 1 + std::size_t(stream) % 9;
    const bool signed_rates = stream % 2 == 1;
    Rates rates;
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double u = uniform(random);
      const double v = u < 0.1 ? 0.0 : u < 0.15 ? 1.5 : magnitude(random);
      rates.value.push_back(signed_rates && uniform(random) < 0.4 ? -v : v);
      total += rates.weight.emplace_back(uniform(random) * (stream % 3 == 0 ? 1.0 : std::exp(4 * uniform(random))));
    }
    for (double& w : rates.weight) w /= total;
    Bucketed bucketed;
    for (int frame = 0; frame < 30; ++frame) {
      INFO("stream " << stream << " (" << n << " rates, " << k << " quantiles), frame " << frame);
      require_same_bits(bucketed(rates, k), radix(rates, k));
      for (double& v : rates.value)
        if (v != 0 && v != 1.5) v *= std::exp(0.3 * (uniform(random) - 0.5) + (frame % 10 == 9 ? 3.0 : 0.0));
    }
  }
}

TEST_CASE("Bucket_quantiles: weights not finite or negative, and one value, as the radix selection",
          "[motion_signature]") {
  Rates rates{{3.0, 1.0, 2.0, 5.0, 4.0}, {0.2, 0.2, -0.1, 0.5, 0.2}};
  Bucketed bucketed;
  require_same_bits(bucketed(rates, 4), radix(rates, 4));
  rates.weight[2] = std::numeric_limits<double>::quiet_NaN();
  require_same_bits(bucketed(rates, 4), radix(rates, 4));
  rates.weight[2] = std::numeric_limits<double>::infinity();
  require_same_bits(bucketed(rates, 4), radix(rates, 4));
  const Rates same{{2.0, 2.0, 2.0}, {0.1, 0.1, 0.1}};  // short of the levels: the one value still
  require_same_bits(bucketed(same, 3), {2.0, 2.0, 2.0});
  require_same_bits(radix(same, 3), {2.0, 2.0, 2.0});
}
