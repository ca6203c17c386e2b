// The fork-join pool: every item once, item i on thread i % threads, exceptions passed on.

#include "parksim/rl/StepPool.h"

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/Error.h"

namespace parksim {
namespace {

TEST(StepPool, RunsEveryItemOnceOnItsThread) {
  StepPool pool({3, 50e-6});
  for (std::size_t count : {0U, 1U, 2U, 7U, 100U}) {
    std::vector<int> calls(count, 0);
    std::vector<std::thread::id> ids(count);
    pool.run(count, [&](std::size_t i) {
      ++calls[i];
      ids[i] = std::this_thread::get_id();
    });
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_EQ(calls[i], 1) << i;
      EXPECT_EQ(ids[i], ids[i % 3]) << i;
    }
    if (count > 0) {
      EXPECT_EQ(ids[0], std::this_thread::get_id());
    }
  }
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
  EXPECT_THROW(StepPool({1, -1.0}), Error);
}

}  // namespace
}  // namespace parksim
