// WorkerPool: a fixed set of threads that share out one index range at a time, for
// Batch.step. Threads are made once. Indices are claimed one by one from a shared ticket, so a
// thread that starts late (on a busy machine) takes fewer, and the caller never waits for a
// thread that has nothing left to do: only for indices already being worked on.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sinew::python {

class WorkerPool {
 public:
  /// `threads` >= 1 threads in all, the caller's included.
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }
  /// Calls work(i) once for every i in [0, n) on any of the threads and returns when all are
  /// done. Rethrows the first exception a call threw (the other indices still run).
  void Run(int n, const std::function<void(int)>& work);

 private:
  // Claims and runs indices of the current run until none is left.
  void Work();
  void WorkerLoop();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  uint32_t generation_ = 0;  // runs started (under mutex_)
  bool quit_ = false;
  // The current run: its generation in the high 32 bits, the next unclaimed index in the low
  // ones; closed (low bits all set) between runs, so a late thread's claim fails.
  std::atomic<uint64_t> ticket_{0xFFFFFFFFu};
  std::atomic<int> done_{0};  // indices of the current run finished
  std::atomic<int> n_{0};     // set before the ticket opens a run (read by late threads too)
  const std::function<void(int)>* work_ = nullptr;
  std::mutex error_mutex_;
  std::exception_ptr error_;
};

}  // namespace sinew::python
