// deformseg strain INPUT: the per-triangle strain of every frame, as a field file, coloured
// meshes and a JSON summary.
#include "command.h"
#include "figures/render.h"

#include <frontend/strain.h>

#include <deformseg/color/strain_colors.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/strain/strain.h>
#include <deformseg/strain/strain_field_files.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

struct Strain_command_options {
  std::string input;
  Input_options read;
  frontend::Strain_request strain;
  std::string out;
  std::string mesh_dir;
  std::string png;
  std::vector<std::size_t> png_frames;  // none given: up to 6, evenly spaced
  std::string json;
};

// The colours of frame t: of the normalised strain, or, for a raw field, of the strain normalised
// the default way for the picture only.
std::vector<float> colour_values(const strain::Strain_field<float>& field) {
  std::vector<float> values(field.values().begin(), field.values().end());
  if (!field.sigma())
    strain::Gaussian_normalization{}.normalize(strain::Raw_strain_field<float>{values, field.num_faces()});
  return values;
}

void write_meshes(const mesh::Surface_mesh_animation& animation, const strain::Strain_field<float>& field,
                  const std::string& folder) {
  progress("writing " + std::to_string(animation.num_frames()) + " coloured meshes to " + folder);
  const std::vector<float> values = colour_values(field);
  const std::size_t faces = field.num_faces();
  io::write_sequence(animation, folder,
                     {.face_colors = [&](std::size_t t) {
                       return color::strain_colors(std::span<const float>(values).subspan(t * faces, faces));
                     }});
}

// The frames --png draws: those given, each checked, or up to 6 from the first to the last.
std::vector<std::size_t> frames_to_draw(const Strain_command_options& o, std::size_t frames) {
  for (std::size_t t : o.png_frames)
    if (t >= frames)
      throw invalid_input("--png-frames: frame " + std::to_string(t) + " is past the last, " +
                          std::to_string(frames - 1), {.file = o.input});
  return o.png_frames.empty() ? evenly_spaced_frames(frames, 6) : o.png_frames;
}

// A strip of frames, each seen from the same side and coloured by normalised strain (viridis),
// named by its frame, with the colour bar on the right.
void write_picture(const mesh::Surface_mesh_animation& animation, const strain::Strain_field<float>& field,
                   const std::vector<std::size_t>& frames, const Strain_command_options& o) {
  progress("drawing " + std::to_string(frames.size()) + " frames coloured by strain into " + o.png);
  const std::vector<float> values = colour_values(field);
  const View view = view_of(animation);
  constexpr int panel = 240, gap = 12, padding = 8;
  std::vector<Image> pictures;
  for (std::size_t t : frames) {
    const auto strains = std::span<const float>(values).subspan(t * field.num_faces(), field.num_faces());
    pictures.push_back(render_frame(animation, t, view, color::strain_colors(strains), panel));
  }
  const Color_bar bar{field.sigma() ? "normalised strain" : "strain, normalised for the picture", 0, 1,
                      [](double f) { return color::strain_color(f); }};
  const int title_height = text_height(2) + gap, label_height = text_height() + 4;
  const int height = pictures.front().height;
  Image image(padding + int(frames.size()) * (pictures.front().width + gap) + padding + color_bar_width(bar) + padding,
              padding + title_height + label_height + height + padding);
  draw_text(image, o.strain.measure + " strain of " + short_name(o.input), padding, padding, 2);
  int x = padding;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    draw_text(image, "frame " + std::to_string(frames[k]), x, padding + title_height);
    image.paste(pictures[k], x, padding + title_height + label_height);
    x += pictures[k].width + gap;
  }
  draw_color_bar(image, x + padding, padding + title_height + label_height, height, bar);
  write_png(image, o.png);
}

void write_field(const strain::Strain_field<float>& field, const std::string& path) {
  progress("writing the field to " + path);
  if (std::filesystem::path(path).extension() == ".csv")
    strain::write_strain_csv(field, path);
  else
    strain::write_strain_binary(field, path);
}

nlohmann::json summary(const Strain_command_options& o, const frontend::Read_input& input,
                       const strain::Strain_field<float>& field) {
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t t = 0; t < field.num_frames(); ++t) {
    const auto values = field.frame(t);
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    double sum = 0;
    for (float v : values) sum += v;
    frames.push_back({{"frame", t}, {"min", *low}, {"max", *high}, {"mean", sum / double(values.size())}});
  }
  const frontend::Strain_request& r = o.strain;
  nlohmann::json document = {{"input", o.input},
                             {"sources", sources({&input, 1}, o.read)},
                             {"frames", field.num_frames()},
                             {"triangles", field.num_faces()},
                             {"reference", r.reference},
                             {"measure", r.measure},
                             {"normalize", r.normalize},
                             {"sigma", nullptr},
                             {"degenerate_count", field.degenerate_count()},
                             {"per_frame", frames}};
  const bool against_rest = frontend::entry_named(frontend::strain_references, r.reference).value ==
                            strain::Strain_reference::rest_pose;
  if (against_rest && r.reference_mesh.empty()) document["rest_frame"] = r.rest_frame;
  if (!r.reference_mesh.empty()) document["reference_mesh"] = r.reference_mesh;
  if (field.sigma()) document["sigma"] = *field.sigma();
  return document;
}

// The summary: sigma to six significant digits, the strains with six decimals, so that a strain
// of 4e-41 (a float's rounding noise on a still triangle) reads 0.000000, as meant; the JSON keeps
// every digit.
void print(const nlohmann::json& s) {
  const std::string sigma = s["sigma"].is_number() ? figure_text(s["sigma"].get<double>()) : "null";
  std::cout << "frames      " << s["frames"] << "\ntriangles   " << s["triangles"] << "\nsigma       " << sigma
            << "\ndegenerate  " << s["degenerate_count"] << "\nframe  min  max  mean\n"
            << std::fixed << std::setprecision(6);
  for (const auto& f : s["per_frame"])
    std::cout << f["frame"] << "  " << f["min"].get<double>() << "  " << f["max"].get<double>() << "  "
              << f["mean"].get<double>() << '\n';
}

void run(const Strain_command_options& o) {
  frontend::check(o.strain, frontend::Front::command_line);
  if (!o.png_frames.empty() && o.png.empty()) throw invalid_input("--png-frames asks for --png");
  const frontend::Read_input input = read_input(o.input, o.read);
  const mesh::Surface_mesh_animation& animation = input.animation;
  const std::vector<std::size_t> drawn =
      o.png.empty() ? std::vector<std::size_t>{} : frames_to_draw(o, animation.num_frames());
  progress("computing the strain of " + std::to_string(animation.num_faces()) + " triangles x " +
           std::to_string(animation.num_frames()) + " frames");
  const strain::Strain_field<float> field = frontend::strain_field(animation, o.strain, o.read.threads);
  if (!o.out.empty()) write_field(field, o.out);
  if (!o.mesh_dir.empty()) write_meshes(animation, field, o.mesh_dir);
  if (!o.png.empty()) write_picture(animation, field, drawn, o);
  const nlohmann::json document = summary(o, input, field);
  write_outputs(document, o.json, [&] { print(document); });
}

}  // namespace

void add_strain_command(CLI::App& app) {
  auto options = std::make_shared<Strain_command_options>();
  CLI::App* command = app.add_subcommand(
      "strain", "Per-triangle strain of every frame: a field file, meshes coloured by strain, a JSON summary");
  add_input(*command, options->input, options->read);
  add_parameters(*command, frontend::strain_parameters, options->strain);
  command->add_option("--out", options->out,
                      "Write the field: FILE.csv (a line per frame, a column per triangle) or any other "
                      "name for a one-line JSON header and little-endian float32 values, frame after frame")
      ->check(output_file());
  command->add_option("--mesh-dir", options->mesh_dir,
                      "Write every frame as a PLY mesh coloured by normalised strain (viridis: dark purple "
                      "0, yellow 1) into DIR (created when missing)")
      ->check(output_folder());
  command->add_option("--png", options->png,
                      "Draw frames coloured by normalised strain (viridis), side by side, seen along the axis in "
                      "which the motion is thinnest, into FILE.png")
      ->check(output_file());
  command->add_option("--png-frames", options->png_frames, "The frames --png draws. Default: 6, evenly spaced")
      ->check(whole_numbers(frontend::counts()))
      ->delimiter(',');
  add_json_option(*command, options->json, "the summary");
  command->callback([options] { run(*options); });
}

}  // namespace deformseg::tool
