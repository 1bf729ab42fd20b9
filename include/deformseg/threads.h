/// @file threads.h
/// @brief How the parallel algorithms run: the one rule for their number of threads
/// (`thread_count`, `max_threads`) and the one convention for stopping a long
/// call from the thread that made it, by its `Progress` callback or by an `Interruption_scope`
/// (either way the call throws `cancelled`, of exceptions.h).
///
/// Every `threads` option of deformseg (and `--threads` of the tool, `threads=` in Python) means
/// the same: 0, the default, for the environment's count or else all the hardware's threads
/// (`thread_count`), or a count from 1 to `max_threads`; any other is refused with `invalid_input`
/// naming it. Every parallel entry point takes its count explicitly, as a parameter or an option;
/// no setting of the calling thread stands in for it. The threads are made for each call and
/// joined before it returns (no pool lives between calls, so a process may `fork` after any call),
/// and a parallel loop started on one of them runs on that thread alone, as nested OpenMP regions
/// do by default; so does a loop inside one asked for one thread, so that `threads = 1` means one
/// thread for the whole call. Results never depend on the number of threads.
#pragma once

#include <deformseg/exceptions.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <utility>

namespace deformseg {

/// @brief The most threads any call of deformseg takes; a larger count is refused. Far above the
/// cores of today's machines, low enough that a mistyped count fails at once rather than making
/// tens of thousands of threads.
inline constexpr int max_threads = 1024;

namespace internal {

// A whole number from 1 to max_threads, or nothing.
inline std::optional<int> parse_thread_count(std::string_view text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > max_threads)
    return std::nullopt;
  return value;
}

// DEFORMSEG_NUM_THREADS, deformseg's own setting: refused unless a valid count.
inline std::optional<int> threads_of_deformseg_variable() {
  const char* text = std::getenv("DEFORMSEG_NUM_THREADS");
  if (!text || !*text) return std::nullopt;
  if (const auto n = parse_thread_count(text)) return n;
  throw invalid_input("DEFORMSEG_NUM_THREADS is '" + std::string(text) + "': expected a whole number from 1 to " +
                      std::to_string(max_threads));
}

// OMP_NUM_THREADS, shared with other libraries: its first number (OpenMP allows a list, "4,2"),
// at most max_threads; ignored when it is not a number of at least 1, as OpenMP ignores it.
inline std::optional<int> threads_of_openmp_variable() {
  const char* text = std::getenv("OMP_NUM_THREADS");
  if (!text) return std::nullopt;
  const std::string_view all(text);
  const std::string_view first = all.substr(0, all.find(','));
  long value = 0;
  const auto [end, error] = std::from_chars(first.data(), first.data() + first.size(), value);
  if (error == std::errc::result_out_of_range) return max_threads;
  if (error != std::errc() || end != first.data() + first.size() || value < 1) return std::nullopt;
  return int(std::min<long>(value, max_threads));
}

}  // namespace internal

namespace internal {

// What a `threads` option of 0 stands for: DEFORMSEG_NUM_THREADS, else OMP_NUM_THREADS, else the
// hardware's threads. Read at each call, so that a program may set the variables as it runs.
inline int automatic_threads() {
  if (const auto n = threads_of_deformseg_variable()) return *n;
  if (const auto n = threads_of_openmp_variable()) return *n;
  return int(std::clamp(std::thread::hardware_concurrency(), 1u, unsigned(max_threads)));
}

}  // namespace internal

/// @brief The count a `threads` option gives: `requested` itself from 1 to `max_threads`; for 0
/// (the default everywhere), the environment variable `DEFORMSEG_NUM_THREADS`, else
/// `OMP_NUM_THREADS` (its first number, at most `max_threads`, ignored when not a number of at
/// least 1), which schedulers such as SLURM set, else the hardware's threads
/// (`std::thread::hardware_concurrency()`, at least 1, at most `max_threads`). There is no other
/// default: every parallel call takes its count as a parameter or an option.
/// @param requested the option's value.
/// @param context what takes the option, put before the message (e.g. "compute_strain"); may be
/// empty.
/// @return a count from 1 to `max_threads`.
/// @throws invalid_input for a negative count or one above `max_threads`, naming it, e.g.
/// "compute_strain: threads must be 0 (the default) to 1024, not 70000"; for 0, when
/// `DEFORMSEG_NUM_THREADS` is set but not a whole number from 1 to `max_threads`, naming its value.
/// @par Complexity O(1): reads the environment at each call with 0.
/// @par Example
/// @include thread_count.cpp
inline int thread_count(int requested, const std::string& context = {}) {
  if (requested < 0 || requested > max_threads)
    throw invalid_input((context.empty() ? "" : context + ": ") + "threads must be 0 (the default) to " +
                        std::to_string(max_threads) + ", not " + std::to_string(requested));
  return requested == 0 ? internal::automatic_threads() : requested;
}

/// @brief The progress callback of deformseg's long calls (`similarity::similarity_matrix`,
/// `ged::ged_matrix_results`): called as the work advances with `done` of `total` steps finished,
/// always on the thread that made the call (never on a worker thread, so it needs no locking and
/// may use what belongs to that thread), with `done` increasing, last with `done == total`.
/// Returning true lets the call go on; returning false stops it: the call takes no more work,
/// waits for the steps in progress and throws `cancelled`. An exception the callback throws
/// stops the call too and comes out of it. An empty function (the default) is never called.
/// What a step is and how often the callback is called, each call says.
/// @par Example
/// @include progress.cpp
using Progress = std::function<bool(std::size_t done, std::size_t total)>;

namespace internal {

// Reports `done` of `total` to `progress`, if any; throws cancelled when it returns false.
inline void report_progress(const Progress& progress, std::size_t done, std::size_t total) {
  if (progress && !progress(done, total)) throw cancelled("the computation was stopped by its progress callback");
}

}  // namespace internal

/// @brief A check that a long call makes on the thread that made it, about every
/// `interruption_interval` while it runs: returning true lets it go on, false stops it (it then
/// throws `cancelled`); an exception it throws stops the call too and comes out of it.
using Interruption_check = std::function<bool()>;

/// @brief How often a long call makes its `Interruption_check`: about every 20 ms of its work
/// (more when one step of the work, a frame or a pair, takes longer: a step is never broken off).
inline constexpr std::chrono::milliseconds interruption_interval{20};

namespace internal {

struct Interruption_state {
  const Interruption_check* check = nullptr;
  std::chrono::steady_clock::time_point last{};
};

// The calling thread's check, installed by an Interruption_scope; none on the loops' workers.
inline thread_local Interruption_state interruption_state{};

}  // namespace internal

/// @brief Installs an `Interruption_check` for the calls made on the calling thread while it
/// lives (the one installed before, if any, is back after it), so that they can be stopped:
/// every parallel loop of deformseg, while its threads work, and the long serial loops call
/// `check` on this thread, at least every `interruption_interval` plus the time of the step in
/// progress. The Python module installs one around each call that makes
/// Ctrl-C raise `KeyboardInterrupt`.
///
/// When `check` returns false the loop stops taking work, waits for the steps in progress and
/// throws `cancelled`. Without a scope (the default) nothing is checked. Only the calling thread
/// calls `check`, never the loops' worker threads, so it may use what belongs to that thread.
///
/// @code
/// std::atomic<bool> stop_requested{false};  // set by a GUI's Cancel button
/// deformseg::Interruption_scope scope([&] { return !stop_requested.load(); });
/// try { auto m = deformseg::similarity::similarity_matrix(animations); } catch (const deformseg::cancelled&) {}
/// @endcode
/// @par Example
/// @include interruption_scope.cpp
class Interruption_scope {
public:
  /// @brief Installs `check` (an empty function checks nothing).
  explicit Interruption_scope(Interruption_check check)
      : check_(std::move(check)), previous_(internal::interruption_state) {
    internal::interruption_state = {check_ ? &check_ : nullptr, std::chrono::steady_clock::now()};
  }
  /// @brief Restores the check installed before.
  ~Interruption_scope() { internal::interruption_state = previous_; }
  Interruption_scope(const Interruption_scope&) = delete;
  Interruption_scope& operator=(const Interruption_scope&) = delete;

private:
  Interruption_check check_;
  internal::Interruption_state previous_;
};

/// @brief Whether an `Interruption_check` is installed on the calling thread.
/// @par Example
/// @include interruption_scope.cpp
inline bool interruption_check_installed() noexcept { return internal::interruption_state.check != nullptr; }

/// @brief Calls the calling thread's `Interruption_check`, if any, and throws `cancelled` when it
/// returns false. Long serial loops call it after each step; it costs a clock read when less than
/// `interruption_interval` has passed since the check was last called.
/// @throws cancelled when the check returns false; what the check throws.
/// @par Example
/// @include interruption_scope.cpp
inline void interruption_point() {
  internal::Interruption_state& state = internal::interruption_state;
  if (!state.check) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - state.last < interruption_interval) return;
  state.last = now;
  if (!(*state.check)()) throw cancelled();
}

}  // namespace deformseg
