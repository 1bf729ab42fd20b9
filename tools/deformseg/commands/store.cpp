// The motion store: deformseg describe INPUTS... --store S writes the clips' descriptions once;
// deformseg search QUERY... --store S finds a query's nearest clips in it, deformseg knn-graph
// every clip's; deformseg store info S and store verify S say what it holds and check every byte.
#include "command.h"
#include "policy_options.h"

#include <frontend/store.h>
#include <frontend/store_search.h>

#include <deformseg/search/nearest_motions.h>
#include <deformseg/store/motion_store.h>
#include <deformseg/store/stored_motions.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

namespace deformseg::tool {
namespace {

// Values in text as JSON writes them: the shortest decimal that reads back to the same double.
std::string exact(double value) { return nlohmann::json(value).dump(); }

void add_store_option(CLI::App& command, std::string& store, const std::string& help) {
  command.add_option("--store", store, help)->required();
}

// ---- deformseg describe INPUTS... --store S --------------------------------------------------

struct Describe_options {
  std::vector<std::string> inputs;
  Input_options read;
  Policy_options policy;
  std::string store;
  bool hash = false;
  bool skip_unreadable = false;
  std::string json;
};

void run_describe(const Describe_options& o) {
  const similarity::Default_similarity policy = frontend::store_policy(o.policy, frontend::Front::command_line);
  frontend::check(o.read, frontend::Front::command_line);
  const auto start = std::chrono::steady_clock::now();
  const frontend::Describe_report report = frontend::describe_inputs(
      o.store, o.inputs, o.read, policy, {.hash = o.hash, .skip_unreadable = o.skip_unreadable}, progress);
  const double seconds = seconds_since(start);
  const nlohmann::json document = {{"store", o.store},         {"clips", report.clips},
                                   {"described", report.described}, {"redescribed", report.redescribed},
                                   {"skipped", report.skipped},  {"unreadable", report.unreadable},
                                   {"poses_left_out", report.poses}, {"seconds", seconds}};
  write_outputs(document, o.json, [&] {
    std::cout << "described    " << report.described.size() << "\nre-described " << report.redescribed.size()
              << "\nskipped      " << report.skipped.size() << " (unchanged)\nunreadable   "
              << report.unreadable.size() << " (left out by --skip-unreadable)\nleft out     " << report.poses.size()
              << " (poses of 1 frame in character files read whole)\nstore        " << o.store << ", "
              << report.clips << " clips\n";
    for (const auto& name : report.described) std::cout << "  described    " << name << '\n';
    for (const auto& name : report.redescribed) std::cout << "  re-described " << name << '\n';
    for (const auto& line : report.unreadable) std::cout << "  unreadable   " << line << '\n';
  });
  if (report.described.empty() && report.redescribed.empty() && report.skipped.empty())
    throw invalid_input("nothing described: " +
                            (report.unreadable.empty() ? std::string("the inputs hold no clip")
                                                       : "every input was unreadable (" +
                                                             std::to_string(report.unreadable.size()) + ")"),
                        {.file = o.store});
}

// ---- deformseg search QUERY... --store S -----------------------------------------------------

struct Search_options {
  std::vector<std::string> queries;
  std::vector<std::size_t> clip_indices;
  Input_options read;
  std::string store;
  std::size_t k = 10;
  std::string json;
};

nlohmann::json pruning_json(const search::Pruning_report& p) {
  return {{"candidates", p.candidates},     {"pruned_by_summary", p.pruned_by_summary},
          {"pruned_by_rows", p.pruned_by_rows}, {"abandoned", p.abandoned},
          {"aligned", p.aligned},           {"rows_aligned", p.rows_aligned},
          {"rows_abandoned", p.rows_abandoned}, {"pruned_share", p.pruned_share()}};
}

nlohmann::json neighbours_json(const std::vector<search::Neighbour>& neighbours, const store::Motion_store& store) {
  nlohmann::json found = nlohmann::json::array();
  for (std::size_t r = 0; r < neighbours.size(); ++r) {
    const store::Store_record record = store.record(neighbours[r].index);
    found.push_back({{"rank", r + 1}, {"index", neighbours[r].index}, {"path", record.path}, {"clip", record.clip},
                     {"body", record.body}, {"name", frontend::clip_name(record.path, record.clip, record.body)},
                     {"value", neighbours[r].value}});
  }
  return found;
}

void run_search(const Search_options& o) {
  if (o.queries.empty() && o.clip_indices.empty())
    throw invalid_input("search needs a query: an animation, or --clip-index I for a clip of the store");
  frontend::check(o.read, frontend::Front::command_line);
  const frontend::Store_search library(o.store);
  const store::Motion_store& store = library.store();
  for (const std::size_t i : o.clip_indices)
    if (i >= store.size())
      throw invalid_input("--clip-index " + std::to_string(i) + ": the store holds " + std::to_string(store.size()) +
                          " clips", {.file = o.store});
  if (store.size() == 0) throw invalid_input("the store holds no clip", {.file = o.store});
  const search::Nearest_motions_options options{.k = o.k, .threads = o.read.threads};
  nlohmann::json results = nlohmann::json::array();
  const auto start = std::chrono::steady_clock::now();
  const auto record = [&](const std::string& name, std::optional<std::size_t> index,
                          const search::Nearest_motions& found) {
    results.push_back({{"query", name}, {"clip_index", index ? nlohmann::json(*index) : nlohmann::json()},
                       {"neighbours", neighbours_json(found.neighbours, store)},
                       {"pruning", pruning_json(found.pruning)}});
  };
  for (const frontend::Read_input& query : read_inputs(o.queries, o.read)) {
    const std::string name = query.gltf ? query.name.file + "#" + query.gltf->clip : query.name.file;
    record(name, std::nullopt, library.nearest(query.animation, options));
  }
  for (const std::size_t i : o.clip_indices) record(library.name(i), i, library.nearest_to_clip(i, options));
  const double seconds = seconds_since(start);
  const nlohmann::json document = {{"store", o.store}, {"k", o.k}, {"queries", results}, {"seconds", seconds}};
  write_outputs(document, o.json, [&] {
    for (const auto& q : results) {
      const auto& p = q["pruning"];
      std::cout << "query " << q["query"].get<std::string>() << "  (" << p["candidates"] << " candidates, "
                << p["aligned"] << " aligned whole)\n";
      for (const auto& n : q["neighbours"])
        std::cout << "  " << n["rank"] << "  " << value_text(n["value"].get<double>()) << "  "
                  << n["name"].get<std::string>() << '\n';
    }
  });
}

// ---- deformseg knn-graph --store S -------------------------------------------------------------

struct Knn_options {
  std::string store;
  std::size_t k = 10;
  int threads = 0;
  std::string csv;
  std::string json;
};

// `text` as a CSV field: in double quotes, its quotes doubled, when it holds a comma, a quote or a
// line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}

// The edges, a line each: the store's indices, the rank, the value (every digit), then the two
// clips' names.
void write_edges_csv(const std::vector<search::Nearest_motions>& graph, const frontend::Store_search& library,
                     const std::string& path) {
  std::ofstream file;
  if (path != "-") {
    progress("writing the edges to " + path);
    file.open(path);
    if (!file) throw invalid_input("cannot write the file", {.file = path});
  }
  std::ostream& out = path == "-" ? std::cout : file;
  out << "source,target,rank,value,source_name,target_name\n";
  for (std::size_t i = 0; i < graph.size(); ++i)
    for (std::size_t r = 0; r < graph[i].neighbours.size(); ++r) {
      const search::Neighbour& n = graph[i].neighbours[r];
      out << i << ',' << n.index << ',' << r + 1 << ',' << exact(n.value) << ',' << csv_field(library.name(i)) << ','
          << csv_field(library.name(n.index)) << '\n';
    }
  if (!out) throw invalid_input("cannot write the file", {.file = path});
}

void run_knn_graph(const Knn_options& o) {
  const frontend::Store_search library(o.store);
  const store::Motion_store& store = library.store();
  if (store.size() == 0) throw invalid_input("the store holds no clip", {.file = o.store});
  progress("searching the " + std::to_string(store.size()) + " clips' nearest " + std::to_string(o.k));
  const auto start = std::chrono::steady_clock::now();
  const std::vector<search::Nearest_motions> graph =
      library.knn_graph({.k = o.k, .threads = o.threads});
  const double seconds = seconds_since(start);
  search::Pruning_report total;
  for (const auto& node : graph) total += node.pruning;
  if (!o.csv.empty()) write_edges_csv(graph, library, o.csv);
  nlohmann::json document;
  if (!o.json.empty()) {
    nlohmann::json edges = nlohmann::json::array(), clips = nlohmann::json::array();
    for (std::size_t i = 0; i < store.size(); ++i) {
      const store::Store_record record = store.record(i);
      clips.push_back({{"index", i}, {"name", library.name(i)}, {"path", record.path}, {"clip", record.clip},
                       {"body", record.body}});
      for (std::size_t r = 0; r < graph[i].neighbours.size(); ++r) {
        const search::Neighbour& n = graph[i].neighbours[r];
        const store::Store_record target = store.record(n.index);
        edges.push_back({{"source", i}, {"target", n.index}, {"rank", r + 1}, {"value", n.value},
                         {"source_path", record.path}, {"source_clip", record.clip}, {"source_body", record.body},
                         {"target_path", target.path}, {"target_clip", target.clip}, {"target_body", target.body}});
      }
    }
    document = {{"store", o.store}, {"k", o.k},          {"clips", clips},
                {"edges", edges},   {"pruning", pruning_json(total)}, {"seconds", seconds}};
  }
  write_outputs(document, o.json, [&] {
    std::size_t edges = 0;
    for (const auto& node : graph) edges += node.neighbours.size();
    std::cout << "clips       " << store.size() << "\nedges       " << edges << "\ncandidates  " << total.candidates
              << "\naligned     " << total.aligned << " whole (" << percent_text(total.pruned_share())
              << " % pruned before a full alignment)\nseconds     " << seconds_text(seconds) << '\n';
  }, o.csv == "-");
}

// ---- deformseg store info S / store verify S -------------------------------------------------

struct Store_command_options {
  std::string store;
  std::string json;
};

nlohmann::json clips_json(const store::Motion_store& store) {
  nlohmann::json clips = nlohmann::json::array();
  for (std::size_t i = 0; i < store.size(); ++i) {
    const store::Store_record r = store.record(i);
    clips.push_back({{"index", i}, {"path", r.path}, {"clip", r.clip}, {"body", r.body}, {"frames", r.frame_count},
                     {"fps", r.fps}, {"rows", r.rows},
                     {"input_options", nlohmann::json::parse(r.input_options, nullptr, false)},
                     {"source_size", r.source_size}, {"source_mtime_ns", r.source_mtime_ns},
                     {"source_hash", r.source_hash}, {"topology_path", r.topology_path}});
  }
  return clips;
}

void run_store_info(const Store_command_options& o) {
  const store::Motion_store store = store::Motion_store::open(o.store);
  const nlohmann::json document = {{"store", o.store},
                                   {"generation", store.generation()},
                                   {"version", store.version()},
                                   {"clips", clips_json(store)},
                                   {"width", store.width()},
                                   {"summary_width", store.summary_width()},
                                   {"description", nlohmann::json::parse(store.description(), nullptr, false)},
                                   {"summary_layout", nlohmann::json::parse(store.summary_layout(), nullptr, false)}};
  write_outputs(document, o.json, [&] {
    std::size_t rows = 0;
    for (std::size_t i = 0; i < store.size(); ++i) rows += store.record(i).rows;
    std::cout << "store        " << o.store << "\nclips        " << store.size() << "\nsignatures   " << rows
              << " rows of " << store.width() << " floats\nappends      " << store.generation()
              << "\ndescription  " << store.description() << '\n';
  });
}

void run_store_verify(const Store_command_options& o) {
  const store::Motion_store store = store::Motion_store::open(o.store, store::Verify::checksums);
  const nlohmann::json document = {{"store", o.store}, {"clips", store.size()}, {"verified", true}};
  write_outputs(document, o.json, [&] {
    std::cout << "ok: " << store.size() << " clips, every file and clip matches its checksum\n";
  });
}

}  // namespace

void add_describe_command(CLI::App& app) {
  auto o = std::make_shared<Describe_options>();
  CLI::App* command = app.add_subcommand(
      "describe", "Describe clips once into a motion store: new clips are added, changed ones described again, "
                  "unchanged ones skipped; a clip is its file, its name and the body it plays on (one clip on two "
                  "bodies is two clips of the store)");
  add_inputs(*command, "inputs", o->inputs, 1, -1, o->read,
             "The clips: every clip of a glTF, FBX or Collada file that names none, or a labels CSV (evaluate's) "
             "for its rows, each on its body_file (else --body's body, else its own); or");
  add_parameter(*command, std::get<3>(frontend::policy_parameters), o->policy.up);
  add_parameter(*command, std::get<4>(frontend::policy_parameters), o->policy.bands);
  add_parameter(*command, std::get<5>(frontend::policy_parameters), o->policy.sides);
  add_store_option(*command, o->store, "The store's folder (made when missing)");
  command->add_flag("--hash", o->hash,
                    "Tell a changed source by its bytes' hash rather than its modification time (reads every file)");
  command->add_flag("--skip-unreadable", o->skip_unreadable,
                    "Leave out, with a line on standard error, the inputs and clips that cannot be read or described "
                    "(a pose of one frame), instead of stopping at the first; the clips described before a stop stay "
                    "in the store either way, and a second run describes the rest");
  add_json_option(*command, o->json, "what was described, described again, skipped and left out unreadable");
  command->callback([o] { run_describe(*o); });
}

void add_search_command(CLI::App& app) {
  auto o = std::make_shared<Search_options>();
  CLI::App* command =
      app.add_subcommand("search", "The k clips of a motion store that move most like each query, exactly");
  command->add_option("queries", o->queries, std::string("The queries, each ") + "an animation as matrix reads it");
  add_parameters(*command, frontend::input_parameters, o->read);
  add_store_option(*command, o->store, "The store (deformseg describe)");
  command->add_option("--clip-index", o->clip_indices,
                      "Also search with clip I of the store as a query, itself left out (repeatable)")
      ->check(whole_numbers(frontend::counts()));
  command->add_option("-k", o->k, "How many clips to find per query (more than the store holds: all)")
      ->check(whole_numbers(frontend::result_counts))
      ->capture_default_str();
  add_json_option(*command, o->json,
                  "the neighbours of each query (path, clip, body: '' for the clip's own, name) and how many "
                  "candidates each bound pruned");
  command->callback([o] { run_search(*o); });
}

void add_knn_graph_command(CLI::App& app) {
  auto o = std::make_shared<Knn_options>();
  CLI::App* command = app.add_subcommand("knn-graph", "Every clip's k nearest other clips of a motion store");
  add_store_option(*command, o->store, "The store (deformseg describe)");
  command->add_option("-k", o->k, "How many clips to find per clip (more than the store holds: all)")
      ->check(whole_numbers(frontend::result_counts))
      ->capture_default_str();
  command->add_option("--threads", o->threads, "Threads to use (0: all); results do not depend on it")
      ->check(whole_numbers(frontend::thread_counts));
  command->add_option("--csv", o->csv,
                      "Write the edges as CSV to FILE ('-': standard output): source,target,rank,value,"
                      "source_name,target_name (a name FILE#CLIP, with ' on BODY' for a clip played on another "
                      "file's body)")
      ->check(output_file());
  add_json_option(*command, o->json, "the clips (path, clip, body), the edges and the pruning counts");
  command->callback([o] { run_knn_graph(*o); });
}

void add_store_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("store", "What a motion store holds, and whether it is intact");
  command->require_subcommand(1);
  for (const bool verify : {false, true}) {
    auto o = std::make_shared<Store_command_options>();
    CLI::App* sub = command->add_subcommand(
        verify ? "verify" : "info",
        verify ? "Check every byte of a store against its checksums: fails naming the damaged file and clip"
               : "The store's clips, description options and sizes");
    sub->add_option("store", o->store, "The store's folder")->required();
    add_json_option(*sub, o->json, verify ? "the result" : "the store's clips and options");
    sub->callback([o, verify] { verify ? run_store_verify(*o) : run_store_info(*o); });
  }
}

}  // namespace deformseg::tool
