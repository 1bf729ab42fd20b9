// deformseg's one parallel loop, which every parallel loop of the library uses (parallel_for,
// parallel_for_with_locals, and parallel_for_reporting for the calls that take a Progress), on
// std::thread: the threads are made for the call and joined
// before it returns, so that no pool outlives a call (a process may fork after any call, which
// GNU OpenMP's pool did not survive). The count follows the rule of threads.h. Indices are handed
// out in increasing order, `chunk` at a time (a dynamic schedule); after a body throws, indices
// above it are no longer run and the exception of the lowest index that threw is rethrown, so
// that the error does not depend on the number of threads. While the workers run, the calling
// thread makes its Interruption_check, if it has one, every interruption_interval; without one it
// works too. A loop started on a worker of a loop of several threads runs on that worker alone
// (no threads of threads, as OpenMP's nested regions by default).
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/threads.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace deformseg::internal {

// Whether the calling thread is working for a parallel loop.
inline thread_local bool inside_parallel_loop = false;

// The state a loop's workers share.
class Parallel_loop {
public:
  Parallel_loop(std::size_t count, std::size_t chunk) : count_(count), chunk_(chunk), failed_at_(count) {}

  // Runs the indices this worker takes; `checks` when it is the calling thread with nobody to
  // check for it.
  template <class Local, class Body>
  void work(Local& local, const Body& body, bool checks) {
    for (;;) {
      const std::size_t begin = next_.fetch_add(chunk_, std::memory_order_relaxed);
      if (begin >= count_) return;
      for (std::size_t i = begin; i < std::min(count_, begin + chunk_); ++i) {
        if (stopped_.load(std::memory_order_relaxed) || i > failed_at_.load(std::memory_order_relaxed)) return;
        try {
          body(local, i);
        } catch (...) {
          fail(i, std::current_exception());
          return;
        }
        if (checks && !check_here()) return;
      }
    }
  }

  // Records the exception of index i; the lowest index's is kept.
  void fail(std::size_t i, std::exception_ptr error) {
    const std::lock_guard lock(mutex_);
    if (i < failed_at_.load() || !failure_) {
      failed_at_.store(std::min(i, failed_at_.load()));
      failure_ = std::move(error);
    }
  }

  // Stops the loop with `error` (a cancelled, or what the check threw).
  void interrupt(std::exception_ptr error) {
    const std::lock_guard lock(mutex_);
    if (!interruption_) interruption_ = std::move(error);
    stopped_.store(true);
  }

  // The calling thread's check, made when due; false when the loop is to stop.
  bool check_here() {
    try {
      interruption_point();
      return true;
    } catch (...) {
      interrupt(std::current_exception());
      return false;
    }
  }

  void started() {
    const std::lock_guard lock(mutex_);
    ++running_;
  }

  void finished() {
    {
      const std::lock_guard lock(mutex_);
      --running_;
    }
    all_done_.notify_one();
  }

  // Waits for the workers, making the calling thread's check every interruption_interval.
  void wait_checking(const Interruption_check& check) {
    std::unique_lock lock(mutex_);
    while (!all_done_.wait_for(lock, interruption_interval, [&] { return running_ == 0; })) {
      if (stopped_.load()) continue;
      lock.unlock();
      try {
        if (!check()) interrupt(std::make_exception_ptr(cancelled()));
      } catch (...) {
        interrupt(std::current_exception());
      }
      lock.lock();
    }
  }

  // Rethrows the interruption, else the lowest index's exception, if any.
  void rethrow() const {
    if (interruption_) std::rethrow_exception(interruption_);
    if (failure_) std::rethrow_exception(failure_);
  }

private:
  const std::size_t count_, chunk_;
  std::atomic<std::size_t> next_{0};
  std::atomic<std::size_t> failed_at_;
  std::atomic<bool> stopped_{false};
  std::mutex mutex_;
  std::condition_variable all_done_;
  int running_ = 0;
  std::exception_ptr failure_, interruption_;
};

// Marks the calling thread as a loop's worker while it lives (when `marks`).
class Worker_mark {
public:
  explicit Worker_mark(bool marks = true) : before_(inside_parallel_loop) { inside_parallel_loop = before_ || marks; }
  ~Worker_mark() { inside_parallel_loop = before_; }
  Worker_mark(const Worker_mark&) = delete;
  Worker_mark& operator=(const Worker_mark&) = delete;

private:
  bool before_;
};

// The workers a loop of `count` indices takes from `threads` (a thread_count): one when nested.
inline std::size_t loop_workers(std::size_t count, std::size_t chunk, int threads) {
  if (inside_parallel_loop) return 1;
  return std::min<std::size_t>(std::size_t(threads), (count + chunk - 1) / chunk);
}

// Runs body(local, i) for every i in [0, count) on up to `threads` threads (a `threads` option:
// 0 for the default, refused above max_threads), each worker with a `local` of its own made by
// make_local() on it (scratch memory, partial sums). Gives the workers' locals for a reduction,
// which must not depend on how the indices were shared (integer sums, say).
// Throws: the lowest index's exception; cancelled (or what the check threw) when the calling
// thread's Interruption_check stopped the loop; invalid_input for a bad `threads`.
template <class MakeLocal, class Body>
auto parallel_for_with_locals(std::size_t count, int threads, std::size_t chunk, const MakeLocal& make_local,
                              const Body& body) {
  using Local = std::invoke_result_t<MakeLocal>;
  chunk = std::max<std::size_t>(chunk, 1);
  const int asked = thread_count(threads);
  const std::size_t workers = count == 0 ? 0 : loop_workers(count, chunk, asked);
  std::vector<Local> locals;
  if (workers <= 1) {  // on this thread, in index order: the first exception is the lowest index's
    // A loop asked for one thread keeps the loops its body starts on it too, as its workers would.
    const Worker_mark mark(asked == 1);
    locals.push_back(make_local());
    for (std::size_t i = 0; i < count; ++i) {
      body(locals.front(), i);
      interruption_point();
    }
    return locals;
  }
  Parallel_loop loop(count, chunk);
  std::vector<std::optional<Local>> made(workers);
  const auto run = [&](std::size_t w, bool checks) {
    const Worker_mark mark;
    try {
      made[w].emplace(make_local());
    } catch (...) {
      loop.fail(0, std::current_exception());
      return;
    }
    loop.work(*made[w], body, checks);
  };
  // With a check to make, this thread makes it and every worker is a new thread; else this
  // thread is worker 0 (and is when no thread could be made: a thread the system refuses to make
  // leaves its share to the others).
  const bool checking = interruption_check_installed();
  std::vector<std::thread> team;
  team.reserve(workers);
  for (std::size_t w = checking ? 0 : 1; w < workers; ++w) {
    loop.started();
    try {
      team.emplace_back([&, w] {
        run(w, false);
        loop.finished();
      });
    } catch (const std::system_error&) {
      loop.finished();
      break;
    }
  }
  if (checking && !team.empty())
    loop.wait_checking(*internal::interruption_state.check);
  else
    run(0, true);
  for (std::thread& t : team) t.join();
  loop.rethrow();
  for (auto& local : made)
    if (local) locals.push_back(std::move(*local));
  return locals;
}

struct No_local {};

// How a loop's indices are handed out: `chunk` at a time, and all on the calling thread when the
// loop has fewer than `min_parallel` indices (for cheap steps, where making threads would cost
// more than the loop).
struct Loop_grain {
  std::size_t chunk = 1;
  std::size_t min_parallel = 0;
};

// The grain of loops whose steps are cheap, a pass over one row of a matrix (clustering).
inline constexpr Loop_grain cheap_steps{.chunk = 16, .min_parallel = 65};

// parallel_for_with_locals without locals: body(i) for every i in [0, count), on `threads`
// threads (a `threads` option), handed out as `grain` says.
template <class Body>
void parallel_for(std::size_t count, int threads, const Body& body, Loop_grain grain) {
  const int used = count < grain.min_parallel ? 1 : threads;
  if (used != threads) thread_count(threads);  // a bad count is refused whatever the loop's length
  parallel_for_with_locals(count, used, grain.chunk, [] { return No_local{}; },
                           [&](No_local&, std::size_t i) { body(i); });
}

// parallel_for, `chunk` indices at a time.
template <class Body>
void parallel_for(std::size_t count, int threads, const Body& body, std::size_t chunk = 1) {
  parallel_for(count, threads, body, Loop_grain{.chunk = chunk});
}

// parallel_for for a long call that reports its progress (threads.h): runs body(0) ...
// body(count - 1) in batches of about 5 % of the loop, at least 16 indices, one parallel_for
// each, and after each batch reports `first_step` + the indices done, of `total_steps`, on the
// calling thread, so that the callback needs no locking; without a callback, in one loop. The
// batches keep the loop's exception rule: the lowest index's exception comes out.
// Throws: cancelled when `progress` returns false; as parallel_for.
template <class Body>
void parallel_for_reporting(std::size_t count, int threads, const Progress& progress, std::size_t first_step,
                            std::size_t total_steps, const Body& body) {
  if (!progress) return parallel_for(count, threads, body);
  const std::size_t batch = std::max<std::size_t>(16, count / 20);
  for (std::size_t begin = 0; begin < count; begin += batch) {
    const std::size_t size = std::min(batch, count - begin);
    parallel_for(size, threads, [&](std::size_t k) { body(begin + k); });
    report_progress(progress, first_step + begin + size, total_steps);
  }
}

}  // namespace deformseg::internal
