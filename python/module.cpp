// deformseg._deformseg: the compiled half of the Python module, over the library's default types
// (Surface_mesh_animation, float strains). One translation unit, so that CGAL, Boost and Eigen are
// parsed once. The pure-Python half (python/deformseg/) re-exports these names and adds the
// evolving graph's classes, networkx conversions and `ged` on networkx graphs.
//
// Every call that can take long releases the GIL and can be interrupted by Ctrl-C; the arguments
// it reads stay referenced by Python objects held for the call. Option names, defaults and checks
// are those of the C++ options and of the `deformseg` tool, whose names the string options take.
#include <deformseg/alignment/dtw.h>
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/mesh/default_mesh.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/exceptions.h>
#include <deformseg/mesh/face_areas.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/strain/frame_distances.h>
#include <deformseg/ged/bipartite_ged.h>
#include <deformseg/ged/exact_ged.h>
#include <deformseg/ged/lower_bound.h>
#include <deformseg/io/motion_labels.h>
#include <deformseg/io/read_animation.h>
#include <deformseg/io/graphviz.h>
#include <deformseg/io/read_mesh.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/similarity/policy_choice.h>
#include <deformseg/similarity/self_similarity_matching.h>
#include <deformseg/similarity/significance.h>
#include <deformseg/strain/strain.h>
#include <deformseg/temporal/temporal_segmentation.h>
#include <deformseg/threads.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
using namespace deformseg;

namespace {

// ---- Long calls ----------------------------------------------------------------------------------

// The library's long loops call this on the calling thread about every 20 ms (threads.h): a
// signal caught meanwhile runs its Python handler, and what the handler raises
// (KeyboardInterrupt for Ctrl-C) stops the call and comes out of it.
bool no_signal_raised() {
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  return true;
}

// The GIL released for a call that can take long, which Ctrl-C can interrupt.
struct Interruptible_call {
  Interruption_scope scope{&no_signal_raised};
  py::gil_scoped_release release;
};

// ---- Animations --------------------------------------------------------------------------------

// An animation as Python holds it: the library's default model, and what the reader repaired.
struct Animation {
  mesh::Surface_mesh_animation mesh;
  std::optional<io::Repair_report> repair{};
};

[[noreturn]] void refuse(const std::string& message) { throw invalid_input(message); }

std::string shape_of(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtype_of(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

// The (T, V, 3) coordinates of `frames` as the library stores them, doubles frame after frame:
// one copy of a C-contiguous float64 or float32 array, a NumPy conversion first for any other.
std::vector<double> positions_of(const py::array& frames) {
  if (frames.dtype().kind() != 'f' || (frames.itemsize() != 4 && frames.itemsize() != 8))
    throw py::type_error("frames: expected a float32 or float64 array of shape (T, V, 3), got dtype " +
                         dtype_of(frames));
  if (frames.ndim() != 3 || frames.shape(2) != 3 || frames.shape(0) < 1 || frames.shape(1) < 3)
    throw py::value_error("frames: expected shape (T, V, 3) with T >= 1 and V >= 3, got " + shape_of(frames));
  const auto count = std::size_t(frames.size());
  const bool contiguous = (frames.flags() & py::array::c_style) != 0;
  if (contiguous && frames.itemsize() == 8) {
    const auto* data = static_cast<const double*>(frames.data());
    Interruptible_call call;
    return std::vector<double>(data, data + count);
  }
  if (contiguous) {
    const auto* data = static_cast<const float*>(frames.data());
    Interruptible_call call;
    return std::vector<double>(data, data + count);
  }
  const auto converted = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(frames);
  return std::vector<double>(converted.data(), converted.data() + count);
}

// The triangles of `faces`, an (F, 3) array of integers, each checked to be in [0, vertices).
std::vector<std::array<std::uint32_t, 3>> triangles_of(const py::array& faces, std::size_t vertices) {
  if (faces.dtype().kind() != 'i' && faces.dtype().kind() != 'u')
    throw py::type_error("faces: expected an integer array of shape (F, 3), got dtype " + dtype_of(faces));
  if (faces.ndim() != 2 || faces.shape(1) != 3 || faces.shape(0) < 1)
    throw py::value_error("faces: expected shape (F, 3) with F >= 1, got " + shape_of(faces));
  const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(faces);
  const auto read = indices.unchecked<2>();
  std::vector<std::array<std::uint32_t, 3>> triangles(std::size_t(read.shape(0)));
  for (py::ssize_t j = 0; j < read.shape(0); ++j)
    for (py::ssize_t k = 0; k < 3; ++k) {
      const std::int64_t v = read(j, k);
      if (v < 0 || std::uint64_t(v) >= vertices)
        throw invalid_input("faces: triangle " + std::to_string(j) + " has vertex index " + std::to_string(v) +
                            " out of range [0, " + std::to_string(vertices) + ")");
      triangles[std::size_t(j)][std::size_t(k)] = std::uint32_t(v);
    }
  return triangles;
}

// Any array-like (a list, a memory view, an array of another library) as a NumPy array, without
// copy when it is one already.
py::array as_array(const py::object& value, const char* name) {
  py::array a = py::array::ensure(value);
  if (!a) throw py::type_error(std::string(name) + ": expected an array, got " +
                               py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  return a;
}

Animation animation_of_arrays(const py::object& faces_like, const py::object& frames_like, double fps) {
  if (!(fps > 0) || !std::isfinite(fps)) throw invalid_input("fps must be positive and finite");
  const py::array frames = as_array(frames_like, "frames");
  const py::array faces = as_array(faces_like, "faces");
  std::vector<double> positions = positions_of(frames);
  const auto vertices = std::size_t(frames.shape(1));
  const auto triangles = triangles_of(faces, vertices);
  Interruptible_call call;
  std::vector<std::array<double, 3>> rest(vertices);
  std::copy_n(positions.data(), 3 * vertices, rest.front().data());
  mesh::Surface_mesh graph = mesh::make_face_graph<mesh::Surface_mesh>(rest, triangles);
  mesh::Surface_mesh_animation mesh(std::move(graph), std::move(positions));
  mesh.set_frames_per_second(fps);
  return {std::move(mesh), std::nullopt};
}

// A read-only NumPy view of `count` values at `data`, kept alive by `owner`.
template <class T>
py::array view(const T* data, std::vector<py::ssize_t> shape, const py::object& owner) {
  py::array a(py::dtype::of<T>(), std::move(shape), {}, data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

// A NumPy array that owns `value` (moved to the heap) and shows `data` of it.
template <class Owned, class T>
py::array owning(Owned&& value, const T* (*data)(const Owned&), std::vector<py::ssize_t> shape,
                 std::vector<py::ssize_t> strides = {}) {
  auto* held = new Owned(std::forward<Owned>(value));
  py::capsule owner(held, [](void* p) { delete static_cast<Owned*>(p); });
  return py::array(py::dtype::of<T>(), std::move(shape), std::move(strides), data(*held), owner);
}

py::dict repair_dict(const io::Repair_report& r) {
  py::dict d;
  for (const auto& [name, count] : r.counts()) d[py::str(name.data(), name.size())] = count;
  return d;
}

// read_animation: the rules of the tool's input options ("FILE.glb#CLIP", clip and topology only
// where they apply, glTF welded unless weld=False, other formats only with weld=True).
Animation read_input(const std::filesystem::path& path, std::optional<std::string> clip, double fps,
               std::optional<std::filesystem::path> topology, bool triangulate, std::optional<bool> weld,
               bool refuse_defects, int threads) {
  auto [input, named_clip] = io::split_clip_suffix(path.string());
  if (named_clip) {
    if (clip) throw invalid_input("the clip is given twice: by clip= and after '#'", {.file = path.string()});
    clip = std::move(named_clip);
  }
  const bool gltf = io::is_gltf(input);
  const auto location = Input_location{.file = input};
  if (!gltf && clip) throw invalid_input("clip applies to glTF files only", location);
  if (gltf && topology) throw invalid_input("topology does not apply to a glTF file: it has its own", location);
  if (!(fps > 0)) throw invalid_input("fps must be positive", location);
  try {
    thread_count(threads);
  } catch (const invalid_input& e) {
    throw e.located(location);
  }
  const io::Repair_options repair{.weld = weld.value_or(gltf),
                                  .defects = refuse_defects ? io::Defect_policy::refuse : io::Defect_policy::repair};
  io::Animation_read_options options{.topology = topology, .triangulate = triangulate, .threads = threads,
                                     .repair = repair, .clip = clip.value_or(""), .fps = fps};
  Interruptible_call call;
  io::Repair_report report;
  mesh::Surface_mesh_animation mesh = io::read_animation(input, options, &report);
  return {std::move(mesh), report};
}

// ---- Strain, temporal segmentation, evolving graph ---------------------------------------------

strain::Strain_reference reference_of(const std::string& name) {
  if (name == "rest") return strain::Strain_reference::rest_pose;
  if (name == "previous") return strain::Strain_reference::previous_pose;
  refuse("reference must be 'rest' or 'previous', got '" + name + "'");
}

// The tool's --reference-mesh: a rest pose kept apart from the frames (the cat folder's
// cat-reference.obj), read from a mesh file, with the connectivity of the animation as read.
struct Reference_mesh {
  std::string path;
  mesh::Surface_mesh graph;
};

std::optional<Reference_mesh> reference_mesh_of(const std::optional<std::filesystem::path>& path) {
  if (!path) return std::nullopt;
  const io::Triangle_soup soup = io::read_mesh(*path);
  return Reference_mesh{path->string(), mesh::make_face_graph<mesh::Surface_mesh>(io::points_of(soup), soup.triangles)};
}

// The strain field of `a` with `options`, against `reference` when there is one; its errors then
// name the reference mesh's file, as the tool's do: a mismatch of connectivity is that file's.
strain::Strain_field<float> field_of(const mesh::Surface_mesh_animation& a, const std::optional<Reference_mesh>& reference,
                             const strain::Strain_options& options) {
  if (!reference) return strain::compute_strain(a, options);
  try {
    return strain::compute_strain(a, reference->graph, options);
  } catch (const invalid_input& error) {
    throw invalid_input(std::string(error.what()) + " (the reference mesh must have the connectivity of the "
                        "animation as read: its num_vertices and num_faces)", {.file = reference->path});
  }
}

// The built-in strain measures by their names.
const std::map<std::string, strain::Strain_measure_choice> strain_measures{
    {"max-principal", strain::Max_principal_strain{}},
    {"green-lagrange", strain::Green_lagrange_strain{}},
    {"frobenius", strain::Frobenius_strain{}},
    {"area-ratio", strain::Area_ratio_strain{}}};

py::array strain(const Animation& a, const std::string& reference, std::size_t rest_frame,
                 const std::optional<std::filesystem::path>& reference_mesh, const std::string& measure,
                 const std::string& normalize, std::optional<double> sigma, double degenerate_tolerance, int threads) {
  const strain::Strain_reference ref = reference_of(reference);
  if (normalize != "gaussian" && normalize != "none")
    refuse("normalize must be 'gaussian' or 'none', got '" + normalize + "'");
  const bool gaussian = normalize == "gaussian";
  if (sigma && !gaussian) refuse("sigma asks for normalize='gaussian'");
  if (sigma && !(*sigma > 0)) refuse("sigma must be positive");
  if (ref == strain::Strain_reference::previous_pose && rest_frame != 0) refuse("rest_frame asks for reference='rest'");
  if (reference_mesh && (ref == strain::Strain_reference::previous_pose || rest_frame != 0))
    refuse("reference_mesh takes the place of the rest frame: it excludes reference='previous' and rest_frame");
  const auto chosen = strain_measures.find(measure);
  if (chosen == strain_measures.end())
    refuse("measure must be 'max-principal', 'green-lagrange', 'frobenius' or 'area-ratio', got '" + measure + "'");
  const strain::Strain_options options{
      .reference = ref,
      .rest_frame = rest_frame,
      .measure = chosen->second,
      .normalization = gaussian ? strain::Strain_normalization_choice(strain::Gaussian_normalization{.sigma = sigma})
                                : strain::No_normalization{},
      .degenerate_tolerance = degenerate_tolerance,
      .threads = threads};
  strain::Strain_field<float> field;
  {
    Interruptible_call call;
    field = field_of(a.mesh, reference_mesh_of(reference_mesh), options);
  }
  const auto shape = std::vector<py::ssize_t>{py::ssize_t(field.num_frames()), py::ssize_t(field.num_faces())};
  return owning(std::move(field), +[](const strain::Strain_field<float>& f) { return f.values().data(); }, shape);
}

strain::Frame_metric metric_of(const std::string& name) {
  if (name == "euclidean") return strain::Frame_metric::euclidean;
  if (name == "l1") return strain::Frame_metric::l1;
  if (name == "cosine") return strain::Frame_metric::cosine;
  refuse("metric must be 'euclidean', 'l1' or 'cosine', got '" + name + "'");
}

void check_rest(const std::optional<std::filesystem::path>& reference_mesh, std::size_t rest_frame) {
  if (reference_mesh && rest_frame != 0)
    refuse("reference_mesh takes the place of the rest frame: it excludes rest_frame");
}

// The frame distances of the temporal segmentation: the default strain against `rest_frame`, or
// against the reference mesh.
Eigen::MatrixXf distances_of(const mesh::Surface_mesh_animation& a, strain::Frame_metric metric, std::size_t rest_frame,
                             const std::optional<std::filesystem::path>& reference_mesh, int threads) {
  const strain::Strain_field<float> field =
      field_of(a, reference_mesh_of(reference_mesh), strain::Strain_options{.rest_frame = rest_frame, .threads = threads});
  return frame_distances(field, {.metric = metric, .threads = threads});
}

py::array distances(const Animation& a, const std::string& metric, std::size_t rest_frame,
                    const std::optional<std::filesystem::path>& reference_mesh, int threads) {
  const strain::Frame_metric m = metric_of(metric);
  check_rest(reference_mesh, rest_frame);
  Eigen::MatrixXf d;
  {
    Interruptible_call call;
    d = distances_of(a.mesh, m, rest_frame, reference_mesh, threads);
  }
  const auto n = py::ssize_t(d.rows());
  const auto item = py::ssize_t(sizeof(float));
  return owning(std::move(d), +[](const Eigen::MatrixXf& x) { return x.data(); }, {n, n}, {item, n * item});
}

std::vector<std::pair<std::size_t, std::size_t>> temporal(const Animation& a, const std::string& method,
                                                          std::optional<double> threshold, bool absolute,
                                                          std::optional<std::size_t> segments, std::size_t min_length,
                                                          const std::string& metric, std::size_t rest_frame,
                                                          const std::optional<std::filesystem::path>& reference_mesh,
                                                          int threads) {
  if (method != "optimal" && method != "binary-split" && method != "greedy" && method != "barbic")
    refuse("method must be 'optimal', 'binary-split', 'greedy' or 'barbic', got '" + method + "'");
  const strain::Frame_metric m = metric_of(metric);
  if (segments && method != "optimal") refuse("segments asks for method='optimal'");
  check_rest(reference_mesh, rest_frame);
  if (segments && *segments == 0) refuse("segments must be at least 1");
  if (min_length == 0) refuse("min_length must be at least 1");
  if (threshold && !(*threshold >= 0)) refuse("threshold must be non-negative");
  const auto threshold_or = [&](temporal::Segmentation_threshold fallback) {
    return threshold ? temporal::Segmentation_threshold{.value = *threshold, .relative = !absolute} : fallback;
  };
  temporal::Temporal_segmentation result;
  {
    Interruptible_call call;
    const temporal::Segment_cost cost(distances_of(a.mesh, m, rest_frame, reference_mesh, threads));
    if (method == "binary-split")
      result = temporal::segment_frames(
          cost, temporal::Binary_split{.threshold = threshold_or(temporal::Binary_split{}.threshold), .min_length = min_length});
    else if (method == "greedy")
      result = temporal::segment_frames(cost, temporal::Thesis_greedy{.threshold = threshold_or(temporal::Thesis_greedy{}.threshold)});
    else if (method == "barbic")
      result = temporal::segment_frames(cost, temporal::Barbic_pca{});
    else
      result = temporal::segment_frames(cost, temporal::Optimal_partition{.penalty = threshold_or(temporal::Optimal_partition{}.penalty),
                                                      .segments = segments, .min_length = min_length});
  }
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const temporal::Temporal_segment& s : result.segments) out.emplace_back(s.first, s.last);
  return out;
}

// The evolving graph as plain data, which python/deformseg/_graphs.py makes into classes:
// (frames, segments, [(first, last, [(kind, segment or None, triangles, area)], [(u, v)])]).
// The reference: none given, previous, or rest with a reference mesh (as the tool's).
py::tuple evolving(const Animation& a, double threshold, const std::optional<std::string>& reference,
                   const std::optional<std::filesystem::path>& reference_mesh, std::size_t min_triangles,
                   std::size_t min_frames, std::size_t max_island) {
  if (!(threshold >= 0 && threshold <= 1)) refuse("threshold must be in [0, 1]");
  if (reference_mesh && reference == "previous")
    refuse("reference_mesh is a rest pose: it excludes reference='previous'");
  const spatiotemporal::Spatiotemporal_options options{.reference = reference_of(reference.value_or(reference_mesh ? "rest" : "previous")),
                                       .threshold = threshold, .min_triangles = min_triangles,
                                       .min_frames = min_frames, .max_island = max_island};
  const spatiotemporal::Evolving_graph graph = [&] {
    Interruptible_call call;
    if (!reference_mesh) return spatiotemporal::evolving_graph(a.mesh, options);
    const strain::Strain_field<float> field = field_of(a.mesh, reference_mesh_of(reference_mesh), strain::Strain_options{});
    const std::vector<double> areas = mesh::face_areas(a.mesh, 0);
    const spatiotemporal::Spatiotemporal_segmentation segmentation = spatiotemporal::spatiotemporal_segmentation(field, a.mesh.triangles(), options);
    return spatiotemporal::evolving_graph(spatiotemporal::Frame_segments(segmentation, a.mesh.triangles(), areas));
  }();
  py::list key_frames;
  for (const spatiotemporal::Key_frame& k : graph) {
    const spatiotemporal::Segment_graph& g = k.graph;
    py::list nodes, edges;
    for (std::size_t v = 0; v < boost::num_vertices(g); ++v) {
      const bool rigid = g[v].kind == spatiotemporal::Segment_kind::rigid;
      nodes.append(py::make_tuple(rigid ? "rigid" : "deformed", rigid ? py::object(py::none()) : py::int_(g[v].segment),
                                  g[v].triangles, g[v].area));
    }
    for (auto e : boost::make_iterator_range(boost::edges(g)))
      edges.append(py::make_tuple(std::min(boost::source(e, g), boost::target(e, g)),
                                  std::max(boost::source(e, g), boost::target(e, g))));
    key_frames.append(py::make_tuple(k.first_frame, k.last_frame, nodes, edges));
  }
  return py::make_tuple(graph.num_frames(), graph.num_segments(), key_frames);
}

// ---- Similarity ----------------------------------------------------------------------------------

struct Similarity_result {
  similarity::Similarity similarity;
  std::optional<double> z_score;
  std::size_t shuffled_copies = 0;
};

// The keywords policy, alignment, threshold and up, as the library's Policy_choice.
similarity::Policy_choice policy_choice(const std::string& policy, const std::optional<std::string>& alignment,
                            std::optional<double> threshold, const std::optional<std::string>& up) {
  return {.policy = policy, .alignment = alignment.value_or(""), .threshold = threshold, .up = up.value_or("")};
}

void require_motion(const mesh::Surface_mesh_animation& a, const char* which) {
  if (a.num_frames() < 2)
    throw invalid_input(std::string(which) + ": an animation of " + std::to_string(a.num_frames()) +
                        " frame: a motion needs at least 2");
}

Similarity_result similarity(const Animation& a, const Animation& b, const std::string& policy,
                             const std::optional<std::string>& alignment, std::optional<double> threshold,
                             const std::optional<std::string>& up, std::optional<std::size_t> significance,
                             unsigned seed) {
  const similarity::Policy_choice choice = policy_choice(policy, alignment, threshold, up);
  similarity::check_policy_choice(choice);
  if (significance == 1) refuse("significance needs 0 (none) or at least 2 shuffled copies");
  if (significance.value_or(0) >= 2 && policy == "graph")
    refuse("significance does not apply to the graph policy, whose frames are key-frame labels");
  const std::size_t copies = significance.value_or(policy == "graph" ? 0 : 20);
  require_motion(a.mesh, "a");
  require_motion(b.mesh, "b");
  return similarity::with_policy_choice(choice, [&](const auto& p) {
    Interruptible_call call;
    const auto da = p.describe(a.mesh), db = p.describe(b.mesh);
    Similarity_result out{p.compare(da, db), std::nullopt, 0};
    if constexpr (requires { frame_count(db); reordered_frames(db, std::span<const std::size_t>()); }) {
      if (copies >= 2) {
        std::mt19937 random(seed);
        out.z_score = similarity::similarity_significance(p, da, db, copies, random);
        out.shuffled_copies = copies;
      }
    }
    return out;
  });
}

// The animations of a Python sequence, as a random-access range of references (no copy); the
// Python objects stay referenced in `held` while the GIL is released.
struct Animation_list {
  std::vector<py::object> held;
  std::vector<const mesh::Surface_mesh_animation*> meshes;

  Animation_list(const py::sequence& animations, const char* what) {
    for (std::size_t i = 0; i < animations.size(); ++i) {
      py::object item = animations[i];
      if (!py::isinstance<Animation>(item))
        throw py::type_error(std::string(what) + "[" + std::to_string(i) + "]: expected an Animation, got " +
                             py::str(py::type::of(item).attr("__name__")).cast<std::string>());
      const mesh::Surface_mesh_animation& mesh = item.cast<const Animation&>().mesh;
      require_motion(mesh, (std::string(what) + "[" + std::to_string(i) + "]").c_str());
      meshes.push_back(&mesh);
      held.push_back(std::move(item));
    }
  }
  auto range() const {
    return meshes |
           std::views::transform([](const mesh::Surface_mesh_animation* m) -> const mesh::Surface_mesh_animation& { return *m; });
  }
};

py::array matrix(const py::sequence& animations, const std::optional<py::sequence>& database, const std::string& policy,
                 const std::optional<std::string>& alignment, std::optional<double> threshold,
                 const std::optional<std::string>& up, const std::optional<py::function>& progress) {
  const similarity::Policy_choice choice = policy_choice(policy, alignment, threshold, up);
  similarity::check_policy_choice(choice);
  const Animation_list rows(animations, "animations");
  const std::optional<Animation_list> columns =
      database ? std::optional<Animation_list>(std::in_place, *database, "database") : std::nullopt;
  similarity::Similarity_progress report;
  if (progress)
    report = [&progress](std::size_t done, std::size_t total) {
      py::gil_scoped_acquire acquire;
      const py::object go = (*progress)(done, total);
      return go.is_none() || go.cast<bool>();
    };
  Eigen::MatrixXd m = similarity::with_policy_choice(choice, [&](const auto& p) {
    Interruptible_call call;
    return columns ? similarity::similarity_matrix(rows.range(), columns->range(), p, report)
                   : similarity::similarity_matrix(rows.range(), p, report);
  });
  const auto r = py::ssize_t(m.rows()), c = py::ssize_t(m.cols()), item = py::ssize_t(sizeof(double));
  return owning(std::move(m), +[](const Eigen::MatrixXd& x) { return x.data(); }, {r, c}, {item, r * item});
}

std::vector<similarity::Motion_match> find(const Animation& query, const Animation& long_animation, std::size_t count,
                               double shortest) {
  if (count == 0) refuse("count must be at least 1");
  if (!(shortest > 0 && shortest <= 1)) refuse("shortest must be in (0, 1]");
  Interruptible_call call;
  return similarity::find_motion(query.mesh, long_animation.mesh, {.count = count, .shortest = shortest});
}

// ---- Retrieval evaluation ------------------------------------------------------------------------

std::string field_of(const py::handle& item, const char* name) {
  if (py::isinstance<py::dict>(item)) {
    const auto d = py::reinterpret_borrow<py::dict>(item);
    return d.contains(name) && !d[name].is_none() ? py::str(d[name]).cast<std::string>() : std::string();
  }
  if (py::hasattr(item, name) && !item.attr(name).is_none()) return py::str(item.attr(name)).cast<std::string>();
  return {};
}

// Item `index` of evaluate's labels: a motion name, or a dict or an object with `motion` and
// optionally `body`, `rig`, `clip` (and `file`). The body defaults to the file, as in a labels
// file, else to the item alone: then every other item is a candidate of its query.
evaluation::Labelled_item labelled_item(const py::handle& item, std::size_t index) {
  const std::string where = "labels[" + std::to_string(index) + "]";
  evaluation::Labelled_item l;
  if (py::isinstance<py::str>(item)) {
    l.motion = item.cast<std::string>();
  } else if (py::isinstance<py::dict>(item) || py::hasattr(item, "motion")) {
    l = {field_of(item, "motion"), field_of(item, "body"), field_of(item, "rig"), field_of(item, "clip")};
    if (l.body.empty()) l.body = field_of(item, "file");
  } else {
    throw py::type_error(where + ": expected a motion name (str), a dict or an object with a 'motion', got " +
                         py::str(py::type::of(item).attr("__name__")).cast<std::string>());
  }
  if (l.motion.empty()) throw py::value_error(where + ": no motion (a name, or '-' for a distractor)");
  // A body no given name can equal (it starts with a NUL character): the item's own.
  if (l.body.empty()) l.body = std::string(1, '\0') + "item " + std::to_string(index);
  return l;
}

evaluation::Retrieval_scores evaluate(const py::array_t<double, py::array::forcecast>& similarity, const py::sequence& labels) {
  if (similarity.ndim() != 2 || similarity.shape(0) != similarity.shape(1))
    throw py::value_error("similarity: expected a square (N, N) array, got " + shape_of(similarity));
  if (std::size_t(similarity.shape(0)) != labels.size())
    throw py::value_error("similarity is " + shape_of(similarity) + " but there are " + std::to_string(labels.size()) +
                          " labels");
  std::vector<evaluation::Labelled_item> items;
  for (std::size_t i = 0; i < labels.size(); ++i) items.push_back(labelled_item(labels[i], i));
  const auto n = Eigen::Index(similarity.shape(0));
  Eigen::MatrixXd m(n, n);
  const auto read = similarity.unchecked<2>();
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) m(i, j) = read(i, j);
  Interruptible_call call;
  return evaluation::evaluate_retrieval(m, items);
}

py::list motion_labels(const std::filesystem::path& path) {
  const std::vector<io::Labelled_clip> clips = io::read_motion_labels(path);
  py::list out;
  for (const auto& c : clips) {
    py::dict d;
    d["file"] = c.file.string();
    d["clip"] = c.item.clip;
    d["motion"] = c.item.motion;
    d["rig"] = c.item.rig;
    d["body"] = c.item.body;
    out.append(d);
  }
  return out;
}

// ---- Graph edit distance -------------------------------------------------------------------------

io::Labelled_graph labelled_graph(const std::vector<std::string>& labels,
                                  const std::vector<std::pair<std::size_t, std::size_t>>& edges, const char* which) {
  io::Labelled_graph g(labels.size());
  for (std::size_t v = 0; v < labels.size(); ++v) g[v] = labels[v];
  for (const auto& [u, v] : edges) {
    if (u >= labels.size() || v >= labels.size())
      throw py::value_error(std::string(which) + ": edge (" + std::to_string(u) + ", " + std::to_string(v) +
                            ") names a node past the last, " + std::to_string(labels.size()) + " nodes");
    if (u != v && !boost::edge(u, v, g).second) boost::add_edge(u, v, g);
  }
  return g;
}

ged::Ged_result graph_edit_distance(const std::vector<std::string>& labels_a,
                                    const std::vector<std::pair<std::size_t, std::size_t>>& edges_a,
                                    const std::vector<std::string>& labels_b,
                                    const std::vector<std::pair<std::size_t, std::size_t>>& edges_b,
                                    const std::string& method, std::size_t max_expanded, double max_seconds) {
  if (method != "exact" && method != "bipartite" && method != "lower")
    refuse("method must be 'exact', 'bipartite' or 'lower', got '" + method + "'");
  if (!(max_seconds >= 0)) refuse("max_seconds must be non-negative");
  const io::Labelled_graph a = labelled_graph(labels_a, edges_a, "g1"), b = labelled_graph(labels_b, edges_b, "g2");
  Interruptible_call call;
  if (method == "bipartite") return ged::Bipartite_ged{}(a, b, ged::Unit_costs{});
  if (method == "lower") return ged::Assignment_lower_bound{}(a, b, ged::Unit_costs{});
  return ged::Exact_ged{.max_expanded = max_expanded, .max_seconds = max_seconds}(a, b, ged::Unit_costs{});
}

std::optional<double> bound_or_none(double x) { return std::isinf(x) ? std::nullopt : std::optional(x); }

// ---- Pickling ------------------------------------------------------------------------------------
// Every result pickles, so that it can come back from a worker process: __getstate__ gives a tuple
// (version, fields...) of plain Python values and NumPy arrays, __setstate__ checks it and rebuilds
// the C++ value. A layout that changes takes a new version; a state of another version or layout
// is refused with a ValueError naming the class.

constexpr int pickle_version = 1;

[[noreturn]] void refuse_state(const char* type, const std::string& why) {
  throw py::value_error(std::string("deformseg.") + type + ": cannot restore a pickled state: " + why);
}

// The fields of `state` after its version: `state` must be a tuple of the version `pickle_version`
// and `fields` values, laid out as `layout` says (for the message).
py::tuple state_fields(const py::object& pickled, const char* type, std::size_t fields, const char* layout) {
  const std::string expected = std::string("expected the tuple ") + layout;
  if (!py::isinstance<py::tuple>(pickled))
    refuse_state(type, expected + ", got a " + py::str(py::type::of(pickled).attr("__name__")).cast<std::string>());
  const auto state = py::reinterpret_borrow<py::tuple>(pickled);
  if (state.size() != fields + 1) refuse_state(type, expected + ", got " + std::to_string(state.size()) + " items");
  if (!py::isinstance<py::int_>(state[0]) || state[0].cast<long long>() != pickle_version)
    refuse_state(type, "state version " + py::repr(state[0]).cast<std::string>() + ", this deformseg reads version " +
                           std::to_string(pickle_version) + " (pickled by another version of deformseg?)");
  return py::tuple(state[py::slice(1, py::ssize_t(fields + 1), 1)]);
}

// Field `index` of `fields` as a T, or a ValueError naming the class and the field.
template <class T>
T state_field(const py::tuple& fields, std::size_t index, const char* type, const char* name) {
  try {
    return fields[index].cast<T>();
  } catch (const py::cast_error&) {
    refuse_state(type, std::string("field '") + name + "' is a " +
                           py::str(py::type::of(fields[index]).attr("__name__")).cast<std::string>() +
                           ", not of the type pickled");
  }
}

// The members of Repair_report in the order of its counts(), to restore them by name.
constexpr std::array repair_members{
    &io::Repair_report::input_vertices,        &io::Repair_report::input_triangles,
    &io::Repair_report::welded_vertices,       &io::Repair_report::degenerate_triangles,
    &io::Repair_report::duplicate_triangles,   &io::Repair_report::non_manifold_edges,
    &io::Repair_report::non_manifold_vertices, &io::Repair_report::duplicated_vertices,
    &io::Repair_report::reoriented_triangles,  &io::Repair_report::unrepairable_triangles,
    &io::Repair_report::vertices,              &io::Repair_report::triangles};
static_assert(repair_members.size() == std::tuple_size_v<decltype(io::Repair_report{}.counts())>);

std::optional<io::Repair_report> repair_of_state(const py::handle& value) {
  if (value.is_none()) return std::nullopt;
  if (!py::isinstance<py::dict>(value)) refuse_state("Animation", "field 'repair' is neither a dict nor None");
  const auto counts = py::reinterpret_borrow<py::dict>(value);
  io::Repair_report report;
  for (std::size_t k = 0; k < repair_members.size(); ++k) {
    const std::string_view name = report.counts()[k].first;
    const py::str key(name.data(), name.size());
    if (!counts.contains(key)) refuse_state("Animation", "field 'repair' has no count '" + std::string(name) + "'");
    report.*repair_members[k] = state_field<std::size_t>(py::make_tuple(counts[key]), 0, "Animation", "repair");
  }
  return report;
}

// Animation: (1, faces (F, 3) uint32, frames (T, V, 3) float64, fps, repair dict or None). The
// frames are copied bit for bit; the connectivity is rebuilt from the faces in their order.
py::object animation_state(const py::object& self) {
  const Animation& a = self.cast<const Animation&>();
  return py::make_tuple(pickle_version, self.attr("faces"), self.attr("frames"), a.mesh.frames_per_second(),
                        a.repair ? py::object(repair_dict(*a.repair)) : py::object(py::none()));
}

Animation animation_of_state(const py::object& state) {
  const py::tuple f = state_fields(state, "Animation", 4, "(1, faces, frames, fps, repair)");
  const auto faces = py::array::ensure(f[0]), frames = py::array::ensure(f[1]);
  if (!faces || (faces.dtype().kind() != 'i' && faces.dtype().kind() != 'u'))
    refuse_state("Animation", "field 'faces' is not an array of integers");
  if (!frames || frames.dtype().kind() != 'f' || frames.itemsize() != 8)
    refuse_state("Animation", "field 'frames' is not an array of float64");
  Animation a = animation_of_arrays(faces, frames, state_field<double>(f, 2, "Animation", "fps"));
  a.repair = repair_of_state(f[3]);
  return a;
}

// Similarity: (1, value, score, alignment, labels_a, labels_b, compared, z_score, shuffled_copies).
py::object similarity_state(const Similarity_result& r) {
  const similarity::Similarity& s = r.similarity;
  return py::make_tuple(pickle_version, s.value, s.score, s.alignment, s.labels_a, s.labels_b, s.compared, r.z_score,
                        r.shuffled_copies);
}

Similarity_result similarity_of_state(const py::object& state) {
  constexpr const char* type = "Similarity";
  const py::tuple f = state_fields(
      state, type, 8, "(1, value, score, alignment, labels_a, labels_b, compared, z_score, shuffled_copies)");
  Similarity_result r;
  r.similarity.value = state_field<double>(f, 0, type, "value");
  r.similarity.score = state_field<double>(f, 1, type, "score");
  r.similarity.alignment = state_field<decltype(r.similarity.alignment)>(f, 2, type, "alignment");
  r.similarity.labels_a = state_field<std::vector<std::size_t>>(f, 3, type, "labels_a");
  r.similarity.labels_b = state_field<std::vector<std::size_t>>(f, 4, type, "labels_b");
  r.similarity.compared = state_field<std::string>(f, 5, type, "compared");
  r.z_score = state_field<std::optional<double>>(f, 6, type, "z_score");
  r.shuffled_copies = state_field<std::size_t>(f, 7, type, "shuffled_copies");
  return r;
}

// MotionMatch: (1, first, last, value, alignment).
py::object motion_match_state(const similarity::Motion_match& m) {
  return py::make_tuple(pickle_version, m.first, m.last, m.value, m.alignment);
}

similarity::Motion_match motion_match_of_state(const py::object& state) {
  constexpr const char* type = "MotionMatch";
  const py::tuple f = state_fields(state, type, 4, "(1, first, last, value, alignment)");
  return {.first = state_field<std::size_t>(f, 0, type, "first"),
          .last = state_field<std::size_t>(f, 1, type, "last"),
          .value = state_field<double>(f, 2, type, "value"),
          .alignment = state_field<decltype(similarity::Motion_match::alignment)>(f, 3, type, "alignment")};
}

// RetrievalScores: (1, queries, queries_without_relevant, queries_without_candidate, nn_accuracy,
// mean_average_precision, roc_auc, median_same, median_different, same_pairs, different_pairs,
// labels, confusion, per_motion, per_query), per_motion and per_query as lists of tuples in the
// order of the members of Motion_retrieval and Query_retrieval.
constexpr const char* retrieval_layout =
    "(1, queries, queries_without_relevant, queries_without_candidate, nn_accuracy, mean_average_precision, "
    "roc_auc, median_same, median_different, same_pairs, different_pairs, labels, confusion, per_motion, per_query)";

py::object retrieval_state(const evaluation::Retrieval_scores& s) {
  py::list per_motion, per_query;
  for (const evaluation::Motion_retrieval& m : s.per_motion)
    per_motion.append(py::make_tuple(m.motion, m.queries, m.correct, m.nn_accuracy));
  for (const evaluation::Query_retrieval& q : s.per_query)
    per_query.append(
        py::make_tuple(q.query, q.nearest, q.nearest_similarity, q.first_relevant_rank, q.average_precision));
  return py::make_tuple(pickle_version, s.queries, s.queries_without_relevant, s.queries_without_candidate,
                        s.nn_accuracy, s.mean_average_precision, s.roc_auc, s.median_same, s.median_different,
                        s.same_pairs, s.different_pairs, s.labels, s.confusion, per_motion, per_query);
}

evaluation::Retrieval_scores retrieval_of_state(const py::object& state) {
  constexpr const char* type = "RetrievalScores";
  const py::tuple f = state_fields(state, type, 14, retrieval_layout);
  using Motion_tuple = std::tuple<std::string, std::size_t, std::size_t, double>;
  using Query_tuple =
      std::tuple<std::size_t, std::size_t, double, std::optional<std::size_t>, std::optional<double>>;
  evaluation::Retrieval_scores s;
  s.queries = state_field<std::size_t>(f, 0, type, "queries");
  s.queries_without_relevant = state_field<std::size_t>(f, 1, type, "queries_without_relevant");
  s.queries_without_candidate = state_field<std::size_t>(f, 2, type, "queries_without_candidate");
  s.nn_accuracy = state_field<std::optional<double>>(f, 3, type, "nn_accuracy");
  s.mean_average_precision = state_field<std::optional<double>>(f, 4, type, "mean_average_precision");
  s.roc_auc = state_field<std::optional<double>>(f, 5, type, "roc_auc");
  s.median_same = state_field<std::optional<double>>(f, 6, type, "median_same");
  s.median_different = state_field<std::optional<double>>(f, 7, type, "median_different");
  s.same_pairs = state_field<std::size_t>(f, 8, type, "same_pairs");
  s.different_pairs = state_field<std::size_t>(f, 9, type, "different_pairs");
  s.labels = state_field<std::vector<std::string>>(f, 10, type, "labels");
  s.confusion = state_field<std::vector<std::vector<std::size_t>>>(f, 11, type, "confusion");
  for (const auto& [motion, queries, correct, accuracy] :
       state_field<std::vector<Motion_tuple>>(f, 12, type, "per_motion"))
    s.per_motion.push_back({.motion = motion, .queries = queries, .correct = correct, .nn_accuracy = accuracy});
  for (const auto& [query, nearest, similarity, rank, precision] :
       state_field<std::vector<Query_tuple>>(f, 13, type, "per_query"))
    s.per_query.push_back({.query = query, .nearest = nearest, .nearest_similarity = similarity,
                           .first_relevant_rank = rank, .average_precision = precision});
  return s;
}

// GedResult: (1, distance, exact, lower, upper, mapping), upper as stored (inf for none).
py::object ged_state(const ged::Ged_result& r) {
  return py::make_tuple(pickle_version, r.distance, r.exact, r.lower, r.upper, r.mapping);
}

ged::Ged_result ged_of_state(const py::object& state) {
  constexpr const char* type = "GedResult";
  const py::tuple f = state_fields(state, type, 5, "(1, distance, exact, lower, upper, mapping)");
  return {.distance = state_field<double>(f, 0, type, "distance"), .exact = state_field<bool>(f, 1, type, "exact"),
          .lower = state_field<double>(f, 2, type, "lower"), .upper = state_field<double>(f, 3, type, "upper"),
          .mapping = state_field<std::vector<int>>(f, 4, type, "mapping")};
}

}  // namespace

PYBIND11_MODULE(_deformseg, m) {
  m.doc() = "The compiled half of deformseg; import `deformseg`, which re-exports it.";
  using namespace pybind11::literals;

  // invalid_input -> InvalidInput(ValueError), its message kept, its location as attributes.
  static py::exception<invalid_input> invalid(m, "InvalidInput", PyExc_ValueError);
  invalid.doc() = "Input that breaks a documented precondition (deformseg::invalid_input). A ValueError whose "
                  "message reads 'FILE:LINE: frame K: MESSAGE' (unknown parts left out); `file` (str or None), "
                  "`line` (int or None, from 1) and `frame` (int or None, from 0) give the parts.";
  static py::exception<similarity::similarity_stopped> stopped(m, "SimilarityStopped", PyExc_RuntimeError);
  stopped.doc() = "similarity_matrix was stopped: its progress callback returned False.";
  py::register_exception_translator([](std::exception_ptr error) {
    if (!error) return;
    try {
      std::rethrow_exception(error);
    } catch (const invalid_input& e) {
      py::object instance = py::reinterpret_borrow<py::object>(invalid.ptr())(e.what());
      const Input_location& w = e.where();
      instance.attr("file") = w.file.empty() ? py::object(py::none()) : py::str(w.file);
      instance.attr("line") = w.line ? py::object(py::int_(*w.line)) : py::object(py::none());
      instance.attr("frame") = w.frame ? py::object(py::int_(*w.frame)) : py::object(py::none());
      instance.attr("message") = e.message();
      PyErr_SetObject(invalid.ptr(), instance.ptr());
    } catch (const similarity::similarity_stopped& e) {
      stopped(e.what());
    }
  });

  py::class_<Animation>(m, "Animation", R"doc(An animation of one triangle mesh: fixed connectivity, vertex positions per frame.

Animation(faces, frames, fps=30): from an (F, 3) integer array of vertex indices (each triangle
counter-clockwise seen from outside; together an oriented 2-manifold, with or without boundary)
and a (T, V, 3) float32 or float64 array of positions, sampled at `fps` frames per second.
Raises TypeError for another dtype, ValueError for another shape, InvalidInput for an index out
of range, a non-manifold or inconsistently oriented triangle, a non-finite coordinate (naming the
triangle, or the frame and vertex), or an fps that is not positive. No repair is made: vertex i and face j stay the i-th and j-th given.

What is copied: the library stores one contiguous block of float64 (x, y, z per vertex, frame
after frame) that it owns, so `frames` is copied once: straight from a C-contiguous float32 or
float64 array (float32 converted on the way), through one NumPy conversion first from any other
layout. `frames` and `faces` are then read-only views of that storage, no copy.
Complexity O(T V + F).)doc")
      .def(py::init(&animation_of_arrays), "faces"_a, "frames"_a, "fps"_a = 30.0)
      .def(py::pickle(&animation_state, &animation_of_state))
      .def_property_readonly(
          "frames",
          [](const py::object& self) {
            const mesh::Surface_mesh_animation& a = self.cast<const Animation&>().mesh;
            return view(a.all_positions().data(),
                        {py::ssize_t(a.num_frames()), py::ssize_t(a.num_vertices()), py::ssize_t(3)}, self);
          },
          "The (T, V, 3) float64 positions: a read-only view of the animation's own storage (no copy), "
          "valid as long as it is referenced.")
      .def_property_readonly(
          "faces",
          [](const py::object& self) {
            const mesh::Surface_mesh_animation& a = self.cast<const Animation&>().mesh;
            static_assert(sizeof(mesh::Surface_mesh_animation::Triangle) == 3 * sizeof(std::uint32_t));
            const auto* indices = reinterpret_cast<const std::uint32_t*>(a.triangles().data());
            return view(indices, {py::ssize_t(a.num_faces()), py::ssize_t(3)}, self);
          },
          "The (F, 3) uint32 vertex indices of the triangles: a read-only view (no copy).")
      .def_property_readonly("num_frames", [](const Animation& a) { return a.mesh.num_frames(); },
                             "T, the number of frames.")
      .def_property_readonly("fps", [](const Animation& a) { return a.mesh.frames_per_second(); },
                             "The frame rate, in frames per second: the motion signatures measure rates per "
                             "second, so that the same motion sampled at any rate compares as the same.")
      .def_property_readonly("num_vertices", [](const Animation& a) { return a.mesh.num_vertices(); },
                             "V, the number of vertices.")
      .def_property_readonly("num_faces", [](const Animation& a) { return a.mesh.num_faces(); },
                             "F, the number of triangles.")
      .def_property_readonly(
          "repair",
          [](const Animation& a) { return a.repair ? py::object(repair_dict(*a.repair)) : py::object(py::none()); },
          "What the reader's repair changed, as a dict of counts (the keys of the tool's `info --json` "
          "'repair': input_vertices, welded_vertices, degenerate_triangles, ..., vertices, triangles); "
          "None for an animation made from arrays.")
      .def("__repr__", [](const Animation& a) {
        return "<deformseg.Animation: " + std::to_string(a.mesh.num_frames()) + " frames, " +
               std::to_string(a.mesh.num_vertices()) + " vertices, " + std::to_string(a.mesh.num_faces()) + " triangles>";
      });

  m.def("read_animation", &read_input, "path"_a, "clip"_a = py::none(), "fps"_a = 30.0, "topology"_a = py::none(),
        "triangulate"_a = false, "weld"_a = py::none(), "refuse_defects"_a = false, "threads"_a = 0,
        R"doc(Reads an animation: a glTF clip (.glb, .gltf; clip by name or index, or "FILE.glb#CLIP";
needed when the file holds several, which are then listed in the error; a file of one clip gives
it), a folder of frame files (.obj, .off, .ply, in natural order), a glob pattern, or a point
cache (.pc2, .mdd) with `topology` (a mesh file). `fps` (default 30) is the frame rate of every
format (`Animation.fps`): a glTF clip is sampled at it; frame files and point caches, whose files
do not say their rate, are taken to be sampled at it.

`triangulate` (default False) fans polygons; `weld` (default: True for glTF, False otherwise)
merges vertices that coincide in every frame (for glTF, by what the file fixes: the same rest
position, skin weights and morph deltas, so that every clip of a file has one mesh, the same
vertices and triangles); degenerate, duplicate and non-manifold triangles
are repaired unless `refuse_defects` (default False); `threads` (default 0: all, at most 1024) read
in parallel. `Animation.repair` says what the repair changed. Raises InvalidInput naming the file,
line and frame of the first problem, or for an option that does not apply (clip for frames,
topology for glTF), as the tool does. Complexity linear in the input's size. Releases the GIL.)doc");

  m.def("strain", &strain, "animation"_a, py::kw_only(), "reference"_a = "rest", "rest_frame"_a = 0,
        "reference_mesh"_a = py::none(), "measure"_a = "max-principal", "normalize"_a = "gaussian", "sigma"_a = py::none(),
        "degenerate_tolerance"_a = 1e-12, "threads"_a = 0,
        R"doc(The strain of every triangle at every frame: a (T, F) float32 array, row t the frame t
(compute_strain; Strain_options' defaults).

reference: "rest" (default; against frame `rest_frame`, default 0) or "previous" (against the
frame before; frame 0's strain is 0). reference_mesh (default None): a mesh file (.obj, .off,
.ply) with the animation's connectivity in another pose, a rest pose kept apart from the frames,
in the place of frame `rest_frame`. measure: "max-principal" (default, max |l - 1| over the
principal stretches l), "green-lagrange", "frobenius" or "area-ratio". normalize: "gaussian"
(default, 1 - exp(-s^2 / 2 sigma^2), sigma the 95th percentile of the strains unless `sigma` gives
it) or "none" (raw strains). degenerate_tolerance (default 1e-12): reference triangles thinner than
this have strain 0. threads: 0 (default) all, at most 1024; the result is the same for any number.
Invariant to rotation, translation and uniform scale of the whole animation. The array owns the
library's result (no copy). Complexity O(T F). Releases the GIL.)doc");

  m.def("frame_distances", &distances, "animation"_a, py::kw_only(), "metric"_a = "euclidean", "rest_frame"_a = 0,
        "reference_mesh"_a = py::none(), "threads"_a = 0,
        R"doc(The (T, T) float32 matrix of distances between the frames' normalised rest-pose strains
(the frame descriptors of the temporal segmentation): metric "euclidean" (default), "l1" or
"cosine"; the strain against frame `rest_frame` (default 0), or against `reference_mesh` (default
None; as in `strain`). Symmetric, zero diagonal; a
Fortran-ordered array that owns the library's matrix (no copy). Complexity O(T F) for the strain,
O(T^2 F) for the distances. Releases the GIL.)doc");

  m.def("temporal_segmentation", &temporal, "animation"_a, py::kw_only(), "method"_a = "optimal",
        "threshold"_a = py::none(), "absolute"_a = false, "segments"_a = py::none(), "min_length"_a = 1,
        "metric"_a = "euclidean", "rest_frame"_a = 0, "reference_mesh"_a = py::none(), "threads"_a = 0,
        R"doc(Intervals of similar poses: a list of (first, last) frame intervals, inclusive, covering
0..T-1 in order, from the frame distances of `frame_distances(animation, metric=..., rest_frame=...,
reference_mesh=...)`.

method: "optimal" (default; least length-weighted cost with a penalty per segment, or exactly
`segments` segments), "binary-split", "greedy" (the thesis' Algorithm 4-1) or "barbic" (PCA change
detection). threshold: binary-split and greedy, the largest within-segment dissimilarity (default
0.5 and 0.2); optimal, the penalty per segment (default 0.03); relative to the mean frame distance
(optimal: to the one-segment cost) unless `absolute`. min_length (default 1): fewest frames of a
segment (optimal, binary-split). Complexity O(T^2 F) for the distances, then the method's
(optimal: O(T^2) per segment count). Releases the GIL.)doc");

  m.def("_evolving_graph", &evolving, "animation"_a, "threshold"_a = 0.5, "reference"_a = py::none(),
        "reference_mesh"_a = py::none(), "min_triangles"_a = 10, "min_frames"_a = 2, "max_island"_a = 30,
        "The evolving graph as tuples; `deformseg.evolving_graph` makes it an EvolvingGraph. Releases the GIL.");

  py::class_<Similarity_result>(m, "Similarity", "What `similarity` gives: how alike two animations move.")
      .def(py::pickle(&similarity_state, &similarity_of_state))
      .def_property_readonly("value", [](const Similarity_result& s) { return s.similarity.value; },
                             "The similarity in [0, 1]: 1 for an animation and itself (or a moved, scaled copy).")
      .def_property_readonly("score", [](const Similarity_result& s) { return s.similarity.score; },
                             "The alignment's raw score (its sense is the alignment policy's).")
      .def_property_readonly("alignment", [](const Similarity_result& s) { return s.similarity.alignment; },
                             "The aligned frames: a list of (frame of a, frame of b), increasing in both.")
      .def_property_readonly("labels_a", [](const Similarity_result& s) { return s.similarity.labels_a; },
                             "Per frame of a, the label aligned (graph policy: its key frame's cluster); else [].")
      .def_property_readonly("labels_b", [](const Similarity_result& s) { return s.similarity.labels_b; },
                             "Per frame of b, as labels_a.")
      .def_property_readonly("compared", [](const Similarity_result& s) { return s.similarity.compared; },
                             "What the policy compared, in words.")
      .def_property_readonly("z_score", [](const Similarity_result& s) { return s.z_score; },
                             "The z-score of value against frame-shuffled copies of b, or None.")
      .def_property_readonly("shuffled_copies", [](const Similarity_result& s) { return s.shuffled_copies; },
                             "How many shuffled copies the z-score was computed against (0: none).")
      .def("__repr__", [](const Similarity_result& s) {
        return "<deformseg.Similarity value=" + std::to_string(s.similarity.value) + ", " +
               std::to_string(s.similarity.alignment.size()) + " aligned pairs>";
      });

  m.def("similarity", &similarity, "a"_a, "b"_a, py::kw_only(), "policy"_a = "motion-signature",
        "alignment"_a = py::none(), "threshold"_a = py::none(), "up"_a = py::none(), "significance"_a = py::none(),
        "seed"_a = 1u,
        R"doc(How alike two animations move (motion_similarity), as the tool's `similarity` command.

policy: "motion-signature" (default, Default_similarity: per-frame distributions of how fast,
and how fast up or down, the surface moves), "histogram" (strain histograms; its values crowd near
1: the Knight's Walking_A against a frozen copy of itself 0.997, against its Death_A 0.996, so
read the z-score or a rank, not the value), "graph" (the thesis' evolving graphs) or
"self-similarity". alignment: "smith-waterman", "dtw" or
"subsequence-dtw" (default: dtw for motion-signature, smith-waterman otherwise). threshold: the
graph policy's deformed threshold in [0, 1] (default 0.5). up: the motion signatures' up axis,
"+x", "-x", "+y", "-y", "+z", "-z" or "none" for speeds alone (default "+y"). significance: the number of frame-shuffled copies of b the z-score is
computed against (default 20, none for the graph policy; 0 none), shuffled by a std::mt19937
seeded with `seed` (default 1). Returns a Similarity (value, score, alignment, z_score, ...).
Complexity: the policy's describe of each, one compare, plus one compare per shuffled copy
(motion-signature with DTW: O(T V) to describe, O(Ta Tb) to compare). Releases the GIL.)doc");

  m.def("similarity_matrix", &matrix, "animations"_a, "database"_a = py::none(), py::kw_only(),
        "policy"_a = "motion-signature", "alignment"_a = py::none(), "threshold"_a = py::none(), "up"_a = py::none(),
        "progress"_a = py::none(),
        R"doc(The similarity of every pair of `animations`: an (N, N) float64 array, symmetric, entry (i, j)
equal to similarity(animations[i], animations[j], ...).value; or, with `database`, the (Q, D)
array of each animation against each of the database. Each animation is described once, then
pairs are compared in parallel; the result does not depend on the number of threads.
policy (default "motion-signature"), alignment (default: the policy's), threshold (default: the
graph policy's), up (default "+y"): as `similarity`. progress (default None): called as progress(done, total) on the
calling thread (with the GIL) as the work advances, N + N (N + 1) / 2 steps (Q + D + Q D with a
database); returning False stops the work and raises SimilarityStopped. The animations are not
copied. Complexity N describes and N (N + 1) / 2 compares. Releases the GIL.)doc");

  py::class_<similarity::Motion_match>(m, "MotionMatch", "A window of a long animation that matches a query (find_motion).")
      .def(py::pickle(&motion_match_state, &motion_match_of_state))
      .def_readonly("first", &similarity::Motion_match::first, "The window's first frame in the long animation.")
      .def_readonly("last", &similarity::Motion_match::last, "Its last frame (inclusive).")
      .def_readonly("value", &similarity::Motion_match::value,
                    "The similarity of the query to the window's frames cut out as an animation of their own, "
                    "in [0, 1]: 1 for an exact, moved or scaled copy.")
      .def_readonly("alignment", &similarity::Motion_match::alignment,
                    "The warping path: (frame of the query, frame of the long animation).")
      .def("__repr__", [](const similarity::Motion_match& x) {
        return "<deformseg.MotionMatch frames " + std::to_string(x.first) + "-" + std::to_string(x.last) +
               " value=" + std::to_string(x.value) + ">";
      });

  m.def("find_motion", &find, "query"_a, "long_animation"_a, "count"_a = 1, py::kw_only(), "shortest"_a = 0.5,
        R"doc(Where a short motion occurs in a long animation: at most `count` (default 1, as
Find_motion_options; the tool's `find` asks for 3) non-overlapping windows of `long_animation`,
best first, each a MotionMatch (first, last, value, alignment), by motion signatures: windows
proposed by a slope-bounded subsequence DTW, each re-described alone and scored against the query
(value 1 for an exact, moved or scaled copy, found at its frames). shortest (default 0.5): a
window lasts from `shortest` to 1 / `shortest` times the query's duration. Complexity two
descriptions, O(count Tq Tl / shortest^2), then a few descriptions of candidate windows per match.
Releases the GIL.)doc");

  py::class_<evaluation::Retrieval_scores>(m, "RetrievalScores", "The figures of `evaluate` (evaluate_retrieval).")
      .def(py::pickle(&retrieval_state, &retrieval_of_state))
      .def_readonly("queries", &evaluation::Retrieval_scores::queries, "Queries evaluated.")
      .def_readonly("queries_without_relevant", &evaluation::Retrieval_scores::queries_without_relevant,
                    "Queries with no candidate of their motion.")
      .def_readonly("queries_without_candidate", &evaluation::Retrieval_scores::queries_without_candidate,
                    "Items left out for having no candidate at all.")
      .def_readonly("nn_accuracy", &evaluation::Retrieval_scores::nn_accuracy, "Fraction of queries whose nearest candidate has their motion, or None.")
      .def_readonly("mean_average_precision", &evaluation::Retrieval_scores::mean_average_precision, "mAP, or None.")
      .def_readonly("roc_auc", &evaluation::Retrieval_scores::roc_auc, "ROC-AUC over same- vs different-motion pairs, or None.")
      .def_readonly("median_same", &evaluation::Retrieval_scores::median_same, "Median similarity of same-motion pairs, or None.")
      .def_readonly("median_different", &evaluation::Retrieval_scores::median_different, "Median of different-motion pairs, or None.")
      .def_readonly("same_pairs", &evaluation::Retrieval_scores::same_pairs, "Number of same-motion pairs.")
      .def_readonly("different_pairs", &evaluation::Retrieval_scores::different_pairs, "Number of different-motion pairs.")
      .def_readonly("labels", &evaluation::Retrieval_scores::labels, "Every motion, sorted: the rows and columns of confusion.")
      .def_readonly("confusion", &evaluation::Retrieval_scores::confusion, "confusion[r][c]: queries of labels[r] whose nearest has labels[c].")
      .def_property_readonly(
          "per_motion",
          [](const evaluation::Retrieval_scores& s) {
            py::list out;
            for (const auto& x : s.per_motion)
              out.append(py::dict("motion"_a = x.motion, "queries"_a = x.queries, "correct"_a = x.correct,
                                  "nn_accuracy"_a = x.nn_accuracy));
            return out;
          },
          "Per query motion: dicts of motion, queries, correct, nn_accuracy.")
      .def_property_readonly(
          "per_query",
          [](const evaluation::Retrieval_scores& s) {
            py::list out;
            for (const auto& x : s.per_query)
              out.append(py::dict("query"_a = x.query, "nearest"_a = x.nearest,
                                  "nearest_similarity"_a = x.nearest_similarity,
                                  "first_relevant_rank"_a = x.first_relevant_rank,
                                  "average_precision"_a = x.average_precision));
            return out;
          },
          "Per query, in the items' order: dicts of query and nearest (item indices), nearest_similarity, "
          "first_relevant_rank (1 for the nearest; None without a candidate of its motion) and "
          "average_precision (or None).");

  m.def("evaluate", &evaluate, "similarity"_a, "labels"_a,
        R"doc(How well a similarity matrix retrieves the same motion on other bodies (evaluate_retrieval):
`similarity` an (N, N) array (as similarity_matrix gives), `labels` N items, each a motion name
(str) or a dict or an object with `motion` and optionally `body`, `rig`, `clip`, `file` (as
read_motion_labels gives); '-' as motion marks a distractor (a candidate, never a query). The
candidates of a query are the items of other bodies; an item's body defaults to its `file`, and
without either the item is a body of its own (so every other item is a candidate: a list of motion
names compares every item with every other). Raises TypeError for an item of another type,
ValueError for an item without a motion. Returns RetrievalScores: NN accuracy, mAP, ROC-AUC,
medians, the confusion table, and what each query found (items of one body have no candidate:
queries_without_candidate counts them). Complexity O(N^2 log N).)doc");

  m.def("read_motion_labels", &motion_labels, "path"_a,
        R"doc(The rows of a labels CSV file (header file,clip,motion[,rig][,body]; fields may be quoted
as spreadsheets and R write them): a list of dicts with
file (relative paths made relative to the CSV's folder), clip, motion, rig and body. Raises
InvalidInput naming the file and line of a bad row. Complexity O(rows).)doc");

  py::class_<ged::Ged_result>(m, "GedResult", "What `ged` gives: lower <= distance <= upper.")
      .def(py::pickle(&ged_state, &ged_of_state))
      .def_readonly("distance", &ged::Ged_result::distance, "The distance found (exact, or the best upper bound).")
      .def_readonly("exact", &ged::Ged_result::exact, "Whether distance is proven to be the graph edit distance.")
      .def_readonly("lower", &ged::Ged_result::lower, "A proven lower bound.")
      .def_property_readonly("upper", [](const ged::Ged_result& r) { return bound_or_none(r.upper); },
                             "The cost of mapping, an upper bound; None when there is none (a pure lower bound).")
      .def_readonly("mapping", &ged::Ged_result::mapping, "Node i of g1 -> node of g2, or -1 when i is deleted.")
      .def("__repr__", [](const ged::Ged_result& r) {
        return "<deformseg.GedResult distance=" + std::to_string(r.distance) + (r.exact ? " exact>" : ">");
      });

  m.def("_ged", &graph_edit_distance, "labels_a"_a, "edges_a"_a, "labels_b"_a, "edges_b"_a, "method"_a = "exact",
        "max_expanded"_a = ged::Exact_ged{}.max_expanded, "max_seconds"_a = 0.0,
        "The graph edit distance of two graphs given as node labels and edges; `deformseg.ged` takes graphs. "
        "Releases the GIL.");
  m.attr("EXACT_GED_MAX_EXPANDED") = ged::Exact_ged{}.max_expanded;
  m.attr("__version__") = DEFORMSEG_VERSION;
}
