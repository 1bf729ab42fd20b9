/// @file mesh/deforming_mesh.h
/// @brief The default model `Deforming_mesh` of the `DeformingMesh` concept (mesh/concepts.h),
/// and `make_deforming_mesh`, which copies any model into one.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/mesh/concepts.h>
#include <deformseg/mesh/coordinate_buffer.h>
#include <deformseg/mesh/make_face_graph.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::mesh {

/// @brief The frame rate of an animation that does not say its own: 30 frames per second.
inline constexpr double default_frames_per_second = 30;

/// @brief The one check of a frame rate given to deformseg (an animation's, a reader's option, a
/// signature's): it must be positive and finite.
/// @param fps the frame rate, in frames per second.
/// @param where what takes it, put before the message (e.g. "motion_signatures"); may be empty.
/// @param location the file it applies to, if any.
/// @throws invalid_input otherwise, e.g. "fps must be positive and finite (the frame rate, in
/// frames per second), not 0.000000".
/// @par Example
/// @include check_frames_per_second.cpp
inline void check_frames_per_second(double fps, const std::string& where = {}, const Input_location& location = {}) {
  if (!(fps > 0) || !std::isfinite(fps))
    throw invalid_input((where.empty() ? "" : where + ": ") +
                            "fps must be positive and finite (the frame rate, in frames per second), not " +
                            std::to_string(fps),
                        location);
}

/// @brief The default model of `DeformingMesh`: the connectivity of a `FaceGraph` and the vertex
/// positions of every frame, stored contiguously.
///
/// Positions are one block of `3 x V` coordinates per frame (x, y, z of vertex 0, then vertex 1,
/// ...), frames one after the other, so that kernels stream through memory. Vertex `i` is the
/// vertex whose index is `i` in the graph's initialized vertex index map (for a `Surface_mesh`
/// without removed elements, and for a `Polyhedron_3` built in order, the `i`-th vertex of
/// `vertices(g)`); face `j` likewise.
///
/// Copies share the connectivity, which never changes once built, and copy the positions.
///
/// The animation carries its frame rate (`frames_per_second`, default 30), which the readers set
/// and descriptors that measure time in seconds read (`motion_signatures`).
///
/// @tparam Graph a `FaceGraph` whose faces are all triangles. Its vertex and face indices are its
/// internal index maps, or, for a graph without them, the order of `vertices(g)` and `faces(g)`.
/// @tparam Coordinate the stored coordinate type: `double` (default, exact for any input) or
/// `float` (half the memory; about 7 significant digits).
template <FaceGraph Graph, std::floating_point Coordinate = double>
class Deforming_mesh {
public:
  using Face_graph = Graph;                      ///< the connectivity type
  using coordinate_type = Coordinate;            ///< the stored coordinate type
  /// @brief The graph's vertex descriptor.
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;
  /// @brief The graph's face descriptor.
  using face_descriptor = typename boost::graph_traits<Graph>::face_descriptor;
  /// @brief The point type the frame point maps give: the value type of the graph's vertex point
  /// map, or `CGAL::Simple_cartesian<double>::Point_3` for a graph without one.
  using Point_3 = typename internal::Graph_point<Graph>::type;
  /// @brief A triangle as the indices of its three vertices, counter-clockwise seen from outside.
  using Triangle = std::array<std::uint32_t, 3>;
  /// @brief A map from vertex descriptors to their indices in `[0, num_vertices())`.
  using Vertex_index_map = typename CGAL::GetInitializedVertexIndexMap<Graph>::type;
  /// @brief A map from face descriptors to their indices in `[0, num_faces())`.
  using Face_index_map = typename CGAL::GetInitializedFaceIndexMap<Graph>::type;
  /// @brief The positions of all vertices at one frame, as a `3 x V` column-major matrix.
  using Frame_matrix = Eigen::Map<const Eigen::Matrix<Coordinate, 3, Eigen::Dynamic>>;

  /// @brief The readable property map of one frame: vertex descriptor to `Point_3`.
  /// Valid while the `Deforming_mesh` it came from lives and gains no frame.
  class Frame_point_map {
  public:
    using key_type = vertex_descriptor;             ///< Boost property map key
    using value_type = Point_3;                     ///< Boost property map value
    using reference = Point_3;                      ///< returned by value
    using category = boost::readable_property_map_tag;  ///< read only

    /// @brief The position of `v` at this map's frame.
    friend Point_3 get(const Frame_point_map& map, vertex_descriptor v) {
      const Coordinate* p = map.xyz_ + 3 * std::size_t(get(map.index_, v));
      return Point_3(p[0], p[1], p[2]);
    }

  private:
    friend class Deforming_mesh;
    Frame_point_map(const Coordinate* xyz, Vertex_index_map index) : xyz_(xyz), index_(index) {}
    const Coordinate* xyz_;
    Vertex_index_map index_;
  };

  /// @brief An animation with the connectivity of `connectivity` and no frame yet.
  /// @pre every face of `connectivity` is a triangle, and the graph has no removed elements;
  /// otherwise throws `invalid_input`.
  /// @par Complexity O(V + F).
  explicit Deforming_mesh(Graph connectivity)
      : topology_(std::make_shared<const Topology>(std::move(connectivity))) {}

  /// @brief An animation with the connectivity of `connectivity` and the frames in `positions`:
  /// `3 V` coordinates per frame, frames one after the other. They become the animation's, not
  /// copied.
  /// @pre `positions.size()` is a multiple of `3 V`, and every coordinate is finite; otherwise
  /// throws `invalid_input` naming the frame and the vertex.
  /// @par Complexity O(V + F + T V).
  Deforming_mesh(Graph connectivity, Coordinate_buffer<Coordinate> positions)
      : Deforming_mesh(std::move(connectivity)) {
    check_positions(positions);
    positions_ = std::move(positions);
  }

  /// @brief As the constructor from a `Coordinate_buffer`, the positions copied once into one.
  /// @par Complexity O(V + F + T V).
  Deforming_mesh(Graph connectivity, const std::vector<Coordinate>& positions)
      : Deforming_mesh(std::move(connectivity)) {
    check_positions(positions);
    positions_.assign(positions.begin(), positions.end());
  }

  /// @brief Appends a frame: `3 V` coordinates, x, y, z of each vertex in index order.
  /// @pre `xyz.size() == 3 V` and every coordinate is finite; otherwise throws `invalid_input`.
  /// @par Complexity O(V) amortised.
  template <class T>
  void add_frame(std::span<const T> xyz) {
    if (xyz.size() != 3 * num_vertices())
      throw invalid_input("frame has " + std::to_string(xyz.size() / 3) + " vertices, the mesh " +
                              std::to_string(num_vertices()),
                          {.frame = num_frames()});
    check_finite(xyz, num_frames());
    positions_.insert(positions_.end(), xyz.begin(), xyz.end());
  }

  /// @brief Appends a frame taken from a vertex point map of the connectivity graph (for instance
  /// the graph's own `get(CGAL::vertex_point, g)`).
  /// @pre every coordinate is finite; otherwise throws `invalid_input`.
  /// @par Complexity O(V) amortised.
  template <ReadablePointMap<vertex_descriptor> VertexPointMap>
  void add_frame_from(const VertexPointMap& points) {
    add_frame_from(points, vertex_descriptors());
  }

  /// @brief Appends a frame taken from a point map of another mesh with the same vertices:
  /// vertex `i` is at `get(points, keys[i])`.
  /// @pre `keys.size() == V` and every coordinate is finite; otherwise throws `invalid_input`.
  /// @par Complexity O(V) amortised.
  template <class Key, ReadablePointMap<Key> PointMap>
  void add_frame_from(const PointMap& points, std::span<const Key> keys) {
    std::vector<Coordinate> xyz(3 * keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const auto& p = get(points, keys[i]);
      for (int k = 0; k < 3; ++k) xyz[3 * i + k] = static_cast<Coordinate>(CGAL::to_double(p[k]));
    }
    add_frame(std::span<const Coordinate>(xyz));
  }

  /// @brief The frames `first` to `last` (inclusive) as an animation of their own: the same
  /// connectivity (shared, not copied), those frames' positions and this frame rate.
  /// @pre `first <= last < num_frames()`; otherwise throws `invalid_input`.
  /// @par Complexity O((last - first + 1) V).
  Deforming_mesh frames(std::size_t first, std::size_t last) const {
    if (first > last) throw invalid_input("frames " + std::to_string(first) + " to " + std::to_string(last) +
                                          ": the first is after the last");
    check_frame(last);
    Deforming_mesh window(topology_, frames_per_second_);
    const std::size_t block = 3 * num_vertices();
    window.positions_.assign(positions_.begin() + std::ptrdiff_t(first * block),
                             positions_.begin() + std::ptrdiff_t((last + 1) * block));
    return window;
  }

  /// @brief The frame rate, in frames per second. Default 30.
  double frames_per_second() const noexcept { return frames_per_second_; }
  /// @brief Sets the frame rate, in frames per second.
  /// @pre `fps` is finite and positive; otherwise throws `invalid_input`.
  void set_frames_per_second(double fps) {
    check_frames_per_second(fps);
    frames_per_second_ = fps;
  }

  /// @brief Reserves storage for `frames` frames in all, so that adding them does not reallocate.
  void reserve_frames(std::size_t frames) { positions_.reserve(frames * 3 * num_vertices()); }

  /// @brief The connectivity.
  const Graph& face_graph() const noexcept { return topology_->graph; }
  /// @brief The number of frames T.
  std::size_t num_frames() const noexcept {
    return num_vertices() == 0 ? 0 : positions_.size() / (3 * num_vertices());
  }
  /// @brief The number of vertices V.
  std::size_t num_vertices() const noexcept { return topology_->vertex_of_index.size(); }
  /// @brief The number of triangles F.
  std::size_t num_faces() const noexcept { return topology_->triangles.size(); }

  /// @brief The face-vertex index table: triangle `j` as the indices of its vertices, in the order
  /// of the face's halfedge cycle. Kernels read this instead of walking the graph.
  std::span<const Triangle> triangles() const noexcept { return topology_->triangles; }
  /// @brief The vertex descriptor of each vertex index.
  std::span<const vertex_descriptor> vertex_descriptors() const noexcept { return topology_->vertex_of_index; }
  /// @brief The face descriptor of each face index.
  std::span<const face_descriptor> face_descriptors() const noexcept { return topology_->face_of_index; }
  /// @brief Vertex descriptor to vertex index.
  Vertex_index_map vertex_index_map() const { return topology_->vertex_index; }
  /// @brief Face descriptor to face index, for writing per-face results into a face property map.
  Face_index_map face_index_map() const { return topology_->face_index; }

  /// @brief The `3 V` coordinates of frame `t`.
  /// @pre `t < num_frames()`; otherwise throws `invalid_input`.
  std::span<const Coordinate> frame_positions(std::size_t t) const {
    check_frame(t);
    return std::span(positions_).subspan(t * 3 * num_vertices(), 3 * num_vertices());
  }
  /// @brief Frame `t` as a `3 x V` Eigen matrix, without copy.
  /// @pre `t < num_frames()`; otherwise throws `invalid_input`.
  Frame_matrix frame_matrix(std::size_t t) const {
    return Frame_matrix(frame_positions(t).data(), 3, Eigen::Index(num_vertices()));
  }
  /// @brief The coordinates of all frames, `3 V T` values.
  std::span<const Coordinate> all_positions() const noexcept { return positions_; }
  /// @brief The vertex point map of frame `t`.
  /// @pre `t < num_frames()`; otherwise throws `invalid_input`.
  Frame_point_map frame_point_map(std::size_t t) const {
    return Frame_point_map(frame_positions(t).data(), topology_->vertex_index);
  }

  /// @brief The memory held by the positions and the index tables, in bytes (the graph not
  /// counted, as its layout is its own).
  std::size_t memory_bytes() const noexcept {
    return positions_.capacity() * sizeof(Coordinate) + num_faces() * sizeof(Triangle) +
           num_vertices() * sizeof(vertex_descriptor) + num_faces() * sizeof(face_descriptor);
  }

private:
  // Connectivity and the tables derived from it. Held behind a shared pointer so that it never
  // moves: CGAL's index maps for some graphs (Polyhedron_3) hold pointers into the graph.
  struct Topology {
    explicit Topology(Graph g)
        : graph(std::move(g)),
          vertex_index(CGAL::get_initialized_vertex_index_map(graph)),
          face_index(CGAL::get_initialized_face_index_map(graph)) {
      vertex_of_index = ordered<vertex_descriptor>(vertices(graph), vertex_index, "vertex");
      face_of_index = ordered<face_descriptor>(faces(graph), face_index, "face");
      triangles.reserve(face_of_index.size());
      for (std::size_t j = 0; j < face_of_index.size(); ++j) triangles.push_back(triangle(j));
    }

    // The descriptors of a range sorted by their index, checking that the indices are 0..n-1. The
    // descriptor type is the graph traits', not the range's: OpenMesh's ranges give smart handles.
    template <class Descriptor, class Range, class IndexMap>
    static std::vector<Descriptor> ordered(const Range& range, const IndexMap& index, const char* what) {
      const auto n = static_cast<std::size_t>(std::distance(range.begin(), range.end()));
      std::vector<Descriptor> by_index(n);
      std::vector<bool> seen(n, false);
      for (auto d : range) {
        const std::size_t i = get(index, d);
        if (i >= n || seen[i])
          throw invalid_input(std::string("the connectivity's ") + what +
                              " indices are not 0..n-1 (a Surface_mesh with removed elements "
                              "needs collect_garbage())");
        seen[i] = true;
        by_index[i] = d;
      }
      return by_index;
    }

    Triangle triangle(std::size_t j) {
      Triangle tri{};
      std::size_t k = 0;
      const face_descriptor f = face_of_index[j];
      for (auto v : CGAL::vertices_around_face(halfedge(f, graph), graph)) {
        if (k == 3) break;
        tri[k++] = static_cast<std::uint32_t>(get(vertex_index, v));
      }
      if (k != 3 || next(next(next(halfedge(f, graph), graph), graph), graph) != halfedge(f, graph))
        throw invalid_input("face " + std::to_string(j) + " has " +
                            std::to_string(CGAL::vertices_around_face(halfedge(f, graph), graph).size()) +
                            " vertices; deformseg needs triangles");
      return tri;
    }

    Graph graph;
    Vertex_index_map vertex_index;
    Face_index_map face_index;
    std::vector<vertex_descriptor> vertex_of_index;
    std::vector<face_descriptor> face_of_index;
    std::vector<Triangle> triangles;
  };

  template <class T>
  static void check_finite(std::span<const T> xyz, std::size_t frame) {
    for (std::size_t i = 0; i < xyz.size(); ++i)
      if (!std::isfinite(xyz[i]))
        throw invalid_input("vertex " + std::to_string(i / 3) + " has a non-finite coordinate",
                            {.frame = frame});
  }

  void check_positions(std::span<const Coordinate> positions) const {
    const std::size_t block = 3 * num_vertices();
    if (block == 0 ? !positions.empty() : positions.size() % block != 0)
      throw invalid_input("expected a multiple of 3 x " + std::to_string(num_vertices()) +
                          " coordinates, got " + std::to_string(positions.size()));
    for (std::size_t t = 0; block != 0 && t < positions.size() / block; ++t)
      check_finite(positions.subspan(t * block, block), t);
  }

  void check_frame(std::size_t t) const {
    if (t >= num_frames())
      throw invalid_input("frame " + std::to_string(t) + " asked of an animation of " +
                          std::to_string(num_frames()) + " frames");
  }

  // An animation on the connectivity of another, without frames.
  Deforming_mesh(std::shared_ptr<const Topology> topology, double fps)
      : topology_(std::move(topology)), frames_per_second_(fps) {}

  std::shared_ptr<const Topology> topology_;
  Coordinate_buffer<Coordinate> positions_;
  double frames_per_second_ = default_frames_per_second;
};

/// @brief Whether `Mesh` is a `Deforming_mesh`, whose stored positions the algorithms read as
/// contiguous arrays rather than through a FaceGraph's point maps. False for any other type.
/// @par Example
/// @include is_deforming_mesh_v.cpp
template <class Mesh>
inline constexpr bool is_deforming_mesh_v = false;
/// @brief True: `Deforming_mesh<Graph, Coordinate>` is a `Deforming_mesh`.
template <class Graph, class Coordinate>
inline constexpr bool is_deforming_mesh_v<Deforming_mesh<Graph, Coordinate>> = true;

/// @brief The frame rate of `animation`: its `frames_per_second()` when its type has one (as
/// `Deforming_mesh`), else `default_frames_per_second` (30).
/// @par Complexity O(1).
template <DeformingMesh M>
double frames_per_second(const M& animation) {
  if constexpr (requires { { animation.frames_per_second() } -> std::convertible_to<double>; })
    return animation.frames_per_second();
  else
    return default_frames_per_second;
}

/// @brief A `Deforming_mesh` copy of any model of `DeformingMesh`, for algorithms that want
/// contiguous positions.
///
/// The copy's connectivity is a copy of `animation.face_graph()`; its vertices correspond to the
/// original's in the order of `vertices(g)`, which copying a `FaceGraph` keeps. Its frame rate is
/// the original's (`frames_per_second`).
/// @par Complexity O(T V).
template <std::floating_point Coordinate = double, DeformingMesh M>
Deforming_mesh<typename M::Face_graph, Coordinate> make_deforming_mesh(const M& animation) {
  using Graph = typename M::Face_graph;
  Deforming_mesh<Graph, Coordinate> copy(animation.face_graph());
  // The original's vertex descriptors, by the copy's vertex index.
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;
  std::vector<vertex_descriptor> original(copy.num_vertices());
  auto copied = vertices(copy.face_graph()).begin();
  for (auto v : vertices(animation.face_graph()))
    original[get(copy.vertex_index_map(), *copied++)] = v;

  copy.set_frames_per_second(frames_per_second(animation));
  copy.reserve_frames(animation.num_frames());
  for (std::size_t t = 0; t < animation.num_frames(); ++t)
    copy.add_frame_from(animation.frame_point_map(t), std::span<const vertex_descriptor>(original));
  return copy;
}

}  // namespace deformseg::mesh
