// A car's plan along Reeds-Shepp curves (CarPlanAlong.h) passes the test-side car checker
// (tests/support/CarPlanChecker.h) and ends where the curve does: in open space with clothoids
// at the speed limit, next to an obstacle with shorter ones or, at worst, stopping at each
// curvature jump.

#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/planner/motion/CarPath.h"
#include "parksim/planner/motion/CarPlanAlong.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/CarScenes.h"

namespace parksim {
namespace {

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

TEST(CarPlanAlong, ReedsSheppCurvesInOpenSpaceBecomeDrivablePlansEndingAtTheirEnd) {
  Scenario s = testing::car_scenes::carScenario("open", {-100.0, -100.0, 100.0, 100.0}, {}, {});
  const BulletCollisionWorld checker(s);
  const MotionValidator validator(checker, s.robot, s.lot);
  const ReedsSheppSteering curves(s.robot);
  const CarLimits limits = carLimits(s.robot, 0.2, 0.02);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> xy(-30.0, 30.0);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  int full_clothoids = 0;
  for (int k = 0; k < 40; ++k) {
    s.start = {xy(rng), xy(rng), heading(rng)};
    s.goal.pose = {xy(rng), xy(rng), heading(rng)};
    const std::vector<PathPiece> pieces = curves.pieces(s.start, s.goal.pose);
    double share = -1.0;
    const std::optional<Trajectory> plan =
        carPlanAlong(s.start, pieces, s.robot, limits, validator, 1e-3, &share);
    ASSERT_TRUE(plan.has_value()) << k;
    const auto problems = testing::carPlanViolations(s, *plan);
    EXPECT_TRUE(problems.empty()) << k << ":\n" << joined(problems);
    EXPECT_LE(positionDistance(plan->points.back().pose, s.goal.pose), 1e-3) << k;
    if (share == 1.0) ++full_clothoids;
    // Never slower than stopping at every jump, nor faster than the estimate says by much.
    const double estimate = carPlanDuration(pieces, s.robot, limits);
    EXPECT_NEAR(plan->duration(), estimate, 0.05 * estimate + 1.0) << k;
  }
  EXPECT_GE(full_clothoids, 36);
}

}  // namespace
}  // namespace parksim
