/// \page FaceGraphConcept The FaceGraph concept
///
/// The connectivity of a deforming mesh, in the sense of CGAL's BGL extension, with exactly what
/// deformseg's algorithms use of it; checked at compile time by the C++20 concept
/// deformseg::mesh::FaceGraph. CGAL's `FaceGraph` concept asks more (edges, halfedge opposites,
/// `face(h, g)`, null descriptors), which deformseg does not use.
///
/// A type `G` is a model when, for `const G& g`, a face descriptor `f` and a halfedge descriptor `h`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `boost::graph_traits<G>::vertex_descriptor` | `std::semiregular` | a vertex |
/// | `boost::graph_traits<G>::halfedge_descriptor` | `std::semiregular` | a halfedge |
/// | `boost::graph_traits<G>::face_descriptor` | `std::semiregular` | a face |
/// | `boost::graph_traits<G>::vertices_size_type`, `faces_size_type` | integral | the index types |
/// | `vertices(g)` | a range (`begin()`, `end()`) of vertex descriptors | every vertex |
/// | `faces(g)` | a range of face descriptors | every face |
/// | `num_vertices(g)`, `num_faces(g)` | convertible to `std::size_t` | the sizes of those ranges |
/// | `halfedge(f, g)` | halfedge descriptor | a halfedge of face f |
/// | `next(h, g)` | halfedge descriptor | the next halfedge around h's face |
/// | `target(h, g)` | vertex descriptor | the vertex h points to |
/// | `G(g)` | `G` | a copy, which lists its vertices in the order of g's |
///
/// and its vertex and face descriptors are each deformseg::mesh::Indexable_descriptor: the graph
/// has an internal index property map for them (`CGAL::graph_has_property<G, boost::vertex_index_t>`,
/// `boost::face_index_t`), or they are equality comparable and hashable (`std::hash`), so that
/// `CGAL::get_initialized_vertex_index_map` numbers them by a dynamic property map in the order of
/// their range. The free functions are found by argument-dependent lookup.
///
/// Every face is a triangle. No point map is required: an animation's positions are its own
/// (\ref DeformingMeshConcept "DeformingMesh"), and the entry points that read a graph's points or
/// indices take them as CGAL named parameters, defaulting to the graph's own:
///
/// - deformseg::strain::compute_strain against a reference mesh: `vertex_point_map`,
///   `vertex_index_map`, `face_index_map`;
/// - deformseg::strain::put_strain_frame, deformseg::strain::put_principal_directions and
///   deformseg::spatiotemporal::put_face_segments: `face_index_map`;
/// - deformseg::mesh::make_face_graph, which writes the points: `vertex_point_map`.
///
/// \par Has models
/// `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, OpenMesh's `TriMesh_ArrayKernelT` (through CGAL's
/// graph traits for OpenMesh), and the archetype of `test/mesh_archetype.h`, which has nothing else.
///
/// \sa deformseg::mesh::Deforming_mesh, whose vertex and face indices are the graph's index maps.
