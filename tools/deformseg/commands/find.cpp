// deformseg find QUERY LONG: where a short motion occurs in a long animation, by find_motion with
// the default policy (motion signatures).
#include "command.h"

#include <deformseg/similarity/find_motion.h>

#include <iomanip>
#include <iostream>
#include <memory>

namespace deformseg::tool {
namespace {

struct Find_command_options {
  std::vector<std::string> inputs;  // the query, then the long animation
  Input_options read;
  std::size_t count = 3;
  double shortest = similarity::Find_motion_options{}.shortest;
  std::string json;
};

void run_find(const Find_command_options& o) {
  if (o.count == 0) throw invalid_input("--count must be at least 1");
  if (!(o.shortest > 0 && o.shortest <= 1)) throw invalid_input("--shortest must be in (0, 1]");
  const std::vector<frontend::Read_input> inputs = read_inputs(o.inputs, o.read);
  const mesh::Surface_mesh_animation &query = inputs[0].animation, &long_animation = inputs[1].animation;
  progress("looking for " + std::to_string(query.num_frames()) + " frames in " +
           std::to_string(long_animation.num_frames()));
  const auto matches = similarity::find_motion(query, long_animation, {.count = o.count, .shortest = o.shortest});
  nlohmann::json found = nlohmann::json::array();
  for (const similarity::Motion_match& m : matches) {
    nlohmann::json pairs = nlohmann::json::array();
    for (const auto& [i, j] : m.alignment) pairs.push_back({i, j});
    found.push_back({{"first", m.first}, {"last", m.last}, {"similarity", m.value}, {"alignment", pairs}});
  }
  const nlohmann::json document = {
      {"query", o.inputs[0]}, {"long", o.inputs[1]}, {"sources", sources(inputs, o.read)},
      {"policy", "motion-signature"}, {"matches", found}};
  write_outputs(document, o.json, [&] {
    for (const similarity::Motion_match& m : matches)
      std::cout << "frames " << m.first << " to " << m.last << "  similarity " << std::fixed << std::setprecision(3)
                << m.value << '\n';
  });
}

}  // namespace

void add_find_command(CLI::App& app) {
  auto o = std::make_shared<Find_command_options>();
  CLI::App* command = app.add_subcommand(
      "find", "Where a short motion occurs in a long animation: the best non-overlapping windows, by motion "
              "signatures; a window's value is the query against its frames described alone (1 for a copy)");
  add_inputs(*command, "inputs", o->inputs, 2, 2, o->read, "The short motion (the query), then the long animation");
  command->add_option("--count", o->count, "How many windows at most")->capture_default_str();
  command->add_option("--shortest", o->shortest,
                      "A window lasts from this fraction of the query's duration to its inverse, in (0, 1] "
                      "(0.5: from half to twice, a motion up to twice as fast or as slow)")
      ->capture_default_str();
  add_json_option(*command, o->json, "the windows, their values and warping paths");
  command->callback([o] { run_find(*o); });
}

}  // namespace deformseg::tool
