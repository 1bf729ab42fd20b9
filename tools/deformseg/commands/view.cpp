// deformseg view INPUT [INPUT_B] --out DIR: a web page that plays the animations with what the
// library computed of them (strain, temporal segments, the evolving graph, the alignment of two).
// DIR/index.html opens from disk, with no server: three.js comes from Debian's libjs-three, copied
// beside it, and the data are a script, data.js.
#include "command.h"
#include "viewer/view_data.h"
#include "viewer_assets.h"

#include <deformseg/io/files.h>
#include <deformseg/similarity/motion_similarity.h>

#include <filesystem>
#include <iostream>
#include <memory>

namespace deformseg::tool {
namespace {

struct View_command_options {
  std::vector<std::string> inputs;
  Input_options read;
  std::string out;
  std::string color = "strain";
  std::size_t max_frames = 1000;
};

// three.js and its orbit controls, where the build found Debian's libjs-three.
std::vector<std::pair<std::filesystem::path, std::string>> three_js_files() {
  const std::filesystem::path three(DEFORMSEG_THREE_JS_DIR);
  if (three.empty())
    throw invalid_input("this deformseg was built without three.js: install Debian's libjs-three and build it again");
  std::vector<std::pair<std::filesystem::path, std::string>> files{
      {three / "three.min.js", "three.min.js"}, {three / "examples/js/controls/OrbitControls.js", "OrbitControls.js"}};
  for (const auto& [source, name] : files)
    if (!std::filesystem::is_regular_file(source))
      throw invalid_input("three.js is missing (Debian: apt-get install libjs-three)", {.file = source.string()});
  return files;
}

void run(const View_command_options& o) {
  const View_coloring coloring = view_coloring(o.color);
  if (o.max_frames < 2) throw invalid_input("--max-frames must be at least 2");
  const auto three_js = three_js_files();
  std::vector<mesh::Surface_mesh_animation> animations;
  std::vector<std::vector<std::size_t>> numbers(o.inputs.size());
  const std::vector<frontend::Read_input> inputs = read_inputs(o.inputs, o.read, false);
  for (std::size_t k = 0; k < inputs.size(); ++k)
    animations.push_back(evenly_sampled(inputs[k].animation, o.max_frames, numbers[k]));
  // The page plays at the input's pace: a sampled animation's frames are further apart in time.
  nlohmann::json document = {
      {"title", "deformseg view: " + short_name(o.inputs.front()) +
                    (o.inputs.size() == 2 ? " and " + short_name(o.inputs.back()) : "")},
      {"fps", o.read.fps * double(numbers[0].size() - 1) / double(std::max<std::size_t>(numbers[0].back(), 1))},
      {"animations", nlohmann::json::array()},
      {"alignment", nullptr}};
  for (std::size_t k = 0; k < animations.size(); ++k) {
    progress("describing " + o.inputs[k] + ": " + std::to_string(animations[k].num_frames()) + " frames shown");
    document["animations"].push_back(
        view_json(animations[k], short_name(o.inputs[k]), numbers[k], coloring, o.read.threads));
  }
  if (animations.size() == 2) {
    progress("aligning the two animations");
    const similarity::Similarity s = similarity::motion_similarity(animations[0], animations[1]);
    nlohmann::json pairs = nlohmann::json::array();
    for (const auto& [i, j] : s.alignment) pairs.push_back({i, j});
    document["alignment"] = {{"value", s.value}, {"policy", "motion signatures, DTW"}, {"pairs", pairs}};
  }
  const std::filesystem::path out(o.out);
  io::create_folder(out);
  progress("writing the page into " + o.out);
  io::write_file(out / "data.js", "window.DEFORMSEG_VIEW = " + frontend::json_text(document) + ";\n");
  io::write_file(out / "index.html", viewer_assets::index_html);
  io::write_file(out / "viewer.js", viewer_assets::viewer_js);
  io::write_file(out / "viewer_core.js", viewer_assets::viewer_core_js);
  for (const auto& [source, name] : three_js)
    std::filesystem::copy_file(source, out / name, std::filesystem::copy_options::overwrite_existing);
  std::cout << "open " << (std::filesystem::absolute(out) / "index.html").string() << '\n';
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto o = std::make_shared<View_command_options>();
  CLI::App* command = app.add_subcommand(
      "view", "A web page that plays one animation, or two side by side in step through their alignment, "
              "coloured by strain or segments, with its timeline and key-frame graphs");
  add_inputs(*command, "inputs", o->inputs, 1, 2, o->read, "One or two animations");
  command->add_option("--out", o->out,
                      "The folder to write index.html and what it needs into (created when missing)")
      ->required()
      ->check(output_folder());
  command->add_option("--color", o->color,
                      "strain: against frame 0 (default); previous-strain: against the frame before; temporal: by "
                      "temporal segment; segments: by spatio-temporal segment, as the graph's nodes; none")
      ->check(CLI::IsMember({"strain", "previous-strain", "temporal", "segments", "none"}));
  command->add_option("--max-frames", o->max_frames,
                      "At most this many frames, evenly spaced, are shown. Default: 1000")
      ->check(whole_numbers(frontend::positive_counts(1e6)));
  command->callback([o] { run(*o); });
}

}  // namespace deformseg::tool
