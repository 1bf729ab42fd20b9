/// @file mesh/make_face_graph.h
/// @brief `make_face_graph`: a `FaceGraph` built from points and triangles given by vertex indices.
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/mesh/concepts.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

namespace deformseg::mesh {

namespace internal {

// Sets the point of vertex `v` of `g` to `p`. Through the graph's vertex point map, except for a
// graph that holds points of its own type and sets them with `g.set_point(v, point)` (OpenMesh):
// CGAL's point map for OpenMesh rounds every coordinate to float on the way in, whatever the mesh's
// point type (unless CGAL_USE_OM_POINTS), so that a TriMesh of Vec3d would hold other points than
// those given. Its own point type keeps them (Vec3d to the last bit; Vec3f rounds, as it must).
template <class Point, class Graph, class PointMap, class Vertex, class P>
void set_vertex_point(Graph& g, const PointMap& point_map, Vertex v, const P& p) {
  if constexpr (requires { typename Graph::Point::value_type; } &&
                requires(Graph& m, const typename Graph::Point& q) { m.set_point(v, q); }) {
    using Scalar = typename Graph::Point::value_type;
    g.set_point(v, typename Graph::Point(static_cast<Scalar>(p[0]), static_cast<Scalar>(p[1]),
                                         static_cast<Scalar>(p[2])));
  } else {
    put(point_map, v, Point(p[0], p[1], p[2]));
  }
}

}  // namespace internal

/// @brief Builds a `FaceGraph` from points and triangles given by vertex indices, keeping the
/// points' order as the vertex index order and the triangles' order as the face index order.
///
/// The points are kept as the graph's point type holds them: to the last bit for double points
/// (`Surface_mesh`, `Polyhedron_3` on an inexact kernel, an OpenMesh mesh of `Vec3d`, which is
/// written through its own `set_point`, as CGAL's point map for OpenMesh would round to float).
///
/// @tparam Graph a default-constructible `FaceGraph` that `add_vertex` and `CGAL::Euler::add_face`
/// build (a `MutableFaceGraph`), with a writable vertex point map unless one is given.
/// @param points the vertex positions, any range of 3-element indexable values.
/// @param triangles any range of 3 vertex indices each.
/// @param np optional CGAL named parameters: `vertex_point_map`, a writable property map from the
/// graph's vertex descriptors to points constructible from three coordinates, where the points
/// are written. Default: the graph's own, `get(CGAL::vertex_point, g)`.
/// @pre every index is in range and the triangles form an oriented 2-manifold (with or without
/// boundary); otherwise throws `invalid_input` naming the first triangle that breaks it.
/// @par Complexity O(V + F) expected.
template <FaceGraph Graph, class PointRange, class TriangleRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Graph make_face_graph(const PointRange& points, const TriangleRange& triangles,
                      const NamedParameters& np = CGAL::parameters::default_values()) {
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;
  Graph g;
  std::vector<vertex_descriptor> vertex;
  vertex.reserve(std::size(points));
  for (const auto& p : points) {
    vertex.push_back(add_vertex(g));
    if constexpr (CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value) {
      using Point = typename internal::Graph_point<Graph>::type;
      internal::set_vertex_point<Point>(g, get(CGAL::vertex_point, g), vertex.back(), p);
    } else {
      const auto point_map = CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point);
      using Point = typename boost::property_traits<std::remove_cvref_t<decltype(point_map)>>::value_type;
      put(point_map, vertex.back(), Point(p[0], p[1], p[2]));
    }
  }
  std::size_t j = 0;
  for (const auto& tri : triangles) {
    std::array<vertex_descriptor, 3> corners;
    for (int k = 0; k < 3; ++k) {
      if (std::size_t(tri[k]) >= vertex.size())
        throw invalid_input("triangle " + std::to_string(j) + " has vertex index " +
                            std::to_string(tri[k]) + " out of range [0, " +
                            std::to_string(vertex.size()) + ")");
      corners[k] = vertex[tri[k]];
    }
    if (CGAL::Euler::add_face(corners, g) == boost::graph_traits<Graph>::null_face())
      throw invalid_input("triangle " + std::to_string(j) +
                          " cannot be added: it repeats a vertex, or makes an edge or a vertex "
                          "non-manifold, or is oriented against its neighbours");
    ++j;
  }
  return g;
}

}  // namespace deformseg::mesh
