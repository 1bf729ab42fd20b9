// Merging motion stores described apart (a cluster's workers each describe a part; one writer
// merges them): `deformseg store merge`.
#pragma once

#include "store_describe.h"

#include <functional>
#include <string>
#include <vector>

namespace deformseg::frontend {

/// Appends the clips of the stores `parts`, in their order, into the store in `folder` (made when
/// missing) as they are: their records, signatures, frames and summaries; a clip the store holds
/// already is replaced at its index. One commit at the end: the store is the merge of stores
/// described apart (a cluster's workers each describe a part; one writer merges them). `say` gets
/// a line per part.
/// @throws invalid_input naming the part or the store when a part cannot be opened, a clip's block
/// in a part does not match its checksum, the parts' descriptions differ from each other or from
/// the store's, or the store cannot be written; the store is then as it was.
Describe_report merge_stores(const std::string& folder, const std::vector<std::string>& parts,
                             const std::function<void(const std::string&)>& say);

}  // namespace deformseg::frontend
