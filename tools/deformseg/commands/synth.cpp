// deformseg synth OUT: writes a synthetic bending tube and its ground truth.
#include "command.h"

#include <deformseg/io/point_cache.h>
#include <deformseg/io/obj.h>
#include <deformseg/io/frame_sequence.h>
#include <deformseg/mesh/synthetic.h>

#include <charconv>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>

namespace deformseg::tool {
namespace {

struct Synth_options {
  std::string out;
  std::string format = "obj";
  std::vector<double> joints{0.5};
  std::vector<double> directions;
  double blend_width = 0.15;
  std::vector<std::string> schedule{"10:0", "10:90", "10:", "10:0"};
  std::string easing = "smooth";
  mesh::Tube_shape shape;
  double scale = 1.0;
  std::vector<double> rotate{0, 0, 1, 0};
  std::vector<double> translate{0, 0, 0};
  std::string json;
};

constexpr double degree = std::numbers::pi / 180;

double parse_number(std::string_view text, std::string_view what) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    throw invalid_input("--schedule: '" + std::string(text) + "' is not a number in " + std::string(what));
  return value;
}

// "FRAMES:ANGLE,ANGLE,..." in degrees, one angle per joint; "FRAMES:" holds the pose.
mesh::Tube_phase parse_phase(const std::string& phase) {
  const auto colon = phase.find(':');
  if (colon == std::string::npos)
    throw invalid_input("--schedule: phase '" + phase + "' is not FRAMES:ANGLE[,ANGLE...]");
  mesh::Tube_phase result{.frames = std::size_t(parse_number(phase.substr(0, colon), phase)), .angles = {}};
  for (std::size_t begin = colon + 1; begin < phase.size();) {
    const auto comma = std::min(phase.find(',', begin), phase.size());
    result.angles.push_back(parse_number(phase.substr(begin, comma - begin), phase) * degree);
    begin = comma + 1;
  }
  return result;
}

mesh::Bending_tube specification(const Synth_options& o) {
  mesh::Bending_tube spec{.shape = o.shape, .joints = {}, .schedule = {}, .placement = {}};
  for (std::size_t j = 0; j < o.joints.size(); ++j)
    spec.joints.push_back({.position = o.joints[j], .blend_width = o.blend_width,
                           .direction = j < o.directions.size() ? o.directions[j] * degree : 0.0});
  for (const auto& phase : o.schedule) {
    spec.schedule.push_back(parse_phase(phase));
    spec.schedule.back().easing = o.easing == "linear" ? mesh::Easing::linear : mesh::Easing::smooth;
  }
  const Eigen::Vector3d axis(o.rotate[0], o.rotate[1], o.rotate[2]);
  if (axis.norm() == 0) throw invalid_input("--rotate: the axis must not be zero");
  spec.placement = {.scale = o.scale,
                    .rotation = Eigen::Quaterniond(Eigen::AngleAxisd(o.rotate[3] * degree, axis.normalized())),
                    .translation = Eigen::Vector3d(o.translate[0], o.translate[1], o.translate[2])};
  return spec;
}

nlohmann::json ground_truth(const mesh::Synthetic_animation<>& tube, const std::vector<std::filesystem::path>& files) {
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& [first, last] : tube.phase_frames) phases.push_back({{"first", first}, {"last", last}});
  nlohmann::json angles = nlohmann::json::array();
  for (const auto& pose : tube.joint_angles) {
    angles.push_back(nlohmann::json::array());
    for (double a : pose) angles.back().push_back(a / degree);
  }
  nlohmann::json written = nlohmann::json::array();
  for (const auto& file : files) written.push_back(file.string());
  return {{"frames", tube.animation.num_frames()},     {"vertices", tube.animation.num_vertices()},
          {"triangles", tube.animation.num_faces()},   {"phases", phases},
          {"joint_angles_degrees", angles},            {"face_joint", tube.face_joint},
          {"files", written}};
}

std::vector<std::filesystem::path> write(const mesh::Synthetic_animation<>& tube, const Synth_options& o) {
  const std::filesystem::path out(o.out);
  std::filesystem::create_directories(out);
  if (o.format == "obj" || o.format == "ply")
    return io::write_sequence(tube.animation, out,
                              {.format = o.format == "obj" ? io::Mesh_format::obj : io::Mesh_format::ply});
  const auto topology = out / "tube.obj";
  const auto cache = out / ("tube." + o.format);
  io::write_obj(tube.animation, 0, topology);
  if (o.format == "pc2")
    io::write_pc2(tube.animation, cache);
  else
    io::write_mdd(tube.animation, cache);
  return {topology, cache};
}

}  // namespace

void add_synth_command(CLI::App& app) {
  auto o = std::make_shared<Synth_options>();
  CLI::App* command = app.add_subcommand(
      "synth", "Write a synthetic tube bending at joints on a schedule, with its ground truth "
               "(OUT/ground_truth.json: which joint deforms each triangle, the phases)");
  command->add_option("out", o->out, "Folder to write the animation into (created when missing)")
      ->required()
      ->check(output_folder());
  command->add_option("--format", o->format, "obj or ply: a file per frame; pc2 or mdd: a point "
                                             "cache with tube.obj as its topology")
      ->check(CLI::IsMember({"obj", "ply", "pc2", "mdd"}))->capture_default_str();
  command->add_option("--joints", o->joints, "Joint heights as fractions of the length, bottom up")
      ->delimiter(',')
      ->check(numbers(frontend::shares))
      ->capture_default_str();
  command->add_option("--directions", o->directions,
                      "Side each joint bends towards, degrees around the axis (default 0: +x)")
      ->delimiter(',')
      ->check(numbers(frontend::Range{}));
  command->add_option("--blend-width", o->blend_width, "Blend zone of a joint, as a fraction of the length")
      ->check(numbers(frontend::Range{.min = 0, .max = 1, .min_open = true}))
      ->capture_default_str();
  command->add_option("--schedule", o->schedule,
                      "Phases FRAMES:ANGLE[,ANGLE...] in degrees, one angle per joint; FRAMES: holds")
      ->capture_default_str();
  command->add_option("--easing", o->easing,
                      "How the angles move in each phase: smooth (soft start and stop) or linear (constant speed)")
      ->check(CLI::IsMember({"smooth", "linear"}))
      ->capture_default_str();
  command->add_option("--radius", o->shape.radius, "Tube radius")->check(numbers(frontend::positive))
      ->capture_default_str();
  command->add_option("--length", o->shape.length, "Tube length")->check(numbers(frontend::positive))
      ->capture_default_str();
  command->add_option("--sectors", o->shape.sectors, "Vertices around the axis")
      ->check(whole_numbers({.min = 3, .max = 10000}))
      ->capture_default_str();
  command->add_option("--rings", o->shape.rings, "Segments along the axis")
      ->check(whole_numbers({.min = 1, .max = 100000}))
      ->capture_default_str();
  command->add_option("--scale", o->scale, "Uniform scale of every frame")->check(numbers(frontend::positive))
      ->capture_default_str();
  command->add_option("--rotate", o->rotate, "Rotation of every frame: AXIS_X,AXIS_Y,AXIS_Z,DEGREES")
      ->delimiter(',')
      ->expected(4)
      ->check(numbers(frontend::Range{}));
  command->add_option("--translate", o->translate, "Translation of every frame: X,Y,Z")
      ->delimiter(',')
      ->expected(3)
      ->check(numbers(frontend::Range{}));
  add_json_option(*command, o->json, "the ground truth");
  command->callback([o] {
    const auto tube = mesh::make_bending_tube(specification(*o));
    progress("writing " + std::to_string(tube.animation.num_frames()) + " frames to " + o->out);
    const nlohmann::json truth = ground_truth(tube, write(tube, *o));
    frontend::write_json(truth, (std::filesystem::path(o->out) / "ground_truth.json").string());
    write_outputs(truth, o->json, [&] { print_written(truth); });
  });
}

}  // namespace deformseg::tool
