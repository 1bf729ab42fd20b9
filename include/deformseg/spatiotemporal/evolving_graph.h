/// @file spatiotemporal/evolving_graph.h
/// @brief The evolving graph of a deforming mesh (@ref method_spatiotemporal): consecutive frames
/// with the same segment graph form a key frame: `evolving_graph`, `Evolving_graph`, `Key_frame`.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/spatiotemporal/body_layout.h>
#include <deformseg/spatiotemporal/frame_segments.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::spatiotemporal {

/// @brief A key frame: an interval of frames with one segment graph.
struct Key_frame {
  std::size_t first_frame = 0;  ///< its first frame
  std::size_t last_frame = 0;   ///< its last frame (inclusive)
  /// @brief The graph its frames share, nodes in the canonical order of `Frame_segments`; node
  /// attributes (`triangles`, `area`) are means over its frames.
  Segment_graph graph;
  /// @brief The number of frames it lasts.
  std::size_t num_frames() const noexcept { return last_frame - first_frame + 1; }
};

/// @brief The evolving graph of an animation: its key frames in time order, which cover frames
/// 0..T-1 exactly once. A sequence of `Key_frame`s (iterate it, index it); each key frame's
/// `graph` is a `boost::adjacency_list`, so it models Boost.Graph's VertexListGraph, EdgeListGraph,
/// AdjacencyGraph and IncidenceGraph.
class Evolving_graph {
public:
  /// @brief The iterator over key frames.
  using const_iterator = std::vector<Key_frame>::const_iterator;
  /// @brief A key frame.
  using value_type = Key_frame;

  /// @brief An evolving graph of `frames` frames and `segments` spatio-temporal segments from its
  /// key frames.
  /// @throws invalid_input unless the key frames cover 0..frames-1 in order, each once.
  Evolving_graph(std::size_t frames, std::size_t segments, std::vector<Key_frame> key_frames)
      : frames_(frames), segments_(segments), key_frames_(std::move(key_frames)) {
    std::size_t next = 0;
    for (const Key_frame& k : key_frames_) {
      if (k.first_frame != next || k.last_frame < k.first_frame)
        throw invalid_input("Evolving_graph: a key frame spans frames " + std::to_string(k.first_frame) + "-" +
                            std::to_string(k.last_frame) + " where frame " + std::to_string(next) + " comes next");
      next = k.last_frame + 1;
    }
    if (next != frames)
      throw invalid_input("Evolving_graph: the key frames cover " + std::to_string(next) + " of " +
                          std::to_string(frames) + " frames");
  }

  /// @brief The number of key frames.
  std::size_t size() const noexcept { return key_frames_.size(); }
  /// @brief True when there is no key frame (an animation of no frame).
  bool empty() const noexcept { return key_frames_.empty(); }
  /// @brief Key frame `i`. @pre `i < size()` (unchecked).
  const Key_frame& operator[](std::size_t i) const noexcept { return key_frames_[i]; }
  /// @brief The first key frame.
  const_iterator begin() const noexcept { return key_frames_.begin(); }
  /// @brief Past the last key frame.
  const_iterator end() const noexcept { return key_frames_.end(); }
  /// @brief The number of frames T.
  std::size_t num_frames() const noexcept { return frames_; }
  /// @brief The number of spatio-temporal segments K (deformed node ids are in [0, K)).
  std::size_t num_segments() const noexcept { return segments_; }

  /// @brief The index of the key frame that holds frame `t`.
  /// @throws invalid_input when `t >= num_frames()`.
  /// @par Complexity O(log size()).
  std::size_t key_frame_of(std::size_t t) const {
    if (t >= frames_)
      throw invalid_input("frame " + std::to_string(t) + " asked of an evolving graph of " + std::to_string(frames_) +
                          " frames");
    const auto after = std::upper_bound(key_frames_.begin(), key_frames_.end(), t,
                                        [](std::size_t frame, const Key_frame& k) { return frame < k.first_frame; });
    return std::size_t(after - key_frames_.begin()) - 1;
  }

private:
  std::size_t frames_ = 0;
  std::size_t segments_ = 0;
  std::vector<Key_frame> key_frames_;
};

namespace internal {

// A key frame of the frames [first, last], which all have the shape of frames[first]; its
// attributes are the means over them.
inline Key_frame averaged_key_frame(const std::vector<Frame_graph>& frames, std::size_t first, std::size_t last) {
  Frame_graph mean = frames[first];
  for (std::size_t t = first + 1; t <= last; ++t)
    for (std::size_t v = 0; v < mean.nodes.size(); ++v) {
      mean.triangles[v] += frames[t].triangles[v];
      mean.area[v] += frames[t].area[v];
    }
  const double count = double(last - first + 1);
  for (std::size_t v = 0; v < mean.nodes.size(); ++v) {
    mean.triangles[v] = std::size_t(std::llround(double(mean.triangles[v]) / count));
    mean.area[v] /= count;
  }
  return {first, last, Frame_segments_access::to_graph(mean)};
}

}  // namespace internal

/// @brief The evolving graph of a spatio-temporal segmentation: each frame's segment graph
/// (`Frame_segments`), consecutive frames with the same graph joined into one key frame.
///
/// Two consecutive frames have the same graph when they have the same nodes (deformed ones by
/// segment id, rigid ones by the segments they touch, with their multiplicity) and the same
/// edges: exactly what the canonical order of `Frame_segments` makes comparable.
/// @param frames the frames of a segmentation, as `Frame_segments` gives them.
/// @param threads the threads of the frames' graphs: 0 (default) for all the hardware's threads
/// (`thread_count`), else 1 to `max_threads`.
/// @return the key frames, in time order.
/// @throws invalid_input when `threads` is out of range.
/// @par Complexity O(T (F + E)) for T frames of F triangles and E shared edges, frames on
/// `threads` threads; the result does not depend on their number. Memory O(F) per thread besides
/// the frames' (small) graphs.
inline Evolving_graph evolving_graph(const Frame_segments& frames, int threads = 0) {
  const std::size_t count = frames.num_frames();
  std::vector<internal::Frame_graph> graphs(count);
  deformseg::internal::parallel_for(count, threads, [&](std::size_t t) {
    graphs[t] = internal::Frame_segments_access::frame_graph(frames, t);
  });
  std::vector<Key_frame> key_frames;
  for (std::size_t first = 0; first < count;) {
    std::size_t last = first;
    while (last + 1 < count && graphs[last + 1].same_shape(graphs[first])) ++last;
    key_frames.push_back(internal::averaged_key_frame(graphs, first, last));
    first = last + 1;
  }
  return Evolving_graph(count, frames.segmentation().num_segments(), std::move(key_frames));
}

/// @brief The evolving graph of an animation: its spatio-temporal segmentation
/// (`spatiotemporal_segmentation` with `options`, the strain with `strain_options(options)`) over
/// its `body_layout` (with `options.parts`, area shares from the triangles' areas in frame 0), then
/// the overload for `Frame_segments`.
/// @tparam Mesh a `DeformingMesh`; a `Deforming_mesh` is read in place, any other model is first
/// copied once with `make_deforming_mesh`, which the strain and `body_layout` then share, where each
/// would copy it: O(T V) time and 3 T V doubles.
/// @throws invalid_input as `compute_strain`, `body_layout` and `spatiotemporal_segmentation`.
/// @par Complexity O(T F) besides the strain and `part_links`.
template <mesh::DeformingMesh Mesh>
Evolving_graph evolving_graph(const Mesh& animation, const Spatiotemporal_options& options = {}) {
  if constexpr (mesh::is_deforming_mesh_v<Mesh>) {
    const auto field = strain::compute_strain(animation, strain_options(options));
    Body_layout layout = body_layout(animation, options.parts);
    const Spatiotemporal_segmentation segmentation = spatiotemporal_segmentation(field, layout, options);
    return evolving_graph(Frame_segments(segmentation, std::move(layout)), options.threads);
  } else {
    return evolving_graph(mesh::make_deforming_mesh(animation), options);
  }
}

}  // namespace deformseg::spatiotemporal

#if DEFORMSEG_COMPILED
// deformseg::compiled holds this instantiation (src/compiled/spatiotemporal.cpp): a program that
// links it compiles against its declaration. Any other type instantiates where it is used.
#include <deformseg/mesh/default_mesh.h>

namespace deformseg::spatiotemporal {
extern template Evolving_graph evolving_graph<mesh::Surface_mesh_animation>(const mesh::Surface_mesh_animation&,
                                                                           const Spatiotemporal_options&);
}  // namespace deformseg::spatiotemporal
#endif
