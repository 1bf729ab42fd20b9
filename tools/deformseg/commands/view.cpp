// deformseg view INPUT [INPUT_B] --out DIR: a web page that plays the animations with what the
// library computed of them (strain, temporal segments, the evolving graph, the alignment of two).
// DIR/index.html opens from disk, with no server: three.js comes from Debian's libjs-three, copied
// beside it, and the data are a script, data.js.
#include "command.h"
#include "viewer/view_data.h"
#include "viewer_assets.h"

#include <deformseg/io/files.h>
#include <deformseg/similarity/motion_similarity.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace deformseg::tool {
namespace {

struct View_command_options {
  std::vector<std::string> inputs;
  Input_options read;
  std::string out;
  std::string color = "strain";
  std::optional<std::size_t> max_frames{};  ///< none: as many as the page's budget holds, at most 1000
};

// The page holds the shown frames' coordinates (quantised, in base64) and a colour per triangle per
// frame: about 3.5 bytes per coordinate with the triangles' colours (chapter 9 of the manual). A
// browser holds pages of 100 MB (a 24 million coordinate page opens in Chromium in seconds); above
// that, parsing the page's script takes longer and longer, and V8 refuses strings of 512 MB.
constexpr std::size_t page_coordinates = 24'000'000;
constexpr double page_bytes_per_coordinate = 3.5;
// The frames shown by default however small the animation.
constexpr std::size_t default_max_frames = 1000;

// The frames of an input shown on the page: an animation of them, their numbers in the input.
struct Shown_frames {
  mesh::Surface_mesh_animation animation;
  std::vector<std::size_t> numbers;
  std::size_t input_frames = 0;
};

// The frames to show of an animation of `vertices` vertices, one of `inputs`: `max_frames` when
// given, else as many as the page's budget of coordinates holds (shared among the inputs), at most
// `default_max_frames`, at least 2.
std::size_t frames_to_show(const std::optional<std::size_t>& max_frames, std::size_t vertices, std::size_t inputs) {
  if (max_frames) return *max_frames;
  const std::size_t held = page_coordinates / std::max<std::size_t>(3 * vertices * inputs, 1);
  return std::clamp<std::size_t>(held, 2, default_max_frames);
}

// The frames `numbers` (ascending) of a source, read frame by frame, the others dropped as they
// are read; all of them as `read_input` gives them (the input's fps), a sample as
// `evenly_sampled` gives it.
template <class Source>
Shown_frames streamed_frames(Source& source, std::vector<std::size_t> numbers) {
  const std::size_t vertices = source.num_vertices(), frames = source.num_frames();
  mesh::Coordinate_buffer<double> kept;
  kept.reserve(3 * vertices * numbers.size());
  std::vector<typename Source::Coordinate> frame(3 * vertices);
  for (std::size_t t = 0, next = 0; t < frames; ++t) {
    source.read_frame(std::span(frame));
    if (next < numbers.size() && numbers[next] == t) kept.insert(kept.end(), frame.begin(), frame.end()), ++next;
  }
  std::vector<std::array<double, 3>> first(vertices);
  for (std::size_t i = 0; i < vertices && !kept.empty(); ++i)
    first[i] = {kept[3 * i], kept[3 * i + 1], kept[3 * i + 2]};
  mesh::Surface_mesh_animation animation(mesh::make_face_graph<mesh::Surface_mesh>(first, source.triangles()),
                                         std::move(kept));
  if (numbers.size() == frames) animation.set_frames_per_second(source.frames_per_second());
  return {std::move(animation), std::move(numbers), frames};
}

// The frames shown of each input: read frame by frame when it can be, keeping those shown; else
// read whole (welded frame files), then sampled.
std::vector<Shown_frames> shown_frames(const View_command_options& o) {
  std::vector<Shown_frames> shown;
  for (const std::string& input : o.inputs) {
    frontend::Stream_read streamed;
    const auto keep = [&](auto& source) {
      const std::size_t count = frames_to_show(o.max_frames, source.num_vertices(), o.inputs.size());
      shown.push_back(streamed_frames(source, evenly_spaced_frames(source.num_frames(), count)));
    };
    if (stream_input(input, o.read, false, streamed, keep)) continue;
    const frontend::Read_input read = read_one_of(input, o.read);
    const std::size_t count = frames_to_show(o.max_frames, read.animation.num_vertices(), o.inputs.size());
    std::vector<std::size_t> numbers;
    mesh::Surface_mesh_animation sampled = evenly_sampled(read.animation, count, numbers);
    shown.push_back({std::move(sampled), std::move(numbers), read.animation.num_frames()});
  }
  return shown;
}

// Says what was chosen: "showing 243 of 3841 frames (one in 15.8), at 60.8 fps: the page holds at
// most ...", and warns of a page over the budget that --max-frames asked for.
void report_shown(const View_command_options& o, const std::string& input, const Shown_frames& shown) {
  const std::size_t count = shown.numbers.size(), coordinates = 3 * shown.animation.num_vertices() * count;
  const double step = count > 1 ? double(shown.input_frames - 1) / double(count - 1) : 1;
  char words[400];
  if (count < shown.input_frames && o.max_frames)
    std::snprintf(words, sizeof words, "showing %zu of %zu frames (one in %.3g), at %.3g fps, as --max-frames asks",
                  count, shown.input_frames, step, o.read.fps / step);
  else if (count < shown.input_frames)
    std::snprintf(words, sizeof words,
                  "showing %zu of %zu frames (one in %.3g), at %.3g fps: the page holds at most %zu coordinates "
                  "(frames x vertices x 3, about %.3g bytes each); --max-frames chooses",
                  count, shown.input_frames, step, o.read.fps / step, page_coordinates, page_bytes_per_coordinate);
  else
    std::snprintf(words, sizeof words, "showing all %zu frames, at %.3g fps", count, o.read.fps);
  progress(input + ": " + words);
  if (o.max_frames && coordinates * o.inputs.size() > page_coordinates)
    progress("warning: " + input + ": " + std::to_string(count) + " frames of " +
             std::to_string(shown.animation.num_vertices()) + " vertices make a page of about " +
             std::to_string(std::llround(double(coordinates) * page_bytes_per_coordinate / 1e6)) +
             " MB, more than a browser holds well (" + std::to_string(page_coordinates) +
             " coordinates in all); a smaller --max-frames shows fewer");
}

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
  if (o.max_frames && *o.max_frames < 2) throw invalid_input("--max-frames must be at least 2");
  const auto three_js = three_js_files();
  frontend::check_clip_applies(o.inputs, o.read, frontend::Front::command_line);
  std::vector<mesh::Surface_mesh_animation> animations;
  std::vector<std::vector<std::size_t>> numbers;
  for (std::size_t k = 0; Shown_frames& shown : shown_frames(o)) {
    report_shown(o, o.inputs[k++], shown);
    animations.push_back(std::move(shown.animation));
    numbers.push_back(std::move(shown.numbers));
  }
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
                      "At most this many frames, evenly spaced, are shown (the page then plays at a lower frame rate). "
                      "Default: as many as a page of 24 million coordinates (frames x vertices x 3, about 80 MB) "
                      "holds, at most 1000: 242 frames of a 33,000-vertex character")
      ->check(whole_numbers(frontend::positive_counts(1e6)));
  command->callback([o] { run(*o); });
}

}  // namespace deformseg::tool
