// thread_count: the one rule every `threads` option of deformseg follows: 0 for the environment's
// count (DEFORMSEG_NUM_THREADS, else OMP_NUM_THREADS) or else all the hardware's threads, or a
// count from 1 to max_threads; any other is refused. Each parallel call takes its own count.
#include <deformseg/exceptions.h>
#include <deformseg/threads.h>

#include <cstdio>

int main() {
  using namespace deformseg;
  std::printf("thread_count(0) %d, thread_count(2) %d\n", thread_count(0), thread_count(2));
  bool refused = false;
  try {
    thread_count(5000, "my_function");
  } catch (const invalid_input& e) {
    std::printf("%s\n", e.what());
    refused = true;
  }
  std::printf("a count from 1 to %d threads\n", max_threads);
  return refused && thread_count(0) >= 1 && thread_count(2) == 2 ? 0 : 1;
}
