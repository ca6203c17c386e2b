// time-a-star, parksim's default planner: Hybrid A* whose cost is the plan's duration
// (TimeAStar.h), as a registered Planner. It smooths and times each path it finds itself.

#include <memory>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/base/Planner.h"
#include "parksim/planner/search/ReachableBudget.h"
#include "parksim/planner/search/TimeAStar.h"

namespace parksim {

namespace {

class TimeAStarPlanner : public Planner {
 public:
  explicit TimeAStarPlanner(const TimeAStarDef& def) : def_(def) {}

  PlanResult solve(const PlanningProblem& p) override {
    const Scenario& s = p.scenario;
    if (s.robot.isCar()) {
      throw Error(
          "time-a-star turns in place, which a car cannot: a car is planned by car-a-star "
          "(planScenario chooses it for time-a-star)");
    }
    // The obstacles' shapes make the heuristic's grid (FootprintFit.h), a tenth of the cost of
    // footprint queries.
    const TimeAStar planner(s.robot, s.lot, p.validator, p.search(), def_, p.limits,
                            p.setup.smoothing, &s.obstacles);
    return planner.solve(s.start, s.goal, p.progress);
  }

 private:
  TimeAStarDef def_;
};

void bind(TimeAStarDef& d, ParamSet& s) {
  s.add("cell_m", &d.cell_m, "(x, y) cell side, m; 0: the footprint radius / 4", 0.0, 1e3);
  s.add("heading_bins", &d.heading_bins, "heading cells", 4, 3600);
  s.add("step_m", &d.step_m, "straight and arc move length, m; 0: 1.5 cells", 0.0, 1e3);
  s.add("arc_radii_m", &d.arc_radii_m, "arc radii of the moves, m", 1e-6, 1e6, 16);
  s.add("spin_angles_rad", &d.spin_angles_rad, "turns in place, rad", 1e-6, 6.3, 16);
  s.add("heuristic_weight", &d.heuristic_weight, "f = g + w h of the first search", 1.0, 100.0);
  s.add("anytime_weight_step", &d.anytime_weight_step,
        "weight decrease between anytime searches (with a time budget)", 1e-3, 100.0);
  s.add("analytic_near_s", &d.analytic_near_s,
        "analytic expansion from every node whose heuristic is below this, s", 0.0, 1e6);
  s.add("analytic_interval", &d.analytic_interval,
        "analytic expansion from every n-th expanded node otherwise", 1, 1000000);
  s.add("from_goal", &d.from_goal, "search from the goal back to the start");
  s.add("fine_zone_m", &d.fine_zone_m,
        "fine zone radius when the coarse search runs dry, m; < 0: twice the footprint radius, "
        "0: none",
        -1.0, 1e3);
  s.add("fine_cell_m", &d.fine_cell_m, "cell side in the fine zone, m", 1e-4, 1e3);
  s.add("fine_heading_bins", &d.fine_heading_bins, "heading cells in the fine zone", 4, 3600);
  s.add("fine_step_m", &d.fine_step_m, "move length in the fine zone, m", 1e-4, 1e3);
  s.add("fine_spin_angles_rad", &d.fine_spin_angles_rad, "turns in place in the fine zone, rad",
        1e-6, 6.3, 16);
  s.add("window_min_margin_m", &d.window.min_margin_m,
        "the search window reaches at least this far beyond start and goal, m", 1e-6, 1e6);
  s.add("window_margin_fraction", &d.window.margin_fraction,
        "... and at least this fraction of their distance", 0.0, 100.0);
  s.add("max_heuristic_cells_per_side", &d.max_heuristic_cells_per_side,
        "the obstacle heuristic's grid cells along the window's longer side", 1, 4000);
}

}  // namespace

PlannerEntry timeAStarPlanner() {
  PlannerInfo info;
  info.name = "time-a-star";
  info.description =
      "Hybrid A* costed by driving time, spins in place, time-optimal free-space expansion";
  // Its window, not the lot, sets the size of its search (SearchWindow.h): 200,000 expansions,
  // or 8 per search cell (of its 72 headings; cells of footprint radius / 4, TimeAStarDef's
  // default) of the free area it can reach from the start (ReachableBudget.h), whichever is more.
  info.default_budget = [](const Scenario& s) {
    const double cell = 0.25 * footprintRadius(s.robot);
    return boundedBudget(8.0 * reachableFreeArea(s) / (cell * cell), 200000);
  };
  return plannerEntry<TimeAStarPlanner>(std::move(info), TimeAStarDef{}, &bind);
}

}  // namespace parksim
