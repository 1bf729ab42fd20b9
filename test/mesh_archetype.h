// The archetype of the mesh concepts, as Boost.Graph's concept archetypes: a FaceGraph and a
// DeformingMesh with exactly what mesh::FaceGraph and mesh::DeformingMesh state, and nothing else.
//
// archetype::Graph is a Surface_mesh's connectivity behind boost::graph_traits and the seven free
// functions of FaceGraph. Its descriptors are its own types with only copying, equality and a hash:
// no internal index map, no point map, no property at all, so that an algorithm that calls anything
// the concept does not state fails to compile on it. archetype::Animation keeps its positions as
// std::array<double, 3> (no CGAL point) in a map of its own and has no frame rate.
#pragma once

#include <deformseg/mesh/concepts.h>
#include <deformseg/mesh/default_mesh.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <utility>
#include <vector>

namespace deformseg::test::archetype {

/// A descriptor: an index into the Surface_mesh behind the graph, with only what the concept asks.
template <class Tag>
struct Descriptor {
  std::uint32_t index = 0;
  friend bool operator==(Descriptor, Descriptor) = default;
};
struct Vertex_tag {};
struct Halfedge_tag {};
struct Face_tag {};
using Vertex = Descriptor<Vertex_tag>;      ///< vertex descriptor
using Halfedge = Descriptor<Halfedge_tag>;  ///< halfedge descriptor
using Face = Descriptor<Face_tag>;          ///< face descriptor

/// A forward iterator over the descriptors 0..n-1, and the non-owning range of two of them.
template <class D>
class Descriptor_iterator {
public:
  using value_type = D;
  using difference_type = std::ptrdiff_t;
  using reference = D;
  using pointer = void;
  using iterator_category = std::forward_iterator_tag;
  Descriptor_iterator() = default;
  explicit Descriptor_iterator(std::uint32_t i) : i_(i) {}
  D operator*() const { return D{i_}; }
  Descriptor_iterator& operator++() {
    ++i_;
    return *this;
  }
  Descriptor_iterator operator++(int) { return Descriptor_iterator(i_++); }
  friend bool operator==(Descriptor_iterator, Descriptor_iterator) = default;

private:
  std::uint32_t i_ = 0;
};
template <class D>
struct Descriptor_range {
  Descriptor_iterator<D> first, last;
  Descriptor_iterator<D> begin() const { return first; }
  Descriptor_iterator<D> end() const { return last; }
};

/// The graph: a Surface_mesh without removed elements, reachable only through the free functions.
class Graph {
public:
  explicit Graph(mesh::Surface_mesh mesh) : mesh_(std::move(mesh)) {}

  friend Descriptor_range<Vertex> vertices(const Graph& g) {
    return {Descriptor_iterator<Vertex>(0), Descriptor_iterator<Vertex>(std::uint32_t(g.mesh_.number_of_vertices()))};
  }
  friend Descriptor_range<Face> faces(const Graph& g) {
    return {Descriptor_iterator<Face>(0), Descriptor_iterator<Face>(std::uint32_t(g.mesh_.number_of_faces()))};
  }
  friend std::size_t num_vertices(const Graph& g) { return g.mesh_.number_of_vertices(); }
  friend std::size_t num_faces(const Graph& g) { return g.mesh_.number_of_faces(); }
  friend Halfedge halfedge(Face f, const Graph& g) {
    return {std::uint32_t(g.mesh_.halfedge(mesh::Surface_mesh::Face_index(f.index)).idx())};
  }
  friend Halfedge next(Halfedge h, const Graph& g) {
    return {std::uint32_t(g.mesh_.next(mesh::Surface_mesh::Halfedge_index(h.index)).idx())};
  }
  friend Vertex target(Halfedge h, const Graph& g) {
    return {std::uint32_t(g.mesh_.target(mesh::Surface_mesh::Halfedge_index(h.index)).idx())};
  }

private:
  mesh::Surface_mesh mesh_;
};

/// A readable property map from vertices to std::array<double, 3>, the positions of one frame in a
/// vector of the animation's own (by the vertex's index).
class Point_map {
public:
  using key_type = Vertex;
  using value_type = std::array<double, 3>;
  using reference = const std::array<double, 3>&;
  using category = boost::readable_property_map_tag;
  explicit Point_map(const std::vector<std::array<double, 3>>* points) : points_(points) {}
  friend reference get(const Point_map& map, Vertex v) { return (*map.points_)[v.index]; }

private:
  const std::vector<std::array<double, 3>>* points_;
};

/// The animation: what DeformingMesh states, nothing else (no frame rate).
class Animation {
public:
  using Face_graph = Graph;
  Animation(Graph graph, std::vector<std::vector<std::array<double, 3>>> frames)
      : graph_(std::move(graph)), frames_(std::move(frames)) {}
  const Graph& face_graph() const { return graph_; }
  std::size_t num_frames() const { return frames_.size(); }
  Point_map frame_point_map(std::size_t t) const { return Point_map(&frames_.at(t)); }

private:
  Graph graph_;
  std::vector<std::vector<std::array<double, 3>>> frames_;
};

/// The positions of every frame of `reference`, vertex by vertex.
inline std::vector<std::vector<std::array<double, 3>>> frames_of(const mesh::Surface_mesh_animation& reference) {
  std::vector<std::vector<std::array<double, 3>>> frames(reference.num_frames());
  for (std::size_t t = 0; t < frames.size(); ++t) {
    const auto xyz = reference.frame_positions(t);
    for (std::size_t i = 0; i < reference.num_vertices(); ++i)
      frames[t].push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
  }
  return frames;
}

/// The archetype of `reference` (a Surface_mesh animation built in order, whose indices are its
/// vertices' and faces' positions), as test::Mesh_types' entries give a model.
struct Model_on {
  using Model = Animation;  ///< what model() gives
  explicit Model_on(const mesh::Surface_mesh_animation& reference)
      : animation(Graph(reference.face_graph()), frames_of(reference)) {}
  const Model& model() const { return animation; }
  Animation animation;
};

}  // namespace deformseg::test::archetype

namespace boost {

/// The graph traits of the archetype: the descriptor and size types FaceGraph names.
template <>
struct graph_traits<deformseg::test::archetype::Graph> {
  using vertex_descriptor = deformseg::test::archetype::Vertex;
  using halfedge_descriptor = deformseg::test::archetype::Halfedge;
  using face_descriptor = deformseg::test::archetype::Face;
  using vertices_size_type = std::size_t;
  using faces_size_type = std::size_t;
};
template <>
struct graph_traits<const deformseg::test::archetype::Graph> : graph_traits<deformseg::test::archetype::Graph> {};

}  // namespace boost

namespace std {

/// The hash the concept asks of descriptors without an internal index map.
template <class Tag>
struct hash<deformseg::test::archetype::Descriptor<Tag>> {
  std::size_t operator()(deformseg::test::archetype::Descriptor<Tag> d) const noexcept {
    return std::hash<std::uint32_t>{}(d.index);
  }
};

}  // namespace std

static_assert(deformseg::mesh::FaceGraph<deformseg::test::archetype::Graph>);
static_assert(deformseg::mesh::DeformingMesh<deformseg::test::archetype::Animation>);
