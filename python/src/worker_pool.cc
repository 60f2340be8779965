#include "worker_pool.h"

namespace sinew::python {

WorkerPool::WorkerPool(int threads) : errors_(threads > 1 ? threads : 1) {
  for (int chunk = 1; chunk < threads; ++chunk) {
    workers_.emplace_back([this, chunk] { WorkerLoop(chunk); });
  }
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
  }
  start_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void WorkerPool::RunChunk(int chunk) {
  const int count = threads();
  const int begin = static_cast<int>(static_cast<long>(chunk) * n_ / count);
  const int end = static_cast<int>(static_cast<long>(chunk + 1) * n_ / count);
  try {
    for (int i = begin; i < end; ++i) (*work_)(i);
  } catch (...) {
    errors_[chunk] = std::current_exception();
  }
}

void WorkerPool::WorkerLoop(int chunk) {
  long seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return quit_ || generation_ != seen; });
      if (quit_) return;
      seen = generation_;
    }
    RunChunk(chunk);
    std::lock_guard lock(mutex_);
    if (--pending_ == 0) done_.notify_one();
  }
}

void WorkerPool::Run(int n, const std::function<void(int)>& work) {
  {
    std::lock_guard lock(mutex_);
    n_ = n;
    work_ = &work;
    for (auto& error : errors_) error = nullptr;
    pending_ = static_cast<int>(workers_.size());
    ++generation_;
  }
  start_.notify_all();
  RunChunk(0);
  {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
  }
  for (const auto& error : errors_) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace sinew::python
