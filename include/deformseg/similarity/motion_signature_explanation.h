/// @file similarity/motion_signature_explanation.h
/// @brief `explain_signatures`: what made two animations' motion signatures alike or different
/// along their alignment, channel by channel (which time scale, which height band, the slower or
/// the faster half of the surface, speeds or vertical rates), so that a user can see why a search
/// ranked what it ranked (beyond the thesis).
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/signatures/motion_signatures.h>

#include <Eigen/Core>

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::similarity {

/// @brief One channel of the motion signatures (`signatures::motion_signatures`) and its part in
/// the difference of two animations along their alignment.
struct Signature_channel {
  /// @brief What the channel's columns hold.
  enum class Kind {
    speed,         ///< logarithms of speeds: a difference d means A moves exp(d) times as fast as B
    vertical_rate  ///< signed vertical rates, `sqrt(vertical_weight) asinh(rate / vertical_unit)`
  };
  Kind kind = Kind::speed;  ///< what the channel holds
  double lag = 0;         ///< the lag, in seconds (`Motion_signature_options::lags`)
  std::size_t band = 0;   ///< the height band, 0 the lowest (`Motion_signature_options::bands`)
  int side = 0;  ///< -1 the negative half across the body, +1 the positive, 0 both (`Motion_signature_options::sides`)
  bool upper_half = false;  ///< the quantiles from the median up (the faster, or more rising, half of the surface)
  /// @brief The channel's share of the squared differences of the aligned rows, summed over the
  /// alignment: the shares of all channels sum to 1 (all 0 when the aligned rows are equal).
  double share = 0;
  /// @brief The mean over the aligned pairs and the channel's columns of A's value less B's, in
  /// the signature's units (see `Kind`).
  double mean_difference = 0;
};

/// @brief Where two animations' motion signatures differ along their alignment.
struct Motion_signature_explanation {
  /// @brief Every channel, in the signatures' column order: the speeds' then the vertical rates',
  /// each by lag, then band, then side, then the lower and upper half of the quantiles.
  std::vector<Signature_channel> channels;
  /// @brief The aligned pairs of rows the differences were summed over.
  std::size_t pairs = 0;
};

/// @brief The channels of two animations' signatures along an alignment of their rows: each
/// channel's share of the summed squared differences (the quantity the similarity's kernel
/// turns into dissimilarities) and its mean difference, A's less B's.
/// @param a, b the signatures (rows at instants, as `Motion_signature_description::signatures`),
/// made with `options`.
/// @param row_pairs the aligned pairs (row of a, row of b), as the alignment policy gives them.
/// @param options the options the signatures were made with: their lags, quantiles, bands, sides
/// and up direction fix the columns' meaning.
/// @pre every pair's rows exist in `a` and `b`.
/// @throws invalid_input when the signatures' width is not the options', or a pair names a row
/// beyond them.
/// @par Complexity O(P W) for P pairs and W columns.
/// @par Example
/// @include explain_similarity.cpp
inline Motion_signature_explanation explain_signatures(const Eigen::MatrixXf& a, const Eigen::MatrixXf& b,
                                                       std::span<const std::pair<std::size_t, std::size_t>> row_pairs,
                                                       const signatures::Motion_signature_options& options) {
  const std::size_t k = options.quantiles, bands = options.bands, lags = options.lags.size();
  const std::size_t halves = options.sides ? 2 : 1, kinds = options.up ? 2 : 1;
  const std::size_t width = kinds * lags * bands * halves * k;
  if (std::size_t(a.cols()) != width || std::size_t(b.cols()) != width)
    throw invalid_input("explain_signatures: signatures of " + std::to_string(a.cols()) + " and " +
                        std::to_string(b.cols()) + " columns, where the options make " + std::to_string(width));
  Motion_signature_explanation out;
  out.pairs = row_pairs.size();
  for (std::size_t kind = 0; kind < kinds; ++kind)
    for (std::size_t l = 0; l < lags; ++l)
      for (std::size_t band = 0; band < bands; ++band)
        for (std::size_t half = 0; half < halves; ++half)
          for (const bool upper : {false, true})
            out.channels.push_back({.kind = kind == 0 ? Signature_channel::Kind::speed
                                                      : Signature_channel::Kind::vertical_rate,
                                    .lag = options.lags[l],
                                    .band = band,
                                    .side = halves == 1 ? 0 : half == 0 ? -1 : 1,
                                    .upper_half = upper});
  // Column c's channel: its (kind, lag, band, side) block of k quantiles, then the half it falls in.
  const auto channel_of = [&](std::size_t c) { return 2 * (c / k) + (2 * (c % k) + 1 > k ? 1 : 0); };
  std::vector<double> squares(out.channels.size()), sums(out.channels.size());
  std::vector<std::size_t> columns(out.channels.size());
  for (std::size_t c = 0; c < width; ++c) ++columns[channel_of(c)];
  double total = 0;
  for (const auto& [i, j] : row_pairs) {
    if (i >= std::size_t(a.rows()) || j >= std::size_t(b.rows()))
      throw invalid_input("explain_signatures: the pair (" + std::to_string(i) + ", " + std::to_string(j) +
                          ") beyond signatures of " + std::to_string(a.rows()) + " and " + std::to_string(b.rows()) +
                          " rows");
    for (std::size_t c = 0; c < width; ++c) {
      const double d = double(a(Eigen::Index(i), Eigen::Index(c))) - double(b(Eigen::Index(j), Eigen::Index(c)));
      squares[channel_of(c)] += d * d;
      sums[channel_of(c)] += d;
      total += d * d;
    }
  }
  Motion_signature_explanation kept{{}, out.pairs};  // a channel of one quantile has no upper half
  for (std::size_t ch = 0; ch < out.channels.size(); ++ch) {
    if (columns[ch] == 0) continue;
    Signature_channel channel = out.channels[ch];
    if (total > 0) channel.share = squares[ch] / total;
    if (out.pairs > 0) channel.mean_difference = sums[ch] / double(out.pairs * columns[ch]);
    kept.channels.push_back(channel);
  }
  return kept;
}

}  // namespace deformseg::similarity
