// Similarity, similarity and similarity_matrix: how alike animations move.
#include "bindings.h"

#include "arrays.h"
#include "inputs.h"
#include "pickling.h"

#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/policy_choice.h>
#include <deformseg/similarity/significance.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <optional>
#include <random>
#include <ranges>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

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
    if constexpr (similarity::ReorderableDescription<std::remove_cvref_t<decltype(db)>>) {
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
                             type_name(item));
      const mesh::Surface_mesh_animation& mesh = item.cast<const Animation&>().mesh;
      require_motion(mesh, (std::string(what) + "[" + std::to_string(i) + "]").c_str());
      meshes.push_back(&mesh);
      held.push_back(std::move(item));
    }
  }
  auto range() const {
    return meshes |
           std::views::transform(
               [](const mesh::Surface_mesh_animation* m) -> const mesh::Surface_mesh_animation& { return *m; });
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
  Progress report;
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

}  // namespace

void bind_similarity(py::module_& m) {
  using namespace pybind11::literals;
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
}

}  // namespace deformseg::python
