// deformseg ged A B and deformseg ged-matrix FILE...: graph edit distances between the user's
// labelled graphs (Graphviz DOT or GraphML, nodes with a `label` attribute).
#include "command.h"

#include <frontend/ged.h>
#include <frontend/outputs.h>

#include <deformseg/ged/ged_matrix.h>
#include <deformseg/io/graphviz.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <variant>

namespace deformseg::tool {
namespace {

struct Ged_command_options {
  std::string a, b;
  frontend::Ged_request method;
  std::string json;
};

struct Ged_matrix_command_options {
  std::vector<std::string> files;
  frontend::Ged_request method;
  int threads = 0;
  std::string json;
  std::string csv;
};

// Runs the policy the request names on a pair.
template <class Work>
auto with_policy(const frontend::Ged_request& request, const Work& work) {
  return std::visit(work, frontend::make_ged(request));
}

nlohmann::json number_or_null(double value) {
  return std::isinf(value) ? nlohmann::json(nullptr) : nlohmann::json(value);
}

io::Labelled_graph read_graph(const std::string& path) {
  progress("reading " + path);
  return io::read_labelled_graph(path);
}

void run_ged(const Ged_command_options& o) {
  const io::Labelled_graph a = read_graph(o.a), b = read_graph(o.b);
  const ged::Ged_result r = with_policy(o.method, [&](const auto& policy) { return policy(a, b, ged::Unit_costs{}); });
  nlohmann::json mapping = nlohmann::json::array();
  for (std::size_t i = 0; i < r.mapping.size(); ++i) mapping.push_back({i, r.mapping[i]});
  const nlohmann::json document = {{"a", o.a}, {"b", o.b}, {"nodes", {boost::num_vertices(a), boost::num_vertices(b)}},
                                   {"method", o.method.method}, {"distance", r.distance}, {"exact", r.exact},
                                   {"lower", r.lower}, {"upper", number_or_null(r.upper)}, {"mapping", mapping}};
  write_outputs(document, o.json, [&] {
    std::cout << "distance  " << r.distance << (r.exact ? " (exact)" : "") << "\nbounds    " << r.lower << " to "
              << r.upper << "\nmapping  ";
    for (std::size_t i = 0; i < r.mapping.size(); ++i)
      std::cout << ' ' << i << "->" << (r.mapping[i] < 0 ? "deleted" : std::to_string(r.mapping[i]));
    std::cout << '\n';
  });
}

nlohmann::json rows_of(const Eigen::MatrixXd& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(number_or_null(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

void write_csv(const Eigen::MatrixXd& d, const std::string& path) {
  if (path != "-") progress("writing the distance matrix to " + path);
  frontend::write_matrix_csv(d, path);
}

void run_ged_matrix(const Ged_matrix_command_options& o) {
  std::vector<io::Labelled_graph> graphs;
  for (const std::string& file : o.files) graphs.push_back(read_graph(file));
  const std::size_t pairs = graphs.size() * (graphs.size() - 1) / 2;
  progress("comparing " + std::to_string(pairs) + " pairs of graphs");
  // Called after each batch of about 5 % of the pairs.
  const ged::Ged_matrix_options options{.threads = o.threads, .progress = [](std::size_t done, std::size_t total) {
    progress(std::to_string(done) + " of " + std::to_string(total) + " pairs");
    return true;
  }};
  const ged::Ged_matrix_result r = with_policy(o.method, [&](const auto& policy) {
    return ged::ged_matrix_results(graphs, policy, ged::Unit_costs{}, options);
  });
  if (!o.csv.empty()) write_csv(r.distance, o.csv);
  const nlohmann::json document = {{"files", o.files}, {"method", o.method.method}, {"exact", r.exact},
                                   {"distance", rows_of(r.distance)}, {"lower", rows_of(r.lower)},
                                   {"upper", rows_of(r.upper)}};
  write_outputs(document, o.json, [&] {
    std::cout << "graph edit distances (" << o.method.method << (r.exact ? ", exact" : "") << "):\n";
    for (std::size_t i = 0; i < o.files.size(); ++i) {
      std::cout << i << "  " << o.files[i] << "\n  ";
      for (Eigen::Index j = 0; j < r.distance.cols(); ++j) std::cout << ' ' << r.distance(Eigen::Index(i), j);
      std::cout << '\n';
    }
  }, o.csv == "-");
}

}  // namespace

void add_ged_command(CLI::App& app) {
  auto options = std::make_shared<Ged_command_options>();
  CLI::App* command = app.add_subcommand(
      "ged", "Graph edit distance between two labelled graphs (Graphviz DOT or GraphML, each node with a "
             "'label' attribute; unit costs): the distance, its bounds and the node mapping");
  command->add_option("a", options->a, "The first graph (.dot, .gv, .graphml)")->required();
  command->add_option("b", options->b, "The second graph")->required();
  add_parameters(*command, frontend::ged_parameters, options->method);
  add_json_option(*command, options->json,
                  "distance, exact, lower, upper (null: none) and mapping [[i, j], ...] (j = -1: node i deleted)");
  command->callback([options] { run_ged(*options); });
}

void add_ged_matrix_command(CLI::App& app) {
  auto options = std::make_shared<Ged_matrix_command_options>();
  CLI::App* command = app.add_subcommand(
      "ged-matrix", "Graph edit distances between every two of the labelled graphs given, in parallel: a "
                    "symmetric matrix, pair i < j computed as i -> j");
  command->add_option("files", options->files, "The graphs (.dot, .gv, .graphml)")->required();
  add_parameters(*command, frontend::ged_parameters, options->method);
  command->add_option("--threads", options->threads, "Threads to use (0: all)")
      ->check(whole_numbers(frontend::thread_counts));
  command->add_option("--csv", options->csv, "Write the distance matrix as CSV to FILE ('-': standard output)")
      ->check(output_file());
  add_json_option(*command, options->json, "distances and bounds");
  command->callback([options] { run_ged_matrix(*options); });
}

}  // namespace deformseg::tool
