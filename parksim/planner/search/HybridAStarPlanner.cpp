// hybrid-a-star: Hybrid A* with Reeds-Shepp curves (HybridAStar.h) as a registered Planner,
// smoothed and timed by PlanFinishing.h (for a car: without the moves a car cannot make, and
// made a car's plan).

#include <memory>

#include "parksim/planner/base/PlanFinishing.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/base/Planner.h"
#include "parksim/planner/base/PlannerRegistry.h"
#include "parksim/planner/search/HybridAStar.h"
#include "parksim/planner/search/ReachableBudget.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"

namespace parksim {

namespace {

class HybridAStarPlanner : public Planner {
 public:
  explicit HybridAStarPlanner(const HybridAStarDef& def) : def_(def) {}

  PlanResult solve(const PlanningProblem& p) override {
    const Scenario& s = p.scenario;
    // The setup's Reeds-Shepp curves give its primitives' turning radius and its analytic
    // expansion, whatever the setup's steering function.
    const ReedsSheppSteering curves(s.robot, p.setup.reeds_shepp);
    HybridAStarDef def = def_;
    if (s.robot.isCar()) {
      // A car turns neither in place nor tighter than its own radius (the curves' for a car);
      // the fine zone's lengths, the study robot's, are taken in the car's size.
      def.tight_turning_radius_m = 0.0;
      def.turn_in_place_rad = 0.0;
      def.fine_turn_in_place_rad = 0.0;
      def.fine_cell_m *= s.robot.sizeScale();
      def.fine_step_m *= s.robot.sizeScale();
    }
    // A car's moves keep the clearance that lets its plan along them validate (PlanFinishing.h).
    const std::unique_ptr<ClearanceValidator> clear = carSearchValidation(p);
    const HybridAStar planner(s.robot, s.lot, curves, clear ? clear->validator() : p.validator,
                              p.search(), def);
    PlanResult result = planner.solve(s.start, s.goal, p.progress);
    // It times its own plan; smoothed under study timing, it keeps that timing's limits.
    if (result.solved()) finishPlan(p, p.search().smooth, result);
    return result;
  }

 private:
  HybridAStarDef def_;
};

void bind(HybridAStarDef& d, ParamSet& s) {
  s.add("cell_m", &d.cell_m, "(x, y) cell side, m; 0: the footprint radius / 4", 0.0, 1e3);
  s.add("heading_bins", &d.heading_bins, "heading cells", 4, 3600);
  s.add("step_m", &d.step_m, "primitive arc length, m; 0: 1.5 cells", 0.0, 1e3);
  s.add("tight_turning_radius_m", &d.tight_turning_radius_m, "arcs of this radius too, m (0: none)",
        0.0, 1e6);
  s.add("from_goal", &d.from_goal, "search from the goal back to the start");
  s.add("fine_zone_m", &d.fine_zone_m,
        "fine zone radius when the coarse search runs dry, m; < 0: twice the footprint radius, "
        "0: none",
        -1.0, 1e3);
  s.add("fine_cell_m", &d.fine_cell_m, "cell side in the fine zone, m", 1e-4, 1e3);
  s.add("fine_heading_bins", &d.fine_heading_bins, "heading cells in the fine zone", 4, 3600);
  s.add("fine_step_m", &d.fine_step_m, "primitive arc length in the fine zone, m", 1e-4, 1e3);
  s.add("fine_turn_in_place_rad", &d.fine_turn_in_place_rad, "turn in place in the fine zone, rad",
        0.0, 6.3);
  s.add("turn_in_place_rad", &d.turn_in_place_rad, "turn-in-place primitive, rad (0: none)", 0.0,
        6.3);
  s.add("analytic_near_steps", &d.analytic_near_steps,
        "analytic expansion from every node whose heuristic is below this many steps", 0.0, 1e6);
  s.add("analytic_interval", &d.analytic_interval,
        "analytic expansion from every n-th expanded node otherwise", 1, 1000000);
  s.add("heuristic_weight", &d.heuristic_weight, "f = g + w h", 1.0, 100.0);
}

}  // namespace

PlannerEntry hybridAStarPlanner() {
  PlannerInfo info;
  info.name = "hybrid-a-star";
  info.description = "Hybrid A* with Reeds-Shepp curves, then smoothed and timed";
  // 20,000 expansions per study lot of the free area it can reach from the start
  // (ReachableBudget.h), measured in the robot's size as its cells are (lotSizeInStudyLots), at
  // least the lot's.
  info.default_budget = [](const Scenario& s) {
    const double scale = s.robot.sizeScale();  // exactly 1 for the study's robot
    return boundedBudget(20000.0 * reachableFreeArea(s) / (kStudyLotAreaM2 * scale * scale),
                         lotScaledBudget(20000, s));
  };
  return plannerEntry<HybridAStarPlanner>(std::move(info), HybridAStarDef{}, &bind);
}

}  // namespace parksim
