#include "opf/core/worker_pool.h"

#include <stdexcept>

namespace opf {
namespace {

// Spins until done() or kSpin has passed; true when done() held.
template <class Done>
bool spin_until(const Done& done) {
  const auto until = std::chrono::steady_clock::now() + WorkerPool::kSpin;
  for (;;) {
    for (int i = 0; i < 64; ++i) {
      if (done()) return true;
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();  // eases the spin on the sibling hyperthread and the memory bus
#endif
    }
    if (std::chrono::steady_clock::now() >= until) return done();
  }
}

}  // namespace

WorkerPool::WorkerPool(std::size_t threads) {
  if (threads == 0) throw std::invalid_argument("WorkerPool: at least one thread is needed");
  workers_.reserve(threads - 1);
  for (std::size_t i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void WorkerPool::for_each(std::size_t count, const std::function<void(std::size_t)>& task) {
  if (count == 0) return;
  {
    const std::lock_guard lock(mutex_);
    task_ = &task;
    count_ = count;
    next_ = 0;
    errors_.assign(count, nullptr);
    running_ = workers_.size();
    ++generation_;  // publishes the round to spinning workers (sequentially consistent)
  }
  if (!workers_.empty()) start_.notify_all();
  run_tasks();  // the caller works too
  if (!spin_until([this] { return running_.load() == 0; })) {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return running_.load() == 0; });
  }
  const std::lock_guard lock(mutex_);  // orders the workers' writes to errors_ before the reads
  task_ = nullptr;
  for (const std::exception_ptr& error : errors_)
    if (error) std::rethrow_exception(error);
}

void WorkerPool::run_tasks() {
  for (;;) {
    const std::size_t index = next_.fetch_add(1);
    if (index >= count_) return;
    try {
      (*task_)(index);
    } catch (...) {
      errors_[index] = std::current_exception();  // each index has its own slot
    }
  }
}

void WorkerPool::work() {
  std::size_t seen = 0;
  for (;;) {
    const auto round_started = [&] { return stopping_.load() || generation_.load() != seen; };
    if (!spin_until(round_started)) {
      std::unique_lock lock(mutex_);
      start_.wait(lock, round_started);
    }
    if (stopping_) return;
    seen = generation_;
    run_tasks();
    {
      const std::lock_guard lock(mutex_);
      --running_;
    }
    done_.notify_one();
  }
}

}  // namespace opf
