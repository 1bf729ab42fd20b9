// The policy a motion store's clips are described by, and the description options the store
// records of it: what tells a store this front end can search and extend from one it cannot.
#pragma once

#include "similarity.h"

#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/store/motion_store.h>
#include <deformseg/store/stored_motions.h>

#include <cstddef>
#include <string>

namespace deformseg::frontend {

/// The summaries a store's clips get: `search::summarize(view, store_summary_chunks)`.
inline constexpr std::size_t store_summary_chunks = 4;

/// The default policy with the signatures' up direction of `choice` (its policy must be
/// motion-signature and its alignment dtw: what a store holds).
/// @throws invalid_input naming the option otherwise.
similarity::Default_similarity store_policy(const Policy_choice& choice, Front front);

/// The values per row of `policy`'s signatures: lags x quantiles, twice that with an up direction
/// (the vertical rates' quantiles follow the speeds'); the "width" a store's description records.
std::size_t signature_width(const similarity::Default_similarity& policy);

/// The description options a store records for `policy`, as a JSON object: policy, alignment,
/// lags, quantiles, floor, up ([x, y, z] or null), vertical_unit, vertical_weight,
/// signature_rate, scale and width (the values per signature).
std::string store_description(const similarity::Default_similarity& policy);

/// The policy choice a store's description names (its up direction), for describing queries as
/// the store's clips were.
/// @throws invalid_input naming the store when its description is not one this front end writes
/// (another version of deformseg, other options): the message says which member differs.
Policy_choice stored_policy_choice(const store::Motion_store& store);

}  // namespace deformseg::frontend
