#pragma once
// Worker threads kept for the length of one load, so that its thirty-odd parallel steps do not each
// start and join their own threads (some 50-80 µs a thread here, as much as a small step's work).
// The pool is an object of the load (see build_mesh, read_input), handed to the steps through
// Threads::pool; nothing outlives it. A call made while the pool is busy (a range that itself
// splits its work) gets false and starts threads of its own, as without a pool.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "hbc/threads.hpp"

namespace hbc::detail {

// False in a build without threads (HBC_SINGLE_THREADED, e.g. WebAssembly without pthreads): the
// parallel helpers then run every range on the calling thread, in order, and no pool is made.
#if defined(HBC_SINGLE_THREADED)
inline constexpr bool kThreadsAvailable = false;
#else
inline constexpr bool kThreadsAvailable = true;
#endif

class WorkerPool {
 public:
  explicit WorkerPool(int workers) {
    threads_.reserve(static_cast<size_t>(std::max(0, workers)));
    for (int w = 1; w <= workers; ++w) threads_.emplace_back([this] { work(); });
  }
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  ~WorkerPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
  }

  // Runs job(i) for i in [0, n) and returns once all have ended: the calling thread runs job(0),
  // then it and the workers each claim the next job not yet claimed. A worker may be late (see
  // kPoll): the caller, rather than sleep until it has run its range and woken it in turn, runs
  // that range itself. Which thread runs a job does not change what it writes, and n may exceed
  // the threads. False (nothing run) when the pool is busy. job must not throw (parallel_ranges
  // catches per range).
  bool run(int n, const std::function<void(int)>& job) {
    bool wake = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (busy_) return false;
      busy_ = true;
      job_ = &job;
      count_ = n;
      next_ = 1;
      generation_.fetch_add(1, std::memory_order_release);
      wake = sleepers_ > 0;
    }
    if (n > 1 && wake) wake_.notify_all();
    job(0);
    std::unique_lock<std::mutex> lock(mutex_);
    for (int i; (i = claim()) >= 0;) {
      lock.unlock();
      job(i);
      lock.lock();
    }
    lock.unlock();
    poll_until([&] { return running_.load(std::memory_order_acquire) == 0; });
    lock.lock();
    waiting_ = true;
    done_.wait(lock, [&] { return running_.load(std::memory_order_acquire) == 0; });
    waiting_ = false;
    busy_ = false;
    job_ = nullptr;
    return true;
  }

 private:
  // A sleeping thread is woken here only once the hypervisor runs its idle virtual CPU again,
  // 25 µs to a millisecond later: on armadillo's load (some 70 calls) the caller often ran a
  // worker's range of several hundred µs itself before the worker had started. The steps follow
  // each other within microseconds, so a worker that has ended a job, and a caller waiting for
  // one, poll this long before they sleep. They poll by yielding: the scheduler at times puts
  // both threads on one CPU, where a busy poll would hold it from the thread it waits for.
  static constexpr auto kPoll = std::chrono::microseconds(200);

  template <class Ready>
  static void poll_until(Ready&& ready) {
    const auto until = std::chrono::steady_clock::now() + kPoll;
    while (!ready() && std::chrono::steady_clock::now() < until) std::this_thread::yield();
  }

  // The next unclaimed job, or -1 when all are claimed; under mutex_.
  int claim() { return job_ && next_ < count_ ? next_++ : -1; }

  void work() {
    uint64_t seen = 0;
    for (;;) {
      poll_until([&] { return generation_.load(std::memory_order_acquire) != seen || stop_.load(std::memory_order_relaxed); });
      std::unique_lock<std::mutex> lock(mutex_);
      ++sleepers_;
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      --sleepers_;
      if (stop_) return;
      seen = generation_;
      for (int i; (i = claim()) >= 0;) {
        // job_ stays valid until run() has seen running_ fall back to 0.
        const std::function<void(int)>* job = job_;
        running_.fetch_add(1, std::memory_order_relaxed);
        lock.unlock();
        (*job)(i);
        lock.lock();
        if (running_.fetch_sub(1, std::memory_order_release) == 1 && next_ >= count_ && waiting_) done_.notify_one();
      }
    }
  }

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* job_ = nullptr;
  // Changed under mutex_, read also while polling.
  std::atomic<uint64_t> generation_{0};
  std::atomic<int> running_{0};
  std::atomic<bool> stop_{false};
  int count_ = 0, next_ = 0, sleepers_ = 0;
  bool busy_ = false, waiting_ = false;
};

// The options of one run (a load, an analysis, a test): resolved, with the caller's pool when it
// handed one down, else a pool of the run's own while more than one thread works. Not copyable:
// the options point at the pool, which lives as long as this object.
class RunOptions {
 public:
  explicit RunOptions(const Threads& threads) : par_(resolved(threads)) {
    if (kThreadsAvailable && !par_.pool && par_.count > 1) par_.pool = &own_.emplace(par_.count - 1);
  }
  RunOptions(const RunOptions&) = delete;
  RunOptions& operator=(const RunOptions&) = delete;
  const Threads& get() const { return par_; }

 private:
  std::optional<WorkerPool> own_;
  Threads par_;
};

}  // namespace hbc::detail
