// Every built-in planner plans for a car on the car scenes (tests/support/CarScenes.h), and each
// plan passes the test-side checker (tests/support/CarPlanChecker.h): no turning in place,
// curvature and steering within the car's limits, speed, acceleration, stops at gear changes,
// no overlap with any obstacle. A car is planned by car-a-star when time-a-star (the default) is
// asked for, and its tree planners steer with Reeds-Shepp curves at its tightest radius.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/planner/base/PlanCheck.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/CarPlanning.h"
#include "tests/support/CarScenes.h"
#include "tests/support/StudyLot.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace car_planners_test {

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

struct Case {
  std::string planner;
  int scene;  // index into carScenes()
};

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  std::string name = info.param.planner + "_" +
                     testing::carScenes()[static_cast<std::size_t>(info.param.scene)].name;
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

class CarPlanners : public ::testing::TestWithParam<Case> {};

TEST_P(CarPlanners, SolveAndThePlanPassesTheCarChecker) {
  const Case c = GetParam();
  const Scenario s = testing::carScenes()[static_cast<std::size_t>(c.scene)];
  const BulletCollisionWorld checker(s);
  const PlanResult r = testing::planForCarTest(s, checker, c.planner);
  ASSERT_TRUE(r.solved()) << s.name << ": " << r.message;
  const auto problems = testing::carPlanViolations(s, r.trajectory);
  EXPECT_TRUE(problems.empty()) << s.name << ":\n" << joined(problems);
  // And parksim's own check, which every plan it did not make gets (PlanCheck.h).
  const std::optional<PlanViolation> v = checkPlan(s, checker, r.trajectory);
  EXPECT_FALSE(v.has_value()) << (v ? v->reason : "");
}

std::vector<Case> allCases() {
  std::vector<Case> out;
  for (const std::string& planner : testing::carTestPlanners()) {
    for (int k = 0; k < static_cast<int>(testing::carScenes().size()); ++k) {
      out.push_back({planner, k});
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, CarPlanners, ::testing::ValuesIn(allCases()), caseName);

TEST(CarPlanning, TimeAStarAndSpinningSteeringGiveWayToTheirCarCounterparts) {
  const Scenario car = testing::carGarageScene();
  PlanSetup setup;  // time-a-star, balkcom-mason steering: the defaults
  const PlanSetup resolved = resolvedPlanSetup(setup, car);
  EXPECT_EQ(resolved.planner, "car-a-star");
  EXPECT_EQ(resolved.steering_kind, SteeringKind::kReedsShepp);
  setup.planner = "rrt";
  setup.steering_kind = SteeringKind::kRotateTranslateRotate;
  EXPECT_EQ(resolvedPlanSetup(setup, car).planner, "rrt");
  EXPECT_EQ(resolvedPlanSetup(setup, car).steering_kind, SteeringKind::kReedsShepp);
  // A differential drive keeps what it asks for.
  Scenario diff = car;
  diff.robot = RobotDef{};
  EXPECT_EQ(resolvedPlanSetup(PlanSetup{}, diff).planner, "time-a-star");
  EXPECT_EQ(resolvedPlanSetup(PlanSetup{}, diff).steering_kind, SteeringKind::kBalkcomMason);
}

TEST(CarPlanning, EachDrivesPlannerCostedByTimeRefusesTheOtherDrive) {
  const Scenario car = testing::carGarageScene();
  const BulletCollisionWorld checker(car);
  const PlanSetup setup;
  const MotionValidator validator(checker, car.robot, car.lot);
  const ReedsSheppSteering steering(car.robot);
  const PlanningProblem problem{car, checker, validator, steering, setup, TimingLimits{}, {}};
  try {
    (void)builtInPlanners().make("time-a-star", {})->solve(problem);
    FAIL() << "time-a-star planned for a car";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("car-a-star"), std::string::npos) << e.what();
  }
  const Scenario diff = testing::studyLot();
  const BulletCollisionWorld diff_checker(diff);
  const MotionValidator diff_validator(diff_checker, diff.robot, diff.lot);
  const PlanningProblem diff_problem{
      diff, diff_checker, diff_validator, steering, setup, TimingLimits{}, {}};
  try {
    (void)builtInPlanners().make("car-a-star", {})->solve(diff_problem);
    FAIL() << "car-a-star planned for a differential drive";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("differential drive"), std::string::npos) << e.what();
  }
  // Asked of planScenario, each gives way to the other.
  PlanSetup asked;
  asked.planner = "car-a-star";
  EXPECT_EQ(resolvedPlanSetup(asked, diff).planner, "time-a-star");
}

}  // namespace car_planners_test
}  // namespace parksim
