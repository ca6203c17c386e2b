#include "parksim/planner/base/PlannerRegistry.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "parksim/core/io/Error.h"

namespace parksim {

// Each built-in planner's file defines its entry (one concept per file); this is their list, in
// the order help texts and benchmarks show them. A new built-in planner: its file, and a line
// here.
std::vector<PlannerEntry> treePlanners();  // TreePlanners.cpp: rrt, rrt-goal-connect, ...
PlannerEntry hybridAStarPlanner();         // HybridAStarPlanner.cpp
PlannerEntry timeAStarPlanner();           // TimeAStarPlanner.cpp
PlannerEntry carAStarPlanner();            // CarAStarPlanner.cpp

const PlannerRegistry& builtInPlanners() {
  static const PlannerRegistry registry = [] {
    PlannerRegistry r;
    for (PlannerEntry& e : treePlanners()) r.add(std::move(e));
    r.add(hybridAStarPlanner());
    r.add(timeAStarPlanner());
    r.add(carAStarPlanner());
    return r;
  }();
  return registry;
}

std::string plannerFor(const std::string& planner, const RobotDef& robot) {
  // time-a-star's moves turn in place; car-a-star is its car counterpart (costed by time too).
  if (robot.isCar() && planner == "time-a-star") return "car-a-star";
  if (!robot.isCar() && planner == "car-a-star") return "time-a-star";
  return planner;
}

double lotSizeInStudyLots(const Scenario& scenario) {
  const LotBounds& lot = scenario.lot;
  const double area = (lot.x_max_m - lot.x_min_m) * (lot.y_max_m - lot.y_min_m);
  // In the robot's own units: a car's tree grows in car-sized steps. The study's robot has
  // sizeScale() exactly 1, so its budgets are those of lot area / 2.16 m^2, to the bit.
  const double scale = scenario.robot.sizeScale();
  return area / (kStudyLotAreaM2 * scale * scale);
}

int lotScaledBudget(int base, const Scenario& scenario) {
  // Capped so that a lot of kilometres still gets a bounded search (and no int overflow).
  constexpr double kMaxDefaultBudget = 1'000'000.0;
  return static_cast<int>(
      std::min(kMaxDefaultBudget, std::ceil(base * std::max(1.0, lotSizeInStudyLots(scenario)))));
}

int defaultIterationBudget(const PlannerInfo& info, const Scenario& scenario) {
  if (info.default_budget) return info.default_budget(scenario);
  return lotScaledBudget(2000, scenario);
}

}  // namespace parksim
