#include "worker_pool.h"

namespace sinew::python {

namespace {
constexpr uint64_t kIndexMask = 0xFFFFFFFFu;
}  // namespace

WorkerPool::WorkerPool(int threads) {
  for (int k = 1; k < threads; ++k) workers_.emplace_back([this] { WorkerLoop(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
  }
  start_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void WorkerPool::Work() {
  uint64_t ticket = ticket_.load(std::memory_order_acquire);
  for (;;) {
    // A claimed index's run cannot end before the index is done, so work_ is that run's (the
    // successful claim acquires the ticket Run released after setting it). n_ may already be
    // the next run's for a stale ticket: then the claim fails and the ticket is read again.
    const uint64_t index = ticket & kIndexMask;
    if (index >= static_cast<uint64_t>(n_.load(std::memory_order_relaxed))) return;
    if (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel,
                                       std::memory_order_acquire)) {
      continue;  // another thread claimed it, or a new run began: `ticket` is reloaded
    }
    try {
      (*work_)(static_cast<int>(index));
    } catch (...) {
      std::lock_guard lock(error_mutex_);
      if (!error_) error_ = std::current_exception();
    }
    done_.fetch_add(1, std::memory_order_acq_rel);
    ticket = ticket_.load(std::memory_order_acquire);
  }
}

void WorkerPool::WorkerLoop() {
  uint32_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return quit_ || generation_ != seen; });
      if (quit_) return;
      seen = generation_;
    }
    Work();
  }
}

void WorkerPool::Run(int n, const std::function<void(int)>& work) {
  uint64_t ticket;
  {
    std::lock_guard lock(mutex_);
    // The ticket is closed, so no thread claims an index while n_ and work_ change.
    n_.store(n, std::memory_order_relaxed);
    work_ = &work;
    error_ = nullptr;
    done_.store(0, std::memory_order_relaxed);
    ++generation_;
    ticket = static_cast<uint64_t>(generation_) << 32;
    ticket_.store(ticket, std::memory_order_release);
  }
  start_.notify_all();
  Work();
  while (done_.load(std::memory_order_acquire) < n) std::this_thread::yield();
  ticket_.store(ticket | kIndexMask, std::memory_order_release);  // close the run
  if (error_) std::rethrow_exception(error_);
}

}  // namespace sinew::python
