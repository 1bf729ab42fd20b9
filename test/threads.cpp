// Tests of threads.h and internal/parallel_for.h: the thread-count rule (the default, the
// environment, the bound every `threads` option shares), the parallel loop (every index once, the
// lowest index's exception, nested loops, per-worker locals), interruption from the calling
// thread, and results that do not depend on the number of threads for the loops not tested
// elsewhere.
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/strain/frame_distances.h>
#include <deformseg/ged/exact_ged.h>
#include <deformseg/strain/histogram_distance.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>
#include <deformseg/strain/strain.h>
#include <deformseg/strain/strain_histograms.h>
#include <deformseg/mesh/synthetic.h>
#include <deformseg/threads.h>

#include "ged_support.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

using namespace deformseg;
using deformseg::internal::cheap_steps;
using deformseg::internal::parallel_for;
using deformseg::internal::parallel_for_with_locals;
using deformseg::test::Scoped_variable;

namespace {

const std::vector<int> thread_counts{1, 2, 7};

mesh::Surface_mesh_animation bending_tube() {
  mesh::Bending_tube spec;
  spec.joints = {{.position = 0.3}, {.position = 0.7}};
  const double right = std::numbers::pi / 2;
  spec.schedule = {{5, {0.0, 0.0}}, {10, {right, 0.0}}, {5, {}}, {10, {right, right}}, {5, {}}};
  return mesh::make_bending_tube(spec).animation;
}

}  // namespace

TEST_CASE("threads: 0 is the default, counts above max_threads are refused naming them", "[threads]") {
  const Scoped_variable own("DEFORMSEG_NUM_THREADS", nullptr), openmp("OMP_NUM_THREADS", nullptr);
  const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
  CHECK(thread_count(0) == std::min(hardware, max_threads));
  CHECK(thread_count(1) == 1);
  CHECK(thread_count(max_threads) == max_threads);
  CHECK_THROWS_AS(thread_count(max_threads + 1), invalid_input);
  CHECK_THROWS_WITH(thread_count(70000, "compute_strain"),
                    "compute_strain: threads must be 0 (the default) to 1024, not 70000");
  CHECK_THROWS_WITH(thread_count(-1), "threads must be 0 (the default) to 1024, not -1");
}

TEST_CASE("threads: 0 follows the environment, a count given is kept", "[threads]") {
  const Scoped_variable own("DEFORMSEG_NUM_THREADS", nullptr), openmp("OMP_NUM_THREADS", nullptr);
  {
    const Scoped_variable list("OMP_NUM_THREADS", "5,2");  // OpenMP's nested list: its first number
    CHECK(thread_count(0) == 5);
    const Scoped_variable ours("DEFORMSEG_NUM_THREADS", "3");  // deformseg's own comes first
    CHECK(thread_count(0) == 3);
    CHECK(thread_count(6) == 6);  // and a count given before either
  }
  {
    const Scoped_variable large("OMP_NUM_THREADS", "100000");
    CHECK(thread_count(0) == max_threads);
  }
  {
    const Scoped_variable other("OMP_NUM_THREADS", "dynamic");  // not ours, not a count: ignored
    CHECK(thread_count(0) >= 1);
  }
  for (const char* bad : {"0", "-2", "two", "4,2", "2000"}) {
    const Scoped_variable ours("DEFORMSEG_NUM_THREADS", bad);
    CHECK_THROWS_WITH(thread_count(0), Catch::Contains("DEFORMSEG_NUM_THREADS is '" + std::string(bad) + "'"));
    CHECK(thread_count(2) == 2);  // a count given does not read the environment
  }
}

TEST_CASE("threads: every threads option refuses a count above max_threads", "[threads]") {
  const auto tube = bending_tube();
  CHECK_THROWS_WITH(strain::compute_strain(tube, {.threads = 30000}),
                    Catch::Contains("compute_strain: threads must be 0 "
                                    "(the default) to 1024, not 30000"));
  CHECK_THROWS_AS(strain::compute_strain(tube, {.threads = -1}), invalid_input);
  const auto field = strain::compute_strain(tube, {.threads = 1});
  CHECK_THROWS_WITH(frame_distances(field, {.threads = 70000}), Catch::Contains("not 70000"));
  CHECK_THROWS_WITH(strain::strain_histograms(field, std::vector<double>(field.num_faces(), 1.0), {.threads = 40000}),
                    Catch::Contains("not 40000"));
  const Eigen::MatrixXd h = Eigen::MatrixXd::Constant(3, 4, 0.25);
  CHECK_THROWS_WITH(strain::histogram_distances(h, h, strain::Histogram_metric::earth_movers, 1025),
                    Catch::Contains("not 1025"));
}

TEST_CASE("parallel_for: every index once, the lowest index's exception, on any threads", "[threads]") {
  for (const int threads : thread_counts)
    for (const std::size_t chunk : {std::size_t(1), std::size_t(16)})
      for (const std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(1000)}) {
        INFO(threads << " threads, chunks of " << chunk << ", " << count << " indices");
        std::vector<std::atomic<int>> runs(count);
        parallel_for(count, threads, [&](std::size_t i) { ++runs[i]; }, chunk);
        for (std::size_t i = 0; i < count; ++i) CHECK(runs[i].load() == 1);
      }
  for (const int threads : thread_counts) {
    INFO(threads << " threads");
    const auto failing = [](std::size_t i) {
      if (i == 900 || i == 5 || i == 600) throw std::runtime_error("index " + std::to_string(i));
    };
    CHECK_THROWS_WITH(parallel_for(1000, threads, failing), "index 5");
    CHECK_THROWS_WITH(parallel_for(1000, threads, failing, 64), "index 5");
  }
}

TEST_CASE("parallel_for: per-worker locals, and nested loops run on their worker", "[threads]") {
  for (const int threads : thread_counts) {
    INFO(threads << " threads");
    const auto sums = parallel_for_with_locals(
        10000, threads, 3, [] { return std::size_t(0); }, [](std::size_t& sum, std::size_t i) { sum += i; });
    CHECK(sums.size() <= std::size_t(threads));
    std::size_t total = 0;
    for (const std::size_t s : sums) total += s;
    CHECK(total == 10000 * 9999 / 2);

    std::atomic<bool> other_thread{false};
    std::mutex seen;
    std::set<std::thread::id> workers;
    parallel_for(50, threads, [&](std::size_t) {
      const auto worker = std::this_thread::get_id();
      {
        const std::lock_guard lock(seen);
        workers.insert(worker);
      }
      parallel_for(20, 7, [&](std::size_t) {
        if (std::this_thread::get_id() != worker) other_thread = true;
      });
    });
    // On one thread as on several: the loops below run on their worker (threads = 1 is one thread).
    CHECK_FALSE(other_thread.load());
    CHECK(workers.size() <= std::size_t(threads));
  }
}

TEST_CASE("interruption: the check runs on the calling thread and stops the loop", "[threads]") {
  const auto caller = std::this_thread::get_id();
  for (const int threads : {2, 7}) {
    INFO(threads << " threads");
    // Every step waits for the check to have said stop, then lasts a little more: a worker
    // finishes the step it has and takes no other once the loop has seen the stop. Between the
    // check's answer and the loop's seeing it a worker may begin one more step, so at most two
    // steps per worker run, of 1000.
    std::atomic<bool> stopped{false};
    std::atomic<bool> checked_elsewhere{false};
    std::atomic<int> steps{0};
    const Interruption_scope scope([&] {
      if (std::this_thread::get_id() != caller) checked_elsewhere = true;
      stopped = true;
      return false;
    });
    CHECK(interruption_check_installed());
    CHECK_THROWS_AS(parallel_for(1000, threads,
                                           [&](std::size_t) {
                                             ++steps;
                                             while (!stopped) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                                             std::this_thread::sleep_for(std::chrono::milliseconds(2));
                                           }),
                    cancelled);
    CHECK_FALSE(checked_elsewhere.load());
    CHECK(steps.load() <= 2 * threads);
  }
  CHECK_FALSE(interruption_check_installed());
}

TEST_CASE("interruption: serial loops check between steps / what the check throws comes out", "[threads]") {
  int checks = 0, steps = 0;
  {
    const Interruption_scope scope([&] {
      ++checks;
      return false;
    });
    // Each step lasts longer than interruption_interval, so the check is due after the first.
    CHECK_THROWS_AS(parallel_for(100, 1,
                                           [&](std::size_t) {
                                             ++steps;
                                             std::this_thread::sleep_for(interruption_interval * 3 / 2);
                                           }),
                    cancelled);
  }
  CHECK(checks == 1);
  CHECK(steps == 1);
  const Interruption_scope scope([]() -> bool { throw std::runtime_error("the user's reason"); });
  CHECK_THROWS_WITH(parallel_for(100, 2,
                                           [&](std::size_t) {
                                             std::this_thread::sleep_for(interruption_interval * 3 / 2);
                                           }),
                    "the user's reason");
  {
    const Interruption_scope inner({});  // an empty check: nothing is checked
    CHECK_FALSE(interruption_check_installed());
    CHECK_NOTHROW(interruption_point());
  }
  CHECK(interruption_check_installed());  // the outer scope's check is back
}

TEST_CASE("interruption: an exact graph edit distance search stops between expansions", "[threads][ged]") {
  // Two dense 20-node graphs of one label: the search runs to its 200,000 expansions, seconds.
  std::mt19937 random(2);
  const auto a = test::random_labelled_graph(random, 20, 1, 0.5), b = test::random_labelled_graph(random, 20, 1, 0.5);
  const Interruption_scope scope([] { return false; });
  CHECK_THROWS_AS(ged::Exact_ged{}(a, b), cancelled);
}

TEST_CASE("parallel_for: a loop of one index, not asked for one thread, lets the loops below use threads",
          "[threads]") {
  std::atomic<bool> elsewhere{false};
  const auto caller = std::this_thread::get_id();
  parallel_for(1, 2, [&](std::size_t) {
    parallel_for(
        64, 2, [&](std::size_t) {
          if (std::this_thread::get_id() != caller) elsewhere = true;
          std::this_thread::sleep_for(std::chrono::milliseconds(1));  // long enough for the second to start
        },
        std::size_t{1});
  });
  CHECK(elsewhere.load());
}

TEST_CASE("parallel_for: a loop of cheap steps below its grain runs on the calling thread alone", "[threads]") {
  const auto caller = std::this_thread::get_id();
  std::atomic<bool> elsewhere{false};
  std::vector<int> runs(64, 0);
  parallel_for(64, 7, [&](std::size_t i) {
    ++runs[i];
    if (std::this_thread::get_id() != caller) elsewhere = true;
  }, cheap_steps);
  CHECK_FALSE(elsewhere.load());
  CHECK(runs == std::vector<int>(64, 1));
  std::vector<std::atomic<int>> more(1000);
  parallel_for(1000, 7, [&](std::size_t i) { ++more[i]; }, cheap_steps);
  for (const auto& count : more) CHECK(count.load() == 1);
  // A bad count is refused however short the loop.
  CHECK_THROWS_AS(parallel_for(3, -1, [](std::size_t) {}, cheap_steps),
                  invalid_input);
}

TEST_CASE("interruption: cancelled is a runtime_error", "[threads]") {
  STATIC_REQUIRE(std::is_base_of_v<std::runtime_error, cancelled>);
}

TEST_CASE("threads: histograms, their distances, segments and graphs are the same on 1, 2 and 7 threads",
          "[threads]") {
  const auto tube = bending_tube();
  const auto field = strain::compute_strain(tube, {.reference = strain::Strain_reference::previous_pose, .threads = 1});
  const std::vector<double> weights(field.num_faces(), 1.0);
  const strain::Strain_histograms one = strain::strain_histograms(field, weights, {.threads = 1});
  const Eigen::MatrixXd distances = strain::histogram_distances(one, one, strain::Histogram_metric::earth_movers, 1);
  spatiotemporal::Spatiotemporal_options options{.threshold = 0.01, .max_island = 8, .threads = 1};
  const spatiotemporal::Spatiotemporal_segmentation segments =
      spatiotemporal::spatiotemporal_segmentation(field, tube.triangles(), options);
  const spatiotemporal::Evolving_graph graph = spatiotemporal::evolving_graph(tube, options);
  for (const int threads : thread_counts) {
    INFO(threads << " threads");
    CHECK(strain::compute_strain(tube, {.reference = strain::Strain_reference::previous_pose, .threads = threads})
              .matrix() == field.matrix());
    CHECK(strain::strain_histograms(field, weights, {.threads = threads}) == one);
    CHECK(strain::histogram_distances(one, one, strain::Histogram_metric::earth_movers, threads) == distances);
    options.threads = threads;
    const spatiotemporal::Spatiotemporal_segmentation other =
        spatiotemporal::spatiotemporal_segmentation(field, tube.triangles(), options);
    for (std::size_t t = 0; t < field.num_frames(); ++t)
      CHECK(std::ranges::equal(other.frame_labels(t), segments.frame_labels(t)));
    const spatiotemporal::Evolving_graph other_graph = spatiotemporal::evolving_graph(tube, options);
    REQUIRE(other_graph.size() == graph.size());
    for (std::size_t k = 0; k < graph.size(); ++k) {
      CHECK(other_graph[k].first_frame == graph[k].first_frame);
      CHECK(boost::num_vertices(other_graph[k].graph) == boost::num_vertices(graph[k].graph));
      for (std::size_t v = 0; v < boost::num_vertices(graph[k].graph); ++v)
        CHECK(other_graph[k].graph[v].area == graph[k].graph[v].area);
    }
  }
}
