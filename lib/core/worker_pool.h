#pragma once
// A fixed set of threads that run the same task over indices 0..count-1: the Tracker steps its
// estimators with it, one object per index. Each index is independent (every estimator owns its
// state and generators and reads the same previous-frame view of the others), so the results do
// not depend on the number of threads or on which thread ran which index.
//
// Frames arrive back to back, so handing a frame to a sleeping thread is the cost to avoid: on a
// virtual machine, waking an idle vCPU took 50-100 us per frame (two objects on two threads ran
// slower than on one). Threads therefore wait for the next round, and the caller for the end of
// one, by spinning for up to kSpin before they block on a condition variable.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace opf {

class WorkerPool {
 public:
  /// How long an idle thread spins for the next round before it sleeps: a few frames' gap in a
  /// replay, and 2% of a core at 100 Hz when frames come from a camera.
  static constexpr std::chrono::microseconds kSpin{200};

  /// `threads` >= 1 threads in all, the caller's included (1: no extra thread, tasks run inline).
  explicit WorkerPool(std::size_t threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  std::size_t threads() const { return workers_.size() + 1; }

  /// Calls task(i) for every i < count, spread over the threads, and returns when all are done.
  /// If tasks throw, every index still runs and the exception of the lowest index is rethrown.
  void for_each(std::size_t count, const std::function<void(std::size_t)>& task);

 private:
  void work();
  void run_tasks();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  const std::function<void(std::size_t)>* task_ = nullptr;  // set before generation_ moves
  std::size_t count_ = 0;
  std::atomic<std::size_t> next_ = 0;        // next index to hand out
  std::atomic<std::size_t> running_ = 0;     // workers still busy with this round
  std::atomic<std::size_t> generation_ = 0;  // bumped per for_each (under mutex_), starts a round
  std::atomic<bool> stopping_ = false;
  std::vector<std::exception_ptr> errors_;  // per index of this round
};

}  // namespace opf
