// Footprint queries on the study's lot: BulletCollisionWorld::isFree (broadphase + box-box)
// against hand-written separating-axis tests (core's exact reference as is, and a version with
// precomputed axes), on the same seeded random poses, plus the cost of clearance().
// Results: docs/benchmarks.md, "Footprint queries".

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace parksim {
namespace {

// The study's lot as the project's worlds hold it (its obstacles, the head-in goal). Read from
// the world file: a benchmark does not build on the tests' support code.
const Scenario& studyLot() {
  static const Scenario lot =
      loadScenario(std::string(PARKSIM_SOURCE_DIR) + "/worlds/head_in.yaml");
  return lot;
}

// Enough poses that the branch predictor cannot learn the answers; same seed for all methods.
std::vector<Pose2> randomLotPoses(std::size_t count) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> x(-0.1, 1.9);
  std::uniform_real_distribution<double> y(-0.1, 1.3);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  std::vector<Pose2> poses(count);
  for (Pose2& p : poses) p = {x(rng), y(rng), heading(rng)};
  return poses;
}

constexpr std::size_t kPoseCount = 1 << 16;

// Margin in micrometres from the benchmark argument, so it shows in the benchmark's name.
double marginOf(const benchmark::State& state) {
  return 1e-6 * static_cast<double>(state.range(0));
}

// One query per iteration, so the reported time per iteration is the time per query.
void reportCollisionShare(benchmark::State& state, std::size_t colliding, std::size_t queries) {
  state.SetItemsProcessed(static_cast<std::int64_t>(queries));
  state.counters["colliding"] = static_cast<double>(colliding) / static_cast<double>(queries);
}

void BM_IsFreeBullet(benchmark::State& state) {
  const Scenario& lot = studyLot();
  const BulletCollisionWorld world(lot);
  const std::vector<Pose2> poses = randomLotPoses(kPoseCount);
  const double margin = marginOf(state);
  std::size_t i = 0;
  std::size_t colliding = 0;
  for (auto _ : state) {
    const bool free = world.isFree(poses[i], margin);
    benchmark::DoNotOptimize(free);
    colliding += free ? 0 : 1;
    i = (i + 1) % kPoseCount;
  }
  reportCollisionShare(state, colliding, static_cast<std::size_t>(state.iterations()));
}

// The exact reference as the tests use it: core's footprintAt and boxesOverlap against every
// obstacle until the first overlap (boxesOverlap recomputes both boxes' axes each call).
void BM_IsFreeHandSat(benchmark::State& state) {
  const Scenario& lot = studyLot();
  const std::vector<Pose2> poses = randomLotPoses(kPoseCount);
  const double margin = marginOf(state);
  std::size_t i = 0;
  std::size_t colliding = 0;
  for (auto _ : state) {
    const OrientedBox footprint = footprintAt(lot.robot, poses[i], margin);
    bool free = true;
    for (const Obstacle& o : lot.obstacles) {
      if (boxesOverlap(footprint, o.box)) {
        free = false;
        break;
      }
    }
    benchmark::DoNotOptimize(free);
    colliding += free ? 0 : 1;
    i = (i + 1) % kPoseCount;
  }
  reportCollisionShare(state, colliding, static_cast<std::size_t>(state.iterations()));
}

// The lower bound a hand-written checker reaches: each obstacle's axes and bounding box
// precomputed, one sine and cosine per query, a bounding-box reject, then the four axes.
class PrecomputedSat {
 public:
  explicit PrecomputedSat(const Scenario& scenario) : robot_(scenario.robot) {
    for (const Obstacle& o : scenario.obstacles) {
      Box b;
      b.center = o.box.center;
      b.half = o.box.half_extents;
      b.ax = {std::cos(o.box.yaw), std::sin(o.box.yaw)};
      b.ay = {-b.ax.y(), b.ax.x()};
      b.reach = {std::abs(b.ax.x()) * b.half.x() + std::abs(b.ay.x()) * b.half.y(),
                 std::abs(b.ax.y()) * b.half.x() + std::abs(b.ay.y()) * b.half.y()};
      boxes_.push_back(b);
    }
  }

  bool isFree(const Pose2& pose, double margin) const {
    const double c = std::cos(pose.theta);
    const double s = std::sin(pose.theta);
    const double offset = robot_.footprintCenterOffset();
    const Eigen::Vector2d center(pose.x + offset * c, pose.y + offset * s);
    const Eigen::Vector2d half(0.5 * robot_.length_m + margin, 0.5 * robot_.width_m + margin);
    const Eigen::Vector2d ax(c, s);
    const Eigen::Vector2d ay(-s, c);
    const Eigen::Vector2d reach(std::abs(c) * half.x() + std::abs(s) * half.y(),
                                std::abs(s) * half.x() + std::abs(c) * half.y());
    for (const Box& b : boxes_) {
      const Eigen::Vector2d d = b.center - center;
      if (std::abs(d.x()) >= reach.x() + b.reach.x() ||
          std::abs(d.y()) >= reach.y() + b.reach.y()) {
        continue;
      }
      const auto separated = [&](const Eigen::Vector2d& axis) {
        const double ra = half.x() * std::abs(ax.dot(axis)) + half.y() * std::abs(ay.dot(axis));
        const double rb =
            b.half.x() * std::abs(b.ax.dot(axis)) + b.half.y() * std::abs(b.ay.dot(axis));
        return std::abs(d.dot(axis)) >= ra + rb;
      };
      if (!separated(ax) && !separated(ay) && !separated(b.ax) && !separated(b.ay)) return false;
    }
    return true;
  }

 private:
  struct Box {
    Eigen::Vector2d center, half, ax, ay, reach;
  };
  RobotDef robot_;
  std::vector<Box> boxes_;
};

void BM_IsFreePrecomputedSat(benchmark::State& state) {
  const Scenario& lot = studyLot();
  const PrecomputedSat sat(lot);
  const std::vector<Pose2> poses = randomLotPoses(kPoseCount);
  const double margin = marginOf(state);
  std::size_t i = 0;
  std::size_t colliding = 0;
  for (auto _ : state) {
    const bool free = sat.isFree(poses[i], margin);
    benchmark::DoNotOptimize(free);
    colliding += free ? 0 : 1;
    i = (i + 1) % kPoseCount;
  }
  reportCollisionShare(state, colliding, static_cast<std::size_t>(state.iterations()));
}

void BM_Clearance(benchmark::State& state) {
  const Scenario& lot = studyLot();
  const BulletCollisionWorld world(lot);
  const std::vector<Pose2> poses = randomLotPoses(kPoseCount);
  std::size_t i = 0;
  std::size_t colliding = 0;
  for (auto _ : state) {
    const double d = world.clearance(poses[i]);
    benchmark::DoNotOptimize(d);
    colliding += d == 0.0 ? 1 : 0;
    i = (i + 1) % kPoseCount;
  }
  reportCollisionShare(state, colliding, static_cast<std::size_t>(state.iterations()));
}

// Arguments: margin in micrometres (0, 0.5 mm, 2 mm), as in the tests.
BENCHMARK(BM_IsFreeBullet)->Arg(0)->Arg(500)->Arg(2000);
BENCHMARK(BM_IsFreeHandSat)->Arg(0)->Arg(500)->Arg(2000);
BENCHMARK(BM_IsFreePrecomputedSat)->Arg(0)->Arg(500)->Arg(2000);
BENCHMARK(BM_Clearance);

}  // namespace
}  // namespace parksim
