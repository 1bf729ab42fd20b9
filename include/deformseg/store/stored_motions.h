/// @file store/stored_motions.h
/// @brief `Stored_motions`: a motion store (`Motion_store`) read as a
/// `search::MotionCollection`, so that `search::nearest_motions`, `knn_graph` and
/// `similarity_matrix` search its clips in place; and `motion_summary_layout`, the summary layout
/// its writers record.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/search/motion_bounds.h>
#include <deformseg/search/motion_collection.h>
#include <deformseg/store/motion_store.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::store {

/// @brief The manifest's "summary" object of a store whose summaries are
/// `search::summarize(view, chunks)`'s floats: `{"kind": "motion-summary", "chunks": K}`.
/// A writer passes it to `Store_append` with `search::summary_width(width, chunks)`.
/// @par Complexity O(1).
inline std::string motion_summary_layout(std::size_t chunks) {
  return R"({"kind": "motion-summary", "chunks": )" + std::to_string(chunks) + "}";
}

namespace internal {

// The chunk count of a store's summaries, from its layout; refuses any other layout.
inline std::size_t stored_summary_chunks(const Motion_store& store) {
  const std::string file = (store.folder() / "store.json").string();
  const Json layout = parse_json(store.summary_layout(), file);
  const auto kind = layout.find("kind");
  const auto chunks = layout.find("chunks");
  if (kind == layout.end() || *kind != "motion-summary" || chunks == layout.end() || !chunks->is_number_unsigned() ||
      chunks->get<std::uint64_t>() == 0 || chunks->get<std::uint64_t>() > std::numeric_limits<std::size_t>::max())
    throw invalid_input("the store's summaries are not motion summaries (its \"summary\" is " +
                            store.summary_layout() + "): describe the clips again into a new store",
                        {.file = file});
  const auto count = chunks->get<std::size_t>();
  if (store.summary_width() != search::summary_width(store.width(), count))
    throw invalid_input("the store's summaries have " + std::to_string(store.summary_width()) +
                            " floats, motion summaries of width " + std::to_string(store.width()) + " with " +
                            std::to_string(count) + " chunks " +
                            std::to_string(search::summary_width(store.width(), count)),
                        {.file = file});
  return count;
}

}  // namespace internal

/// @brief A motion store's clips as a `search::MotionCollection`: clip i's signatures and
/// summary are read in the store's mapping, never copied.
///
/// A clip's block is verified against its checksum (`Motion_store::verify_clip`) the first time its
/// signatures are read, so that a search never compares a corrupted clip silently; what a pruned
/// search reads of a clip it prunes, its summary, is not verified (opening the store with
/// `Verify::checksums`, or `deformseg store verify`, checks every byte). Copies share what has been
/// verified; reading from several threads at once is safe.
/// @par Example
/// @include nearest_motions_in_store.cpp
class Stored_motions {
public:
  /// @brief The clips of `store`, whose summaries must be motion summaries
  /// (`motion_summary_layout`); an empty store of no clip is accepted whatever its layout.
  /// @throws invalid_input naming the manifest when the summaries are of another layout or size.
  /// @par Complexity O(1).
  /// @par Complexity O(size()).
  explicit Stored_motions(Motion_store store)
      : store_(std::move(store)),
        chunks_(store_.size() == 0 ? 1 : internal::stored_summary_chunks(store_)),
        verified_(std::make_shared<std::vector<std::atomic<bool>>>(store_.size())) {
    for (std::atomic<bool>& v : *verified_) v.store(false, std::memory_order_relaxed);
  }

  /// @brief The number of clips.
  std::size_t size() const { return store_.size(); }
  /// @brief Clip `i`'s signatures, its block verified on the first read.
  /// @pre `i < size()` (not checked).
  /// @throws invalid_input naming the clip when its block does not match its checksum.
  /// @par Complexity O(1); the first read of a clip O(its block), as `Motion_store::verify_clip`.
  signatures::Motion_signature_view view(std::size_t i) const {
    std::atomic<bool>& verified = (*verified_)[i];
    if (!verified.load(std::memory_order_acquire)) {
      store_.verify_clip(i);  // two threads may both verify a clip: the same answer, once more
      verified.store(true, std::memory_order_release);
    }
    return store_.view(i);
  }
  /// @brief Clip `i`'s summary. @pre `i < size()` (not checked). @par Complexity O(1).
  search::Motion_summary_view summary(std::size_t i) const {
    return {store_.summary(i), store_.width(), chunks_};
  }
  /// @brief The store read.
  const Motion_store& store() const { return store_; }

private:
  Motion_store store_;
  std::size_t chunks_;
  std::shared_ptr<std::vector<std::atomic<bool>>> verified_;  // shared by copies, which read the same mapping
};

static_assert(search::MotionCollection<Stored_motions>);

}  // namespace deformseg::store
