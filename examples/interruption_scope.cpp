// Interruption_scope and interruption_point: stopping a long computation from the thread that
// runs it (a GUI's Cancel button, Ctrl-C). The scope installs a check for the calls made on this
// thread while it lives; a loop of one's own calls interruption_point after each step, as
// deformseg's own loops do, and stops with deformseg::cancelled when the check returns false.
#include <deformseg/exceptions.h>
#include <deformseg/threads.h>

#include <chrono>
#include <cstdio>
#include <thread>

int main() {
  using namespace deformseg;
  bool stop_requested = false;  // a Cancel button would set it; here the check itself does
  int checks = 0;
  bool stopped = false;
  {
    Interruption_scope scope([&] {
      ++checks;
      stop_requested = checks == 2;  // asked to stop at the second check
      return !stop_requested;
    });
    std::printf("check installed: %s\n", interruption_check_installed() ? "yes" : "no");
    try {
      for (int step = 0; step < 1000; ++step) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));  // a step of the work
        interruption_point();  // calls the check at most every interruption_interval (20 ms)
      }
    } catch (const cancelled& e) {
      std::printf("stopped after %d checks: %s\n", checks, e.what());
      stopped = true;
    }
  }
  std::printf("check installed after the scope: %s\n", interruption_check_installed() ? "yes" : "no");
  return stopped && !interruption_check_installed() ? 0 : 1;
}
