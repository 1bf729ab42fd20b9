/// @file strain/strain.h
/// @brief Per-triangle strain of a deforming mesh: `compute_strain`, its options and its result
/// `Strain_field`, and `put_strain_frame` / `put_principal_directions` to hand one frame to a
/// face property map.
#pragma once

#include <deformseg/mesh/deforming_mesh.h>
#include <deformseg/exceptions.h>
#include <deformseg/strain/internal/strain_kernel.h>
#include <deformseg/strain/strain_field.h>
#include <deformseg/strain/strain_measures.h>
#include <deformseg/strain/strain_normalization.h>
#include <deformseg/threads.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace deformseg::strain {

/// @brief What a triangle's deformation is measured against.
enum class Strain_reference {
  /// @brief One fixed frame of the animation, `Strain_options::rest_frame`: strain measures the
  /// pose. Its own strain is 0.
  rest_pose,
  /// @brief The frame before: strain of frame t against frame t - 1 measures the motion. Frame 0's
  /// strain is 0.
  previous_pose,
};

/// @brief The built-in strain measures, one of which `Strain_options::measure` holds.
using Strain_measure_choice =
    std::variant<Max_principal_strain, Green_lagrange_strain, Frobenius_strain, Area_ratio_strain>;

/// @brief The built-in normalisations, one of which `Strain_options::normalization` holds.
using Strain_normalization_choice = std::variant<Gaussian_normalization, No_normalization>;

/// @brief The options of `compute_strain`, a plain aggregate for designated initializers.
///
/// The measure and the normalisation are chosen among the library's (`Strain_measure_choice`,
/// `Strain_normalization_choice`), so that
/// @code
/// compute_strain(animation);                                                  // the defaults
/// compute_strain(animation, {.reference = Strain_reference::previous_pose});  // default policies
/// compute_strain(animation, {.measure = Green_lagrange_strain{}, .normalization = No_normalization{}});
/// compute_strain(animation, {.normalization = Gaussian_normalization{.sigma = 0.05}});
/// @endcode
/// all read as they mean, and a front end chooses them at run time without a template. A measure
/// or normalisation of one's own (a `StrainMeasure`, a `StrainNormalization`) is passed to the
/// `compute_strain` overloads that take the policy objects, in place of these two members.
struct Strain_options {
  /// @brief The reference: the rest pose (default) or the previous pose.
  Strain_reference reference = Strain_reference::rest_pose;
  /// @brief The rest pose's frame, for `Strain_reference::rest_pose`. Default: 0.
  std::size_t rest_frame = 0;
  /// @brief The scalar each triangle's stretches become. Default: `Max_principal_strain`.
  Strain_measure_choice measure{};
  /// @brief How raw strains are normalised. Default: `Gaussian_normalization` with sigma from the
  /// data.
  Strain_normalization_choice normalization{};
  /// @brief Whether to compute the principal directions too (3 more values per triangle-frame).
  /// Default: false.
  bool principal_directions = false;
  /// @brief A reference triangle is degenerate, and its strain 0, when twice its area is at most
  /// this times its longest edge squared (its smallest height at most this times its longest edge).
  /// Default: 1e-12, so only triangles of zero area up to rounding. A larger value (1e-3, say)
  /// also sets the strain of sliver triangles to 0.
  double degenerate_tolerance = 1e-12;
  /// @brief Threads to use: 0 (default) for all the hardware's threads (`thread_count`)
  /// unless `DEFORMSEG_NUM_THREADS` or `OMP_NUM_THREADS` says otherwise), at most `max_threads`
  /// (see threads.h). The result is bit-identical for any number.
  int threads = 0;
};

namespace internal {

// A FaceGraph given as a reference mesh. Strain_options is ruled out first: boost::graph_traits,
// which FaceGraph asks for, is a hard error rather than a failed constraint for a non-graph.
template <class G>
concept Reference_face_graph = !std::same_as<G, Strain_options> && mesh::FaceGraph<G>;

inline void check_strain_options(const Strain_options& options, std::size_t frames, std::size_t faces) {
  if (frames == 0) throw invalid_input("compute_strain: the animation has no frame");
  if (faces == 0) throw invalid_input("compute_strain: the animation has no triangle");
  if (options.reference == Strain_reference::rest_pose && options.rest_frame >= frames)
    throw invalid_input("compute_strain: rest frame " + std::to_string(options.rest_frame) +
                        " out of range for an animation of " + std::to_string(frames) + " frames");
  thread_count(options.threads, "compute_strain");
  if (!(options.degenerate_tolerance >= 0 && options.degenerate_tolerance < 1))
    throw invalid_input("compute_strain: degenerate_tolerance must be in [0, 1), not " +
                        std::to_string(options.degenerate_tolerance));
}

// Calls `f` with a policy object, or with the one a choice of built-in policies holds: the kernel
// is instantiated for the policy's own type either way.
template <class Policy, class F>
decltype(auto) with_policy(const Policy& policy, F&& f) {
  return std::forward<F>(f)(policy);
}
template <class... Policies, class F>
decltype(auto) with_policy(const std::variant<Policies...>& choice, F&& f) {
  return std::visit(std::forward<F>(f), choice);
}

// The field of `animation` against the reference `reference_xyz` (positions of its vertices, 3 V
// values) or, when null, against what options.reference says; `measure` and `normalization` are
// policy objects or choices of built-in ones.
template <std::floating_point Value, class Graph, class Coordinate, class ReferenceCoordinate, class Measure,
          class Normalization>
Strain_field<Value> strain_field(const mesh::Deforming_mesh<Graph, Coordinate>& animation,
                                 const ReferenceCoordinate* reference_xyz, const Strain_options& options,
                                 const Measure& measure, const Normalization& normalization) {
  const std::size_t faces = animation.num_faces();
  const std::size_t frames = animation.num_frames();
  const std::vector<Triangle_indices> canonical = canonical_triangles(animation.triangles());
  const std::span<const Triangle_indices> triangles = canonical;
  const auto positions = animation.all_positions();
  typename Strain_field<Value>::Storage values(faces * frames);
  typename Strain_field<Value>::Storage directions(options.principal_directions ? 3 * faces * frames : 0);
  Value* direction_data = options.principal_directions ? directions.data() : nullptr;

  std::optional<std::size_t> zero_frame;
  std::size_t degenerate = 0;
  if (options.reference == Strain_reference::previous_pose) {
    zero_frame = 0;
    degenerate = with_policy(measure, [&](const auto& m) {
      return previous_pose_strains(positions, frames, triangles, options.degenerate_tolerance, m, options.threads,
                                   values.data(), direction_data);
    });
  } else {
    if (!reference_xyz) zero_frame = options.rest_frame;
    const Reference_bases bases =
        reference_xyz ? reference_bases(reference_xyz, triangles, options.degenerate_tolerance, options.threads)
                      : reference_bases(animation.frame_positions(options.rest_frame).data(), triangles,
                                        options.degenerate_tolerance, options.threads);
    degenerate = with_policy(measure, [&](const auto& m) {
      return fixed_reference_strains(positions, frames, triangles, bases, zero_frame, m, options.threads,
                                     values.data(), direction_data);
    });
  }
  const std::optional<double> sigma = with_policy(normalization, [&](const auto& n) {
    return n.normalize(Raw_strain_field<Value>{std::span<Value>(values), faces, zero_frame, options.threads});
  });
  return Strain_field<Value>(faces, frames, std::move(values), std::move(directions), sigma, degenerate);
}

// The point map of `reference`: the `vertex_point_map` of `np`, else the graph's own. Chosen
// without naming the graph's own map's type when one is given, as a graph may have none.
template <class ReferenceGraph, class NamedParameters>
auto reference_point_map(const ReferenceGraph& reference, const NamedParameters& np) {
  if constexpr (CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value)
    return get(CGAL::vertex_point, reference);
  else
    return CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point);
}

// The triangles of `reference` by its face index, as its vertex indices in the order of each
// face's halfedge cycle; throws for a face that is not a triangle or an index out of range.
template <mesh::FaceGraph ReferenceGraph, class VertexIndexMap, class FaceIndexMap>
std::vector<Triangle_indices> reference_triangles(const ReferenceGraph& reference, const VertexIndexMap& vertex_index,
                                                  const FaceIndexMap& face_index, std::size_t vertex_count) {
  std::vector<Triangle_indices> triangles(num_faces(reference));
  for (auto f : faces(reference)) {
    const std::size_t j = std::size_t(get(face_index, f));
    std::size_t k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, reference), reference)) {
      const std::size_t i = std::size_t(get(vertex_index, v));
      if (j >= triangles.size() || k == 3 || i >= vertex_count)
        throw invalid_input("compute_strain: the reference mesh's face " + std::to_string(j) +
                            " is not a triangle of indexed vertices");
      triangles[j][k++] = std::uint32_t(i);
    }
    if (k != 3)
      throw invalid_input("compute_strain: the reference mesh's face " + std::to_string(j) + " is not a triangle");
  }
  return triangles;
}

// The positions of `reference` in its vertex index order, after checking that its triangles are
// those of `animation` (up to the rotation of each, which does not change the strain). Its points
// and indices are those of `np`, else its own.
template <class Graph, class Coordinate, mesh::FaceGraph ReferenceGraph, class NamedParameters>
std::vector<double> reference_positions(const mesh::Deforming_mesh<Graph, Coordinate>& animation,
                                        const ReferenceGraph& reference, const NamedParameters& np) {
  const std::size_t vertex_count = num_vertices(reference);
  const std::size_t faces = num_faces(reference);
  if (vertex_count != animation.num_vertices() || faces != animation.num_faces())
    throw invalid_input("compute_strain: the reference mesh has " + std::to_string(vertex_count) + " vertices and " +
                        std::to_string(faces) + " faces, the animation " + std::to_string(animation.num_vertices()) +
                        " and " + std::to_string(animation.num_faces()));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(reference, np);
  const auto mine = canonical_triangles(
      reference_triangles(reference, vertex_index, CGAL::get_initialized_face_index_map(reference, np), vertex_count));
  const auto theirs = canonical_triangles(animation.triangles());
  for (std::size_t j = 0; j < faces; ++j)
    if (mine[j] != theirs[j])
      throw invalid_input("compute_strain: face " + std::to_string(j) + " of the reference mesh has vertices " +
                          std::to_string(mine[j][0]) + " " + std::to_string(mine[j][1]) + " " +
                          std::to_string(mine[j][2]) + ", the animation's " + std::to_string(theirs[j][0]) + " " +
                          std::to_string(theirs[j][1]) + " " + std::to_string(theirs[j][2]));
  std::vector<double> xyz(3 * vertex_count);
  const auto points = reference_point_map(reference, np);
  for (auto v : vertices(reference)) {
    const auto& p = get(points, v);
    for (int k = 0; k < 3; ++k) xyz[3 * std::size_t(get(vertex_index, v)) + std::size_t(k)] = CGAL::to_double(p[k]);
  }
  for (std::size_t i = 0; i < xyz.size(); ++i)
    if (!std::isfinite(xyz[i]))
      throw invalid_input("compute_strain: vertex " + std::to_string(i / 3) +
                          " of the reference mesh has a non-finite coordinate");
  return xyz;
}

// compute_strain with its policies given apart from the options (policy objects or choices).
template <std::floating_point Value, mesh::DeformingMesh Mesh, class Measure, class Normalization>
Strain_field<Value> strain_of(const Mesh& animation, const Strain_options& options, const Measure& measure,
                              const Normalization& normalization) {
  if constexpr (mesh::is_deforming_mesh_v<Mesh>) {
    check_strain_options(options, animation.num_frames(), animation.num_faces());
    return strain_field<Value>(animation, static_cast<const double*>(nullptr), options, measure, normalization);
  } else {
    return strain_of<Value>(mesh::make_deforming_mesh(animation), options, measure, normalization);
  }
}

// The same against a reference mesh.
template <std::floating_point Value, mesh::DeformingMesh Mesh, class ReferenceGraph, class Measure,
          class Normalization, class NamedParameters>
Strain_field<Value> strain_against(const Mesh& animation, const ReferenceGraph& reference,
                                   const Strain_options& options, const Measure& measure,
                                   const Normalization& normalization, const NamedParameters& np) {
  if constexpr (mesh::is_deforming_mesh_v<Mesh>) {
    if (options.reference != Strain_reference::rest_pose || options.rest_frame != 0)
      throw invalid_input("compute_strain: a reference mesh takes the place of the rest pose; leave "
                          "options.reference and options.rest_frame at their defaults");
    check_strain_options(options, animation.num_frames(), animation.num_faces());
    const std::vector<double> xyz = reference_positions(animation, reference, np);
    return strain_field<Value>(animation, xyz.data(), options, measure, normalization);
  } else {
    return strain_against<Value>(mesh::make_deforming_mesh(animation), reference, options, measure, normalization,
                                 np);
  }
}

}  // namespace internal

/// @brief The strain of every triangle of an animation at every frame (@ref method_strain).
///
/// For each triangle and frame, the affine map from the reference triangle to the deformed one has
/// the in-plane deformation gradient `F = Ds Dm^-1` (Dm, Ds: 2x2 edge matrices of the reference
/// and deformed triangles, each in a basis of its own plane) with singular values, the principal
/// stretches, `l1 >= l2`. The measure (`options.measure`) maps them to one scalar, by default
/// `max(|l1 - 1|, |l2 - 1|)`; the normalisation (`options.normalization`) then maps the raw
/// strains of the whole animation, by default through the Gaussian kernel
/// `1 - exp(-s^2 / (2 sigma^2))` with sigma a robust statistic of them (see
/// `Gaussian_normalization`). A measure or normalisation of one's own is passed to the overload
/// that takes the policy objects.
///
/// The reference is the rest pose (`options.rest_frame`, default frame 0) or the previous frame
/// (`options.reference`), or a mesh of its own (the overloads taking `reference`). Its triangles' bases are
/// computed once, in double; a degenerate one (zero area, see
/// `Strain_options::degenerate_tolerance`) gives strain 0, never NaN, and is counted in
/// `Strain_field::degenerate_count()`.
///
/// The raw strain is invariant to rotation and translation of each frame; a uniform scale of the
/// whole animation (reference included) leaves it unchanged. Any strain is finite: stretches beyond
/// 4e9 (float; 7e75 for double) saturate.
///
/// @par Precision
/// The edge vectors and the images of the reference basis are computed in double from the stored
/// positions, so that translation far from the origin costs nothing (a triangle's strain depends
/// on its edges only); from there on the arithmetic is `Value`'s and well conditioned, slivers
/// included. With `Value = float` each raw strain is within about 1e-6 x (1 + l1) of the exact
/// strain of the stored positions (the tests compare with a `long double` computation); with
/// `Value = double`, within about 1e-14 x (1 + l1) for triangles that are not slivers.
///
/// @tparam Value the field's value type, `float` (default) or `double`.
/// @tparam Mesh a `DeformingMesh`; a `Deforming_mesh` is read in place, any other model is first
/// copied with `make_deforming_mesh`: the kernel reads every triangle's corners at every frame, in
/// parallel, from contiguous coordinates by vertex index. The copy costs O(T V) time and 3 T V
/// doubles, little beside the O(T F) kernel, and gives the same field to the last bit.
/// @param animation the animation.
/// @param options reference, measure, normalisation, directions, threads (see `Strain_options`).
/// @return the `F x T` field, with sigma and the degenerate count.
/// @pre `animation` has at least one frame and one triangle; `options.rest_frame` is one of its
/// frames; `options.threads` from 0 to `max_threads`; `options.degenerate_tolerance` in [0, 1).
/// @throws invalid_input naming the problem when a precondition fails, or the normalisation's
/// parameters are invalid (a given sigma that is not finite and > 0).
/// @par Complexity
/// O(T F), in parallel over (frame, block of triangles) work items, plus O(T F) for the
/// normalisation (chapter 10 of the manual gives throughputs).
/// @sa Strain_options, Strain_field, put_strain_frame
template <std::floating_point Value = float, mesh::DeformingMesh Mesh>
Strain_field<Value> compute_strain(const Mesh& animation, const Strain_options& options = {}) {
  return internal::strain_of<Value>(animation, options, options.measure, options.normalization);
}

/// @brief The strain of every triangle of an animation at every frame, with a measure and a
/// normalisation of one's own (@ref chapter_08).
///
/// As the overload without policies, with `measure` and `normalization` in place of `options.measure` and
/// `options.normalization`, which are ignored. Pass a built-in policy for the one not replaced:
/// @code
/// compute_strain(animation, {.reference = Strain_reference::previous_pose}, Largest_stretch{}, No_normalization{});
/// @endcode
/// @tparam Measure a `StrainMeasure`.
/// @tparam Normalization a `StrainNormalization`.
/// @param animation the animation.
/// @param options reference, directions, tolerance, threads (see `Strain_options`).
/// @param measure the scalar each triangle's stretches become.
/// @param normalization how the raw strains are normalised.
/// @return the `F x T` field, with what `normalization` returned as sigma.
/// @pre as the overload without policies.
/// @throws invalid_input as the overload without policies, or what the policies throw.
/// @par Complexity as the overload without policies, plus the policies' own costs.
template <std::floating_point Value = float, mesh::DeformingMesh Mesh, StrainMeasure Measure,
          StrainNormalization Normalization>
Strain_field<Value> compute_strain(const Mesh& animation, const Strain_options& options, const Measure& measure,
                                   const Normalization& normalization) {
  return internal::strain_of<Value>(animation, options, measure, normalization);
}

/// @brief The strain of every triangle of an animation at every frame against a reference mesh of
/// its own: a mesh with the same connectivity, in another pose (the rest pose the animation does
/// not hold, or another animation's).
///
/// As the first overload with `Strain_reference::rest_pose` and the reference mesh's positions in
/// place of the rest frame; no frame is 0 by definition, so every frame counts in sigma.
/// @tparam ReferenceGraph a `FaceGraph`, with a vertex point map unless `np` gives one.
/// @param animation the animation.
/// @param reference the reference mesh: vertex i (in its vertex index map) is the animation's
/// vertex i, and its faces are the animation's, in the same order.
/// @param options as for the first overload; `reference` must be `rest_pose` and `rest_frame` 0.
/// @param np optional CGAL named parameters for reading `reference`, each defaulting to the
/// graph's own: `vertex_point_map`, a readable property map from its vertex descriptors to points
/// (`mesh::ReadablePointMap`; default `get(CGAL::vertex_point, reference)`); `vertex_index_map` and
/// `face_index_map`, readable property maps giving each vertex and face its index in
/// `[0, num_vertices)` and `[0, num_faces)` (default: the graph's initialized index maps,
/// `CGAL::get_initialized_vertex_index_map`).
/// @return the `F x T` field.
/// @pre as the first overload; `reference` has the animation's vertex and face counts, the same
/// triangles (face j has the vertices of the animation's triangle j, in the same order) and
/// finite coordinates.
/// @throws invalid_input naming the first mismatch (counts, or the first face that differs), or
/// when `options` asks for another reference.
/// @par Complexity O(T F + V).
/// @par Example
/// @include strain_vertex_point_map.cpp
template <std::floating_point Value = float, mesh::DeformingMesh Mesh, internal::Reference_face_graph ReferenceGraph,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Strain_field<Value> compute_strain(const Mesh& animation, const ReferenceGraph& reference,
                                   const Strain_options& options = {},
                                   const NamedParameters& np = CGAL::parameters::default_values()) {
  return internal::strain_against<Value>(animation, reference, options, options.measure, options.normalization, np);
}

/// @brief The strain against a reference mesh of its own, with a measure and a normalisation of
/// one's own: as the overload without `reference` that takes them, against `reference` as the
/// overload without policies.
/// @tparam ReferenceGraph a `FaceGraph`, with a vertex point map unless `np` gives one.
/// @tparam Measure a `StrainMeasure`.
/// @tparam Normalization a `StrainNormalization`.
/// @param animation the animation.
/// @param reference the reference mesh (see the overload without policies).
/// @param options as for that overload; its `measure` and `normalization` are ignored.
/// @param measure the scalar each triangle's stretches become.
/// @param normalization how the raw strains are normalised.
/// @param np the named parameters of the overload without policies, with their defaults.
/// @return the `F x T` field.
/// @pre as the overload without policies.
/// @throws invalid_input as the overload without policies, or what the policies throw.
/// @par Complexity O(T F + V), with the policies' own costs.
template <std::floating_point Value = float, mesh::DeformingMesh Mesh, internal::Reference_face_graph ReferenceGraph,
          StrainMeasure Measure, StrainNormalization Normalization,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Strain_field<Value> compute_strain(const Mesh& animation, const ReferenceGraph& reference,
                                   const Strain_options& options, const Measure& measure,
                                   const Normalization& normalization,
                                   const NamedParameters& np = CGAL::parameters::default_values()) {
  return internal::strain_against<Value>(animation, reference, options, measure, normalization, np);
}

namespace internal {

// Calls put(face descriptor, j) for each face of `graph`, j its index in the `face_index_map` of
// `np`, else in the graph's own.
template <mesh::FaceGraph Graph, class Put, class NamedParameters = CGAL::parameters::Default_named_parameters>
void for_each_face_index(const Graph& graph, std::size_t expected_faces, const Put& put,
                         const NamedParameters& np = CGAL::parameters::default_values()) {
  if (num_faces(graph) != expected_faces)
    throw invalid_input("the graph has " + std::to_string(num_faces(graph)) + " faces, the strain field " +
                        std::to_string(expected_faces));
  const auto index = CGAL::get_initialized_face_index_map(graph, np);
  for (auto f : faces(graph)) put(f, std::size_t(get(index, f)));
}

}  // namespace internal

/// @brief Writes the strains of frame `t` into a face property map: face f gets the strain of
/// triangle `index(f)`, with `index` the face index map of `np` (default: the graph's initialized one).
///
/// `graph` is the animation's connectivity (`animation.face_graph()`) or a mesh with the same
/// faces in the same order.
/// @tparam FacePropertyMap a writable property map from the graph's face descriptors to a type
/// that `Value` converts to.
/// @param field the strain field.
/// @param t the frame.
/// @param graph the connectivity.
/// @param map where to write.
/// @param np optional CGAL named parameters: `face_index_map`, a readable property map giving each
/// face of `graph` its triangle's index in `[0, F)`. Default: the graph's initialized face index
/// map (`CGAL::get_initialized_face_index_map`).
/// @throws invalid_input when `t` is out of range or the graph has another number of faces.
/// @par Complexity O(F).
/// @sa put_principal_directions
template <std::floating_point Value, mesh::FaceGraph Graph, class FacePropertyMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void put_strain_frame(const Strain_field<Value>& field, std::size_t t, const Graph& graph, FacePropertyMap map,
                      const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto strains = field.frame(t);
  internal::for_each_face_index(
      graph, field.num_faces(), [&](auto f, std::size_t j) { put(map, f, strains[j]); }, np);
}

/// @brief Writes the principal directions of frame `t` into a face property map of vectors: face
/// f gets `Vector(x, y, z)`, the direction of triangle `index(f)` (see
/// `Strain_field::principal_directions`).
/// @tparam FacePropertyMap a writable property map from the graph's face descriptors to a vector
/// type constructible from three doubles (`Kernel::Vector_3`, `Eigen::Vector3d`, ...).
/// @param field a strain field computed with `principal_directions`.
/// @param t the frame.
/// @param graph the connectivity, as for `put_strain_frame`.
/// @param map where to write.
/// @param np as for `put_strain_frame`: `face_index_map`, default the graph's initialized one.
/// @throws invalid_input when `t` is out of range, the directions were not computed, or the graph
/// has another number of faces.
/// @par Complexity O(F).
template <std::floating_point Value, mesh::FaceGraph Graph, class FacePropertyMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void put_principal_directions(const Strain_field<Value>& field, std::size_t t, const Graph& graph,
                              FacePropertyMap map, const NamedParameters& np = CGAL::parameters::default_values()) {
  using Vector = typename boost::property_traits<FacePropertyMap>::value_type;
  const auto directions = field.principal_directions(t);
  internal::for_each_face_index(
      graph, field.num_faces(),
      [&](auto f, std::size_t j) {
        put(map, f, Vector(double(directions(Eigen::Index(j), 0)), double(directions(Eigen::Index(j), 1)),
                           double(directions(Eigen::Index(j), 2))));
      },
      np);
}

}  // namespace deformseg::strain

#if DEFORMSEG_COMPILED
// deformseg::compiled holds these instantiations (src/compiled/strain.cpp): a program that links it
// compiles against their declarations. Any other type or policy instantiates where it is used.
#include <deformseg/mesh/default_mesh.h>

namespace deformseg::strain {
extern template Strain_field<float> compute_strain<float, mesh::Surface_mesh_animation>(
    const mesh::Surface_mesh_animation&, const Strain_options&);
extern template Strain_field<double> compute_strain<double, mesh::Surface_mesh_animation>(
    const mesh::Surface_mesh_animation&, const Strain_options&);
}  // namespace deformseg::strain
#endif
