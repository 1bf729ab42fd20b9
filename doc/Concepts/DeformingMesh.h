/// \page DeformingMeshConcept The DeformingMesh concept
///
/// An animation of one triangle mesh: fixed connectivity, vertex positions per frame. Every
/// algorithm of deformseg takes a model of it, and checks it at compile time with the C++20
/// concept deformseg::mesh::DeformingMesh.
///
/// A type `M` is a model when, for `const M& m` and a frame `t` in `[0, m.num_frames())`:
///
/// | expression | type | meaning |
/// |---|---|---|
/// | `M::Face_graph` | a model of \ref FaceGraphConcept "FaceGraph" | the connectivity type; every face a triangle |
/// | `m.face_graph()` | `const M::Face_graph&` | the connectivity |
/// | `m.num_frames()` | convertible to `std::size_t` | the number of frames T |
/// | `m.frame_point_map(t)` | a `ReadablePointMap`: vertex descriptor to point | the positions at frame t |
///
/// A `ReadablePointMap` (deformseg::mesh::ReadablePointMap) is a readable Boost property map
/// (`boost::property_traits<Map>::value_type`, `get(map, v)`) whose value `p` gives its coordinates
/// as `p[0]`, `p[1]`, `p[2]`, each converted by `CGAL::to_double`: a CGAL `Point_3`, an
/// `Eigen::Vector3d`, a `std::array<double, 3>`.
///
/// Frames are counted from 0. The positions must be finite.
///
/// These are all the expressions the algorithms use of a model: a model that is not a
/// deformseg::mesh::Deforming_mesh is copied into one (deformseg::mesh::make_deforming_mesh), which
/// reads the connectivity through the \ref FaceGraphConcept "FaceGraph" expressions only and the
/// positions through the frame point maps only. The graph's own vertex point map, if it has one, is
/// never read. `test/concept_archetype.cpp` checks it: every public algorithm compiles against an
/// archetype with only these expressions, and gives the default model's result to the last bit.
///
/// Optionally, `m.frames_per_second()` (convertible to `double`) gives the frame rate; the
/// descriptors that count time in seconds (deformseg::signatures::motion_signatures) read it through
/// deformseg::mesh::frames_per_second, which gives 30 for a model without it. deformseg::mesh::Deforming_mesh
/// has it (30 by default; the readers set it from their `fps` option).
///
/// \par Has models
/// deformseg::mesh::Deforming_mesh<FaceGraph, Coordinate>, for any FaceGraph (tested with
/// `CGAL::Surface_mesh`, `CGAL::Polyhedron_3` and OpenMesh's `TriMesh_ArrayKernelT`), and types of
/// one's own: `examples/deforming_mesh_OpenMesh_example.cpp` keeps an OpenMesh mesh and a vector of
/// points per frame (@ref chapter_01, "Your own mesh type").
///
/// \par A type that is not a model
/// is rejected at compile time: `static_assert(deformseg::mesh::DeformingMesh<M>)` names the first
/// requirement it misses.
///
/// \sa deformseg::mesh::make_deforming_mesh, which copies any model into a deformseg::mesh::Deforming_mesh.
