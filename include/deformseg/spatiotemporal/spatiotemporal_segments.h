/// @file spatiotemporal/spatiotemporal_segments.h
/// @brief Spatio-temporal segments of a deforming mesh (@ref method_spatiotemporal): every
/// (triangle, frame) cell labelled rigid or deformed, deformed cells joined across shared edges
/// and consecutive frames: `spatiotemporal_segmentation`, `Spatiotemporal_segmentation`.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/spatiotemporal/body_layout.h>
#include <deformseg/spatiotemporal/part_links.h>
#include <deformseg/strain/strain.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace deformseg::spatiotemporal {

/// @brief The options of `spatiotemporal_segmentation`, an aggregate for designated initializers.
///
/// The clean-up defaults keep the segments a body's parts make and drop the specks that noise in
/// the strain makes; chapter 5 of the manual gives what they change on the shared data.
struct Spatiotemporal_options {
  /// @brief The strain that labels cells: previous pose (default: deformed while it moves) or
  /// rest pose (deformed while it is away from its rest pose). Used by the overload that takes an
  /// animation.
  strain::Strain_reference reference = strain::Strain_reference::previous_pose;
  /// @brief The Gaussian normalisation's sigma of the strain that the overloads taking an
  /// animation compute. None (default): the 95th percentile of the animation's own strains, so
  /// that every animation has as many strained cells; a fixed sigma keeps strains comparable
  /// across animations (an idle's small strains stay below a walk's).
  std::optional<double> sigma{};
  /// @brief A cell is deformed when its strain is above this. Default: 0.5, for the Gaussian
  /// normalisation of `compute_strain` (a strain of about 1.2 sigma). Only the most strained
  /// cells pass it: the band of a bending tube closes into a ring (an evolving graph R-D-R) only
  /// under a low threshold (0.005 to 0.01), as linear blend skinning strains the bend's neutral
  /// axis about ten times less than its outside.
  double threshold = 0.5;
  /// @brief Segments whose largest slice (triangles in one frame) has fewer triangles are
  /// relabelled rigid. Default: 10.
  std::size_t min_triangles = 10;
  /// @brief Segments that last fewer frames are relabelled rigid, so that specks of deformation
  /// do not each start and end a key frame. Default: 6 (0.2 s at 30 frames per second), chosen
  /// leaving each body out (@ref chapter_05); the thesis' reconstruction had 2.
  std::size_t min_frames = 6;
  /// @brief A rigid island of a frame (connected rigid triangles) of at most this many
  /// triangles whose deformed neighbours all belong to one segment joins that segment. Without
  /// it, deformed regions are riddled with small rigid islands where the strain hovers near the
  /// threshold. Default: 30; 0 absorbs none.
  std::size_t max_island = 30;
  /// @brief Segments whose largest slice covers less than this share of the mesh's area are
  /// relabelled rigid. A segment's neighbours in space and time are all rigid cells (deformed
  /// neighbours would be the same segment), so this merges it into them. Default: 0 (none).
  double min_area = 0;
  /// @brief Hysteresis on the threshold, in [0, 1): a cell whose strain is above
  /// `threshold * (1 - hysteresis)` is deformed when it is joined (in space and time, through such
  /// cells) to a cell above `threshold`. Segments then keep their extent while their strain
  /// hovers near the threshold. Default: 0 (none: the threshold alone).
  double hysteresis = 0;
  /// @brief Which separate parts of the mesh are neighbours (`part_links`), for the overloads
  /// that take an animation. Default: `Part_link_options` (touching within 1 % of the diagonal,
  /// moving as one within 0.2 %); `{0, 0}` is the thesis' adjacency, shared edges only.
  Part_link_options parts{};
  /// @brief The threads of the segmentation, of the strain the overloads taking an animation
  /// compute and of `evolving_graph`'s frame graphs: 0 (default) for all the hardware's threads
  /// (`thread_count`), else 1 to `max_threads`. The result does not depend on it.
  int threads = 0;
};

/// @brief The spatio-temporal segments of an animation: for each triangle and frame, rigid or the
/// deformed segment it belongs to, and each segment's extent in time.
class Spatiotemporal_segmentation {
public:
  /// @brief The label of a rigid cell.
  static constexpr std::int32_t rigid = -1;

  /// @brief What a segment spans.
  struct Extent {
    std::size_t first_frame = 0;  ///< its first frame
    std::size_t last_frame = 0;   ///< its last frame
    std::size_t cells = 0;        ///< its (triangle, frame) cells
    std::size_t largest_slice = 0;  ///< its most triangles in one frame
  };

  /// @brief A segmentation from its labels (`faces x frames`, frame after frame: `rigid` or a
  /// segment id in [0, K), ids in order of first appearance), as `spatiotemporal_segmentation`
  /// makes it.
  /// @throws invalid_input when the sizes do not match or a label is out of range.
  /// @par Complexity O(F T).
  Spatiotemporal_segmentation(std::size_t faces, std::size_t frames, std::vector<std::int32_t> labels)
      : faces_(faces), frames_(frames), labels_(std::move(labels)) {
    if (labels_.size() != faces * frames)
      throw invalid_input("Spatiotemporal_segmentation: " + std::to_string(labels_.size()) + " labels for " +
                          std::to_string(faces) + " triangles x " + std::to_string(frames) + " frames");
    for (std::size_t t = 0; t < frames_; ++t)
      for (std::size_t f = 0; f < faces_; ++f) add_to_extent(label(f, t), t);
    for (std::size_t t = 0; t < frames_; ++t) count_slices(t);
  }

  /// @brief The number of triangles F.
  std::size_t num_faces() const noexcept { return faces_; }
  /// @brief The number of frames T.
  std::size_t num_frames() const noexcept { return frames_; }
  /// @brief The number of deformed segments K.
  std::size_t num_segments() const noexcept { return extents_.size(); }

  /// @brief The label of triangle `face` at frame `frame`: `rigid` or a segment id.
  /// @pre `face < num_faces()`, `frame < num_frames()` (unchecked).
  std::int32_t label(std::size_t face, std::size_t frame) const noexcept { return labels_[frame * faces_ + face]; }
  /// @brief The labels of every triangle at frame `t`.
  /// @throws invalid_input when `t >= num_frames()`.
  std::span<const std::int32_t> frame_labels(std::size_t t) const {
    if (t >= frames_)
      throw invalid_input("frame " + std::to_string(t) + " asked of a segmentation of " + std::to_string(frames_) +
                          " frames");
    return std::span<const std::int32_t>(labels_).subspan(t * faces_, faces_);
  }
  /// @brief What segment `k` spans.
  /// @pre `k < num_segments()` (unchecked).
  const Extent& extent(std::size_t k) const noexcept { return extents_[k]; }

private:
  void add_to_extent(std::int32_t k, std::size_t t) {
    if (k == rigid) return;
    if (k < 0 || std::size_t(k) > extents_.size())
      throw invalid_input("Spatiotemporal_segmentation: label " + std::to_string(k) + " at frame " +
                          std::to_string(t) + " is not rigid, an existing segment or the next one");
    if (std::size_t(k) == extents_.size()) extents_.push_back({t, t, 0, 0});
    Extent& e = extents_[std::size_t(k)];
    e.last_frame = t;
    ++e.cells;
  }

  void count_slices(std::size_t t) {
    std::vector<std::size_t> slice(extents_.size(), 0);
    for (std::int32_t k : frame_labels(t))
      if (k != rigid) ++slice[std::size_t(k)];
    for (std::size_t k = 0; k < extents_.size(); ++k)
      extents_[k].largest_slice = std::max(extents_[k].largest_slice, slice[k]);
  }

  std::size_t faces_ = 0;
  std::size_t frames_ = 0;
  std::vector<std::int32_t> labels_;
  std::vector<Extent> extents_;
};

namespace internal {

// Union-find over cell indices, the smaller root winning, so that the result is independent of
// the order of unions; path halving.
class Cell_union_find {
public:
  explicit Cell_union_find(std::size_t cells) : parent_(cells) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t c) {
    while (parent_[c] != c) c = parent_[c] = parent_[parent_[c]];
    return c;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a < b) parent_[b] = a;
    else if (b < a) parent_[a] = b;
  }

private:
  std::vector<std::uint32_t> parent_;
};

// Candidate cells joined across neighbouring triangles in a frame and across consecutive frames;
// the components with a strong cell are the segments, labelled in order of first appearance.
inline std::vector<std::int32_t> connected_cells(const std::vector<std::uint8_t>& candidate,
                                                 const std::vector<std::uint8_t>& strong, std::size_t faces,
                                                 std::size_t frames, const Body_layout& layout) {
  Cell_union_find sets(faces * frames);
  for (std::size_t t = 0; t < frames; ++t)
    for (std::size_t f = 0; f < faces; ++f) {
      const std::size_t cell = t * faces + f;
      if (!candidate[cell]) continue;
      for (std::uint32_t g : layout.neighbours(f))
        if (g < f && candidate[t * faces + g]) sets.unite(std::uint32_t(cell), std::uint32_t(t * faces + g));
      if (t > 0 && candidate[cell - faces]) sets.unite(std::uint32_t(cell), std::uint32_t(cell - faces));
    }
  std::vector<std::uint8_t> root_is_strong(faces * frames, 0);
  for (std::size_t cell = 0; cell < strong.size(); ++cell)
    if (strong[cell]) root_is_strong[sets.find(std::uint32_t(cell))] = 1;
  std::vector<std::int32_t> labels(faces * frames, Spatiotemporal_segmentation::rigid);
  std::vector<std::int32_t> id_of_root(faces * frames, Spatiotemporal_segmentation::rigid);
  std::int32_t next = 0;
  for (std::size_t cell = 0; cell < labels.size(); ++cell) {
    if (!candidate[cell]) continue;
    const std::uint32_t root = sets.find(std::uint32_t(cell));
    if (!root_is_strong[root]) continue;
    std::int32_t& id = id_of_root[root];
    if (id == Spatiotemporal_segmentation::rigid) id = next++;
    labels[cell] = id;
  }
  return labels;
}

// Segment ids in order of first appearance (an absorbed island may come before the first
// triangle of its segment in the same frame).
inline void renumber_by_first_appearance(std::vector<std::int32_t>& labels) {
  constexpr std::int32_t rigid = Spatiotemporal_segmentation::rigid;
  const std::int32_t count = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
  std::vector<std::int32_t> renumbered(std::size_t(count), rigid);
  std::int32_t next = 0;
  for (auto& k : labels)
    if (k != rigid) {
      if (renumbered[std::size_t(k)] == rigid) renumbered[std::size_t(k)] = next++;
      k = renumbered[std::size_t(k)];
    }
}

// The share of the area of each segment's largest slice.
inline std::vector<double> largest_slice_areas(const std::vector<std::int32_t>& labels, std::size_t segments,
                                               std::size_t faces, std::span<const double> area_shares) {
  std::vector<double> largest(segments, 0), slice(segments, 0);
  for (std::size_t cell = 0; cell < labels.size(); ++cell) {
    if (labels[cell] != Spatiotemporal_segmentation::rigid) slice[std::size_t(labels[cell])] += area_shares[cell % faces];
    if ((cell + 1) % faces == 0)
      for (std::size_t k = 0; k < segments; ++k) largest[k] = std::max(largest[k], slice[k]), slice[k] = 0;
  }
  return largest;
}

// Segments that are too small or short become rigid; the others are renumbered in order.
inline void remove_small_segments(std::vector<std::int32_t>& labels, std::size_t faces, std::size_t frames,
                                  std::span<const double> area_shares, const Spatiotemporal_options& options) {
  const Spatiotemporal_segmentation before(faces, frames, labels);
  const std::vector<double> area = options.min_area > 0
                                       ? largest_slice_areas(labels, before.num_segments(), faces, area_shares)
                                       : std::vector<double>(before.num_segments(), 0);
  std::vector<std::int32_t> renumbered(before.num_segments(), Spatiotemporal_segmentation::rigid);
  std::int32_t next = 0;
  for (std::size_t k = 0; k < before.num_segments(); ++k) {
    const auto& e = before.extent(k);
    if (e.largest_slice >= options.min_triangles && e.last_frame - e.first_frame + 1 >= options.min_frames &&
        area[k] >= options.min_area)
      renumbered[k] = next++;
  }
  for (auto& k : labels)
    if (k != Spatiotemporal_segmentation::rigid) k = renumbered[std::size_t(k)];
}

// In frame t, rigid islands of at most `max_island` triangles whose deformed neighbours all
// belong to one segment join it.
inline void absorb_islands(std::span<std::int32_t> labels, const Body_layout& layout, std::size_t max_island) {
  constexpr std::int32_t rigid = Spatiotemporal_segmentation::rigid;
  std::vector<std::uint8_t> seen(labels.size(), 0);
  std::vector<std::uint32_t> island;
  for (std::size_t start = 0; start < labels.size(); ++start) {
    if (labels[start] != rigid || seen[start]) continue;
    island.assign(1, std::uint32_t(start));
    seen[start] = 1;
    std::int32_t neighbour = rigid;
    bool one_neighbour = true;
    for (std::size_t i = 0; i < island.size(); ++i)
      for (std::uint32_t g : layout.neighbours(island[i])) {
        if (labels[g] == rigid) {
          if (!seen[g]) seen[g] = 1, island.push_back(g);
        } else if (neighbour == rigid || neighbour == labels[g]) {
          neighbour = labels[g];
        } else {
          one_neighbour = false;
        }
      }
    if (island.size() <= max_island && one_neighbour && neighbour != rigid)
      for (std::uint32_t f : island) labels[f] = neighbour;
  }
}

}  // namespace internal

/// @brief The spatio-temporal segments of a strain field: cells whose strain is above
/// `options.threshold` are deformed, and deformed cells are joined when their triangles are
/// neighbours in `layout` in the same frame or are the same triangle in consecutive frames; then
/// small segments are removed and small rigid islands absorbed, as `options` says.
/// @param field the strain field (`F x T`), typically normalised previous-pose strain.
/// @param layout the neighbours and area shares of the field's triangles (`body_layout`).
/// @param options threshold, hysteresis and clean-up (`reference` and `parts` are not used here).
/// @return the labels, segments numbered in order of first appearance (frame, then triangle).
/// @throws invalid_input when `layout` and the field have different triangle counts, the
/// threshold is not finite, `min_area` not in [0, 1], `hysteresis` not in [0, 1) or `threads` out
/// of range.
/// @par Complexity O(F T alpha(F T)) time for the union-find over the layout's neighbours, the
/// islands' absorption frames on `options.threads` threads (the result does not depend on them); memory 15
/// bytes per cell (labels, union-find, segment ids, flags), besides the layout.
template <std::floating_point Value>
Spatiotemporal_segmentation spatiotemporal_segmentation(const strain::Strain_field<Value>& field,
                                                        const Body_layout& layout,
                                                        const Spatiotemporal_options& options = {}) {
  const std::size_t faces = field.num_faces(), frames = field.num_frames();
  if (layout.num_faces() != faces)
    throw invalid_input("spatiotemporal_segmentation: " + std::to_string(layout.num_faces()) +
                        " triangles for a strain field of " + std::to_string(faces));
  if (!std::isfinite(options.threshold))
    throw invalid_input("spatiotemporal_segmentation: the threshold must be finite");
  if (!(options.min_area >= 0 && options.min_area <= 1))
    throw invalid_input("spatiotemporal_segmentation: the minimum area share must be in [0, 1]");
  if (!(options.hysteresis >= 0 && options.hysteresis < 1))
    throw invalid_input("spatiotemporal_segmentation: the hysteresis must be in [0, 1)");
  thread_count(options.threads, "spatiotemporal_segmentation");
  const double low = options.threshold * (1 - options.hysteresis);
  std::vector<std::uint8_t> strong(faces * frames), candidate(faces * frames);
  for (std::size_t i = 0; i < strong.size(); ++i) {
    strong[i] = double(field.values()[i]) > options.threshold;
    candidate[i] = strong[i] || double(field.values()[i]) > low;
  }
  std::vector<std::int32_t> labels = internal::connected_cells(candidate, strong, faces, frames, layout);
  internal::remove_small_segments(labels, faces, frames, layout.area_shares(), options);
  if (options.max_island > 0) {
    deformseg::internal::parallel_for(frames, options.threads, [&](std::size_t t) {  // frames apart: each its own labels
      internal::absorb_islands(std::span<std::int32_t>(labels).subspan(t * faces, faces), layout, options.max_island);
    });
    internal::renumber_by_first_appearance(labels);
  }
  return Spatiotemporal_segmentation(faces, frames, std::move(labels));
}

/// @brief The spatio-temporal segments of a strain field over the thesis' adjacency: as the
/// overload that takes a `Body_layout`, with `Body_layout(triangles)` (shared edges, every
/// triangle weighing the same for `min_area`).
/// @param field the strain field (`F x T`).
/// @param triangles the face-vertex index table of the field's triangles (for a
/// `Deforming_mesh`, `triangles()`).
/// @param options as for the other overload.
/// @throws invalid_input as the other overload.
/// @par Complexity O(F log F) for the adjacency, then as the other overload.
template <std::floating_point Value>
Spatiotemporal_segmentation spatiotemporal_segmentation(const strain::Strain_field<Value>& field,
                                                        std::span<const std::array<std::uint32_t, 3>> triangles,
                                                        const Spatiotemporal_options& options = {}) {
  if (triangles.size() != field.num_faces())
    throw invalid_input("spatiotemporal_segmentation: " + std::to_string(triangles.size()) +
                        " triangles for a strain field of " + std::to_string(field.num_faces()));
  return spatiotemporal_segmentation(field, Body_layout(triangles), options);
}

/// @brief The strain options of a segmentation's `reference`, `sigma` and `threads` (`compute_strain`'s
/// defaults otherwise).
/// @par Complexity O(1).
inline strain::Strain_options strain_options(const Spatiotemporal_options& options) {
  return {.reference = options.reference,
          .normalization = strain::Gaussian_normalization{.sigma = options.sigma},
          .threads = options.threads};
}

/// @brief The spatio-temporal segments of an animation: its normalised strain against
/// `options.reference`, with `options.sigma` (`strain_options`) over its `body_layout` with
/// `options.parts`, then as the overload for a strain field and a layout.
/// @tparam Mesh a `DeformingMesh`; a `Deforming_mesh` is read in place, any other model is first
/// copied once with `make_deforming_mesh`, which the strain and `body_layout` then share, where each
/// would copy it: O(T V) time and 3 T V doubles.
/// @throws invalid_input as `compute_strain`, `body_layout` and the other overloads.
/// @par Complexity O(F T) for the strain, `part_links`' cost, then as the other overloads.
template <mesh::DeformingMesh Mesh>
Spatiotemporal_segmentation spatiotemporal_segmentation(const Mesh& animation,
                                                        const Spatiotemporal_options& options = {}) {
  if constexpr (mesh::is_deforming_mesh_v<Mesh>) {
    const auto field = strain::compute_strain(animation, strain_options(options));
    return spatiotemporal_segmentation(field, body_layout(animation, options.parts), options);
  } else {
    return spatiotemporal_segmentation(mesh::make_deforming_mesh(animation), options);
  }
}

}  // namespace deformseg::spatiotemporal

#if DEFORMSEG_COMPILED
// deformseg::compiled holds these instantiations (src/compiled/spatiotemporal.cpp): a program that
// links it compiles against their declarations. Any other type instantiates where it is used.
#include <deformseg/mesh/default_mesh.h>

namespace deformseg::spatiotemporal {
extern template Spatiotemporal_segmentation spatiotemporal_segmentation<float>(const strain::Strain_field<float>&,
                                                                              const Body_layout&,
                                                                              const Spatiotemporal_options&);
extern template Spatiotemporal_segmentation spatiotemporal_segmentation<mesh::Surface_mesh_animation>(
    const mesh::Surface_mesh_animation&, const Spatiotemporal_options&);
}  // namespace deformseg::spatiotemporal
#endif
