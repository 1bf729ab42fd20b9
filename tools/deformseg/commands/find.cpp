// deformseg find QUERY LONG: where a short motion occurs in a long animation, by find_motion with
// the default policy (motion signatures); deformseg find QUERY --store S: where it occurs in a
// motion store's clips, by find_motion_in_collection on the descriptions as stored.
#include "command.h"

#include <frontend/store_search.h>

#include <deformseg/search/find_motion_in_collection.h>
#include <deformseg/similarity/find_motion.h>
#include <deformseg/store/motion_store.h>

#include <iostream>
#include <memory>

namespace deformseg::tool {
namespace {

struct Find_command_options {
  std::vector<std::string> inputs;  // the query, then the long animation (none with --store)
  Input_options read;
  std::string store;
  std::size_t count = similarity::Find_motion_options{}.count;
  double shortest = similarity::Find_motion_options{}.shortest;
  std::string json;
};

nlohmann::json alignment_json(const similarity::Motion_match& m) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& [i, j] : m.alignment) pairs.push_back({i, j});
  return pairs;
}

// find QUERY --store S: the best windows over the store's clips, each in its clip's stored frames.
void run_find_in_store(const Find_command_options& o) {
  if (o.inputs.size() != 1)
    throw invalid_input("find --store takes one input, the query, not " + std::to_string(o.inputs.size()));
  frontend::check(o.read, frontend::Front::command_line);
  const frontend::Store_search library(o.store);
  if (library.size() == 0) throw invalid_input("the store holds no clip", {.file = o.store});
  const std::vector<frontend::Read_input> inputs = read_inputs(o.inputs, o.read);
  progress("looking for " + std::to_string(inputs[0].animation.num_frames()) + " frames in the " +
           std::to_string(library.size()) + " clips of " + o.store);
  const std::vector<search::Clip_match> matches =
      library.find(inputs[0].animation, {.count = o.count, .shortest = o.shortest, .threads = o.read.threads});
  nlohmann::json found = nlohmann::json::array();
  for (const search::Clip_match& c : matches) {
    const store::Store_record record = library.store().record(c.clip);
    found.push_back({{"clip_index", c.clip}, {"path", record.path}, {"clip", record.clip}, {"body", record.body},
                     {"first", c.match.first}, {"last", c.match.last}, {"similarity", c.match.value},
                     {"alignment", alignment_json(c.match)}});
  }
  const nlohmann::json document = {{"query", o.inputs[0]},         {"store", o.store},
                                   {"sources", sources(inputs, o.read)}, {"policy", frontend::Policy_choice{}.policy},
                                   {"values", "descriptions as stored"}, {"matches", found}};
  write_outputs(document, o.json, [&] {
    for (const search::Clip_match& c : matches)
      std::cout << "clip " << c.clip << "  frames " << c.match.first << " to " << c.match.last << "  similarity "
                << value_text(c.match.value) << "  " << library.name(c.clip) << '\n';
  });
}

void run_find(const Find_command_options& o) {
  if (!o.store.empty()) return run_find_in_store(o);
  if (o.inputs.size() != 2)
    throw invalid_input("find takes the query and the long animation, or the query and --store S");
  frontend::check(o.read, frontend::Front::command_line);
  const std::vector<frontend::Read_input> inputs = read_inputs(o.inputs, o.read);
  const mesh::Surface_mesh_animation &query = inputs[0].animation, &long_animation = inputs[1].animation;
  progress("looking for " + std::to_string(query.num_frames()) + " frames in " +
           std::to_string(long_animation.num_frames()));
  const auto matches = similarity::find_motion(query, long_animation,
                                              {.count = o.count, .shortest = o.shortest, .threads = o.read.threads});
  nlohmann::json found = nlohmann::json::array();
  for (const similarity::Motion_match& m : matches)
    found.push_back({{"first", m.first}, {"last", m.last}, {"similarity", m.value}, {"alignment", alignment_json(m)}});
  const nlohmann::json document = {
      {"query", o.inputs[0]}, {"long", o.inputs[1]}, {"sources", sources(inputs, o.read)},
      {"policy", frontend::Policy_choice{}.policy}, {"matches", found}};
  write_outputs(document, o.json, [&] {
    for (const similarity::Motion_match& m : matches)
      std::cout << "frames " << m.first << " to " << m.last << "  similarity " << value_text(m.value) << '\n';
  });
}

}  // namespace

void add_find_command(CLI::App& app) {
  auto o = std::make_shared<Find_command_options>();
  CLI::App* command = app.add_subcommand(
      "find", "Where a short motion occurs in a long animation: the best non-overlapping windows, by motion "
              "signatures; a window's value is the query against its frames described alone (1 for a copy). "
              "With --store, where it occurs in a motion store's clips, valued on their descriptions as stored");
  add_inputs(*command, "inputs", o->inputs, 1, 2, o->read,
             "The short motion (the query), then the long animation (none with --store)");
  command->add_option("--store", o->store,
                      "Look in every clip of this motion store (deformseg describe) instead of a long animation");
  command->add_option("--count", o->count, "How many windows at most")
      ->check(whole_numbers(frontend::result_counts))
      ->capture_default_str();
  command->add_option("--shortest", o->shortest,
                      "A window lasts from this fraction of the query's duration to its inverse (0.5: from half to "
                      "twice, a motion up to twice as fast or as slow)")
      ->check(numbers(frontend::window_shares))
      ->capture_default_str();
  add_json_option(*command, o->json, "the windows, their values and warping paths");
  command->callback([o] { run_find(*o); });
}

}  // namespace deformseg::tool
