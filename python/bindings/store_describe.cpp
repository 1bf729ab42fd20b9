// describe_to_store, and deformseg.distributed's halves of it (_describe_plan, _merge_stores):
// describing clips once into a motion store (chapter 14), as the tool's describe and store merge
// do, through the same front end (frontend/store.h).
#include "bindings.h"

#include "common.h"
#include "parameters.h"

#include "frontend/store.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace py = pybind11;
using namespace pybind11::literals;

namespace deformseg::python {

namespace {

// describe_to_store's keywords: the input options, then the signatures' up direction, bands and sides.
constexpr auto describe_table =
    std::tuple_cat(frontend::input_parameters,
                   std::tuple{std::get<3>(frontend::policy_parameters), std::get<4>(frontend::policy_parameters),
                              std::get<5>(frontend::policy_parameters)});
static_assert(std::string_view(std::get<8>(describe_table).name) == "up");
static_assert(std::string_view(std::get<9>(describe_table).name) == "bands");
static_assert(std::string_view(std::get<10>(describe_table).name) == "sides");

// One path (str or os.PathLike) as its file name's bytes (os.fsencode: a name of bytes that are
// not UTF-8, a Latin-1 name, comes as its own bytes); `where` names the argument in the TypeError.
std::string path_text(const py::handle& item, const std::string& where) {
  if (!py::isinstance<py::str>(item) && !py::hasattr(item, "__fspath__"))
    throw py::type_error(where + ": expected a path (str or os.PathLike), got " + type_name(item));
  const py::object path = py::module_::import("os").attr("fspath")(item);
  if (!py::isinstance<py::str>(path)) throw py::type_error(where + ": expected a str path, got " + type_name(path));
  return py::module_::import("os").attr("fsencode")(path).cast<std::string>();
}

// A file name's bytes as Python's str of it (os.fsdecode), which `path_text` reads back.
py::str path_of_bytes(const std::string& bytes) {
  return py::module_::import("os").attr("fsdecode")(py::bytes(bytes));
}

// describe_to_store's inputs: one path, or a sequence of them.
std::vector<std::string> input_paths(const py::object& inputs) {
  if (py::isinstance<py::str>(inputs) || py::hasattr(inputs, "__fspath__")) return {path_text(inputs, "inputs")};
  if (!py::isinstance<py::sequence>(inputs))
    throw py::type_error("inputs: expected a path or a sequence of paths, got " + type_name(inputs));
  const auto sequence = py::reinterpret_borrow<py::sequence>(inputs);
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < sequence.size(); ++i)
    paths.push_back(path_text(sequence[i], "inputs[" + std::to_string(i) + "]"));
  if (paths.empty())
    refuse("inputs: no input; name animations, character files (glTF, FBX, Collada, BVH) or labels CSVs");
  return paths;
}

py::dict describe_to_store(const py::object& inputs, const std::filesystem::path& store,
                           const frontend::Input_options& options, const frontend::Policy_choice& choice, bool hash,
                           bool skip_unreadable) {
  const std::vector<std::string> paths = input_paths(inputs);
  const similarity::Default_similarity policy = frontend::store_policy(choice, frontend::Front::python);
  frontend::check(options, frontend::Front::python);
  frontend::check_clip_applies(paths, options, frontend::Front::python);
  frontend::Describe_report report;
  {
    Interruptible_call call;
    const frontend::Describe_run run{
        .hash = hash, .skip_unreadable = skip_unreadable, .front = frontend::Front::python};
    report = frontend::describe_inputs(store.string(), paths, options, policy, run, [](const std::string&) {});
  }
  return py::dict("store"_a = store.string(), "clips"_a = report.clips, "described"_a = report.described,
                  "redescribed"_a = report.redescribed, "skipped"_a = report.skipped,
                  "unreadable"_a = report.unreadable, "poses_left_out"_a = report.poses);
}

// What `describe` of deformseg.distributed hands out: the clips describe_to_store would describe, in
// its order, named as reports name them ('FILE', 'FILE#CLIP' or 'FILE#CLIP on BODY'), as inputs name
// them with the body each plays on ('' for its own), and those it would skip.
py::dict describe_plan(const py::object& inputs, const std::filesystem::path& store,
                       const frontend::Input_options& options, const frontend::Policy_choice& choice, bool hash) {
  const std::vector<std::string> paths = input_paths(inputs);
  const similarity::Default_similarity policy = frontend::store_policy(choice, frontend::Front::python);
  frontend::check(options, frontend::Front::python);
  frontend::check_clip_applies(paths, options, frontend::Front::python);
  std::vector<std::string> poses, described, inputs_of_clips, bodies;
  frontend::Description_plan plan;
  {
    Interruptible_call call;
    const std::vector<frontend::Clip_source> clips = frontend::clip_sources(paths, options, poses);
    plan = frontend::plan_description(store.string(), clips, options, policy, hash);
    for (const std::size_t i : plan.order) {
      described.push_back(clips[i].name());
      inputs_of_clips.push_back(clips[i].input());
      bodies.push_back(clips[i].body);
    }
  }
  py::list clip_inputs, clip_bodies;  // file names as Python gives them: back to describe_to_store as they are
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    clip_inputs.append(path_of_bytes(inputs_of_clips[k]));
    clip_bodies.append(path_of_bytes(bodies[k]));
  }
  return py::dict("store"_a = store.string(), "clips"_a = plan.report.clips, "describe"_a = described,
                  "inputs"_a = clip_inputs, "bodies"_a = clip_bodies, "skipped"_a = plan.report.skipped,
                  "poses_left_out"_a = poses);
}

py::dict merge_stores(const std::filesystem::path& store, const std::vector<std::filesystem::path>& parts) {
  std::vector<std::string> folders;
  for (const auto& part : parts) folders.push_back(part.string());
  frontend::Describe_report report;
  {
    Interruptible_call call;
    report = frontend::merge_stores(store.string(), folders, [](const std::string&) {});
  }
  return py::dict("store"_a = store.string(), "clips"_a = report.clips, "described"_a = report.described,
                  "redescribed"_a = report.redescribed);
}

}  // namespace

void bind_store_describe(py::module_& m) {
  // deformseg.distributed's halves of describe_to_store: the plan on the client, the merge of the
  // workers' part stores by one writer.
  define_function<describe_table, Types<const py::object&, const std::filesystem::path&>, Types<bool>,
                  frontend::Input_options, frontend::Policy_choice>(
      m, "_describe_plan",
      "The clips describe_to_store(inputs, store, ...) would describe, in its order, and those it would skip: "
      "a dict of store, clips (the store's count now), describe and skipped (the clips' names), inputs and "
      "bodies (per clip to describe, its input 'FILE' or 'FILE#CLIP' and the body it plays on, '' for its own), "
      "poses_left_out. Raises InvalidInput as describe_to_store. Releases the GIL.",
      &describe_plan, std::tuple{py::arg("inputs"), py::arg("store"), py::kw_only()},
      std::tuple{py::arg_v("hash", false)});
  m.def("_merge_stores", &merge_stores, "store"_a, "parts"_a,
        "Appends the clips of the stores `parts`, in order, into `store` (a clip it holds already replaced at "
        "its index), in one commit: a dict of store, clips, described and redescribed. Raises InvalidInput "
        "naming the part or the store; the store is then as it was. Releases the GIL.");

  define_function<describe_table, Types<const py::object&, const std::filesystem::path&>, Types<bool, bool>,
                  frontend::Input_options, frontend::Policy_choice>(
      m, "describe_to_store",
      R"doc(Describes clips once into the motion store in the folder `store` (made when missing), as the
tool's `deformseg describe INPUTS --store S`: `inputs` a path or a sequence of paths, each an
animation as read_animation reads it (frame files, a folder, a glob, a point cache with
`topology`, FILE.glb#CLIP), a glTF, FBX or Collada file without a clip (every clip of 2 frames or more; its poses
of one frame are left out and listed), or a labels CSV (evaluate's: the clip of each row). New
clips are added, changed ones described again in place, unchanged ones skipped: a clip is
unchanged when its input options, size and modification time (with hash=True, the hash of its
bytes instead of the time), and its body file's size and time, are those recorded. Clips are committed 64 at a time and
at the end: an interrupted or failed run keeps what it committed, and a second run describes the
rest. Returns a dict: store, clips (the store's count after the run), described, redescribed and
skipped (the clips' names, 'FILE', 'FILE#CLIP' or 'FILE#CLIP on BODY': a labels row's clip plays
on its body_file, and one clip on two bodies is two clips), unreadable ('NAME: the error' for each input
or clip left out by skip_unreadable), poses_left_out. up (default None: the policy's default,
none): the signatures' up direction, recorded in the store; a store takes clips of one
description only. hash (default False). skip_unreadable (default False): leave out the inputs
and clips that cannot be read or described instead of raising at the first. Raises InvalidInput
naming the file and clip that cannot be read or described, or the store when it cannot be
written or was made with other options. Complexity linear in the inputs' size for the clips
described, O(clips) for those skipped (plus reading every byte with hash=True). Releases the GIL.)doc",
      &describe_to_store, std::tuple{py::arg("inputs"), py::arg("store"), py::kw_only()},
      std::tuple{py::arg_v("hash", false), py::arg_v("skip_unreadable", false)});
}

}  // namespace deformseg::python
