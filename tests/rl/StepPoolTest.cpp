// The fork-join pool: every item once, a held-up thread leaves its other items to the rest,
// exceptions passed on.

#include "parksim/rl/StepPool.h"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

TEST(StepPool, RunsEveryItemOnce) {
  for (int threads : {1, 2, 3}) {
    StepPool pool({threads, 50e-6});
    for (std::size_t count : {0U, 1U, 2U, 7U, 100U}) {
      std::vector<std::atomic<int>> calls(count);
      for (int round = 0; round < 20; ++round) {
        pool.run(count, [&](std::size_t i) { ++calls[i]; });
      }
      for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(calls[i].load(), 20) << i;
    }
  }
}

// Item 1 (the worker's own) waits for every other item, item 3 (the worker's too) among
// them: a pool that left item 3 to the worker would never finish; this one's caller takes it.
TEST(StepPool, AThreadHeldUpDoesNotHoldUpTheItemsItHasNotStarted) {
  StepPool pool({2, 0.0});
  std::vector<std::atomic<bool>> done(4);
  bool others_done = false;
  pool.run(4, [&](std::size_t i) {
    if (i == 1) {
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
      while (!(done[0] && done[2] && done[3]) && std::chrono::steady_clock::now() < until) {
        std::this_thread::yield();
      }
      others_done = done[0] && done[2] && done[3];
    }
    done[i] = true;
  });
  EXPECT_TRUE(others_done);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_TRUE(done[i].load()) << i;
}

TEST(StepPool, RethrowsTheLowestItemsExceptionAfterAllItems) {
  StepPool pool({2, 0.0});
  std::atomic<int> done{0};
  try {
    pool.run(6, [&](std::size_t i) {
      ++done;
      if (i == 3 || i == 4) throw std::runtime_error("item " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "item 3");
  }
  EXPECT_EQ(done.load(), 6);
  // Still usable.
  std::atomic<int> again{0};
  pool.run(4, [&](std::size_t) { ++again; });
  EXPECT_EQ(again.load(), 4);
}

TEST(StepPool, RefusesNoThreads) {
  EXPECT_THROW(StepPool({0, 0.0}), Error);
  EXPECT_THROW(StepPool({100000, 0.0}), Error);
  EXPECT_THROW(StepPool({1, -1.0}), Error);
}

}  // namespace
}  // namespace parksim
