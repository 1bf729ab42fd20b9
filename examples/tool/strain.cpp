// deformseg strain INPUT: the per-triangle strain of every frame, as a field file, coloured
// meshes and a JSON summary.
#include "command.h"

#include <deformseg/io/write_sequence.h>
#include <deformseg/io/write_strain_field.h>
#include <deformseg/strain.h>
#include <deformseg/strain_colors.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
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
  std::string out;
  std::string mesh_dir;
  std::string json;
};

// The strain field the options ask for, with a measure and a normalisation chosen at run time.
template <StrainMeasure Measure>
Strain_field<float> field_with(const Surface_mesh_animation& animation, const Strain_command_options& o,
                               Measure measure) {
  const auto reference = o.reference == "rest" ? Strain_reference::rest_pose : Strain_reference::previous_pose;
  const int threads = o.input.threads;
  if (o.normalize == "none")
    return compute_strain(animation, Strain_options{.reference = reference, .rest_frame = o.rest_frame,
                                                    .measure = measure, .normalization = No_normalization{},
                                                    .threads = threads});
  return compute_strain(animation, Strain_options{.reference = reference, .rest_frame = o.rest_frame,
                                                  .measure = measure,
                                                  .normalization = Gaussian_normalization{.sigma = o.sigma},
                                                  .threads = threads});
}

Strain_field<float> field_of(const Surface_mesh_animation& animation, const Strain_command_options& o) {
  if (o.measure == "green-lagrange") return field_with(animation, o, Green_lagrange_strain{});
  if (o.measure == "frobenius") return field_with(animation, o, Frobenius_strain{});
  if (o.measure == "area-ratio") return field_with(animation, o, Area_ratio_strain{});
  return field_with(animation, o, Max_principal_strain{});
}

// The colours of frame t: of the normalised strain, or, for a raw field, of the strain normalised
// the default way for the picture only.
std::vector<float> colour_values(const Strain_field<float>& field) {
  std::vector<float> values(field.values().begin(), field.values().end());
  if (!field.sigma()) Gaussian_normalization{}.normalize(Raw_strain_field<float>{values, field.num_faces()});
  return values;
}

void write_meshes(const Surface_mesh_animation& animation, const Strain_field<float>& field,
                  const std::string& folder) {
  progress("writing " + std::to_string(animation.num_frames()) + " coloured meshes to " + folder);
  const std::vector<float> values = colour_values(field);
  const std::size_t faces = field.num_faces();
  io::write_sequence(animation, folder,
                     {.face_colors = [&](std::size_t t) {
                       return strain_colors(std::span<const float>(values).subspan(t * faces, faces));
                     }});
}

void write_field(const Strain_field<float>& field, const std::string& path) {
  progress("writing the field to " + path);
  if (std::filesystem::path(path).extension() == ".csv")
    io::write_strain_csv(field, path);
  else
    io::write_strain_binary(field, path);
}

nlohmann::json summary(const Strain_command_options& o, const Strain_field<float>& field) {
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
  if (o.reference == "rest") document["rest_frame"] = o.rest_frame;
  if (field.sigma()) document["sigma"] = *field.sigma();
  return document;
}

void print(const nlohmann::json& s) {
  std::cout << std::setprecision(6) << "frames      " << s["frames"] << "\ntriangles   " << s["triangles"] << "\nsigma       "
            << s["sigma"].dump() << "\ndegenerate  " << s["degenerate_count"] << "\nframe  min  max  mean\n";
  for (const auto& f : s["per_frame"])
    std::cout << f["frame"] << "  " << f["min"].get<double>() << "  " << f["max"].get<double>() << "  "
              << f["mean"].get<double>() << '\n';
}

void run(const Strain_command_options& o) {
  if (o.sigma && o.normalize == "none") throw invalid_input("--sigma asks for --normalize gaussian");
  if (o.reference == "previous" && o.rest_frame != 0) throw invalid_input("--rest-frame asks for --reference rest");
  const Surface_mesh_animation animation = read_input(o.input);
  progress("computing the strain of " + std::to_string(animation.num_faces()) + " triangles x " +
           std::to_string(animation.num_frames()) + " frames");
  const Strain_field<float> field = field_of(animation, o);
  if (!o.out.empty()) write_field(field, o.out);
  if (!o.mesh_dir.empty()) write_meshes(animation, field, o.mesh_dir);
  const nlohmann::json document = summary(o, field);
  if (o.json.empty())
    print(document);
  else
    write_json(document, o.json);
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
                      "name for a one-line JSON header and little-endian float32 values, frame after frame");
  command->add_option("--mesh-dir", options->mesh_dir,
                      "Write every frame as a PLY mesh coloured by normalised strain (viridis: dark purple "
                      "0, yellow 1) into DIR");
  command->add_option("--json", options->json, "Write the summary as JSON to FILE ('-': standard output)")
      ->check(output_file());
  command->callback([options] { run(*options); });
}

}  // namespace deformseg::tool
