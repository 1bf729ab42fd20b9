// deformseg strain INPUT: the per-triangle strain of every frame, as a field file, coloured
// meshes and a JSON summary.
#include "command.h"
#include "figures/render.h"

#include <deformseg/io/frame_sequence.h>
#include <deformseg/io/strain_field.h>
#include <deformseg/strain/strain.h>
#include <deformseg/color/strain_colors.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

struct Strain_command_options {
  Input_options input;
  std::string reference = "rest";
  std::size_t rest_frame = 0;
  std::string measure = "max-principal";
  std::string normalize = "gaussian";
  std::optional<double> sigma;
  std::string reference_mesh;
  std::string out;
  std::string mesh_dir;
  std::string png;
  std::vector<std::size_t> png_frames;  // none given: up to 6, evenly spaced
  std::string json;
};

// The built-in measures by their names on the command line.
const std::map<std::string, strain::Strain_measure_choice> measures{{"max-principal", strain::Max_principal_strain{}},
                                                                    {"green-lagrange", strain::Green_lagrange_strain{}},
                                                                    {"frobenius", strain::Frobenius_strain{}},
                                                                    {"area-ratio", strain::Area_ratio_strain{}}};

// The strain field the options ask for, against a frame or against the reference mesh when there is one.
strain::Strain_field<float> field_of(const mesh::Surface_mesh_animation& animation,
                                     const mesh::Surface_mesh* reference_mesh, const Strain_command_options& o) {
  const strain::Strain_options options{
      .reference =
          o.reference == "rest" ? strain::Strain_reference::rest_pose : strain::Strain_reference::previous_pose,
      .rest_frame = o.rest_frame,
      .measure = measures.at(o.measure),
      .normalization = o.normalize == "none" ? strain::Strain_normalization_choice(strain::No_normalization{})
                                             : strain::Gaussian_normalization{.sigma = o.sigma},
      .threads = o.input.threads};
  if (!reference_mesh) return strain::compute_strain(animation, options);
  return naming_reference_mesh(o.reference_mesh,
                               [&] { return strain::compute_strain(animation, *reference_mesh, options); });
}

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
                          std::to_string(frames - 1), {.file = o.input.input});
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
  draw_text(image, o.measure + " strain of " + short_name(o.input.input), padding, padding, 2);
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
    io::write_strain_csv(field, path);
  else
    io::write_strain_binary(field, path);
}

nlohmann::json summary(const Strain_command_options& o, const strain::Strain_field<float>& field) {
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t t = 0; t < field.num_frames(); ++t) {
    const auto values = field.frame(t);
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    double sum = 0;
    for (float v : values) sum += v;
    frames.push_back({{"frame", t}, {"min", *low}, {"max", *high}, {"mean", sum / double(values.size())}});
  }
  nlohmann::json document = {{"input", o.input.input},
                             {"frames", field.num_frames()},
                             {"triangles", field.num_faces()},
                             {"reference", o.reference},
                             {"measure", o.measure},
                             {"normalize", o.normalize},
                             {"sigma", nullptr},
                             {"degenerate_count", field.degenerate_count()},
                             {"per_frame", frames}};
  if (o.reference == "rest" && o.reference_mesh.empty()) document["rest_frame"] = o.rest_frame;
  if (!o.reference_mesh.empty()) document["reference_mesh"] = o.reference_mesh;
  if (field.sigma()) document["sigma"] = *field.sigma();
  return document;
}

void print(const nlohmann::json& s) {
  std::cout << std::setprecision(6) << "frames      " << s["frames"] << "\ntriangles   " << s["triangles"]
            << "\nsigma       " << s["sigma"].dump() << "\ndegenerate  " << s["degenerate_count"]
            << "\nframe  min  max  mean\n";
  for (const auto& f : s["per_frame"])
    std::cout << f["frame"] << "  " << f["min"].get<double>() << "  " << f["max"].get<double>() << "  "
              << f["mean"].get<double>() << '\n';
}

void run(const Strain_command_options& o) {
  if (o.sigma && o.normalize == "none") throw invalid_input("--sigma asks for --normalize gaussian");
  if (o.reference == "previous" && o.rest_frame != 0) throw invalid_input("--rest-frame asks for --reference rest");
  if (!o.png_frames.empty() && o.png.empty()) throw invalid_input("--png-frames asks for --png");
  if (!o.reference_mesh.empty() && (o.reference == "previous" || o.rest_frame != 0))
    throw invalid_input("--reference-mesh takes the place of the rest frame: it excludes --reference previous and "
                        "--rest-frame");
  const mesh::Surface_mesh_animation animation = read_input(o.input);
  const std::vector<std::size_t> drawn =
      o.png.empty() ? std::vector<std::size_t>{} : frames_to_draw(o, animation.num_frames());
  std::optional<mesh::Surface_mesh> reference_mesh;
  if (!o.reference_mesh.empty()) reference_mesh = read_reference_mesh(o.reference_mesh);
  progress("computing the strain of " + std::to_string(animation.num_faces()) + " triangles x " +
           std::to_string(animation.num_frames()) + " frames");
  const strain::Strain_field<float> field = field_of(animation, reference_mesh ? &*reference_mesh : nullptr, o);
  if (!o.out.empty()) write_field(field, o.out);
  if (!o.mesh_dir.empty()) write_meshes(animation, field, o.mesh_dir);
  if (!o.png.empty()) write_picture(animation, field, drawn, o);
  const nlohmann::json document = summary(o, field);
  write_outputs(document, o.json, [&] { print(document); });
}

}  // namespace

void add_strain_command(CLI::App& app) {
  auto options = std::make_shared<Strain_command_options>();
  CLI::App* command = app.add_subcommand(
      "strain", "Per-triangle strain of every frame: a field file, meshes coloured by strain, a JSON summary");
  add_input_options(*command, options->input);
  command->add_option("--reference", options->reference, "rest: against one frame (the pose); previous: "
                                                         "against the frame before (the motion). Default: rest")
      ->check(CLI::IsMember({"rest", "previous"}));
  command->add_option("--rest-frame", options->rest_frame, "The rest frame, with --reference rest. Default: 0");
  add_reference_mesh_option(*command, options->reference_mesh);
  command->add_option("--measure", options->measure,
                      "max-principal: max |l - 1| over the principal stretches l (default); green-lagrange: "
                      "max |l^2 - 1| / 2; frobenius: |U - I|; area-ratio: |l1 l2 - 1|")
      ->check(CLI::IsMember({"max-principal", "green-lagrange", "frobenius", "area-ratio"}));
  command->add_option("--normalize", options->normalize,
                      "gaussian: 1 - exp(-s^2 / 2 sigma^2), sigma the 95th percentile of the strains unless "
                      "--sigma gives it (default); none: raw strains")
      ->check(CLI::IsMember({"gaussian", "none"}));
  command->add_option("--sigma", options->sigma, "The Gaussian normalisation's sigma")->check(CLI::PositiveNumber);
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
      ->delimiter(',');
  add_json_option(*command, options->json, "the summary");
  command->callback([options] { run(*options); });
}

}  // namespace deformseg::tool
