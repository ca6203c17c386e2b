#include "parksim/planner/tree/ShortcutSmoother.h"

#include <gtest/gtest.h>

#include "parksim/planner/steering/MoveToPoseSteering.h"
#include "parksim/planner/steering/RotateTranslateRotateSteering.h"
#include "tests/support/PlanChecks.h"

namespace parksim {
namespace {

using testing::SatChecker;

// A zigzag through an empty lot, one rest-to-rest segment per leg.
std::vector<PathSegment> zigzag(const SteeringFunction& steering, const Pose2& goal) {
  const std::vector<Pose2> via = {{0.2, 0.2, 0.0}, {0.4, 0.6, 1.0},  {0.6, 0.2, -1.0},
                                  {0.8, 0.6, 1.0}, {1.0, 0.2, -1.0}, {1.2, 0.6, 0.5},
                                  {1.4, 0.2, 0.0}};
  std::vector<PathSegment> plan;
  for (std::size_t i = 0; i + 1 < via.size(); ++i) {
    plan.push_back({steering.steer(via[i], {}, via[i + 1], SteerMode::kExact).trajectory, true});
  }
  plan.push_back({steering.steer(via.back(), {}, goal, SteerMode::kToGoal).trajectory, true});
  return plan;
}

TEST(ShortcutSmoother, StraightensAZigzagInAnEmptyLot) {
  Scenario s;
  s.start = {0.2, 0.2, 0.0};
  s.goal.pose = {1.6, 0.4, 0.0};
  const SatChecker checker(s);
  const MotionValidator validator(checker, s.robot, s.lot);
  const CostWeights w{1.0, 0.1};
  for (int which = 0; which < 2; ++which) {
    const MoveToPoseSteering controller(s.robot);
    const RotateTranslateRotateSteering rtr(s.robot);
    const SteeringFunction& steering =
        which == 0 ? static_cast<const SteeringFunction&>(controller) : rtr;
    const std::vector<PathSegment> plan = zigzag(steering, s.goal.pose);
    std::mt19937_64 rng(1);
    SmoothingStats stats;
    const ShortcutSmoother smoother(s.robot, steering, validator, w);
    const std::vector<PathSegment> smoothed = smoother.smooth(plan, s.goal.pose, 50, rng, &stats);
    // It stops early once the plan is a single segment.
    EXPECT_LE(stats.attempts, 50);
    EXPECT_GT(stats.accepted, 0);
    EXPECT_LT(smoothed.size(), plan.size());
    EXPECT_LT(segmentsCost(smoothed, s.robot, w), 0.8 * segmentsCost(plan, s.robot, w));
    const Trajectory t = joinSegments(smoothed, s.robot);
    EXPECT_TRUE(validator.isValid(t));
    testing::expectConsistentWithLimits(t, s.robot);
    testing::expectCollisionFree(s, t);
    testing::expectEndsInGoal(s.goal, t);
    EXPECT_EQ(t.points.front().pose, s.start);
  }
}

TEST(ShortcutSmoother, KeepsThePlanWhenTheShortcutCollides) {
  Scenario s;
  s.start = {0.2, 0.2, 0.0};
  s.goal.pose = {1.4, 0.2, 0.0};
  Obstacle block;  // on the straight line from start to goal, not on the detour over it
  block.name = "block";
  block.box.center = {0.8, 0.2};
  block.box.half_extents = {0.1, 0.15};
  s.obstacles.push_back(block);
  const SatChecker checker(s);
  const MotionValidator validator(checker, s.robot, s.lot);
  const RotateTranslateRotateSteering rtr(s.robot);
  const Pose2 over{0.8, 0.6, 0.0};
  const std::vector<PathSegment> plan = {
      {rtr.steer(s.start, {}, over, SteerMode::kExact).trajectory, true},
      {rtr.steer(over, {}, s.goal.pose, SteerMode::kToGoal).trajectory, true}};
  ASSERT_TRUE(validator.isValid(joinSegments(plan, s.robot))) << "test setup";
  std::mt19937_64 rng(2);
  SmoothingStats stats;
  const ShortcutSmoother smoother(s.robot, rtr, validator, {1.0, 0.1});
  const std::vector<PathSegment> smoothed = smoother.smooth(plan, s.goal.pose, 20, rng, &stats);
  EXPECT_EQ(stats.attempts, 20);
  EXPECT_EQ(stats.accepted, 0);
  EXPECT_EQ(stats.validated, 1);  // the one shortcut was checked once, then remembered
  ASSERT_EQ(smoothed.size(), plan.size());
  for (std::size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ(smoothed[i].trajectory, plan[i].trajectory);
  }
}

}  // namespace
}  // namespace parksim
