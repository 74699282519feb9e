#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "gestura/core/parallel_for.hpp"

namespace gestura {
namespace {

TEST(ParallelFor, EveryItemRunsExactlyOnce) {
  for (unsigned threads : {1u, 2u, 4u, 7u}) {
    std::vector<std::atomic<int>> runs(1000);
    parallel_for(runs.size(), [&](std::size_t i) { ++runs[i]; }, threads);
    for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i].load(), 1) << "item " << i << ", threads " << threads;
  }
}

TEST(ParallelFor, UsesSeveralThreadsWhenAsked) {
  std::mutex mutex;
  std::set<std::thread::id> seen;
  std::atomic<int> waiting{0};
  // Each of the first two items waits (bounded) until the other has started: only two threads get both going.
  parallel_for(
      2,
      [&](std::size_t) {
        ++waiting;
        for (int spin = 0; waiting.load() < 2 && spin < 2000; ++spin) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        const std::lock_guard lock(mutex);
        seen.insert(std::this_thread::get_id());
      },
      2);
  EXPECT_EQ(seen.size(), 2u);
}

TEST(ParallelFor, NothingToDoAndOneThreadRunInline) {
  int calls = 0;
  parallel_for(0, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
  std::thread::id where;
  parallel_for(1, [&](std::size_t) { where = std::this_thread::get_id(); }, 4);
  EXPECT_EQ(where, std::this_thread::get_id());
}

TEST(ParallelFor, TheFirstErrorReachesTheCaller) {
  std::atomic<int> ran{0};
  EXPECT_THROW(parallel_for(
                   2000,
                   [&](std::size_t i) {
                     ++ran;
                     if (i == 5) throw std::runtime_error("item 5");
                     std::this_thread::sleep_for(std::chrono::microseconds(100));
                   },
                   2),
               std::runtime_error);
  EXPECT_LT(ran.load(), 1000);  // the others stopped taking items
}

TEST(ParallelFor, WorkerCountFollowsTheEnvironment) {
  setenv("GESTURA_THREADS", "3", 1);
  EXPECT_EQ(worker_count(), 3u);
  setenv("GESTURA_THREADS", "zero", 1);
  EXPECT_GE(worker_count(), 1u);
  unsetenv("GESTURA_THREADS");
  EXPECT_GE(worker_count(), 1u);
}

}  // namespace
}  // namespace gestura
