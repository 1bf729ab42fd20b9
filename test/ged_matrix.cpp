#include <deformseg/ged/ged_matrix.h>
#include <deformseg/ged/lower_bound.h>
#include <deformseg/threads.h>

#include "ged_support.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>
#include <span>

namespace {

using deformseg::ged::Assignment_lower_bound;
using deformseg::ged::Bipartite_ged;
using deformseg::ged::edit_cost;
using deformseg::ged::Exact_ged;
using deformseg::ged::ged_matrix;
using deformseg::ged::Ged_matrix_result;
using deformseg::ged::ged_matrix_results;
using deformseg::ged::Ged_result;
using deformseg::ged::Unit_costs;
using deformseg::test::Ged_graph;

std::vector<Ged_graph> random_graphs(unsigned seed, std::size_t count) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> size(0, 8);
  std::vector<Ged_graph> graphs;
  for (std::size_t k = 0; k < count; ++k)
    graphs.push_back(deformseg::test::random_labelled_graph(rng, size(rng), 3, 0.3));
  return graphs;
}

template <class Policy>
void check_matrix(const std::vector<Ged_graph>& graphs, const Policy& policy) {
  const Ged_matrix_result r = ged_matrix_results(graphs, policy);
  const auto k = graphs.size();
  REQUIRE(r.distance.rows() == static_cast<Eigen::Index>(k));
  REQUIRE(r.pairs.size() == k * (k - 1) / 2);
  CHECK(r.distance == r.distance.transpose());
  CHECK(r.distance.diagonal().isZero(0));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j) {
      const Ged_result alone = policy(graphs[i], graphs[j], Unit_costs{});
      const Ged_result& stored = r.pairs[r.pair_index(j, i)];
      const auto ei = static_cast<Eigen::Index>(i), ej = static_cast<Eigen::Index>(j);
      CHECK(r.distance(ei, ej) == alone.distance);
      CHECK(r.lower(ej, ei) == alone.lower);
      CHECK(r.upper(ei, ej) == alone.upper);
      CHECK(stored.mapping == alone.mapping);
      CHECK(stored.exact == alone.exact);
    }
}

}  // namespace

TEST_CASE("ged_matrix: symmetric, zero diagonal, equal to the pairwise calls", "[ged][matrix]") {
  const auto graphs = random_graphs(71, 9);
  check_matrix(graphs, Exact_ged{});
  check_matrix(graphs, Bipartite_ged{});
  check_matrix(graphs, Assignment_lower_bound{});
  const Ged_matrix_result exact = ged_matrix_results(graphs);
  CHECK(exact.exact);
  CHECK(ged_matrix(std::span<const Ged_graph>(graphs)) == exact.distance);
  CHECK(ged_matrix(std::vector<Ged_graph>{}).size() == 0);
  CHECK(ged_matrix(std::vector<Ged_graph>(1)) == Eigen::MatrixXd::Zero(1, 1));
}

TEST_CASE("ged_matrix: the same for any number of threads", "[ged][matrix]") {
  const auto graphs = random_graphs(72, 12);
  const Ged_matrix_result one = ged_matrix_results(graphs, Exact_ged{}, Unit_costs{}, {.threads = 1});
  const Ged_matrix_result two = ged_matrix_results(graphs, Exact_ged{}, Unit_costs{}, {.threads = 2});
  CHECK(one.distance == two.distance);
  for (std::size_t p = 0; p < one.pairs.size(); ++p) CHECK(one.pairs[p].mapping == two.pairs[p].mapping);
  const auto uneven = deformseg::test::Uneven_costs{};
  const Eigen::MatrixXd serial = ged_matrix(graphs, Bipartite_ged{}, uneven, {.threads = 1});
  const Eigen::MatrixXd parallel = ged_matrix(graphs, Bipartite_ged{}, uneven, {.threads = 7});
  CHECK(serial == parallel);
}

TEST_CASE("ged_matrix: both directions give the tighter bounds", "[ged][matrix]") {
  const auto graphs = random_graphs(73, 10);
  const Ged_matrix_result once = ged_matrix_results(graphs, Bipartite_ged{});
  const Ged_matrix_result both = ged_matrix_results(graphs, Bipartite_ged{}, Unit_costs{}, {.both_directions = true});
  const Ged_matrix_result lower =
      ged_matrix_results(graphs, Assignment_lower_bound{}, Unit_costs{}, {.both_directions = true});
  const Eigen::MatrixXd exact = ged_matrix(graphs);
  int better = 0;
  for (std::size_t i = 0; i < graphs.size(); ++i)
    for (std::size_t j = i + 1; j < graphs.size(); ++j) {
      const auto ei = static_cast<Eigen::Index>(i), ej = static_cast<Eigen::Index>(j);
      const double reverse = Bipartite_ged{}(graphs[j], graphs[i]).upper;
      CHECK(both.distance(ei, ej) == std::min(once.distance(ei, ej), reverse));
      const Ged_result& r = both.pairs[both.pair_index(i, j)];
      CHECK(edit_cost(graphs[i], graphs[j], r.mapping) == r.upper);  // turned round when from j -> i
      CHECK(both.distance(ei, ej) >= exact(ei, ej));
      CHECK(lower.distance(ei, ej) <= exact(ei, ej));
      CHECK(lower.distance(ei, ej) == std::max(Assignment_lower_bound{}(graphs[i], graphs[j]).lower,
                                                Assignment_lower_bound{}(graphs[j], graphs[i]).lower));
      better += both.distance(ei, ej) < once.distance(ei, ej) ? 1 : 0;
    }
  CHECK(better > 0);
}

TEST_CASE("ged_matrix: the progress callback, on the calling thread, reports each batch and can stop the work / "
          "errors propagate",
          "[ged][matrix]") {
  const auto graphs = random_graphs(74, 8);  // 28 pairs
  const auto caller = std::this_thread::get_id();
  std::atomic<bool> called_elsewhere{false};
  std::vector<std::size_t> calls;
  const auto all = ged_matrix_results(graphs, Bipartite_ged{}, Unit_costs{},
                                      {.threads = 7, .progress = [&](std::size_t done, std::size_t total) {
                                         if (std::this_thread::get_id() != caller) called_elsewhere = true;
                                         calls.push_back(done);
                                         CHECK(total == 28);
                                         return true;
                                       }});
  CHECK_FALSE(called_elsewhere.load());
  CHECK(calls == std::vector<std::size_t>{16, 28});  // batches of at least 16 pairs, the last with all 28
  CHECK(all.distance == ged_matrix(graphs, Bipartite_ged{}));
  for (const int threads : {1, 2, 7}) {
    std::size_t calls_before_stop = 0;
    CHECK_THROWS_MATCHES(ged_matrix_results(graphs, Bipartite_ged{}, Unit_costs{},
                                            {.threads = threads, .progress = [&](std::size_t, std::size_t) {
                                               ++calls_before_stop;
                                               return false;
                                             }}),
                         deformseg::cancelled, Catch::Message("the computation was stopped by its progress callback"));
    CHECK(calls_before_stop == 1);  // after the first batch, the second not started
  }
  CHECK_THROWS_WITH(ged_matrix_results(graphs, Bipartite_ged{}, Unit_costs{},
                                       {.progress = [](std::size_t, std::size_t) -> bool {
                                          throw std::runtime_error("the caller's reason");
                                        }}),
                    "the caller's reason");
  struct Negative : Unit_costs {
    double edge_insertion() const { return -2.0; }
  };
  CHECK_THROWS_AS(ged_matrix(graphs, Exact_ged{}, Negative{}), deformseg::invalid_input);
}
