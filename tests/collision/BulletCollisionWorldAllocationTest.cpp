// isFree and clearance must not allocate: the planner calls them millions of times. Counts
// both C++ allocations (operator new, replaced for this test binary) and Bullet's own
// (btAlignedAlloc, which goes through malloc behind a hook of its own).

#include <LinearMath/btAlignedAllocator.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include "parksim/collision/BulletCollisionWorld.h"
#include "tests/support/StudyLot.h"

namespace {

std::atomic<long>& cppAllocations() {
  static std::atomic<long> count{0};
  return count;
}

std::atomic<long>& bulletAllocations() {
  static std::atomic<long> count{0};
  return count;
}

void* bulletMalloc(std::size_t size) {
  ++bulletAllocations();
  return std::malloc(size);
}

void bulletFree(void* p) { std::free(p); }

}  // namespace

void* operator new(std::size_t size) {
  ++cppAllocations();
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace parksim {
namespace {

// Routes Bullet's allocations through the counter while alive. Blocks Bullet allocated before
// keep working: the default aligned allocator frees through the same hook, with std::free.
class BulletAllocationHook {
 public:
  BulletAllocationHook() { btAlignedAllocSetCustom(bulletMalloc, bulletFree); }
  ~BulletAllocationHook() { btAlignedAllocSetCustom(nullptr, nullptr); }
  BulletAllocationHook(const BulletAllocationHook&) = delete;
  BulletAllocationHook& operator=(const BulletAllocationHook&) = delete;
};

TEST(BulletCollisionWorldAllocation, QueriesAllocateNothing) {
  const BulletAllocationHook hook;
  const BulletCollisionWorld world(testing::studyLot());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> x(-0.1, 1.9);
  std::uniform_real_distribution<double> y(-0.1, 1.3);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  std::vector<Pose2> poses(2000);
  for (Pose2& p : poses) p = {x(rng), y(rng), heading(rng)};

  const long cpp_before = cppAllocations().load();
  const long bullet_before = bulletAllocations().load();
  int colliding = 0;
  double clearance_sum = 0.0;
  for (const Pose2& p : poses) {
    for (const double margin : {0.0, 0.0005, 0.002, 0.013}) {
      colliding += world.isFree(p, margin) ? 0 : 1;
    }
    clearance_sum += world.clearance(p);
  }
  const long cpp_after = cppAllocations().load();
  const long bullet_after = bulletAllocations().load();

  EXPECT_EQ(cpp_after - cpp_before, 0);
  EXPECT_EQ(bullet_after - bullet_before, 0);
  EXPECT_GT(colliding, 0);  // the narrowphase ran
  EXPECT_GT(clearance_sum, 0.0);
  // The counters work: building a world allocates, in C++ and in Bullet.
  const BulletCollisionWorld another(testing::studyLot());
  EXPECT_GT(cppAllocations().load(), cpp_after);
  EXPECT_GT(bulletAllocations().load(), bullet_after);
}

}  // namespace
}  // namespace parksim
