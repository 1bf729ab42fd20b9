// thread_count, default_threads and set_default_threads: the one rule every `threads` option of
// deformseg follows: 0 for the default (set_default_threads on this thread, else the environment,
// else the hardware's threads), or a count from 1 to max_threads; any other is refused.
#include <deformseg/exceptions.h>
#include <deformseg/threads.h>

#include <cstdio>

int main() {
  using namespace deformseg;
  set_default_threads(3);  // what 0 stands for in the calls made on this thread
  std::printf("default %d; thread_count(0) %d, thread_count(2) %d\n", default_threads(), thread_count(0),
              thread_count(2));
  bool refused = false;
  try {
    thread_count(5000, "my_function");
  } catch (const invalid_input& e) {
    std::printf("%s\n", e.what());
    refused = true;
  }
  const bool was_three = default_threads() == 3;
  set_default_threads(0);  // back to the environment's or the hardware's count
  std::printf("after set_default_threads(0): from 1 to %d threads\n", max_threads);
  return refused && was_three && default_threads() >= 1 ? 0 : 1;
}
