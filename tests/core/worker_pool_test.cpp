#include "opf/core/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace opf {
namespace {

TEST(WorkerPool, RunsEveryIndexExactlyOnceRoundAfterRound) {
  for (std::size_t threads : {1, 2, 3, 8}) {
    WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (std::size_t count : {0, 1, 2, 7, 100}) {
      for (int round = 0; round < 20; ++round) {
        std::vector<std::atomic<int>> runs(count);
        pool.for_each(count, [&](std::size_t i) { runs[i].fetch_add(1); });
        for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(runs[i].load(), 1) << i;
      }
    }
  }
}

// Rounds further apart than the spin: the threads must fall asleep and still wake for each round;
// and tasks longer than the spin: the caller must sleep until the last worker is done.
TEST(WorkerPool, WakesSleepingThreadsAndWaitsForSlowTasks) {
  WorkerPool pool(3);
  for (int round = 0; round < 5; ++round) {
    std::this_thread::sleep_for(4 * WorkerPool::kSpin);
    std::vector<std::atomic<int>> runs(6);
    pool.for_each(runs.size(), [&](std::size_t i) {
      if (i % 3 == 0) std::this_thread::sleep_for(2 * WorkerPool::kSpin);
      runs[i].fetch_add(1);
    });
    for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i].load(), 1) << i;
  }
}

TEST(WorkerPool, RethrowsTheLowestIndexErrorAfterEveryIndexRan) {
  WorkerPool pool(3);
  std::atomic<int> ran = 0;
  try {
    pool.for_each(50, [&](std::size_t i) {
      ran.fetch_add(1);
      if (i == 31 || i == 12) throw std::runtime_error("task " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 12");
  }
  EXPECT_EQ(ran.load(), 50);
  // The pool is still usable.
  std::atomic<int> again = 0;
  pool.for_each(10, [&](std::size_t) { again.fetch_add(1); });
  EXPECT_EQ(again.load(), 10);
}

TEST(WorkerPool, RejectsZeroThreads) {
  EXPECT_THROW(WorkerPool(0), std::invalid_argument);
}

}  // namespace
}  // namespace opf
