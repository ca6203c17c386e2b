// Every built-in planner on the shipped car worlds (worlds/car_*.yaml with robot.drive: car):
// each plan passes the test-side checker (tests/support/CarPlanChecker.h) and parksim's own plan
// check (PlanCheck.h), which every plan parksim did not make gets.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/planner/base/PlanCheck.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/scenario/ScenarioReader.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

struct Case {
  const char* planner;
  const char* world;
};

class CarWorlds : public ::testing::TestWithParam<Case> {};

TEST_P(CarWorlds, PlanPassesBothChecks) {
  const Case c = GetParam();
  const Scenario s =
      loadScenario(parksim::testing::sourceDir() + "/worlds/" + c.world + ".yaml");
  ASSERT_TRUE(s.robot.isCar());
  const BulletCollisionWorld checker(s);
  PlanSetup setup;
  setup.planner = c.planner;
  setup.search.record_tree = false;
  const PlanResult r = planScenario(s, checker, setup);
  ASSERT_TRUE(r.solved()) << r.message;
  std::printf("%s %s: %.3f s, plan %.2f s\n", c.planner, c.world, r.stats.times.total_s, r.trajectory.duration());
  const auto problems = testing::carPlanViolations(s, r.trajectory);
  EXPECT_TRUE(problems.empty()) << joined(problems);
  const std::optional<PlanViolation> v = checkPlan(s, checker, r.trajectory);
  EXPECT_FALSE(v.has_value()) << (v ? v->reason : "");
}

std::vector<Case> allCases() {
  std::vector<Case> out;
  for (const char* planner : {"car-a-star", "hybrid-a-star", "rrt-connect"}) {
    for (const char* world :
         {"car_parallel", "car_bay_forward", "car_bay_reverse", "car_garage", "car_lot_100m"}) {
      out.push_back({planner, world});
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Worlds, CarWorlds, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = std::string(info.param.planner) + "_" +
                                              info.param.world;
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace parksim
