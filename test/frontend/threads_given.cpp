// Tests of the front end's registry (frontend/registry.h): every similarity policy it makes runs
// its loops on the threads it is given, and no more. The library's threads are std::threads, so
// they are counted where every one starts: pthread_create, interposed here.
#include <frontend/similarity.h>

#include <deformseg/mesh/synthetic.h>
#include <deformseg/similarity/motion_similarity.h>

#include <catch2/catch.hpp>

#include <dlfcn.h>
#include <pthread.h>

#include <atomic>
#include <numbers>
#include <string>
#include <variant>

namespace {

std::atomic<int> threads_started{0};

}  // namespace

// Counts, then starts, a thread: the C library's pthread_create found past this definition.
extern "C" int pthread_create(pthread_t* thread, const pthread_attr_t* attributes, void* (*start)(void*),
                              void* argument) {
  using Create = int (*)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);
  static const auto create = reinterpret_cast<Create>(dlsym(RTLD_NEXT, "pthread_create"));
  threads_started.fetch_add(1);
  return create(thread, attributes, start, argument);
}

namespace {

using namespace deformseg;

mesh::Surface_mesh_animation bending_tube(std::size_t speed) {
  mesh::Bending_tube spec;
  spec.schedule = {{5, {0.0}}, {20 / speed, {std::numbers::pi / 2}}, {10, {}}, {20 / speed, {0.0}}};
  return mesh::make_bending_tube(spec).animation;
}

// The threads started while `policy_name` compares two tubes, made on `threads` threads.
int threads_of(const std::string& policy_name, int threads) {
  static const mesh::Surface_mesh_animation a = bending_tube(1), b = bending_tube(2);
  const similarity::Any_policy policy = frontend::make_policy({.policy = policy_name}, threads);
  const int before = threads_started.load();
  std::visit([&](const auto& chosen) { similarity::motion_similarity(a, b, chosen); }, policy);
  return threads_started.load() - before;
}

}  // namespace

TEST_CASE("every similarity policy of the registry runs on the one thread it is given", "[frontend][threads]") {
  for (const frontend::Policy_entry& entry : frontend::similarity_policies) {
    INFO("policy " << entry.name);
    CHECK(threads_of(std::string(entry.name), 1) == 0);
  }
}

TEST_CASE("the count of threads started sees a policy's threads", "[frontend][threads]") {
  // Else the test above could not fail: the motion signatures describe a tube's frames on 2 threads.
  CHECK(threads_of(std::string(frontend::similarity_policies[0].name), 2) > 0);
}
