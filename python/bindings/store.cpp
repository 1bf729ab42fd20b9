// MotionStore and open_store: searching a motion store (chapter 14), as the tool's search,
// knn-graph, matrix --store and evaluate --store do, through the same front end
// (frontend/store_search.h). Describing clips into a store: store_describe.cpp.
#include "bindings.h"
#include "store.h"

#include "arrays.h"
#include "inputs.h"
#include "parameters.h"
#include "pickling.h"

#include "frontend/store.h"

#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/search/nearest_motions.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace py = pybind11;
using namespace pybind11::literals;

namespace deformseg::python {

const std::array<frontend::Choice, 2> store_verifications{
    {{"structure", "the manifest, the files' sizes and headers, every clip's ranges: O(clips), the default"},
     {"checksums", "also the CRC-32 of every file and every clip's block: reads every byte"}}};

namespace {

store::Verify verify_of(const std::string& name) {
  frontend::check_choice("verify", name, store_verifications, frontend::Front::python);
  return name == "checksums" ? store::Verify::checksums : store::Verify::structure;
}

std::string verify_name(store::Verify verify) { return verify == store::Verify::checksums ? "checksums" : "structure"; }

std::string folder_of(const Opened_store& s) { return s.search.store().folder().string(); }

Opened_store open_store_at(const std::filesystem::path& folder, const std::string& verify) {
  const store::Verify how = verify_of(verify);
  Interruptible_call call;
  return Opened_store{frontend::Store_search(folder.string(), how), how};
}

// Clip `i` of the store, refused naming the store when it has none.
std::size_t clip_index(const Opened_store& s, long long i) {
  if (i < 0 || std::size_t(i) >= s.search.size())
    throw invalid_input("no clip " + std::to_string(i) + ": the store holds " + std::to_string(s.search.size()) +
                            " clips",
                        {.file = folder_of(s)});
  return std::size_t(i);
}

// A search's k and threads as Python gives them, checked as the tool checks them.
std::size_t checked_k(long long k, int threads) {
  whole_argument("threads", threads, frontend::thread_counts);
  return whole_argument("k", k, frontend::result_counts);
}

// A block of the store's clips given as a Python range of step 1 (None: all); the store checks
// that it holds them.
std::optional<search::Clip_range> clip_range(const py::object& range, const char* name) {
  if (range.is_none()) return std::nullopt;
  if (!py::isinstance(range, py::module_::import("builtins").attr("range")))
    throw py::type_error(std::string(name) + ": expected a range of clips (range(begin, end)) or None, got " +
                         type_name(range));
  const long long begin = range.attr("start").cast<long long>(), end = range.attr("stop").cast<long long>();
  if (range.attr("step").cast<long long>() != 1 || begin < 0 || end < begin)
    refuse(std::string(name) + ": expected range(begin, end) with 0 <= begin <= end and step 1, got " +
           py::repr(range).cast<std::string>());
  return search::Clip_range{std::size_t(begin), std::size_t(end)};
}

py::dict record_dict(const Opened_store& s, std::size_t i) {
  const store::Store_record r = s.search.store().record(i);
  return py::dict("index"_a = i, "name"_a = s.search.name(i), "path"_a = r.path, "clip"_a = r.clip,
                  "body"_a = r.body, "frames"_a = r.frame_count, "fps"_a = r.fps, "rows"_a = r.rows,
                  "input_options"_a = python_of(nlohmann::json::parse(r.input_options, nullptr, false)),
                  "source_size"_a = r.source_size, "source_mtime_ns"_a = r.source_mtime_ns,
                  "source_hash"_a = r.source_hash, "topology_path"_a = r.topology_path);
}

py::dict pruning_dict(const search::Pruning_report& p) {
  return py::dict("candidates"_a = p.candidates, "pruned_by_summary"_a = p.pruned_by_summary,
                  "pruned_by_rows"_a = p.pruned_by_rows, "abandoned"_a = p.abandoned, "aligned"_a = p.aligned,
                  "rows_aligned"_a = p.rows_aligned, "rows_abandoned"_a = p.rows_abandoned,
                  "pruned_share"_a = p.pruned_share());
}

py::dict nearest_dict(const Opened_store& s, const search::Nearest_motions& found) {
  py::list neighbours;
  for (std::size_t r = 0; r < found.neighbours.size(); ++r) {
    const search::Neighbour& n = found.neighbours[r];
    const store::Store_record record = s.search.store().record(n.index);
    neighbours.append(py::dict("rank"_a = r + 1, "index"_a = n.index, "name"_a = s.search.name(n.index),
                               "path"_a = record.path, "clip"_a = record.clip, "body"_a = record.body,
                               "value"_a = n.value));
  }
  return py::dict("neighbours"_a = neighbours, "pruning"_a = pruning_dict(found.pruning));
}

// A query's description as MotionStore.describe gives it: an (R, W) float32 array, R >= 1,
// dimension-major (Fortran order; another layout is copied into it).
using Described_query = py::array_t<float, py::array::f_style | py::array::forcecast>;

py::dict search(const Opened_store& s, const py::object& query, long long k, const py::object& candidates,
                int threads) {
  const search::Nearest_motions_options options{.k = checked_k(k, threads), .threads = threads,
                                                    .candidates = clip_range(candidates, "candidates")};
  search::Nearest_motions found;
  if (py::isinstance<Animation>(query)) {
    const Animation& animation = query.cast<const Animation&>();
    require_motion(animation.mesh, "query");
    Interruptible_call call;
    found = s.search.nearest(animation.mesh, options);
  } else if (py::isinstance<py::array>(query)) {
    const auto described = Described_query::ensure(query);
    if (!described || described.ndim() != 2 || described.shape(0) < 1)
      refuse("query: expected an Animation or its description, an (R, W) float32 array of R >= 1 rows (as "
             "MotionStore.describe gives it)");
    const signatures::Motion_signature_view view{described.data(), std::size_t(described.shape(0)),
                                                 std::size_t(described.shape(1))};
    Interruptible_call call;
    found = s.search.nearest(view, options);
  } else {
    throw py::type_error("query: expected an Animation or an (R, W) float32 array, got " + type_name(query));
  }
  return nearest_dict(s, found);
}

// The query described as the store's clips were: (R, W) float32, dimension-major as the store keeps them.
py::array describe_query(const Opened_store& s, const Animation& query) {
  require_motion(query.mesh, "query");
  similarity::Motion_signature_description d;
  {
    Interruptible_call call;
    d = s.search.describe(query.mesh, 0);
  }
  const auto rows = py::ssize_t(d.signatures.rows()), item = py::ssize_t(sizeof(float));
  return owning(std::move(d.signatures), +[](const Eigen::MatrixXf& x) { return x.data(); },
                {rows, py::ssize_t(d.signatures.cols())}, {item, rows * item});
}

py::dict nearest_to_clip(const Opened_store& s, long long i, long long k, const py::object& candidates,
                         int threads) {
  const search::Nearest_motions_options options{.k = checked_k(k, threads), .threads = threads,
                                                    .candidates = clip_range(candidates, "candidates")};
  const std::size_t clip = clip_index(s, i);
  search::Nearest_motions found;
  {
    Interruptible_call call;
    found = s.search.nearest_to_clip(clip, options);
  }
  return nearest_dict(s, found);
}

// The best windows over the store's clips (the tool's `find --store`), each a dict of the clip and
// the MotionMatch's fields.
py::list find_in_store(const Opened_store& s, const Animation& query, long long count, double shortest,
                       int threads) {
  const search::Find_in_collection_options options{
      .count = whole_argument("count", count, frontend::result_counts),
      .shortest = number_argument("shortest", shortest, frontend::window_shares),
      .threads = int(whole_argument("threads", threads, frontend::thread_counts))};
  require_motion(query.mesh, "query");
  std::vector<search::Clip_match> matches;
  {
    Interruptible_call call;
    matches = s.search.find(query.mesh, options);
  }
  py::list out;
  for (const search::Clip_match& c : matches) {
    const store::Store_record record = s.search.store().record(c.clip);
    out.append(py::dict("index"_a = c.clip, "name"_a = s.search.name(c.clip), "path"_a = record.path,
                        "clip"_a = record.clip, "body"_a = record.body, "first"_a = c.match.first,
                        "last"_a = c.match.last, "value"_a = c.match.value, "alignment"_a = c.match.alignment));
  }
  return out;
}

// One query's search results (dicts as search gives) among disjoint blocks of candidates, merged by
// search::merge_nearest: each neighbour's dict kept, its rank renumbered.
py::dict merge_nearest(const py::sequence& parts, long long k) {
  const std::size_t kept = whole_argument("k", k, frontend::result_counts);
  std::vector<search::Nearest_motions> found(parts.size());
  std::map<std::size_t, py::dict> dict_of;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const std::string where = "parts[" + std::to_string(p) + "]";
    if (!py::isinstance<py::dict>(parts[p]))
      throw py::type_error(where + ": expected a dict as MotionStore.search gives, got " + type_name(parts[p]));
    const auto part = parts[p].cast<py::dict>();
    if (!part.contains("neighbours") || !part.contains("pruning"))
      refuse(where + ": expected the dict of a search, with neighbours and pruning");
    for (const py::handle n : part["neighbours"].cast<py::list>()) {
      const auto neighbour = n.cast<py::dict>();
      const auto index = neighbour["index"].cast<std::size_t>();
      if (dict_of.count(index)) refuse(where + ": clip " + std::to_string(index) + " is in two parts");
      found[p].neighbours.push_back({index, neighbour["value"].cast<double>()});
      dict_of[index] = neighbour;
    }
    const auto counts = part["pruning"].cast<py::dict>();
    search::Pruning_report& r = found[p].pruning;
    for (auto [name, field] : {std::pair{"candidates", &r.candidates}, {"pruned_by_summary", &r.pruned_by_summary},
                               {"pruned_by_rows", &r.pruned_by_rows}, {"abandoned", &r.abandoned},
                               {"aligned", &r.aligned}, {"rows_aligned", &r.rows_aligned},
                               {"rows_abandoned", &r.rows_abandoned}})
      *field = counts[name].cast<std::size_t>();
  }
  const search::Nearest_motions merged = search::merge_nearest(found, kept);
  py::list neighbours;
  for (std::size_t r = 0; r < merged.neighbours.size(); ++r) {
    py::dict neighbour(dict_of.at(merged.neighbours[r].index));  // a copy, its rank renumbered
    neighbour["rank"] = r + 1;
    neighbours.append(neighbour);
  }
  return py::dict("neighbours"_a = neighbours, "pruning"_a = pruning_dict(merged.pruning));
}

py::list knn_graph(const Opened_store& s, long long k, const py::object& rows, const py::object& candidates,
                   int threads) {
  const search::Nearest_motions_options options{.k = checked_k(k, threads), .threads = threads,
                                                    .candidates = clip_range(candidates, "candidates")};
  const std::optional<search::Clip_range> block = clip_range(rows, "rows");
  std::vector<search::Nearest_motions> graph;
  {
    Interruptible_call call;
    graph = s.search.knn_graph(options, block);
  }
  py::list out;
  for (const search::Nearest_motions& node : graph) out.append(nearest_dict(s, node));
  return out;
}

// Clip i's signatures as an (R, W) float32 view of the mapping: the store keeps a clip's values
// dimension-major (W blocks of R), so a row's values are R floats apart.
py::array signatures(const py::object& self, long long i) {
  const Opened_store& s = self.cast<const Opened_store&>();
  const signatures::Motion_signature_view v = s.search.clips().view(clip_index(s, i));
  constexpr auto item = py::ssize_t(sizeof(float));
  py::array a(py::dtype::of<float>(), {py::ssize_t(v.rows), py::ssize_t(v.width)}, {item, py::ssize_t(v.rows) * item},
              v.values, self);
  a.attr("setflags")("write"_a = false);
  return a;
}

py::array frames(const py::object& self, long long i) {
  const Opened_store& s = self.cast<const Opened_store&>();
  const std::span<const std::uint32_t> f = s.search.store().frames(clip_index(s, i));
  return view(f.data(), {py::ssize_t(f.size())}, self);
}

// MotionStore: (1, folder, verify): a store pickles as where it is; restored, it is opened again.
py::object store_state(const Opened_store& s) {
  return py::make_tuple(pickle_version, folder_of(s), verify_name(s.verify));
}

Opened_store store_of_state(const py::object& state) {
  constexpr const char* type = "MotionStore";
  const py::tuple f = state_fields(state, type, 2, "(1, folder, verify)");
  return open_store_at(state_field<std::string>(f, 0, type, "folder"), state_field<std::string>(f, 1, type, "verify"));
}

}  // namespace

namespace {

// An Eigen matrix as a NumPy float64 array that owns it (column-major, as Eigen keeps it).
py::array array_of(Eigen::MatrixXd m) {
  const auto rows = py::ssize_t(m.rows()), columns = py::ssize_t(m.cols()), item = py::ssize_t(sizeof(double));
  return owning(std::move(m), +[](const Eigen::MatrixXd& x) { return x.data(); }, {rows, columns},
                {item, rows * item});
}

// The store's tile of `rows` and `columns` (each default all: the whole matrix).
py::array matrix_or_tile(const Opened_store& s, const py::object& rows, const py::object& columns,
                         const std::optional<py::function>& progress, int threads) {
  thread_count(threads, "threads");
  const std::optional<search::Clip_range> r = clip_range(rows, "rows"), c = clip_range(columns, "columns");
  const search::Clip_range all = search::all_clips(s.search.clips());  // the whole matrix is the one tile
  Eigen::MatrixXd m;
  {
    Interruptible_call call;
    m = s.search.tile(r.value_or(all), c.value_or(all), progress_of(progress), threads);
  }
  return array_of(std::move(m));
}

}  // namespace

py::array stored_similarity_matrix(const Opened_store& store, const frontend::Policy_choice& choice,
                                   const Progress& progress, int threads) {
  store.search.check_policy(choice, frontend::Front::python);
  whole_argument("threads", threads, frontend::thread_counts);
  Eigen::MatrixXd m;
  {
    Interruptible_call call;
    m = store.search.matrix(progress, threads);
  }
  return array_of(std::move(m));
}

evaluation::Retrieval_scores evaluate_stored(const Opened_store& store, const std::string& labels) {
  std::vector<evaluation::Labelled_item> items;
  for (const evaluation::Labelled_clip& row : evaluation::read_motion_labels(labels)) items.push_back(row.item);
  Interruptible_call call;
  const std::vector<std::size_t> labelled = store.search.labelled(labels, std::nullopt, frontend::Front::python);
  return evaluation::evaluate_retrieval(store.search.matrix(labelled, {}, 0), items);
}

void bind_store(py::module_& m) {
  py::class_<Opened_store>(m, "MotionStore", R"doc(A motion store opened by `open_store`: the descriptions of clips
written once by `describe_to_store` (or the tool's `deformseg describe --store`), memory-mapped for
as long as the object lives, searched under the policy they were described with (the default
motion-signature policy, its up direction recorded in `description`). The format is
doc/store_format.md; deformseg.store_format reads it with NumPy alone.

len(store) clips, indexed from 0 in the store's order; `names`, `records` and `description` say
what it holds; `signatures(i)` and `frames(i)` are read-only views of the mapping (no copy);
`search`, `nearest_to_clip`, `knn_graph` and `matrix` give exactly the values `similarity_matrix`
gives the same clips described now. A store pickles as its folder and is opened again where it is
unpickled (with the same check): the clips are those the folder holds then. The store stays
readable while another process appends to it; this object goes on showing what it held when opened.)doc")
      .def(py::pickle(&store_state, &store_of_state))
      .def("__len__", [](const Opened_store& s) { return s.search.size(); })
      .def_property_readonly("folder", &folder_of, "The store's folder, as given to open_store.")
      .def_property_readonly("generation", [](const Opened_store& s) { return s.search.store().generation(); },
                             "The number of appends committed.")
      .def_property_readonly("width", [](const Opened_store& s) { return s.search.store().width(); },
                             "W, the values per signature (64 by default; 0 while the store holds no clip).")
      .def_property_readonly(
          "description",
          [](const Opened_store& s) {
            return python_of(nlohmann::json::parse(s.search.store().description(), nullptr, false));
          },
          "The options the clips were described with, as a dict: policy, alignment, lags, quantiles, floor, up "
          "([x, y, z] or None), vertical_unit, vertical_weight, signature_rate, scale and width.")
      .def_property_readonly(
          "names",
          [](const Opened_store& s) {
            std::vector<std::string> names;
            for (std::size_t i = 0; i < s.search.size(); ++i) names.push_back(s.search.name(i));
            return names;
          },
          "Each clip named as reports name it: 'FILE', 'FILE#CLIP' or 'FILE#CLIP on BODY' (a clip played on "
          "another file's body), FILE and BODY canonical and absolute.")
      .def_property_readonly(
          "records",
          [](const Opened_store& s) {
            py::list out;
            for (std::size_t i = 0; i < s.search.size(); ++i) out.append(record_dict(s, i));
            return out;
          },
          "Per clip, a dict of index, name, path, clip ('' for a file of one animation), body (the character "
          "file whose body the clip played on, '' for its own), frames (its frame "
          "count), fps, rows (described instants), input_options (a dict), source_size, source_mtime_ns, "
          "source_hash (0: none) and topology_path: the keys of the tool's `store info --json` clips, with "
          "name and topology_path.")
      .def("index_of",
           [](const Opened_store& s, const std::filesystem::path& path, const std::string& clip,
              const std::filesystem::path& body) { return s.search.store().find(path.string(), clip, body.string()); },
           "path"_a, "clip"_a = "", "body"_a = "",
           "The index of the clip of `path` (canonical and absolute, as records give it: a name of bytes that are "
           "not UTF-8 escaped, a Latin-1 byte E9 as \\xE9) and `clip` (default '': "
           "a file of one animation) played on `body` (canonical and absolute; default '': its own file's body), "
           "or None: one clip on two bodies is two clips. Complexity O(log N).")
      .def("signatures", &signatures, "i"_a,
           "Clip i's signatures: an (R, W) float32 array, one row per described instant, a read-only view "
           "of the store's mapping (no copy; strides (4, 4 R): the store keeps them dimension-major) that "
           "keeps the store open. Raises InvalidInput naming the store for an index out of range, and naming "
           "the clip when its block does not match its checksum (checked on its first read). "
           "Complexity O(1); the first read of a clip O(R W).")
      .def("frames", &frames, "i"_a,
           "Clip i's frame numbers, one per row of its signatures: an (R,) uint32 read-only view (no copy). "
           "Complexity O(1).")
      .def("describe", &describe_query, "query"_a,
           "The Animation `query` described as the store's clips were (the store's policy and up "
           "direction): its signatures, an (R, W) float32 array in Fortran order, which `search` takes as "
           "the query (a description is small to send where the search runs). Complexity linear in the "
           "animation's size. Releases the GIL.")
      .def("search", &search, "query"_a, "k"_a = 10, py::kw_only(), "candidates"_a = py::none(), "threads"_a = 0,
           R"doc(The k clips of the store that move most like the Animation `query` (the tool's
`search`), or like a query described by `describe`: `query` described as the clips were, then
searched exactly, with lower bounds and
early abandoning (chapter 14). Returns a dict: neighbours, a list of dicts of rank (from 1), index,
name, path, clip, body ('' for the clip's own) and value (similarity(query, clip).value under the
store's policy, exactly as
similarity_matrix gives it), best first, ties by index; and pruning, a dict of the counts
candidates, pruned_by_summary, pruned_by_rows, abandoned, aligned, rows_aligned, rows_abandoned
and pruned_share (the share of candidates never aligned whole). k (default 10): at most the
store's size come back. candidates (default None: all): a range(begin, end) of the store's clips,
the only ones searched (deformseg.distributed merges the searches of blocks). threads (default 0:
all): the result and the counts do not depend on it.
Raises InvalidInput for k = 0, a query of one frame, an empty store. Complexity one description
of the query, at worst N alignments. Releases the GIL.)doc")
      .def("nearest_to_clip", &nearest_to_clip, "i"_a, "k"_a = 10, py::kw_only(), "candidates"_a = py::none(),
           "threads"_a = 0,
           "The k clips nearest to clip i of the store, itself left out (the tool's `search --clip-index I`): "
           "a dict as `search` gives, default k 10, candidates None (all; or a range of clips, as search's), "
           "threads 0 (all). Raises InvalidInput naming the store for an index or a range out of range. "
           "Complexity at worst N alignments. Releases the GIL.")
      .def("find", &find_in_store, "query"_a, "count"_a = 3, py::kw_only(), "shortest"_a = 0.5, "threads"_a = 0,
           R"doc(Where the Animation `query` occurs in the store's clips (the tool's `find --store`):
at most `count` (default 3) non-overlapping windows over all the clips, best first (ties by clip
index), each a dict of index, name, path, clip, body, first and last (the window in the clip's stored
frames), value and alignment ((row of the query, frame of the clip) pairs). Each clip is searched
as find_motion searches a long animation, but valued on the descriptions as stored: value is 1
minus the mean dissimilarity along the warping path (1 for a window cut from the clip itself).
shortest (default 0.5): a window spans from `shortest` to 1 / `shortest` times the query's rows.
threads (default 0: all): the result does not depend on it. Raises InvalidInput for count = 0, a
shortest outside (0, 1], a query of one frame, an empty store. Complexity O(Tq Tc / shortest^2)
per clip of Tc rows. Releases the GIL.)doc")
      .def("knn_graph", &knn_graph, "k"_a = 10, py::kw_only(), "rows"_a = py::none(), "candidates"_a = py::none(),
           "threads"_a = 0,
           "Every clip's k nearest other clips (the tool's `knn-graph`): a list, per clip in the store's "
           "order, of dicts as `search` gives (default k 10, threads 0: all). rows (default None: all): a "
           "range(begin, end) of clips, whose rows alone are found (the graph is the concatenation of its "
           "blocks of rows); candidates (default None: all): a range of the clips searched, as search's. "
           "Complexity at worst N^2 alignments, in practice far fewer (chapter 14). Releases the GIL.")
      .def("matrix", &matrix_or_tile, py::kw_only(), "rows"_a = py::none(), "columns"_a = py::none(),
           "progress"_a = py::none(), "threads"_a = 0,
           "The similarity of every pair of the store's clips as described: an (N, N) float64 array, as "
           "similarity_matrix(store) and the tool's `matrix --store` give it. rows, columns (default None: "
           "all): ranges of clips, range(begin, end), for a tile of the matrix, bit for bit its block (a pair "
           "whose two entries are in the tile is aligned once). progress (default None): as "
           "similarity_matrix's, a step a pair. threads (default 0: all): the values do not depend on it. "
           "Complexity a value pass per pair, N (N + 1) / 2 for the whole matrix. Releases the GIL.")
      .def("__repr__", [](const Opened_store& s) {
        return "<deformseg.MotionStore " + folder_of(s) + ": " + std::to_string(s.search.size()) + " clips>";
      });

  m.def("merge_nearest", &merge_nearest, "parts"_a, "k"_a = 10,
        "One query's searches among disjoint blocks of a store's clips (dicts as MotionStore.search, "
        "nearest_to_clip or a row of knn_graph give them with candidates=...) made its search among their "
        "union: a dict as search gives, the k (default 10) best neighbours of all, by value descending and then "
        "index (their dicts kept, ranks renumbered), the pruning counts summed. The neighbours and values equal "
        "those of one search among the union; the counts are the separate searches'. Raises InvalidInput for a "
        "clip in two parts or a dict that is not a search's. Complexity O(P log P) for P neighbours.");

  m.def("open_store", &open_store_at, "folder"_a, "verify"_a = "structure",
        R"doc(Opens the motion store in `folder` (made by describe_to_store or `deformseg describe --store`)
as a MotionStore. verify (default 'structure'): 'structure' checks the manifest, the files' sizes
and headers and every clip's ranges (O(clips)); 'checksums' also the CRC-32 of every byte (the
tool's `store verify`). Raises InvalidInput naming the file (and the clip) when the folder is not
a store, is of a newer version, is truncated or corrupted, or was described with options this
deformseg does not write. Complexity O(clips), or O(bytes) with 'checksums'. Releases the GIL.)doc");

}

}  // namespace deformseg::python
