/// @file signatures/internal/weighted_quantiles.h
/// The weighted quantiles of a frame's rates, as motion signatures take them (twice per lag and
/// frame): quantile q of k is the smallest rate whose cumulative weight reaches (q + 1/2) / k. Two
/// ways to the same values, to the last bit: a radix selection, in rounds until the parts that hold
/// the levels are small (`weighted_quantiles`), and its buckets in fewer passes, checked that
/// rounding cannot have decided a level, which otherwise asks the former (`Bucket_quantiles`, what
/// motion signatures use).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace deformseg::signatures::internal {

/// A rate as the selection of quantiles orders it: its value's `order_key`, and its weight.
struct Keyed_rate {
  std::uint64_t key;
  double weight;
};

/// An unsigned key that orders as `value` does (-0 just below +0): the bits of a positive double
/// with the sign bit set, those of a negative one flipped.
inline std::uint64_t order_key(double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  return bits >> 63 ? ~bits : bits | (std::uint64_t(1) << 63);
}

/// The value whose `order_key` is `key`.
inline double key_value(std::uint64_t key) {
  return std::bit_cast<double>(key >> 63 ? key & ~(std::uint64_t(1) << 63) : ~key);
}

/// The level of quantile q of k: (q + 1/2) / k of the total weight.
inline double quantile_level(std::size_t q, std::size_t k) { return (double(q) + 0.5) / double(k); }

/// The buckets of a round of the selection of quantiles: rates whose keys lie in [low, high] spread
/// over equal spans of their values' logarithms, so that a bucket holds a share of a few rates
/// whatever the magnitudes. Magnitudes below 2^-octaves of the largest (2^-40 unless asked) are
/// lumped with zero (rates of exactly 0, a vertex that stands still, are common), and the sign
/// kept: a key maps to `middle + c` or `middle - c`, c the magnitude's bits above those of
/// 2^-octaves of the largest.
class Key_buckets {
public:
  /// At most 2^bits buckets. @pre low < high; 0 < octaves < 2047.
  Key_buckets(std::uint64_t low, std::uint64_t high, int bits, int octaves = 40) {
    const std::uint64_t largest = std::max(magnitude(low), magnitude(high));
    const std::uint64_t below = std::uint64_t(octaves) << 52;  // the exponent's bits start at bit 52
    tiny_ = largest > below ? largest - below : 0;
    middle_ = largest - tiny_;
    lowest_ = spread(low);
    const std::uint64_t span = spread(high) - lowest_;
    shift_ = std::max(int(std::bit_width(span)) - bits, 0);
    count_ = std::size_t(span >> shift_) + 1;
  }
  /// The number of buckets (1 when every rate is 0).
  std::size_t count() const { return count_; }
  /// The bucket of `key`, in [0, count()): not decreasing with the key.
  std::size_t operator()(std::uint64_t key) const { return std::size_t(offset(key) >> shift_); }
  /// Where `key` falls in the buckets' span: not decreasing with the key; its bits below the
  /// bucket's order the keys of one bucket (but magnitudes lumped with zero).
  std::uint64_t offset(std::uint64_t key) const { return spread(key) - lowest_; }
  /// The bits of |value| of a key, which order as the magnitudes do.
  static std::uint64_t magnitude(std::uint64_t key) {
    return (key ^ ((key >> 63) - 1)) & ~(std::uint64_t(1) << 63);  // key when positive, else ~key
  }

private:
  // Without branches, so that a loop of them is vectorised: the magnitude's bits above tiny_
  // (signed arithmetic is exact: both are below 2^63), then middle_ plus or minus them.
  std::uint64_t spread(std::uint64_t key) const {
    const std::uint64_t negative = (key >> 63) - 1;  // all ones for a negative value
    const auto c = std::uint64_t(std::max<std::int64_t>(std::int64_t(magnitude(key)) - std::int64_t(tiny_), 0));
    return middle_ + ((c ^ negative) - negative);
  }

  std::uint64_t tiny_ = 0, middle_ = 0, lowest_ = 0;
  int shift_ = 0;
  std::size_t count_ = 1;
};

/// The quantiles `first` to `last` (exclusive) of `k`, all of which lie in `rates` after the weight
/// `before` of the rates below them, into `out`: `rates` sorted, then walked up to each level (the
/// largest rate for a level beyond their total).
inline void sort_and_walk(std::span<Keyed_rate> rates, double before, std::size_t first, std::size_t last,
                          std::size_t k, double* out) {
  std::sort(rates.begin(), rates.end(), [](const Keyed_rate& a, const Keyed_rate& b) { return a.key < b.key; });
  std::size_t at = 0;
  double cumulative = before + rates[0].weight;
  for (std::size_t q = first; q < last; ++q) {
    while (cumulative < quantile_level(q, k) && at + 1 < rates.size()) cumulative += rates[++at].weight;
    out[q] = key_value(rates[at].key);
  }
}

/// The quantiles `first` to `last` (exclusive) of `k`, all of which lie in `rates` (whose keys are
/// in [low, high]) after the weight `before` of the rates below it, into `out`: a radix selection.
/// The rates are counted into `Key_buckets` (at most 1024, about 4 rates a bucket), the buckets'
/// weights summed up to each level, and only the rates of the buckets that hold a level gathered
/// into `spare` (as long as `rates`) and selected from further; parts of at most 32 rates are
/// sorted and walked.
inline void select_weighted_quantiles(std::span<Keyed_rate> rates, std::span<Keyed_rate> spare, double before,
                                      std::size_t first, std::size_t last, std::size_t k, std::uint64_t low,
                                      std::uint64_t high, double* out) {
  if (first == last) return;
  if (low == high) {
    for (std::size_t q = first; q < last; ++q) out[q] = key_value(low);
    return;
  }
  if (rates.size() <= 32) return sort_and_walk(rates, before, first, last, k, out);  // few enough to sort
  constexpr int max_bits = 10;
  const int bits = std::clamp(int(std::bit_width(rates.size())) - 2, 4, max_bits);
  const Key_buckets bucket(low, high, bits);
  const std::size_t buckets = bucket.count();
  // Zeros of both signs, which the buckets lump: -0 only up to its weight, as a walk gives it.
  if (buckets == 1) return sort_and_walk(rates, before, first, last, k, out);
  std::array<double, std::size_t(1) << max_bits> weight;
  std::array<std::uint32_t, std::size_t(1) << max_bits> count;
  std::fill_n(weight.begin(), buckets, 0.0);
  std::fill_n(count.begin(), buckets, 0);
  for (const Keyed_rate& r : rates) {
    const std::size_t b = bucket(r.key);
    weight[b] += r.weight, ++count[b];
  }
  // The buckets that hold levels: each with the weight below it, its quantiles and its place in `spare`.
  struct Part {
    std::size_t first, last, begin, size;
    double before;
    std::uint64_t low, high;
  };
  // At most one per quantile: 64 in place, more (k > 64) on the heap.
  std::array<Part, 64> near;
  std::vector<Part> far;
  const auto part = [&](std::size_t p) -> Part& { return p < near.size() ? near[p] : far[p - near.size()]; };
  constexpr std::uint16_t none = 0xffff;
  std::array<std::uint16_t, std::size_t(1) << max_bits> part_of;
  std::fill_n(part_of.begin(), buckets, none);
  std::size_t q = first, parts = 0, filled = 0;
  double cumulative = before;
  for (std::size_t b = 0; b < buckets && q < last; ++b) {
    if (count[b] == 0) continue;
    const double through = cumulative + weight[b];
    std::size_t end = q;
    while (end < last && (b + 1 == buckets || quantile_level(end, k) <= through)) ++end;
    if (end > q) {
      const Part made{q, end, filled, 0, cumulative, ~std::uint64_t(0), 0};
      if (parts < near.size()) near[parts] = made;
      else far.push_back(made);
      part_of[b] = std::uint16_t(parts++), filled += count[b];
    }
    q = end, cumulative = through;
  }
  for (const Keyed_rate& r : rates)
    if (const std::uint16_t p = part_of[bucket(r.key)]; p != none) {
      Part& into = part(p);
      spare[into.begin + into.size++] = r;
      into.low = std::min(into.low, r.key), into.high = std::max(into.high, r.key);
    }
  // Each part's rates are in `spare` now; `rates` serves as their scratch.
  for (std::size_t p = 0; p < parts; ++p) {
    const Part& into = part(p);
    select_weighted_quantiles(spare.subspan(into.begin, into.size), rates.subspan(into.begin, into.size),
                              into.before, into.first, into.last, k, into.low, into.high, out);
  }
}

/// The `k` area-weighted quantiles of `rates` (keyed values and their weights, weights summing to
/// 1), which it reorders, using `spare` (as long) as scratch: quantile q is the smallest rate whose
/// cumulative weight reaches (q + 1/2) / k (the largest rate if rounding leaves the total short of
/// it). O(n) expected for rates spread over many magnitudes, O(n log n) at worst.
inline void weighted_quantiles(std::span<Keyed_rate> rates, std::span<Keyed_rate> spare, std::size_t k,
                               double* out) {
  if (rates.empty()) return;
  std::uint64_t low = rates[0].key, high = low;
  for (const Keyed_rate& r : rates) low = std::min(low, r.key), high = std::max(high, r.key);
  select_weighted_quantiles(rates, spare, 0.0, 0, k, k, low, high, out);
}

/// `weighted_quantiles` of (value, weight) pairs.
inline void weighted_quantiles(const std::vector<std::pair<double, double>>& rates, std::size_t k, double* out) {
  std::vector<Keyed_rate> keyed(rates.size()), spare(rates.size());
  for (std::size_t i = 0; i < rates.size(); ++i) keyed[i] = {order_key(rates[i].first), rates[i].second};
  weighted_quantiles(keyed, spare, k, out);
}

/// The weighted quantiles of a frame's rates by the radix selection's buckets in fewer passes: the
/// rates' buckets and the buckets' weights in two passes (the weights of each bucket summed apart
/// for even and odd rates), the buckets that hold the levels found by blocks of 16, only their rates
/// gathered, split further by the next bits of their keys where more than 16 (without a pass for
/// their span), then sorted and walked. Each level is decided only when the weight below its rate
/// and the weight through it are apart from the level by more than any order of summing the
/// weights can err (a few ulps of the sum per rate); then every order of summation, the radix
/// selection's included, finds the same rate. Otherwise (about never; and for weights not finite
/// and non-negative), `weighted_quantiles` is asked, so that the quantiles always equal its own to
/// the last bit. Its memory serves again from call to call.
///
/// The buckets span the magnitudes from the largest rate's down to 40 octaves below it at first,
/// where the radix selection's stop; a stream of rates (one lag's speeds, say) keeps, from one
/// frame to the next, the octaves its buckets span (`Bucket_span`), 6 below its smallest quantile
/// but 0, so that most buckets fall where its rates are.
class Bucket_quantiles {
public:
  /// The octaves below the largest rate's magnitude that one stream's buckets span, fitted from
  /// call to call; 40 (the radix selection's) at first.
  struct Bucket_span {
    int octaves = 40;
  };

  /// The `k` quantiles of the rates whose keys are `keys` (`order_key` of each rate; the smallest
  /// `low`, the largest `high`) weighted by `weights` (as many), into `out`, the buckets spanning
  /// `span` (then fitted to these rates); `keyed` and `spare` (as many) are the radix selection's
  /// scratch when it is asked.
  void quantiles(std::span<const std::uint64_t> keys, std::uint64_t low, std::uint64_t high,
                 std::span<const double> weights, std::size_t k, double* out, Bucket_span& span,
                 std::span<Keyed_rate> keyed, std::span<Keyed_rate> spare) {
    if (k == 0 || keys.empty()) return;
    if (select(keys, low, high, weights, k, out, span)) return;
    for (std::size_t v = 0; v < keys.size(); ++v) keyed[v] = {keys[v], weights[v]};
    weighted_quantiles(keyed.first(keys.size()), spare, k, out);
  }

private:
  static constexpr int max_bits = 10;
  static constexpr std::size_t most_buckets = std::size_t(1) << max_bits;

  // The selection; false when a level is not decided beyond rounding, or the weights are not all
  // finite and non-negative.
  bool select(std::span<const std::uint64_t> keys, std::uint64_t low, std::uint64_t high,
              std::span<const double> weights, std::size_t k, double* out, Bucket_span& span) {
    const std::size_t n = keys.size();
    // Any sum of m <= n non-negative weights in any order is within gamma = n u / (1 - n u) of
    // its exact value, relatively; 4 gamma of the level leaves room for both sums' errors.
    const double u = std::numeric_limits<double>::epsilon() / 2;
    if (double(n) * u > 0.01 || n > std::numeric_limits<std::uint32_t>::max()) return false;
    apart_ = 4 * 1.01 * double(n) * u;
    if (low == high) {  // as the radix selection: one rate, whatever the weights
      for (std::size_t q = 0; q < k; ++q) out[q] = key_value(low);
      return true;
    }
    const Key_buckets bucket(low, high, std::clamp(int(std::bit_width(n)) - 1, 4, max_bits), span.octaves);
    const std::size_t buckets = bucket.count();
    if (buckets == 1) return false;  // zeros of both signs
    if (!sum_weights(keys, weights, bucket)) return false;
    if (!find_levels(buckets, k)) return false;
    gather(keys, weights, buckets);
    for (std::size_t i = 0; i < wanted_.size(); ++i) {
      const Wanted& w = wanted_[i];
      const std::span<Keyed_rate> part(gathered_.data() + w.begin, w.end - w.begin);
      if (!refine(part, bucket, w.below, w.first,
                  i + 1 < wanted_.size() ? wanted_[i + 1].first : k, k, out))
        return false;
    }
    fit(span, std::max(Key_buckets::magnitude(low), Key_buckets::magnitude(high)), k, out);
    return true;
  }

  // Each rate's bucket, and the weights summed per bucket (in two sets of buckets, even and odd
  // rates apart, so that neighbours in one bucket do not wait for each other); false for a weight
  // not finite or negative.
  bool sum_weights(std::span<const std::uint64_t> keys, std::span<const double> weights, const Key_buckets& bucket) {
    const std::size_t n = keys.size(), buckets = bucket.count();
    bucket_of_.resize(n);
    for (std::size_t v = 0; v < n; ++v) bucket_of_[v] = std::uint16_t(bucket(keys[v]));
    std::fill_n(pair_weight_.begin(), 2 * buckets, 0.0);
    bool finite = true;
    for (std::size_t v = 0; v < n; ++v) {
      pair_weight_[2 * std::size_t(bucket_of_[v]) + (v & 1)] += weights[v];
      finite &= weights[v] >= 0 && weights[v] <= std::numeric_limits<double>::max();
    }
    for (std::size_t b = 0; b < buckets; ++b) weight_[b] = pair_weight_[2 * b] + pair_weight_[2 * b + 1];
    return finite;
  }

  // The bucket of each level, and the weight below that bucket, into `wanted_`: the buckets'
  // weights summed a block at a time (the sums of the blocks do not wait for each other), then
  // the blocks walked up to each level, then the buckets of the blocks that hold levels; false
  // for a level beyond the total (the largest rate, by the radix's rule) or too many buckets.
  bool find_levels(std::size_t buckets, std::size_t k) {
    constexpr std::size_t block = 16;
    const std::size_t blocks = (buckets + block - 1) / block;
    std::fill(weight_.begin() + std::ptrdiff_t(buckets), weight_.begin() + std::ptrdiff_t(blocks * block), 0.0);
    for (std::size_t i = 0; i < blocks; ++i) {
      double sum = 0;
      for (std::size_t b = i * block; b < (i + 1) * block; ++b) sum += weight_[b];
      block_weight_[i] = sum;
    }
    wanted_.clear();
    std::size_t q = 0;
    double cumulative = 0;
    for (std::size_t i = 0; i < blocks && q < k; ++i) {
      if (quantile_level(q, k) > cumulative + block_weight_[i]) {
        cumulative += block_weight_[i];
        continue;
      }
      for (std::size_t b = i * block; b < (i + 1) * block && q < k; ++b) {
        const double through = cumulative + weight_[b];
        if (quantile_level(q, k) <= through) {
          if (wanted_.size() == max_wanted) return false;
          wanted_.push_back({b, cumulative, q});
          while (q < k && quantile_level(q, k) <= through) ++q;
        }
        cumulative = through;
      }
    }
    return q == k;
  }

  // A bucket that holds levels: the weight below it, its first level (the next bucket's first is
  // past its last), and its rates' place in `gathered_`.
  struct Wanted {
    std::size_t bucket;
    double below;
    std::size_t first;
    std::size_t begin = 0, end = 0;
  };

  // The rates of the wanted buckets into `gathered_`, each bucket's together: their indices listed
  // first without a branch (a tenth of the rates are wanted, at random), then counted per bucket
  // and put in place.
  void gather(std::span<const std::uint64_t> keys, std::span<const double> weights, std::size_t buckets) {
    const std::size_t n = keys.size();
    std::fill_n(slot_.begin(), buckets, none);
    for (std::size_t i = 0; i < wanted_.size(); ++i) slot_[wanted_[i].bucket] = std::uint8_t(i);
    listed_.resize(n);
    std::size_t listed = 0;
    for (std::size_t v = 0; v < n; ++v) listed_[listed] = std::uint32_t(v), listed += slot_[bucket_of_[v]] != none;
    for (Wanted& w : wanted_) w.end = 0;
    for (std::size_t i = 0; i < listed; ++i) ++wanted_[slot_[bucket_of_[listed_[i]]]].end;
    std::size_t filled = 0;
    for (Wanted& w : wanted_) w.begin = filled, filled += w.end, w.end = w.begin;
    gathered_.resize(filled);
    for (std::size_t i = 0; i < listed; ++i) {
      const std::uint32_t v = listed_[i];
      gathered_[wanted_[slot_[bucket_of_[v]]].end++] = {keys[v], weights[v]};
    }
  }

  // The levels [first, last) of k, all in `part` after the weight `below`: `part` sorted and walked
  // when small, or when its rates have one offset in the buckets (one key, or magnitudes lumped
  // with zero), else split into 16 sub-buckets over the span of its offsets (a round of the radix
  // selection on the same spread of the keys), the sub-buckets that hold levels refined.
  bool refine(std::span<Keyed_rate> part, const Key_buckets& bucket, double below, std::size_t first,
              std::size_t last, std::size_t k, double* out) {
    if (part.size() <= 16) return walk(part, below, first, last, k, out);
    std::uint64_t low = ~std::uint64_t(0), high = 0;
    for (const Keyed_rate& r : part) {
      const std::uint64_t offset = bucket.offset(r.key);
      low = std::min(low, offset), high = std::max(high, offset);
    }
    if (low == high) return walk(part, below, first, last, k, out);
    constexpr int sub_bits = 4;
    const int sub_shift = std::max(int(std::bit_width(high - low)) - sub_bits, 0);
    const std::size_t subs = std::size_t((high - low) >> sub_shift) + 1;
    const auto sub = [&](const Keyed_rate& r) { return std::size_t((bucket.offset(r.key) - low) >> sub_shift); };
    // Summed in two sets, even and odd rates apart, as the buckets' weights.
    std::array<double, 2 << sub_bits> pair{};
    for (std::size_t i = 0; i < part.size(); ++i) pair[2 * sub(part[i]) + (i & 1)] += part[i].weight;
    std::array<double, std::size_t(1) << sub_bits> weight;
    for (std::size_t s = 0; s < subs; ++s) weight[s] = pair[2 * s] + pair[2 * s + 1];
    // Each sub-bucket that holds levels, in order: its rates moved to the front, then refined.
    std::size_t q = first;
    double cumulative = below;
    auto rest = part.begin();
    for (std::size_t s = 0; s < subs && q < last; ++s) {
      const double through = cumulative + weight[s];
      if (quantile_level(q, k) <= through || s + 1 == subs) {
        const auto end = std::partition(rest, part.end(), [&](const Keyed_rate& r) { return sub(r) <= s; });
        const auto mine = std::partition(rest, end, [&](const Keyed_rate& r) { return sub(r) < s; });
        std::size_t after = q;
        while (after < last && quantile_level(after, k) <= through) ++after;
        if (s + 1 == subs) after = last;
        if (mine == end || !refine({mine, end}, bucket, cumulative, q, after, k, out)) return false;
        q = after, rest = end;
      }
      cumulative = through;
    }
    return q == last;
  }

  // The levels [first, last) of k, all in `part` after the weight `below`: `part` sorted and walked
  // by groups of equal keys.
  bool walk(std::span<Keyed_rate> part, double below, std::size_t first, std::size_t last, std::size_t k,
            double* out) const {
    std::sort(part.begin(), part.end(), [](const Keyed_rate& a, const Keyed_rate& b) { return a.key < b.key; });
    std::size_t q = first;
    for (auto i = part.begin(); i != part.end() && q < last;) {
      const std::uint64_t key = i->key;
      double through = below;
      do through += (i++)->weight;
      while (i != part.end() && i->key == key);
      for (double level = quantile_level(q, k); q < last && level <= through; level = quantile_level(++q, k)) {
        if (!(below < level - apart_ * level && through >= level + apart_ * level)) return false;
        out[q] = key_value(key);
      }
      below = through;
    }
    return q == last;
  }

  // The span of the next call: 6 octaves below the smallest magnitude of a quantile but 0, from
  // the largest (`largest`, as `Key_buckets::magnitude` gives it), 8 to 40.
  static void fit(Bucket_span& span, std::uint64_t largest, std::size_t k, const double* out) {
    std::uint64_t smallest = largest;
    for (std::size_t q = 0; q < k; ++q)
      if (out[q] != 0) smallest = std::min(smallest, Key_buckets::magnitude(order_key(out[q])));
    span.octaves = std::clamp(int((largest >> 52) - (smallest >> 52)) + 6, 8, 40);
  }

  static constexpr std::size_t max_wanted = 255;  // buckets that hold levels, numbered by a byte
  static constexpr std::uint8_t none = 255;
  double apart_ = 0;
  std::vector<std::uint16_t> bucket_of_;
  std::array<double, 2 * most_buckets> pair_weight_;
  std::array<double, most_buckets> weight_;
  std::array<double, most_buckets / 16> block_weight_;
  std::array<std::uint8_t, most_buckets> slot_;
  std::vector<Wanted> wanted_;
  std::vector<std::uint32_t> listed_;
  std::vector<Keyed_rate> gathered_;
};

}  // namespace deformseg::signatures::internal
