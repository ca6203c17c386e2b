// Every built-in planner on the shipped car worlds (worlds/car_*.yaml with robot.drive: car),
// planned as tests/support/CarPlanning.h says: each plan passes the test-side checker
// (tests/support/CarPlanChecker.h) and parksim's own plan check (PlanCheck.h), which every plan
// parksim did not make gets.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/planner/base/PlanCheck.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/CarPlanning.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace car_worlds_planning_test {

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

struct Case {
  std::string planner;
  std::string world;
};

class CarWorlds : public ::testing::TestWithParam<Case> {};

TEST_P(CarWorlds, PlanPassesBothChecks) {
  const Case c = GetParam();
  const Scenario s = loadScenario(parksim::testing::sourceDir() + "/" + c.world + ".yaml");
  ASSERT_TRUE(s.robot.isCar());
  const BulletCollisionWorld checker(s);
  const PlanResult r = testing::planForCarTest(s, checker, c.planner);
  ASSERT_TRUE(r.solved()) << r.message;
  const auto problems = testing::carPlanViolations(s, r.trajectory);
  EXPECT_TRUE(problems.empty()) << joined(problems);
  const std::optional<PlanViolation> v = checkPlan(s, checker, r.trajectory);
  EXPECT_FALSE(v.has_value()) << (v ? v->reason : "");
}

std::vector<Case> allCases() {
  std::vector<Case> out;
  for (const std::string& planner : testing::carTestPlanners()) {
    for (const char* world :
         {"worlds/car_parallel", "worlds/car_bay_forward", "worlds/car_bay_reverse",
          "worlds/car_garage", "worlds/car_lot_100m", "tests/planner/worlds/car_open_lot"}) {
      out.push_back({planner, world});
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Worlds, CarWorlds, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           const std::string& w = info.param.world;
                           std::string name =
                               info.param.planner + "_" + w.substr(w.find_last_of('/') + 1);
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

// In the open lot the default plan takes at most 1.3 times the car's free-space bound as
// plan.json reports it (the Reeds-Shepp length driven from rest to rest at the limits), which
// the test works out itself: L / v + v / a, in continuous time.
TEST(CarWorlds, DefaultPlanInTheOpenLotIsWithinOnePointThreeOfTheFreeSpaceBound) {
  const Scenario s =
      loadScenario(parksim::testing::sourceDir() + "/tests/planner/worlds/car_open_lot.yaml");
  const BulletCollisionWorld checker(s);
  const PlanResult r = planScenario(s, checker, PlanSetup{});
  ASSERT_TRUE(r.solved()) << r.message;
  const double length = ReedsSheppSteering(s.robot).distance(s.start, s.goal.pose);
  const double v = s.robot.max_speed_mps;
  const double a = s.robot.max_accel_mps2;
  ASSERT_GE(length, v * v / a);
  const double bound = length / v + v / a;
  EXPECT_LE(r.trajectory.duration(), 1.3 * bound) << "bound " << bound << " s";
  // plan.json's bound counts rows 0.02 s apart, which may start at one acceleration step.
  EXPECT_NEAR(r.free_space_bound_s, bound, 0.05);
}

}  // namespace car_worlds_planning_test
}  // namespace parksim
