#include "command.h"

#include <deformseg/io/internal/file_io.h>
#include <deformseg/io/read_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace deformseg::tool {

void add_input_options(CLI::App& command, Input_options& options) {
  command.add_option("input", options.input,
                     "A glTF file (.glb, .gltf) with --clip (or as FILE.glb#CLIP), a folder of frames (.obj, "
                     ".off, .ply; natural order), a quoted glob pattern, or a point cache (.pc2, .mdd) with --topology")
      ->required();
  command.add_option("--topology", options.topology,
                     "Mesh file giving the connectivity (required for a point cache)");
  command.add_flag("--triangulate", options.triangulate,
                   "Fan-triangulate polygons instead of rejecting them");
  command.add_option("--threads", options.threads, "Threads to use (0: all)")
      ->check(thread_counts);
  command.add_option("--clip", options.clip,
                     "glTF: the clip to read, by name or index (or as FILE.glb#CLIP); required when the file "
                     "holds several");
  command.add_option("--fps", options.fps,
                     "Frames per second: a glTF clip is sampled at it; frame files and point caches play at it")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  CLI::Option* weld = command.add_flag(
      "--weld", options.weld,
      "Weld the vertices that coincide in every frame (glTF files are always welded, by the rule that gives "
      "every clip of a file one mesh: the same rest position, skin weights and morph deltas)");
  command.add_flag("--no-weld", options.no_weld, "glTF: keep the file's vertices, in its order, unwelded")
      ->excludes(weld);
  command.add_flag("--refuse-defects", options.refuse_defects,
                   "Fail on degenerate, duplicate or non-manifold triangles instead of repairing them");
}

namespace {

// --clip and --no-weld apply to glTF only, --weld and --topology to the other formats.
void check_input_options(const Input_options& options) {
  const auto refuse = [&](const char* message) { throw invalid_input(message, {.file = options.input}); };
  const bool gltf = io::is_gltf(options.input);
  if (!gltf && !options.clip.empty()) refuse("--clip applies to glTF files only");
  if (!gltf && options.no_weld) refuse("--no-weld applies to glTF files only (others are welded only with --weld)");
  if (gltf && options.weld) refuse("--weld: glTF files are welded already (--no-weld keeps their vertices)");
  if (gltf && !options.topology.empty()) refuse("--topology does not apply to a glTF file: it has its own");
}

io::Repair_options repair_options(const Input_options& options) {
  return {.weld = io::is_gltf(options.input) ? !options.no_weld : options.weld,
          .defects = options.refuse_defects ? io::Defect_policy::refuse : io::Defect_policy::repair};
}

}  // namespace

Input_options with_clip_of_name(Input_options options) {
  auto [file, clip] = io::split_clip_suffix(options.input);
  if (!clip) return options;
  if (!options.clip.empty())
    throw invalid_input("the clip is given twice: by --clip and after '#'", {.file = options.input});
  options.input = std::move(file);
  options.clip = std::move(*clip);
  return options;
}

mesh::Surface_mesh_animation read_input(const Input_options& given, Input_report* report) {
  const Input_options options = with_clip_of_name(given);
  check_input_options(options);
  progress("reading " + options.input);
  Input_report found;
  mesh::Surface_mesh_animation animation = [&] {
    if (io::is_gltf(options.input)) {
      found.gltf.emplace();
      const io::Gltf_file file(options.input);
      if (!options.first_clip_by_default) io::require_clip_choice(file, options.clip);
      mesh::Surface_mesh_animation read = file.read({.clip = options.clip, .fps = options.fps,
                                               .repair = repair_options(options), .threads = options.threads},
                                              &*found.gltf);
      found.repair = found.gltf->repair;
      return read;
    }
    io::Animation_read_options read{.triangulate = options.triangulate, .threads = options.threads,
                                    .repair = repair_options(options), .fps = options.fps};
    if (!options.topology.empty()) read.topology = options.topology;
    return io::read_animation(options.input, read, &found.repair);
  }();
  if (found.gltf)
    progress("clip \"" + found.gltf->clip + "\", " + std::to_string(found.gltf->frames) + " frames at " +
             nlohmann::json(options.fps).dump() + " fps");
  if (found.repair.changed()) progress("repaired: " + describe(found.repair));
  if (report) *report = std::move(found);
  return animation;
}

void add_reference_mesh_option(CLI::App& command, std::string& path) {
  command.add_option("--reference-mesh", path,
                     "Measure strain against this mesh (.obj, .off, .ply: the animation's connectivity, in "
                     "another pose) in place of a frame: a rest pose kept apart from the frames");
}

mesh::Surface_mesh read_reference_mesh(const std::string& path) {
  progress("reading the reference mesh " + path);
  const io::Triangle_soup soup = io::read_mesh(path);
  return mesh::make_face_graph<mesh::Surface_mesh>(io::points_of(soup), soup.triangles);
}

nlohmann::json to_json(const io::Repair_report& r) {
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [name, count] : r.counts()) counts[std::string(name)] = count;
  return counts;
}

std::string describe(const io::Repair_report& r) {
  std::string words;
  const auto add = [&](std::size_t count, const char* what) {
    if (count == 0) return;
    if (!words.empty()) words += ", ";
    words += std::to_string(count) + " " + what;
  };
  add(r.welded_vertices, "vertices welded");
  add(r.degenerate_triangles, "degenerate triangles dropped");
  add(r.duplicate_triangles, "duplicate triangles dropped");
  add(r.non_manifold_edges, "non-manifold edges");
  add(r.non_manifold_vertices, "non-manifold vertices");
  add(r.duplicated_vertices, "vertices duplicated to make them manifold");
  add(r.reoriented_triangles, "triangles reoriented");
  add(r.unrepairable_triangles, "unrepairable triangles dropped");
  return words.empty() ? "nothing" : words;
}

void write_json(const nlohmann::json& document, const std::string& path) {
  if (path == "-") {
    std::cout << document.dump(2) << '\n';
    return;
  }
  deformseg::io::internal::write_file_bytes(path, document.dump(2) + '\n');  // names the file and the system's reason
}

void write_outputs(const nlohmann::json& document, const std::string& json_path,
                   const std::function<void()>& print_summary, bool standard_output_taken) {
  if (!json_path.empty()) write_json(document, json_path);
  if (json_path != "-" && !standard_output_taken) print_summary();
}

void add_json_option(CLI::App& command, std::string& path, const std::string& what) {
  command.add_option("--json", path, "Write " + what + " as JSON to FILE ('-': standard output, in place of the "
                                     "summary)")
      ->check(output_file());
}

void print_written(const nlohmann::json& summary) {
  const auto& files = summary["files"];
  std::cout << "frames     " << summary["frames"] << "\nvertices   " << summary["vertices"] << "\ntriangles  "
            << summary["triangles"] << "\nfiles      " << files.size();
  if (!files.empty()) std::cout << ": " << files.front().get<std::string>();
  if (files.size() > 1) std::cout << " ... " << files.back().get<std::string>();
  std::cout << '\n';
}

std::vector<std::size_t> evenly_spaced_frames(std::size_t frames, std::size_t count) {
  count = std::min(count, frames);
  std::vector<std::size_t> chosen;
  for (std::size_t k = 0; k < count; ++k)
    chosen.push_back(count == 1 ? 0 : std::size_t(std::llround(double(k) * double(frames - 1) / double(count - 1))));
  return chosen;
}

CLI::Validator output_file() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        if (path == "-") return {};
        const std::filesystem::path folder = std::filesystem::path(path).parent_path();
        std::error_code error;
        if (!folder.empty() && !std::filesystem::is_directory(folder, error))
          return "cannot write " + path + ": the folder " + folder.string() + " does not exist";
        if (std::filesystem::is_directory(path, error)) return "cannot write " + path + ": it is a folder";
        return {};
      },
      "FILE");
}

CLI::Validator output_folder() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code error;
        // The nearest part of the path that exists must be a folder: the rest is created.
        for (std::filesystem::path part = path; !part.empty(); part = part.parent_path()) {
          if (!std::filesystem::exists(part, error)) {
            if (part == part.parent_path()) break;
            continue;
          }
          if (std::filesystem::is_directory(part, error)) return {};
          return part == std::filesystem::path(path) ? "cannot write into " + path + ": it is a file, not a folder"
                                                     : "cannot create the folder " + path + ": " + part.string() +
                                                           " is a file, not a folder";
        }
        return {};
      },
      "DIR");
}

void progress(const std::string& line) { std::cerr << "deformseg: " << line << '\n'; }

bool Matrix_progress::operator()(std::size_t done, std::size_t total) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.1f s", seconds);
  if (done == descriptions && describe_seconds == 0) {
    describe_seconds = seconds;
    progress("described " + std::to_string(descriptions) + " animations in " + elapsed);
  }
  if (done >= next_report || done == total) {
    progress("matrix: " + std::to_string(done) + " of " + std::to_string(total) + " steps, " + elapsed);
    next_report = done + std::max<std::size_t>(1, total / 20);
  }
  return true;
}

}  // namespace deformseg::tool
