// RetrievalScores, evaluate and read_motion_labels: how well a similarity retrieves the same motion.
#include "bindings.h"

#include "arrays.h"
#include "common.h"
#include "pickling.h"
#include "store.h"

#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/evaluation/retrieval_evaluation.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace py = pybind11;

namespace deformseg::python {
namespace {

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
                         type_name(item));
  }
  if (l.motion.empty()) throw py::value_error(where + ": no motion (a name, or '-' for a distractor)");
  // A body no given name can equal (it starts with a NUL character): the item's own.
  if (l.body.empty()) l.body = std::string(1, '\0') + "item " + std::to_string(index);
  return l;
}

// evaluate(MotionStore, LABELS.csv): the labelled clips as the store holds them.
evaluation::Retrieval_scores evaluate_of_store(const Opened_store& store, const py::object& labels) {
  if (!py::isinstance<py::str>(labels) && !py::hasattr(labels, "__fspath__"))
    throw py::type_error("labels: with a MotionStore, expected the path of a labels CSV (str or os.PathLike), got " +
                         type_name(labels));
  return evaluate_stored(store, labels.cast<std::filesystem::path>().string());
}

evaluation::Retrieval_scores evaluate(const py::object& similarity_like, const py::object& labels_like) {
  if (py::isinstance<Opened_store>(similarity_like))
    return evaluate_of_store(similarity_like.cast<const Opened_store&>(), labels_like);
  const auto similarity = py::array_t<double, py::array::forcecast>::ensure(similarity_like);
  if (!similarity)
    throw py::type_error("similarity: expected an (N, N) array or a MotionStore, got " + type_name(similarity_like));
  if (!py::isinstance<py::sequence>(labels_like))
    throw py::type_error("labels: expected a sequence of labels, got " + type_name(labels_like));
  const auto labels = py::reinterpret_borrow<py::sequence>(labels_like);
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
  const std::vector<evaluation::Labelled_clip> clips = evaluation::read_motion_labels(path);
  py::list out;
  for (const auto& c : clips) {
    py::dict d;
    d["file"] = c.file.string();
    d["clip"] = c.item.clip;
    d["motion"] = c.item.motion;
    d["rig"] = c.item.rig;
    d["body"] = c.item.body;
    d["body_file"] = c.body_file.string();
    out.append(d);
  }
  return out;
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

}  // namespace

void bind_evaluation(py::module_& m) {
  using namespace pybind11::literals;
  py::class_<evaluation::Retrieval_scores>(m, "RetrievalScores", "The figures of `evaluate` (evaluate_retrieval).")
      .def(py::pickle(&retrieval_state, &retrieval_of_state))
      .def_readonly("queries", &evaluation::Retrieval_scores::queries, "Queries evaluated.")
      .def_readonly("queries_without_relevant", &evaluation::Retrieval_scores::queries_without_relevant,
                    "Queries with no candidate of their motion.")
      .def_readonly("queries_without_candidate", &evaluation::Retrieval_scores::queries_without_candidate,
                    "Items left out for having no candidate at all.")
      .def_readonly("nn_accuracy", &evaluation::Retrieval_scores::nn_accuracy,
                    "Fraction of queries whose nearest candidate has their motion, or None.")
      .def_readonly("mean_average_precision", &evaluation::Retrieval_scores::mean_average_precision, "mAP, or None.")
      .def_readonly("roc_auc", &evaluation::Retrieval_scores::roc_auc,
                    "ROC-AUC over same- vs different-motion pairs, or None.")
      .def_readonly("median_same", &evaluation::Retrieval_scores::median_same,
                    "Median similarity of same-motion pairs, or None.")
      .def_readonly("median_different", &evaluation::Retrieval_scores::median_different,
                    "Median of different-motion pairs, or None.")
      .def_readonly("same_pairs", &evaluation::Retrieval_scores::same_pairs, "Number of same-motion pairs.")
      .def_readonly("different_pairs", &evaluation::Retrieval_scores::different_pairs,
                    "Number of different-motion pairs.")
      .def_readonly("labels", &evaluation::Retrieval_scores::labels,
                    "Every motion, sorted: the rows and columns of confusion.")
      .def_readonly("confusion", &evaluation::Retrieval_scores::confusion,
                    "confusion[r][c]: queries of labels[r] whose nearest has labels[c].")
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
queries_without_candidate counts them).
`similarity` may be a MotionStore (open_store) instead, with `labels` the path of a labels CSV
(read_motion_labels'), as the tool's `evaluate LABELS --store S`: the clip of each row (a glTF
row without a clip: the file's only one) is looked up in the store and compared as described,
without reading or describing it; the items are the rows, in their order. Raises InvalidInput
naming the store and listing the clips it lacks or holds as they were before their source
changed (checked as describe_to_store checks them, with the input options each was described
with). Complexity O(N^2 log N); with a store, plus N (N + 1) / 2 alignments.)doc");

  m.def("read_motion_labels", &motion_labels, "path"_a,
        R"doc(The rows of a labels CSV file (header file,clip,motion[,rig][,body][,body_file]; fields may
be quoted as spreadsheets and R write them): a list of dicts with file and body_file (relative
paths made relative to the CSV's folder; body_file empty when the row names none), clip, motion,
rig and body. Raises
InvalidInput naming the file and line of a bad row. Complexity O(rows).)doc");
}

}  // namespace deformseg::python
