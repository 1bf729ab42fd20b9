// Similarity, similarity and similarity_matrix: how alike animations move.
#include "bindings.h"

#include "arrays.h"
#include "inputs.h"
#include "parameters.h"
#include "pickling.h"
#include "store.h"

#include "frontend/similarity.h"

#include <deformseg/similarity/motion_similarity.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

constexpr auto similarity_table = std::tuple_cat(frontend::policy_parameters, frontend::comparison_parameters);

frontend::Compared similarity(const Animation& a, const Animation& b, const frontend::Policy_choice& choice,
                              const frontend::Comparison_request& significance, int threads) {
  frontend::check(choice, frontend::Front::python);
  frontend::check(significance, choice, frontend::Front::python);
  whole_argument("threads", threads, frontend::thread_counts);
  require_motion(a.mesh, "a");
  require_motion(b.mesh, "b");
  Interruptible_call call;
  return frontend::compare(a.mesh, b.mesh, choice, significance, threads);
}

// The animations of a Python sequence, by address (no copy); the Python objects stay referenced
// in `held` while the GIL is released.
struct Animation_list {
  std::vector<py::object> held;
  std::vector<const mesh::Surface_mesh_animation*> meshes;

  Animation_list(const py::sequence& animations, const char* what) {
    for (std::size_t i = 0; i < animations.size(); ++i) {
      py::object item = animations[i];
      if (!py::isinstance<Animation>(item))
        throw py::type_error(std::string(what) + "[" + std::to_string(i) + "]: expected an Animation, got " +
                             type_name(item));
      const mesh::Surface_mesh_animation& mesh = item.cast<const Animation&>().mesh;
      require_motion(mesh, (std::string(what) + "[" + std::to_string(i) + "]").c_str());
      meshes.push_back(&mesh);
      held.push_back(std::move(item));
    }
  }
};

py::array matrix(const py::object& animations, const std::optional<py::sequence>& database,
                 const frontend::Policy_choice& choice, const std::optional<py::function>& progress, int threads) {
  if (py::isinstance<Opened_store>(animations)) {  // the store's clips as described: the tool's matrix --store
    if (database) refuse("database: a MotionStore's matrix is of its own clips; search it for other animations");
    return stored_similarity_matrix(animations.cast<const Opened_store&>(), choice, progress_of(progress), threads);
  }
  if (!py::isinstance<py::sequence>(animations))
    throw py::type_error("animations: expected a sequence of Animation or a MotionStore, got " + type_name(animations));
  frontend::check(choice, frontend::Front::python);
  whole_argument("threads", threads, frontend::thread_counts);
  const Animation_list rows(py::reinterpret_borrow<py::sequence>(animations), "animations");
  const std::optional<Animation_list> columns =
      database ? std::optional<Animation_list>(std::in_place, *database, "database") : std::nullopt;
  const Progress report = progress_of(progress);
  Eigen::MatrixXd m;
  {
    Interruptible_call call;
    m = columns ? frontend::similarity_matrix(rows.meshes, columns->meshes, choice, report, threads)
                : frontend::similarity_matrix(rows.meshes, choice, report, threads);
  }
  const auto r = py::ssize_t(m.rows()), c = py::ssize_t(m.cols()), item = py::ssize_t(sizeof(double));
  return owning(std::move(m), +[](const Eigen::MatrixXd& x) { return x.data(); }, {r, c}, {item, r * item});
}

// Similarity: (1, value, score, alignment, labels_a, labels_b, compared, z_score, shuffled_copies).
py::object similarity_state(const frontend::Compared& r) {
  const similarity::Similarity& s = r.similarity;
  return py::make_tuple(pickle_version, s.value, s.score, s.alignment, s.labels_a, s.labels_b, s.compared, r.z_score,
                        r.shuffled_copies);
}

frontend::Compared similarity_of_state(const py::object& state) {
  constexpr const char* type = "Similarity";
  const py::tuple f = state_fields(
      state, type, 8, "(1, value, score, alignment, labels_a, labels_b, compared, z_score, shuffled_copies)");
  frontend::Compared r{};
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

}  // namespace

void bind_similarity(py::module_& m) {
  using namespace pybind11::literals;
  py::class_<frontend::Compared>(m, "Similarity", "What `similarity` gives: how alike two animations move.")
      .def(py::pickle(&similarity_state, &similarity_of_state))
      .def_property_readonly("value", [](const frontend::Compared& s) { return s.similarity.value; },
                             "The similarity in [0, 1]: 1 for an animation and itself (or a moved, scaled copy).")
      .def_property_readonly("score", [](const frontend::Compared& s) { return s.similarity.score; },
                             "The alignment's raw score (its sense is the alignment policy's).")
      .def_property_readonly("alignment", [](const frontend::Compared& s) { return s.similarity.alignment; },
                             "The aligned frames: a list of (frame of a, frame of b), increasing in both.")
      .def_property_readonly("labels_a", [](const frontend::Compared& s) { return s.similarity.labels_a; },
                             "Per frame of a, the label aligned (graph policies: its key frame's cluster); else [].")
      .def_property_readonly("labels_b", [](const frontend::Compared& s) { return s.similarity.labels_b; },
                             "Per frame of b, as labels_a.")
      .def_property_readonly("compared", [](const frontend::Compared& s) { return s.similarity.compared; },
                             "What the policy compared, in words.")
      .def_property_readonly("z_score", [](const frontend::Compared& s) { return s.z_score; },
                             "The z-score of value against frame-shuffled copies of b, or None.")
      .def_property_readonly("shuffled_copies", [](const frontend::Compared& s) { return s.shuffled_copies; },
                             "How many shuffled copies the z-score was computed against (0: none).")
      .def_property_readonly(
          "explanation",
          [](const frontend::Compared& s) -> py::object {
            if (!s.explanation) return py::none();
            return py::module_::import("json").attr("loads")(frontend::explanation_record(*s.explanation).dump());
          },
          "With explain=True (motion-signature): where the signatures differ along the alignment, a dict "
          "{'pairs', 'channels': [{'kind': 'speed' or 'vertical_rate', 'lag' (s), 'band' (0 the lowest), 'half': "
          "'lower' or 'upper', 'share' (of the squared differences, summing to 1), 'mean_difference' (a's less "
          "b's; for speeds a log ratio)}, ...]}; else None.")
      .def("__repr__", [](const frontend::Compared& s) {
        return "<deformseg.Similarity value=" + std::to_string(s.similarity.value) + ", " +
               std::to_string(s.similarity.alignment.size()) + " aligned pairs>";
      });

  define_function<similarity_table, Types<const Animation&, const Animation&>, Types<int>, frontend::Policy_choice,
                  frontend::Comparison_request>(
      m, "similarity",
      R"doc(How alike two animations move (motion_similarity), as the tool's `similarity` command.

The histogram policy's values crowd near 1 (chapter 7 of the manual gives figures): read the
z-score or a rank, not the value. The z-score is
computed against frame-shuffled copies of b, shuffled by a std::mt19937 seeded with `seed`.
With explain=True (motion-signature), Similarity.explanation says which time scales, height bands
(`bands`) and halves of the surface made the two alike or different.
Returns a Similarity (value, score, alignment, z_score, ...). Complexity: the policy's describe of
each, one compare, plus one compare per shuffled copy (motion-signature with DTW: O(T V) to
describe, O(Ta Tb) to compare). Each is described and the copies scored on `threads` threads
(default 0: all the hardware's, else 1 to the library's max_threads); the result does not depend
on their number. Releases the GIL.)doc",
      &similarity, std::tuple{py::arg("a"), py::arg("b"), py::kw_only()}, std::tuple{py::arg_v("threads", 0)});

  define_function<frontend::policy_parameters, Types<const py::object&, const std::optional<py::sequence>&>,
                  Types<const std::optional<py::function>&, int>, frontend::Policy_choice>(
      m, "similarity_matrix",
      R"doc(The similarity of every pair of `animations`: an (N, N) float64 array, symmetric, entry (i, j)
equal to similarity(animations[i], animations[j], ...).value; or, with `database`, the (Q, D)
array of each animation against each of the database. Each animation is described once, then
pairs are compared in parallel on `threads` threads (default 0: all the hardware's, else 1 to the
library's max_threads); the result does not depend on their number.
policy, alignment, threshold, up: as `similarity`. progress (default None): called as
progress(done, total) on the calling thread (with the GIL) as the work advances, N + N (N + 1) / 2
steps (Q + D + Q D with a database); returning False stops the work and raises SimilarityStopped.
The animations are not copied.
`animations` may be a MotionStore (open_store) instead, without a database: the matrix of its
clips as described, without reading or describing them (the tool's `matrix --store`); the
policy must then be the store's (motion-signature, dtw; `up`, when given, its own), else
InvalidInput naming the store. Complexity N describes and N (N + 1) / 2 compares. Releases the
GIL.)doc",
      &matrix, std::tuple{py::arg("animations"), py::arg_v("database", py::none()), py::kw_only()},
      std::tuple{py::arg_v("progress", py::none()), py::arg_v("threads", 0)});
}

}  // namespace deformseg::python
