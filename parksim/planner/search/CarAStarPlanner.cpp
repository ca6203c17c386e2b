// car-a-star, the default planner of a car: Hybrid A* with a car's moves costed by driving time
// (CarAStar.h) as a registered Planner, smoothed and made a car's plan by PlanFinishing.h.

#include <memory>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/base/PlanFinishing.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/base/Planner.h"
#include "parksim/planner/base/PlannerRegistry.h"
#include "parksim/planner/search/CarAStar.h"
#include "parksim/planner/search/ReachableBudget.h"

namespace parksim {

namespace {

class CarAStarPlanner : public Planner {
 public:
  explicit CarAStarPlanner(const CarAStarDef& def) : def_(def) {}

  PlanResult solve(const PlanningProblem& p) override {
    const Scenario& s = p.scenario;
    if (!s.robot.isCar()) {
      throw Error(
          "car-a-star plans for a car (robot.drive: car); this robot is a differential drive "
          "(time-a-star plans for it)");
    }
    const CarLimits limits = carLimits(s.robot, p.setup.feedback_headroom, p.setup.timing_period_s);
    // Moves keep the clearance that lets the car's plan along them validate (PlanFinishing.h).
    const std::unique_ptr<ClearanceValidator> clear = carSearchValidation(p);
    const CarAStar planner(s.robot, s.lot, clear->validator(), p.search(), def_, limits,
                           &s.obstacles);
    PlanResult result = planner.solve(s.start, s.goal, p.progress);
    if (result.solved()) finishPlan(p, p.search().smooth, result);
    return result;
  }

 private:
  CarAStarDef def_;
};

void bind(CarAStarDef& d, ParamSet& s) {
  s.add("cell_m", &d.cell_m, "(x, y) cell side, m; 0: the footprint radius / 8", 0.0, 1e3);
  s.add("heading_bins", &d.heading_bins, "heading cells", 4, 3600);
  s.add("step_m", &d.step_m, "move length, m; 0: 1.5 cells", 0.0, 1e3);
  s.add("curvature_steps", &d.curvature_steps,
        "curvatures of the moves up to the tightest, each way", 1, 16);
  s.add("heuristic_weight", &d.heuristic_weight, "f = g + w h", 1.0, 100.0);
  s.add("gear_change_penalty_s", &d.gear_change_penalty_s,
        "cost of a gear change besides its stop and steering, s", 0.0, 1e4);
  s.add("analytic_near_s", &d.analytic_near_s,
        "analytic expansion from every node whose heuristic is below this, s", 0.0, 1e6);
  s.add("analytic_interval", &d.analytic_interval,
        "analytic expansion from every n-th expanded node otherwise", 1, 1000000);
  s.add("from_goal", &d.from_goal, "search from the goal back to the start");
  s.add("fine_zone_m", &d.fine_zone_m,
        "fine zone radius when the coarse search runs dry, m; < 0: twice the footprint radius, "
        "0: none",
        -1.0, 1e4);
  s.add("fine_scale", &d.fine_scale, "fine cells and moves per coarse ones", 0.01, 0.99);
  s.add("window_min_margin_m", &d.window.min_margin_m,
        "the search window reaches at least this far beyond start and goal, m", 1e-6, 1e6);
  s.add("window_margin_fraction", &d.window.margin_fraction,
        "... and at least this fraction of their distance", 0.0, 100.0);
  s.add("heuristic_cell_m", &d.heuristic_cell_m,
        "the obstacle heuristic's grid cell side, m; 0: twice the search cells", 0.0, 1e3);
  s.add("max_heuristic_cells_per_side", &d.max_heuristic_cells_per_side,
        "the obstacle heuristic's grid cells along the window's longer side", 1, 4000);
}

}  // namespace

PlannerEntry carAStarPlanner() {
  PlannerInfo info;
  info.name = "car-a-star";
  info.description =
      "Hybrid A* for a car: arcs up to its tightest, forward and reverse, costed by time";
  // 8 expansions per search cell (72 headings; cells of footprint radius / 8, CarAStarDef's
  // default) of the free area it can reach from the start, at least 20,000.
  info.default_budget = [](const Scenario& s) {
    const double cell = 0.125 * footprintRadius(s.robot);
    return boundedBudget(8.0 * reachableFreeArea(s) / (cell * cell), 20000);
  };
  return plannerEntry<CarAStarPlanner>(std::move(info), CarAStarDef{}, &bind);
}

}  // namespace parksim
