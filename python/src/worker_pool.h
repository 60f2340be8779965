// WorkerPool: a fixed set of threads that run one index range at a time, split in contiguous
// chunks (the calling thread takes the first), for Batch.step. Threads are made once, so a
// step costs two condition-variable handoffs, not thread creation.
#pragma once

#include <condition_variable>
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
  /// Calls work(i) for every i in [0, n), chunk c = [c n / T, (c+1) n / T) on thread c, and
  /// returns when all are done. Rethrows the first exception a chunk threw (the other chunks
  /// still run to their end).
  void Run(int n, const std::function<void(int)>& work);

 private:
  void RunChunk(int chunk);
  void WorkerLoop(int chunk);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  long generation_ = 0;
  int pending_ = 0;
  bool quit_ = false;
  int n_ = 0;
  const std::function<void(int)>* work_ = nullptr;
  std::vector<std::exception_ptr> errors_;
};

}  // namespace sinew::python
