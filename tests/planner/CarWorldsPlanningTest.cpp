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
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/CarPlanning.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

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
  const Scenario s = loadScenario(parksim::testing::sourceDir() + "/worlds/" + c.world + ".yaml");
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
         {"car_parallel", "car_bay_forward", "car_bay_reverse", "car_garage", "car_lot_100m"}) {
      out.push_back({planner, world});
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Worlds, CarWorlds, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.planner + "_" + info.param.world;
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace parksim
