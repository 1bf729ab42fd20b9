/// @file mesh/concepts.h
/// @brief The concepts of the mesh module: `FaceGraph`, `DeformingMesh` and the property maps they
/// use, each stating exactly what the algorithms use of a model.
#pragma once

#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <concepts>
#include <cstddef>
#include <functional>

namespace deformseg::mesh {

/// @brief Descriptors of a graph that index maps can be made for: the graph has an internal index
/// property map for them (`IndexTag`: `boost::vertex_index_t` or `boost::face_index_t`), or they
/// are equality comparable and hashable, so that CGAL's dynamic property map numbers them in the
/// order of their range (`CGAL::get_initialized_vertex_index_map`).
template <class G, class Descriptor, class IndexTag>
concept Indexable_descriptor =
    CGAL::graph_has_property<G, IndexTag>::value ||
    (std::equality_comparable<Descriptor> && requires(const Descriptor& d) {
      { std::hash<Descriptor>{}(d) } -> std::convertible_to<std::size_t>;
    });

/// @brief A graph with faces in the sense of CGAL's BGL extension (`CGAL::Surface_mesh`,
/// `CGAL::Polyhedron_3`, OpenMesh, ...), with exactly what deformseg's algorithms use of it.
///
/// For `const G& g`, `f` a face descriptor and `h` a halfedge descriptor:
/// - `boost::graph_traits<G>` gives `vertex_descriptor`, `halfedge_descriptor`, `face_descriptor`
///   (default-constructible and copyable: `std::semiregular`), `vertices_size_type` and
///   `faces_size_type`;
/// - `vertices(g)` and `faces(g)` are ranges (members `begin()`, `end()`) of the descriptors, and
///   `num_vertices(g)`, `num_faces(g)` their sizes;
/// - `halfedge(f, g)`, `next(h, g)` and `target(h, g)` walk a face's corners;
/// - vertex and face descriptors are `Indexable_descriptor`s (an internal index map, or hashable);
/// - `G` is copy-constructible, and a copy lists its vertices in the original's order.
///
/// No point map is required: the positions come from the animation (`DeformingMesh`), and an entry
/// point that reads a graph's points takes them as a `vertex_point_map` named parameter, whose
/// default, the graph's own point map, is then required of the graph.
template <class G>
concept FaceGraph =
    std::copy_constructible<G> && std::semiregular<typename boost::graph_traits<G>::vertex_descriptor> &&
    std::semiregular<typename boost::graph_traits<G>::halfedge_descriptor> &&
    std::semiregular<typename boost::graph_traits<G>::face_descriptor> &&
    requires(const G& g, typename boost::graph_traits<G>::face_descriptor f,
             typename boost::graph_traits<G>::halfedge_descriptor h) {
      typename boost::graph_traits<G>::vertex_descriptor;
      typename boost::graph_traits<G>::vertices_size_type;
      typename boost::graph_traits<G>::faces_size_type;
      { *vertices(g).begin() } -> std::convertible_to<typename boost::graph_traits<G>::vertex_descriptor>;
      vertices(g).end();
      { *faces(g).begin() } -> std::convertible_to<typename boost::graph_traits<G>::face_descriptor>;
      faces(g).end();
      { num_vertices(g) } -> std::convertible_to<std::size_t>;
      { num_faces(g) } -> std::convertible_to<std::size_t>;
      { halfedge(f, g) } -> std::convertible_to<typename boost::graph_traits<G>::halfedge_descriptor>;
      { next(h, g) } -> std::convertible_to<typename boost::graph_traits<G>::halfedge_descriptor>;
      { target(h, g) } -> std::convertible_to<typename boost::graph_traits<G>::vertex_descriptor>;
    } &&
    Indexable_descriptor<G, typename boost::graph_traits<G>::vertex_descriptor, boost::vertex_index_t> &&
    Indexable_descriptor<G, typename boost::graph_traits<G>::face_descriptor, boost::face_index_t>;

/// @brief A Boost readable property map from `Key`: `get(map, key)` gives its value.
template <class Map, class Key>
concept ReadablePropertyMap = requires(const Map& map, const Key& key) {
  typename boost::property_traits<Map>::value_type;
  { get(map, key) } -> std::convertible_to<typename boost::property_traits<Map>::value_type>;
};

/// @brief A readable property map from `Key` to points: `get(map, key)[k]`, for k = 0, 1, 2, gives
/// a coordinate that `CGAL::to_double` converts (a CGAL `Point_3`, an `Eigen::Vector3d`, a
/// `std::array<double, 3>`, ...).
template <class Map, class Key>
concept ReadablePointMap = ReadablePropertyMap<Map, Key> && requires(const Map& map, const Key& key) {
  { CGAL::to_double(get(map, key)[0]) } -> std::convertible_to<double>;
};

/// @brief An animation of one triangle mesh: fixed connectivity, vertex positions per frame.
///
/// A type `M` models `DeformingMesh` when, for `const M& m` and a frame `t` in `[0, m.num_frames())`:
/// - `M::Face_graph` models `FaceGraph`, every face a triangle;
/// - `m.face_graph()` gives the connectivity as a `const M::Face_graph&`;
/// - `m.num_frames()` gives the number of frames;
/// - `m.frame_point_map(t)` gives a `ReadablePointMap` from the graph's vertex descriptors to the
///   vertex positions at frame `t`.
///
/// An animation may also give its frame rate, `m.frames_per_second()` (see `frames_per_second`); the
/// concept does not require it. The algorithms read nothing else of a model: one that is not a
/// `Deforming_mesh` is copied into one first (`make_deforming_mesh`).
///
/// Has models: `deformseg::mesh::Deforming_mesh`. See `doc/Concepts/DeformingMesh.h`.
template <class M>
concept DeformingMesh =
    FaceGraph<typename M::Face_graph> &&
    requires(const M& m, std::size_t frame) {
      { m.face_graph() } -> std::same_as<const typename M::Face_graph&>;
      { m.num_frames() } -> std::convertible_to<std::size_t>;
      { m.frame_point_map(frame) } -> ReadablePointMap<
          typename boost::graph_traits<typename M::Face_graph>::vertex_descriptor>;
    };

namespace internal {

// The point type of a graph's vertex point map, or a double point for a graph without one, whose
// positions come from elsewhere.
template <class Graph, bool = CGAL::graph_has_property<Graph, boost::vertex_point_t>::value>
struct Graph_point {
  using type = CGAL::Simple_cartesian<double>::Point_3;
};
template <class Graph>
struct Graph_point<Graph, true> {
  using type = typename boost::property_traits<
      typename boost::property_map<Graph, CGAL::vertex_point_t>::const_type>::value_type;
};

}  // namespace internal

}  // namespace deformseg::mesh
