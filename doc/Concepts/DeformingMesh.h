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
/// | `M::Face_graph` | a model of CGAL's `FaceGraph` | the connectivity type; every face a triangle |
/// | `m.face_graph()` | `const M::Face_graph&` | the connectivity |
/// | `m.num_frames()` | convertible to `std::size_t` | the number of frames T |
/// | `m.frame_point_map(t)` | a readable property map, vertex descriptor to point | the positions at frame t |
///
/// Frames are counted from 0. The positions must be finite.
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
